// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/geometry/mesh_description.h>

#include <deal.II/base/point.h>

#include <utility>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    /** Gmsh meshing that the 3D cases made by Gmsh (wedge, slope 3d) share. */
    namespace gmsh_3d
    {
      /**
       * Adds to the current Gmsh model (OpenCASCADE) the prism of the
       * polygon @p outline, points (x, z) in the plane y = @p y0, extruded
       * by @p length along y; returns its volume's tag.
       */
      int
      add_extruded_polygon(const std::vector<Point<2>> &outline,
                           const double                 y0,
                           const double                 length);

      /**
       * Meshes the current Gmsh model in 3D: tetrahedra of size @p near up
       * to @p distance_min from the surfaces @p surfaces, growing by a
       * quarter of the further distance up to @p far (Delaunay, sizes from
       * this field only), then all split into hexahedra if @p hexahedra.
       * The split's new vertices (midpoints of the edges, centroids of the
       * faces and of the tetrahedra) stay on the tetrahedra's flat edges
       * and faces: a curved surface's are moved onto it by the generator
       * (move_vertices_keeping_cells_valid()). Needs an active GmshSession.
       */
      void
      mesh_near_surfaces(const std::vector<int> &surfaces,
                         const double            near,
                         const double            far,
                         const double            distance_min,
                         const bool              hexahedra);

      /**
       * Moves each vertex of @p mesh (hexahedra, in deal.II's orientation)
       * in @p targets to its new place, except where that twists a cell:
       * a cell left with a corner sine below @p min_sine
       * (corner_sine_range()) takes back the moves of all its vertices, and
       * so on until no cell is left so. Returns the number of vertices left in
       * place. What this is for: the vertices that splitting tetrahedra added
       * on a curved surface, moved onto it; a sliver of the tetrahedra with two
       * faces on the surface is thinner than the surface's bulge across its
       * edges, so its hexahedra turn inside out when moved (doc/theory.md, "The
       * 3D slope").
       */
      unsigned int
      move_vertices_keeping_cells_valid(
        MeshDescription<3>                                   &mesh,
        const std::vector<std::pair<unsigned int, Point<3>>> &targets,
        const double                                          min_sine);
    } // namespace gmsh_3d
  }   // namespace geometry
} // namespace fdem
