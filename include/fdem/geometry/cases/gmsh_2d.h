// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <deal.II/base/point.h>

#include <vector>

namespace fdem
{
  namespace geometry
  {
    using namespace dealii;

    /**
     * Gmsh settings that the 2D cases made by Gmsh (slope, hertz) share. All
     * need an active GmshSession.
     */
    namespace gmsh_2d
    {
      /**
       * Element size @p size_near on @p curves and up to @p fine_distance
       * from them, then growing linearly with the distance to @p size_far.
       * The growth rate of 0.25 keeps neighbouring elements within about 25%
       * of each other's size. The sizes are those of the final mesh: for
       * quadrilaterals Gmsh meshes at twice the size and then subdivides
       * (see set_unstructured_quad_options()); triangles (@p subdivided
       * false) are meshed at the size itself.
       */
      void
      set_size_field(const std::vector<int> &curves,
                     const double            size_near,
                     const double            size_far,
                     const double            fine_distance = 0,
                     const bool              subdivided    = true);

      /**
       * Unstructured quadrilaterals, guaranteed: Frontal-Delaunay triangles,
       * merged into quadrilaterals by the Blossom matching where possible,
       * then every element is subdivided (a quadrilateral into 4, a triangle
       * left over into 3 quadrilaterals), which halves the element size.
       * Recombination alone left triangles in the slope; Algorithm 8
       * (Frontal-Delaunay for quads) crashes in Debian's Gmsh 4.8.4.
       */
      void
      set_unstructured_quad_options();

      /**
       * Frontal-Delaunay triangles, neither recombined nor subdivided (Gmsh
       * keeps options from one session to the next in a process, so they
       * are set here, not left at their defaults).
       */
      void
      set_triangle_options();

      /** OpenCASCADE plane surface bounded by the closed polygon @p corners. */
      int
      add_occ_polygon(const std::vector<Point<2>> &corners);
    } // namespace gmsh_2d
  }   // namespace geometry
} // namespace fdem
