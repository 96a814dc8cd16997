// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/geometry/cases/slope.h>

#include <deal.II/base/point.h>

#include <array>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    /**
     * The cuts of a slope with a polyline sliding surface: the tension crack
     * at its crest end and the interslice surfaces from its interior
     * vertices up to the ground (Geometry/Slope: Interslice surfaces, Tension
     * crack depth). Pure geometry, computed before Gmsh runs so that
     * Slope::validate() can refuse bad input with one line.
     */
    namespace slope_interslices
    {
      /** Where the sliding mass is cut. */
      struct Cuts
      {
        /** The sliding surface from left to right, ending at the crack. */
        std::vector<Point<2>> surface;
        /** Whether there is a tension crack. */
        bool crack = false;
        /** Whether the crack is at the right end (the crest) of the surface. */
        bool crack_at_right = true;
        /** Bottom (on the sliding surface) and top (on the ground) of the
         * crack. */
        Point<2> crack_bottom, crack_top;
        /** Elevation of the water in the crack; below crack_bottom: dry. */
        double crack_water_level = 0;
        /** Each interslice: its bottom (a vertex) and its top (on the ground).
         */
        std::vector<std::array<Point<2>, 2>> interslices;
      };

      /**
       * The cuts of @p slope (a polyline sliding surface). Throws a
       * one-sentence message naming the entry when an interslice does not
       * reach the ground inside the sliding mass, the inclination list has
       * the wrong length, or the crack is deeper than the sliding mass.
       */
      Cuts
      slope_cuts(const Slope &slope);

      /**
       * The region above the sliding surface, closed by the tension crack:
       * its intersection with the model is the sliding mass. @p top is an
       * elevation above the whole model.
       */
      std::vector<Point<2>>
      region_above(const Cuts &cuts, const double top);

      /**
       * Cuts the OpenCASCADE surface @p mass by the interslices (fragmented
       * together with @p foundation, which keeps the shared curves
       * conforming) and synchronises. Returns the pieces of the mass ordered
       * from left to right; @p foundation becomes its new tag.
       */
      std::vector<int>
      cut_sliding_mass(const int mass, int &foundation, const Cuts &cuts);

      /**
       * The curves of the vertical tension crack among @p curves (those
       * between the mass and the foundation); they are removed from
       * @p curves.
       */
      std::vector<int>
      take_crack_curves(std::vector<int> &curves,
                        const Cuts       &cuts,
                        const double      tolerance);
    } // namespace slope_interslices
  }   // namespace geometry
} // namespace fdem
