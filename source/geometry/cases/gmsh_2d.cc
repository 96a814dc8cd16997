// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/cases/gmsh_2d.h>

#include <gmsh.h>

#include <algorithm>
#include <cmath>

namespace fdem
{
  namespace geometry
  {
    namespace gmsh_2d
    {
      void
      set_size_field(const std::vector<int> &curves,
                     const double            size_near,
                     const double            size_far,
                     const double            fine_distance,
                     const bool              subdivided)
      {
        namespace field       = gmsh::model::mesh::field;
        const double growth   = 0.25;
        const double factor   = subdivided ? 2 : 1;
        const double near     = factor * size_near;
        const double far      = factor * size_far;
        const int    distance = field::add("Distance");
        field::setNumbers(distance,
                          "CurvesList",
                          std::vector<double>(curves.begin(), curves.end()));
        field::setNumber(distance, "NumPointsPerCurve", 1000);
        const int threshold = field::add("Threshold");
        field::setNumber(threshold, "InField", distance);
        field::setNumber(threshold, "SizeMin", near);
        field::setNumber(threshold, "SizeMax", far);
        const double fine = std::max(0.5 * near, fine_distance);
        field::setNumber(threshold, "DistMin", fine);
        field::setNumber(threshold,
                         "DistMax",
                         fine + std::abs(far - near) / growth);
        field::setAsBackgroundMesh(threshold);
        // Only the field decides, not the points or the curvature.
        gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
      }

      void
      set_unstructured_quad_options()
      {
        gmsh::option::setNumber("Mesh.Algorithm", 6);
        gmsh::option::setNumber("Mesh.RecombineAll", 1);
        gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 1);
        gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 1);
      }

      void
      set_triangle_options()
      {
        gmsh::option::setNumber("Mesh.Algorithm", 6);
        gmsh::option::setNumber("Mesh.RecombineAll", 0);
        gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 0);
      }

      int
      add_occ_polygon(const std::vector<Point<2>> &corners)
      {
        std::vector<int> points, lines;
        for (const Point<2> &corner : corners)
          points.push_back(gmsh::model::occ::addPoint(corner[0], corner[1], 0));
        for (unsigned int i = 0; i < points.size(); ++i)
          lines.push_back(
            gmsh::model::occ::addLine(points[i],
                                      points[(i + 1) % points.size()]));
        return gmsh::model::occ::addPlaneSurface(
          {gmsh::model::occ::addCurveLoop(lines)});
      }
    } // namespace gmsh_2d
  }   // namespace geometry
} // namespace fdem
