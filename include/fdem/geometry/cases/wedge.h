// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/geometry/cases/case_input.h>
#include <fdem/geometry/mesh_description.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <array>

namespace fdem
{
  namespace geometry
  {
    /**
     * The case "wedge" (3D), subsection "Geometry/Wedge": a tetrahedral rock
     * wedge cut from a slope by two joint planes A and B, made by Gmsh
     * (make_wedge_mesh()). The apex of the wedge, where the line of
     * intersection of A and B daylights in the slope face, is the origin,
     * on the toe of the slope face (z = 0); the crest passes through the
     * point at height H straight up the face's line of steepest ascent
     * from there, crest_point().
     */
    struct Wedge
    {
      /** Height H of the slope face, from the toe (z = 0) to the crest (m).
       */
      double           slope_height;
      PlaneOrientation slope_face;
      PlaneOrientation upper_slope;
      PlaneOrientation plane_a;
      PlaneOrientation plane_b;
      /**
       * Element size h in and near the wedge (m): tetrahedra of size 2 h,
       * each split into four hexahedra, or tetrahedra of size h.
       */
      double mesh_size;
      /** Hexahedra or tetrahedra. */
      ElementShape element_shape = ElementShape::hypercube;
      /**
       * Least distance from the wedge to the sides, back and base of the
       * rock, and length of the ground in front of the toe (m); 2 H if 0
       * is given.
       */
      double rock_extent;

      /**
       * The point of the crest above the apex, (-H cot psi sin alpha,
       * -H cot psi cos alpha, H) with the slope face's dip psi and dip
       * direction alpha.
       */
      Point<3>
      crest_point() const;

      /**
       * The corners of the wedge: the apex (the origin: slope face, A, B),
       * the top of the line of intersection (upper slope, A, B), and the
       * ends of its crest edge on A (slope face, upper slope, A) and on B
       * (slope face, upper slope, B). Throws if the planes do not form a
       * wedge that daylights in the slope face: the line of intersection
       * must run from the apex up into the rock behind the face and reach
       * the upper slope, and the crest edge must lie above the toe.
       */
      std::array<Point<3>, 4>
      corners() const;

      /** Declare the subsection "Wedge" (inside "Geometry"). */
      static void
      declare_parameters(ParameterHandler &prm);

      /** Read the subsection "Wedge" (inside "Geometry"). */
      void
      parse_parameters(ParameterHandler &prm);

      /** Throw a one-sentence message naming the entry if the data are
       * invalid, including planes that form no wedge. */
      void
      validate() const;
    };

    /**
     * A tetrahedral rock wedge in a slope, cut off by the joint planes A and
     * B (Hoek and Bray's wedge), x = east, y = north, z = up. The wedge's
     * corners are wedge.corners(): the apex at the origin, on the toe of
     * the slope face (z = 0), where the line of intersection of A and B
     * daylights; the top of that line on the upper slope; and the two ends
     * of the crest edge. The crest passes through wedge.crest_point(), at
     * z = H.
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
     * With Element shape = tetrahedron the tetrahedra of size h are kept.
     * Opens its own GmshSession.
     */
    MeshDescription<3>
    make_wedge_mesh(const Wedge &wedge);
  } // namespace geometry
} // namespace fdem
