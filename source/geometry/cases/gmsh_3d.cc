// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/cases/gmsh_3d.h>

#include <gmsh.h>

namespace fdem
{
  namespace geometry
  {
    namespace gmsh_3d
    {
      void
      mesh_near_surfaces(const std::vector<int> &surfaces,
                         const double            near,
                         const double            far,
                         const double            distance_min,
                         const bool              hexahedra)
      {
        namespace field    = gmsh::model::mesh::field;
        const int distance = field::add("Distance");
        field::setNumbers(distance,
                          "SurfacesList",
                          std::vector<double>(surfaces.begin(),
                                              surfaces.end()));
        // The faces are sampled by points 1/100 of their size apart.
        field::setNumber(distance, "NumPointsPerCurve", 100);
        const int threshold = field::add("Threshold");
        field::setNumber(threshold, "InField", distance);
        field::setNumber(threshold, "SizeMin", near);
        field::setNumber(threshold, "SizeMax", far);
        field::setNumber(threshold, "DistMin", distance_min);
        field::setNumber(threshold,
                         "DistMax",
                         distance_min + (far - near) / 0.25);
        field::setAsBackgroundMesh(threshold);
        gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);

        // Delaunay tetrahedra, all split into hexahedra (and the triangles
        // of the surfaces into quadrilaterals, conformingly), or kept.
        gmsh::option::setNumber("Mesh.Algorithm", 6);
        gmsh::option::setNumber("Mesh.Algorithm3D", 1);
        gmsh::option::setNumber("Mesh.RecombineAll", 0);
        gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", hexahedra ? 2 : 0);
        gmsh::model::mesh::generate(3);
      }
    } // namespace gmsh_3d
  }   // namespace geometry
} // namespace fdem
