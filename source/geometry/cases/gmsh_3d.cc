// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/cases/gmsh_3d.h>
#include <fdem/geometry/gmsh_mesh.h>

#include <gmsh.h>

namespace fdem
{
  namespace geometry
  {
    namespace gmsh_3d
    {
      int
      add_extruded_polygon(const std::vector<Point<2>> &outline,
                           const double                 y0,
                           const double                 length)
      {
        namespace occ = gmsh::model::occ;
        std::vector<int> points, lines;
        for (const Point<2> &p : outline)
          points.push_back(occ::addPoint(p[0], y0, p[1]));
        for (unsigned int i = 0; i < points.size(); ++i)
          lines.push_back(
            occ::addLine(points[i], points[(i + 1) % points.size()]));
        const int face = occ::addPlaneSurface({occ::addCurveLoop(lines)});
        gmsh::vectorpair extruded;
        occ::extrude({{2, face}}, 0, length, 0, extruded);
        for (const auto &dim_tag : extruded)
          if (dim_tag.first == 3)
            return dim_tag.second;
        AssertThrow(false, ExcInternalError());
        return 0;
      }



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
        // Gmsh would move the split's new vertices on a curved surface onto
        // it by itself, with no way back for the cells this twists.
        gmsh::option::setNumber("Mesh.SecondOrderLinear", 1);
        gmsh::model::mesh::generate(3);
      }



      unsigned int
      move_vertices_keeping_cells_valid(
        MeshDescription<3>                                   &mesh,
        const std::vector<std::pair<unsigned int, Point<3>>> &targets,
        const double                                          min_sine)
      {
        std::vector<Point<3>>      &vertices = mesh.vertices;
        const std::vector<Point<3>> before   = vertices;
        std::vector<bool>           moved(vertices.size(), false);
        for (const auto &[v, p] : targets)
          {
            vertices[v] = p;
            moved[v]    = true;
          }
        std::vector<unsigned int> cells;
        for (unsigned int c = 0; c < mesh.cells.size(); ++c)
          for (const unsigned int v : mesh.cells[c].vertices)
            if (moved[v])
              {
                cells.push_back(c);
                break;
              }
        // Taking a move back can twist a neighbour that kept its moves, so
        // until nothing changes (at worst every vertex back in place).
        unsigned int kept = 0;
        for (bool changed = true; changed;)
          {
            changed = false;
            for (const unsigned int c : cells)
              if (corner_sine_range(vertices, mesh.cells[c]).first < min_sine)
                for (const unsigned int v : mesh.cells[c].vertices)
                  if (vertices[v] != before[v])
                    {
                      vertices[v] = before[v];
                      ++kept;
                      changed = true;
                    }
          }
        return kept;
      }
    } // namespace gmsh_3d
  }   // namespace geometry
} // namespace fdem
