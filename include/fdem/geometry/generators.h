// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/geometry/mesh_description.h>
#include <fdem/parameters/geometry_parameters.h>

namespace fdem
{
  namespace geometry
  {
    /**
     * @name Built-in cases
     *
     * Each generator builds its case as a Gmsh model, meshes it with
     * quadrilaterals only and returns extract_current_gmsh_model<2>(). Each
     * opens its own GmshSession. The block and face group names are part of
     * the interface: the .prm files refer to them.
     */
    /** @{ */

    /**
     * A slope (the ground polyline closed down to the base elevation) split
     * by a circular or polyline sliding surface. Blocks "sliding mass" (the
     * part of the slope inside the circle, or above the polyline) and
     * "foundation". Face groups "sliding surface" (the curve between the two
     * blocks, with the same nodes on both sides), "ground" (the whole top
     * surface), "left", "right", "bottom". The elements have the size
     * mesh_size_on_sliding_surface there and grow to mesh_size away from it.
     */
    MeshDescription<2>
    make_slope_mesh(const parameters::GeometryParameters::Slope &slope);

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
     */
    MeshDescription<2>
    make_hertz_mesh(const parameters::GeometryParameters::Hertz &hertz);

    /**
     * A block on a plane through the origin inclined by theta (direction
     * (cos theta, sin theta)), structured quadrilaterals. Blocks "block"
     * (length L along the plane from 0, height H normal to it) and
     * "foundation" (a slab of thickness T under the plane from -overhang to
     * L + overhang). Face groups "sliding surface" (block bottom = foundation
     * top under it, same nodes), "block surface", "foundation surface" (the
     * uncovered top), "foundation base", "foundation ends".
     */
    MeshDescription<2>
    make_inclined_block_mesh(
      const parameters::GeometryParameters::InclinedBlock &inclined_block);

    /** @} */
  } // namespace geometry
} // namespace fdem
