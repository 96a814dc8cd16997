// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/geometry/cases/case_input.h>
#include <fdem/geometry/mesh_description.h>

#include <deal.II/base/parameter_handler.h>

namespace fdem
{
  namespace geometry
  {
    /**
     * The case "hertz" (2D), subsection "Geometry/Hertz": a cylinder pressed
     * onto a foundation, as the half model (x >= 0) or the full model,
     * lengths in the user's unit (e.g. mm); made by Gmsh
     * (make_hertz_mesh()).
     */
    struct Hertz
    {
      double radius;
      double foundation_width;
      double foundation_depth;
      /** Length from the axis over which both sides have nodes at equal x. */
      double       contact_zone_width;
      unsigned int n_contact_zone_elements;
      /** Element size far from the contact zone. */
      double mesh_size;
      /**
       * Whether to model the whole width (the half model and its mirror
       * image in x = 0) instead of the half model x >= 0.
       */
      bool full_model = false;
      /** Quadrilaterals or triangles. */
      ElementShape element_shape = ElementShape::hypercube;

      /** Declare the subsection "Hertz" (inside "Geometry"). */
      static void
      declare_parameters(ParameterHandler &prm);

      /** Read the subsection "Hertz" (inside "Geometry"). */
      void
      parse_parameters(ParameterHandler &prm);

      /** Throw a one-sentence message naming the entry if the data are
       * invalid. */
      void
      validate() const;
    };

    /**
     * Half model (x >= 0) of a cylinder of radius r on a foundation. Blocks
     * "cylinder" (the lower quarter: x in [0, r], y <= r, inside the circle
     * of centre (0, r), touching the foundation at the origin) and
     * "foundation" ([0, W] x [-D, 0]); they share the vertex at the origin.
     * Face groups "contact surface" (the arc and the foundation top for x in
     * [0, contact zone width], on both blocks), "load" (y = r), "symmetry"
     * (x = 0, both blocks), "bottom" (y = -D), "cylinder surface" (rest of
     * the arc), "foundation surface" (rest of y = 0), "foundation side"
     * (x = W). In the contact zone both sides have vertices at exactly
     * x_i = i Lc / N, so that pairs can be found along the vertical.
     *
     * With hertz.full_model, the full model: the half model's mesh and its
     * mirror image in x = 0, joined along the axis, so that the mesh is
     * exactly symmetric. Blocks "cylinder" (the lower half: |x| <= r,
     * y <= r) and "foundation" ([-W, W] x [-D, 0]). Face groups, in this
     * order: "contact surface" (|x| <= Lc on both blocks, 2N faces on each,
     * vertices at x_i for i = -N..N), "load" (y = r, x from -r to r),
     * "bottom", "cylinder surface", "foundation surface" and "foundation
     * side" (x = -W and x = W), each on both sides; there is no "symmetry".
     * Opens its own GmshSession.
     */
    MeshDescription<2>
    make_hertz_mesh(const Hertz &hertz);
  } // namespace geometry
} // namespace fdem
