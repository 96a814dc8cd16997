// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Soil layers of the slope generator: each layer is a material region,
// bounded by polylines across the whole model. The model's surfaces are
// split by one strip surface per layer (OpenCASCADE fragment), so that a
// piece's layer is the strip it came from, with no point-in-region test.

#include <fdem/geometry/cases/gmsh_2d.h>
#include <fdem/geometry/cases/slope.h>
#include <fdem/geometry/gmsh_mesh.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <gmsh.h>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

namespace fdem
{
  namespace geometry
  {
    namespace
    {

      /** @p line cut to x_min <= x <= x_max (it spans that range). */
      std::vector<Point<2>>
      clip(const std::vector<Point<2>> &line,
           const double                 x_min,
           const double                 x_max)
      {
        std::vector<Point<2>> clipped{
          Point<2>(x_min, case_input::polyline_elevation(line, x_min))};
        for (const Point<2> &p : line)
          if (p[0] > x_min && p[0] < x_max)
            clipped.push_back(p);
        clipped.emplace_back(x_max,
                             case_input::polyline_elevation(line, x_max));
        return clipped;
      }

      std::string
      number(const double x)
      {
        std::ostringstream out;
        out << x;
        return out.str();
      }
    } // namespace

    void
    Slope::declare_layer_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Layers",
        "",
        Patterns::List(Patterns::Anything(), 0),
        "Soil layers from the top down: the material of each, "
        "a name of Materials/Names (a material may come back "
        "lower down). The layers cut across the sliding mass "
        "and the foundation alike. Empty: no layers (each block "
        "is of its own material).");
      prm.declare_entry("Layer boundaries",
                        "",
                        Patterns::Anything(),
                        "The boundaries between consecutive layers, from the "
                        "top down, separated by '|' (one fewer than Layers): "
                        "each a polyline 'x,y; x,y; ...' (m) with increasing x "
                        "from the left edge of the model (or beyond) to its "
                        "right edge (or beyond), inside the model (on or below "
                        "the ground surface, above the base) and strictly "
                        "below the boundary before it.");
    }

    void
    Slope::parse_layer_parameters(ParameterHandler &prm)
    {
      layers = Utilities::split_string_list(prm.get("Layers"), ',');
      layer_boundaries =
        case_input::parse_layer_boundaries(prm.get("Layer boundaries"),
                                           "Geometry/Slope/Layer boundaries");
    }

    void
    Slope::validate_layers() const
    {
      case_input::validate_layers(layers,
                                  layer_boundaries,
                                  ground_surface,
                                  base_elevation,
                                  "Geometry/Slope");
    }

    namespace case_input
    {
      std::vector<std::vector<Point<2>>>
      parse_layer_boundaries(const std::string &text, const std::string &entry)
      {
        std::vector<std::vector<Point<2>>> boundaries;
        const std::string                  trimmed = Utilities::trim(text);
        if (!trimmed.empty())
          for (const std::string &line :
               Utilities::split_string_list(trimmed, '|'))
            {
              std::vector<Point<2>> points;
              try
                {
                  points = parse_points(line);
                }
              catch (...)
                {
                  AssertThrow(false,
                              ExcMessage(entry + ": '" + line +
                                         "' is not a list of points 'x,y; "
                                         "x,y; ...' of finite numbers."));
                }
              boundaries.push_back(points);
            }
        return boundaries;
      }

      void
      validate_layers(const std::vector<std::string>           &layers,
                      const std::vector<std::vector<Point<2>>> &boundaries,
                      const std::vector<Point<2>>              &ground,
                      const double                              base,
                      const std::string                        &subsection)
      {
        const std::string path = subsection + "/Layer boundaries: ";
        for (const std::string &name : layers)
          require(!name.empty(),
                  subsection + "/Layers: empty name in the list.");
        require(layers.empty() ? boundaries.empty() :
                                 boundaries.size() + 1 == layers.size(),
                path + "give one boundary fewer than Layers (" +
                  std::to_string(layers.size()) + " layers, " +
                  std::to_string(boundaries.size()) + " boundaries).");
        const double x_min = ground.front()[0], x_max = ground.back()[0];
        double       height = 0;
        for (const Point<2> &p : ground)
          height = std::max(height, p[1] - base);
        const double tolerance = 1e-10 * (x_max - x_min + height);
        for (unsigned int k = 0; k < boundaries.size(); ++k)
          {
            const auto       &line  = boundaries[k];
            const std::string which = "boundary " + std::to_string(k + 1) + " ";
            require(line.size() >= 2,
                    path + which + "needs at least two points.");
            for (unsigned int i = 1; i < line.size(); ++i)
              require(line[i][0] > line[i - 1][0],
                      path + which + "must have increasing x.");
            require(line.front()[0] <= x_min + tolerance &&
                      line.back()[0] >= x_max - tolerance,
                    path + which + "must span the model from x = " +
                      number(x_min) + " to x = " + number(x_max) + ".");
            for (const double x :
                 polyline_breakpoints(line, ground, x_min, x_max))
              require(polyline_elevation(line, x) <=
                          polyline_elevation(ground, x) + tolerance &&
                        polyline_elevation(line, x) > base + tolerance,
                      path + which + "leaves the model at x = " + number(x) +
                        " (above the ground surface or not above the base).");
            if (k > 0)
              for (const double x :
                   polyline_breakpoints(line, boundaries[k - 1], x_min, x_max))
                require(polyline_elevation(line, x) <
                          polyline_elevation(boundaries[k - 1], x) - tolerance,
                        path + "boundaries " + std::to_string(k) + " and " +
                          std::to_string(k + 1) +
                          " cross or touch at x = " + number(x) +
                          "; each must lie strictly below the one "
                          "before it.");
          }
      }
    } // namespace case_input

    void
    split_into_layers(const Slope                           &slope,
                      const std::vector<std::vector<int> *> &surface_groups,
                      const std::vector<std::vector<int> *> &curve_groups)
    {
      if (slope.layers.empty())
        return;
      const auto  &ground = slope.ground_surface;
      const double x_min = ground.front()[0], x_max = ground.back()[0];
      double       y_max = ground.front()[1];
      for (const Point<2> &p : ground)
        y_max = std::max(y_max, p[1]);
      // Strips reach well beyond the model, so that its whole outline lies
      // inside their union; the parts outside are removed afterwards.
      const double margin = x_max - x_min + y_max - slope.base_elevation;
      std::vector<std::vector<Point<2>>> lines;
      lines.push_back({Point<2>(x_min - margin, y_max + margin),
                       Point<2>(x_max + margin, y_max + margin)});
      for (const auto &boundary : slope.layer_boundaries)
        {
          std::vector<Point<2>> line = clip(boundary, x_min, x_max);
          line.insert(line.begin(), Point<2>(x_min - margin, line.front()[1]));
          line.emplace_back(x_max + margin, line.back()[1]);
          lines.push_back(line);
        }
      lines.push_back(
        {Point<2>(x_min - margin, slope.base_elevation - margin),
         Point<2>(x_max + margin, slope.base_elevation - margin)});

      gmsh::vectorpair              objects, tools, pieces;
      std::vector<gmsh::vectorpair> origin;
      GmshSession::run(
        "Geometry/Slope/Layer boundaries: Gmsh could not split the model",
        [&]() {
          for (unsigned int k = 0; k + 1 < lines.size(); ++k)
            {
              // The strip of layer k: its lower line left to right, then its
              // upper line right to left.
              std::vector<Point<2>> outline = lines[k + 1];
              outline.insert(outline.end(), lines[k].rbegin(), lines[k].rend());
              tools.emplace_back(2, gmsh_2d::add_occ_polygon(outline));
            }
          for (const auto *group : surface_groups)
            for (const int s : *group)
              objects.emplace_back(2, s);
          for (const auto *group : curve_groups)
            for (const int c : *group)
              objects.emplace_back(1, c);
          gmsh::model::occ::fragment(objects, tools, pieces, origin);
        });

      // Each input's pieces, by its position in objects, then tools.
      std::map<std::pair<int, int>, unsigned int> position;
      for (unsigned int i = 0; i < objects.size(); ++i)
        position[objects[i]] = i;
      std::set<int> inside;
      for (auto *group : surface_groups)
        {
          std::vector<int> split;
          for (const int s : *group)
            for (const auto &piece : origin[position.at({2, s})])
              if (piece.first == 2)
                {
                  split.push_back(piece.second);
                  inside.insert(piece.second);
                }
          *group = split;
        }
      for (auto *group : curve_groups)
        {
          std::vector<int> split;
          for (const int c : *group)
            for (const auto &piece : origin[position.at({1, c})])
              if (piece.first == 1)
                split.push_back(piece.second);
          *group = split;
        }
      // Pieces of the layers inside the model, by material; the rest of the
      // strips is removed.
      group_layer_pieces(
        2,
        origin,
        objects.size(),
        slope.layers,
        inside,
        "Geometry/Slope/Layer boundaries: Gmsh could not split the model");
    }
  } // namespace geometry
} // namespace fdem
