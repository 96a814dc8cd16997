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
     * @name Built-in 3D cases
     *
     * Hexahedral meshes, x = east, y = north, z = up; a plane's orientation
     * is its dip and dip direction (see parameters::PlaneOrientation). The
     * block and face group names are part of the interface: the .prm files
     * refer to them.
     */
    /** @{ */

    /**
     * A tetrahedral rock wedge in a slope, cut off by the joint planes A and
     * B (Hoek and Bray's wedge). The wedge's corners are
     * wedge.corners(): the apex at the origin, on the toe of the slope face
     * (z = 0), where the line of intersection of A and B daylights; the top
     * of that line on the upper slope; and the two ends of the crest edge.
     * The crest passes through wedge.crest_point(), at z = H.
     *
     * The rock is a box in the frame of the face's strike: it reaches the
     * Rock extent E beyond the wedge along the strike, behind it and below
     * it (the base is at z = -E), and E in front of the toe. Its top is the
     * upper slope; in front, the slope face rises from the toe to the crest
     * and the ground in front of the toe is horizontal (z = 0). The wedge
     * is taken out of it; the faces on A and B are shared (OpenCASCADE
     * BooleanFragments), so their vertices are the same on both sides.
     *
     * Blocks "wedge" and "rock". Face groups, in this order: "plane A" and
     * "plane B" (the faces between the wedge and the rock), "slope face"
     * (the free surface below the crest: the slope face, on both blocks,
     * and the ground in front of the toe), "upper slope" (both blocks),
     * "base" (z = -E) and "sides" (the vertical faces of the box: the two
     * ends along the strike, the back, and the front below the ground in
     * front of the toe). Only the rock touches the base and the sides.
     *
     * Gmsh meshes the model with Delaunay tetrahedra of size 2 h (h = Mesh
     * size) in the wedge and up to its inradius from its faces, growing by
     * a quarter of the further distance up to 10 h, and splits each into
     * four hexahedra (Mesh.SubdivisionAlgorithm = 2): in and near the
     * wedge their edges are about h/3 to h long, 0.65 h on average. The
     * split hexahedra have flat faces, so the wedge's volume is exact.
     */
    MeshDescription<3>
    make_wedge_mesh(const parameters::GeometryParameters::Wedge &wedge);

    /**
     * A block on an inclined plane through the origin, structured
     * hexahedra. It is built in the plane's frame (x down the dip, y along
     * the strike, z normal to the plane): the block
     * [0, L] x [-B/2, B/2] x [0, H] with the given numbers of elements,
     * and the foundation slab [-o, L + o] x [-B/2 - o, B/2 + o] x [-T, 0]
     * with elements of the block's size (at least one across the overhang
     * o and the thickness T), its top split at the block's edges. Then it
     * is rotated by block.rotation(), so that the plane has the given dip
     * and dip direction and the block's length runs down the dip.
     *
     * Blocks "block" and "foundation". Face groups, in this order:
     * "sliding surface" (the block's bottom = the foundation's top under
     * it, the same vertices), "block surface" (the block's other five
     * faces), "foundation surface" (the uncovered top of the slab),
     * "foundation base" (its bottom) and "foundation ends" (its four side
     * faces).
     */
    MeshDescription<3>
    make_block_on_plane_mesh(
      const parameters::GeometryParameters::BlockOnPlane &block_on_plane);

    /**
     * Quarter model (x >= 0, y >= 0) of a sphere of radius R on a
     * foundation, for Hertz point contact, structured hexahedra. Blocks
     * "sphere" (the ball of centre (0, 0, R) cut by the planes x = S,
     * y = S and z = H: points of the ball with x, y in [0, S] and z <= H)
     * and "foundation" ([0, W] x [0, W] x [-D, 0]); they share the vertex
     * at the origin.
     *
     * Both blocks use the same grid lines in x and y: Lc/n apart on
     * [0, Lc] (the contact zone), then growing by the growth ratio up to
     * the mesh size, to S (sphere) and on to W (foundation). The
     * foundation's layers are Lc/n thick down to z = -Lc, then grow to D;
     * the sphere's layers follow its surface z = R - sqrt(R^2 - x^2 - y^2)
     * with the same sizes up to the top z = H. So every node of the
     * sphere's surface in the contact zone lies straight above a node of
     * the foundation's top, at the initial gap of the sphere's surface.
     *
     * Face groups, in this order: "contact surface" (the sphere's surface
     * and the foundation's top over [0, Lc]^2), "load" (z = H), "symmetry"
     * (x = 0 and y = 0, both blocks), "bottom" (z = -D), "sphere surface"
     * (the rest of the sphere's surface and its faces x = S, y = S),
     * "foundation surface" (the rest of z = 0) and "foundation side"
     * (x = W, y = W).
     */
    MeshDescription<3>
    make_hertz_sphere_mesh(
      const parameters::GeometryParameters::HertzSphere &hertz_sphere);

    /** @} */
  } // namespace geometry
} // namespace fdem
