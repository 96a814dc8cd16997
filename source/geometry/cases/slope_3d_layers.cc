// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Soil layers of the 3D slope generator: each layer is a material region,
// bounded by the section's polylines running along y. As in 2D
// (slope_layers.cc), the model's volumes are split by one slab
// per layer (OpenCASCADE fragment), so that a piece's layer is the slab it
// came from, with no point-in-region test.

#include <fdem/geometry/cases/gmsh_3d.h>
#include <fdem/geometry/cases/slope_3d.h>
#include <fdem/geometry/gmsh_mesh.h>

#include <gmsh.h>

#include <map>
#include <set>

namespace fdem
{
  namespace geometry
  {
    void
    split_into_layers(const Slope3D                         &slope,
                      const std::vector<std::vector<int> *> &volume_groups)
    {
      if (slope.layers.empty())
        return;
      const double x_min = slope.x_min(), x_max = slope.x_max();
      const double y_min = slope.y_min(), y_max = slope.y_max();
      const double z_top  = slope.top_elevation();
      const double z_base = slope.base_elevation();
      // Slabs reach well beyond the model, so that it lies inside their
      // union; the parts outside are removed afterwards.
      const double margin = x_max - x_min + y_max - y_min + z_top - z_base;
      std::vector<std::vector<Point<2>>> lines;
      lines.push_back({Point<2>(x_min - margin, z_top + margin),
                       Point<2>(x_max + margin, z_top + margin)});
      for (const auto &boundary : slope.layer_boundaries)
        {
          const double z_front =
            case_input::polyline_elevation(boundary, x_min);
          std::vector<Point<2>> line{Point<2>(x_min - margin, z_front),
                                     Point<2>(x_min, z_front)};
          // Not the points at the ends (x_max, from the slope angle's
          // tangent, may differ from a given 50 in the last digit).
          const double tolerance = 1e-9 * margin;
          for (const Point<2> &p : boundary)
            if (p[0] > x_min + tolerance && p[0] < x_max - tolerance)
              line.push_back(p);
          line.emplace_back(x_max,
                            case_input::polyline_elevation(boundary, x_max));
          line.emplace_back(x_max + margin, line.back()[1]);
          lines.push_back(line);
        }
      lines.push_back({Point<2>(x_min - margin, z_base - margin),
                       Point<2>(x_max + margin, z_base - margin)});

      const std::string message =
        "Geometry/Slope 3D/Layer boundaries: Gmsh could not split the model";
      gmsh::vectorpair              objects, tools, pieces;
      std::vector<gmsh::vectorpair> origin;
      GmshSession::run(message, [&]() {
        for (unsigned int k = 0; k + 1 < lines.size(); ++k)
          {
            // The section of layer k: its lower line left to right, then its
            // upper line right to left.
            std::vector<Point<2>> outline = lines[k + 1];
            outline.insert(outline.end(), lines[k].rbegin(), lines[k].rend());
            tools.emplace_back(3,
                               gmsh_3d::add_extruded_polygon(outline,
                                                             y_min - margin,
                                                             y_max - y_min +
                                                               2 * margin));
          }
        for (const auto *group : volume_groups)
          for (const int v : *group)
            objects.emplace_back(3, v);
        gmsh::model::occ::fragment(objects, tools, pieces, origin);
      });

      // Each input's pieces, by its position in objects, then tools.
      std::map<std::pair<int, int>, unsigned int> position;
      for (unsigned int i = 0; i < objects.size(); ++i)
        position[objects[i]] = i;
      std::set<int> inside;
      for (auto *group : volume_groups)
        {
          std::vector<int> split;
          for (const int tag : *group)
            for (const auto &piece : origin[position.at({3, tag})])
              if (piece.first == 3)
                {
                  split.push_back(piece.second);
                  inside.insert(piece.second);
                }
          *group = split;
        }
      // Pieces of the layers inside the model, by material; the rest of the
      // slabs is removed.
      group_layer_pieces(
        3, origin, objects.size(), slope.layers, inside, message);
    }
  } // namespace geometry
} // namespace fdem
