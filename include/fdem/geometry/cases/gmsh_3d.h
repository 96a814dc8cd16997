// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <vector>

namespace fdem
{
  namespace geometry
  {
    /** Gmsh meshing that the 3D cases made by Gmsh (wedge, slope 3d) share. */
    namespace gmsh_3d
    {
      /**
       * Meshes the current Gmsh model in 3D: tetrahedra of size @p near up
       * to @p distance_min from the surfaces @p surfaces, growing by a
       * quarter of the further distance up to @p far (Delaunay, sizes from
       * this field only), then all split into hexahedra if @p hexahedra.
       * Needs an active GmshSession.
       */
      void
      mesh_near_surfaces(const std::vector<int> &surfaces,
                         const double            near,
                         const double            far,
                         const double            distance_min,
                         const bool              hexahedra);
    } // namespace gmsh_3d
  }   // namespace geometry
} // namespace fdem
