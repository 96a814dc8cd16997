// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// A ground or water surface from a Gmsh surface (a .msh of triangles, a
// .geo Gmsh meshes, an .stl): sampled on a rectangular grid, which the mesh
// generator builds the ground from as for a grid file (and the water
// pressures use as a grid file's). Surveys come as triangulated surfaces
// more often than as grids; the samples make the same bilinear surface the
// generator and the water already verify.

#include <fdem/geometry/cases/case_input.h>
#include <fdem/geometry/cases/terrain.h>
#include <fdem/geometry/gmsh_mesh.h>
#include <fdem/geometry/msh_checks.h>

#include <deal.II/base/exceptions.h>

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

namespace fdem
{
  namespace geometry
  {
    namespace
    {
      using Triangle = std::array<Point<3>, 3>;

      /**
       * The triangles of every surface element of the current Gmsh model
       * (a quadrangle as two), by their corner nodes: a curved element is
       * taken as its flat corners.
       */
      std::vector<Triangle>
      surface_triangles()
      {
        std::vector<std::size_t> node_tags;
        std::vector<double>      coordinates, parametric;
        gmsh::model::mesh::getNodes(node_tags, coordinates, parametric);
        std::map<std::size_t, Point<3>> node;
        for (std::size_t k = 0; k < node_tags.size(); ++k)
          node[node_tags[k]] = Point<3>(coordinates[3 * k],
                                        coordinates[3 * k + 1],
                                        coordinates[3 * k + 2]);
        std::vector<int>                      types;
        std::vector<std::vector<std::size_t>> element_tags, element_nodes;
        gmsh::model::mesh::getElements(types, element_tags, element_nodes, 2);
        std::vector<Triangle> triangles;
        for (unsigned int t = 0; t < types.size(); ++t)
          {
            std::string         name;
            int                 dim = 0, order = 0, n_nodes = 0, n_corners = 0;
            std::vector<double> local;
            gmsh::model::mesh::getElementProperties(
              types[t], name, dim, order, n_nodes, local, n_corners);
            const std::vector<std::size_t> &nodes = element_nodes[t];
            for (std::size_t e = 0; e + n_nodes <= nodes.size(); e += n_nodes)
              {
                const auto corner = [&](const int k) {
                  return node.at(nodes[e + k]);
                };
                triangles.push_back(
                  Triangle{{corner(0), corner(1), corner(2)}});
                if (n_corners == 4)
                  triangles.push_back(
                    Triangle{{corner(0), corner(2), corner(3)}});
              }
          }
        return triangles;
      }
    } // namespace



    bool
    is_surface_mesh_file(const std::string &file_name)
    {
      std::string extension =
        std::filesystem::path(file_name).extension().string();
      std::transform(extension.begin(),
                     extension.end(),
                     extension.begin(),
                     [](const unsigned char c) { return std::tolower(c); });
      return extension == ".msh" || extension == ".geo" || extension == ".stl";
    }



    using case_input::number_text;



    TerrainGrid
    terrain_grid_from_surface(const std::string &file_name,
                              const std::string &entry,
                              const double       spacing)
    {
      const std::string where = entry + ": '" + file_name + "'";
      AssertThrow(std::ifstream(file_name).good() &&
                    !std::filesystem::is_directory(file_name),
                  ExcMessage(where + " cannot be read (missing file?)."));
      Assert(spacing >= 0, ExcInternalError());
      check_before_gmsh(file_name);
      std::vector<Triangle> triangles;
      {
        GmshSession session;
        GmshSession::run("Gmsh could not read '" + file_name + "'",
                         [&]() { gmsh::open(file_name); });
        // A .geo (or any file without surface elements) is geometry: mesh
        // its surfaces with the file's own sizes.
        std::vector<int>                      types;
        std::vector<std::vector<std::size_t>> tags, nodes;
        gmsh::model::mesh::getElements(types, tags, nodes, 2);
        if (types.empty() && gmsh::model::getDimension() >= 2)
          GmshSession::run("Gmsh could not mesh '" + file_name + "'",
                           []() { gmsh::model::mesh::generate(2); });
        triangles = surface_triangles();
      }
      AssertThrow(!triangles.empty(),
                  ExcMessage(where +
                             ": has no surface (no triangles or "
                             "quadrangles, nor surfaces Gmsh can mesh)."));

      // The grid spans the surface's extent in x and y, in equal steps of
      // at most the spacing (without one, 200 steps along the longer side).
      double x0 = triangles[0][0][0], x1 = x0, y0 = triangles[0][0][1], y1 = y0;
      for (const Triangle &t : triangles)
        for (const Point<3> &p : t)
          {
            x0 = std::min(x0, p[0]);
            x1 = std::max(x1, p[0]);
            y0 = std::min(y0, p[1]);
            y1 = std::max(y1, p[1]);
          }
      AssertThrow(x1 > x0 && y1 > y0,
                  ExcMessage(where + ": the surface has no extent in x or y."));
      const double step =
        spacing > 0 ? spacing : std::max(x1 - x0, y1 - y0) / 200;
      // The entry of the spacing is named after the file's ("Terrain
      // file", "Terrain grid spacing").
      const std::string spacing_entry =
        entry.substr(0, entry.rfind("file")) + "grid spacing";
      const double n_x = std::ceil((x1 - x0) / step - 1e-9),
                   n_y = std::ceil((y1 - y0) / step - 1e-9);
      AssertThrow((n_x + 1) * (n_y + 1) <= 1e6,
                  ExcMessage(entry + ": sampling the surface every " +
                             number_text(step) + " m gives " +
                             number_text((n_x + 1) * (n_y + 1)) +
                             " grid points (at most 1e6); give a larger " +
                             spacing_entry + "."));
      TerrainGrid grid;
      for (unsigned int i = 0; i <= n_x; ++i)
        grid.x.push_back(i == n_x ? x1 : x0 + i * (x1 - x0) / n_x);
      for (unsigned int j = 0; j <= n_y; ++j)
        grid.y.push_back(j == n_y ? y1 : y0 + j * (y1 - y0) / n_y);

      // Buckets of a coarse grid over the extent, each listing the
      // triangles whose plan bounding box meets it: a grid point looks at
      // its bucket's triangles only.
      const unsigned int n_buckets =
        std::max(1u,
                 static_cast<unsigned int>(std::sqrt(triangles.size() / 4.0)));
      const auto bucket =
        [&](const double value, const double low, const double high) {
          return std::min(n_buckets - 1,
                          static_cast<unsigned int>(
                            std::max(0.0, (value - low) / (high - low)) *
                            n_buckets));
        };
      std::vector<std::vector<unsigned int>> in_bucket(n_buckets * n_buckets);
      const double                           size = std::max(x1 - x0, y1 - y0);
      // Twice each triangle's signed area in the plan.
      std::vector<double> plan_area(triangles.size());
      for (unsigned int k = 0; k < triangles.size(); ++k)
        {
          const Triangle &t = triangles[k];
          plan_area[k]      = (t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) -
                         (t[2][0] - t[0][0]) * (t[1][1] - t[0][1]);
          // A vertical facet (a cliff in the survey) covers no point.
          if (std::abs(plan_area[k]) <= 1e-12 * size * size)
            continue;
          const auto [ax, bx] = std::minmax({t[0][0], t[1][0], t[2][0]});
          const auto [ay, by] = std::minmax({t[0][1], t[1][1], t[2][1]});
          for (unsigned int j = bucket(ay, y0, y1); j <= bucket(by, y0, y1);
               ++j)
            for (unsigned int i = bucket(ax, x0, x1); i <= bucket(bx, x0, x1);
                 ++i)
              in_bucket[j * n_buckets + i].push_back(k);
        }

      const double tolerance = 1e-9;
      for (const double py : grid.y)
        for (const double px : grid.x)
          {
            bool   found = false;
            double z     = 0;
            for (const unsigned int k :
                 in_bucket[bucket(py, y0, y1) * n_buckets + bucket(px, x0, x1)])
              {
                const Triangle &t    = triangles[k];
                const double    area = plan_area[k];
                // Barycentric coordinates of the point in the plan.
                const double b1 = ((px - t[0][0]) * (t[2][1] - t[0][1]) -
                                   (t[2][0] - t[0][0]) * (py - t[0][1])) /
                                  area,
                             b2 = ((t[1][0] - t[0][0]) * (py - t[0][1]) -
                                   (px - t[0][0]) * (t[1][1] - t[0][1])) /
                                  area,
                             b0 = 1 - b1 - b2;
                if (std::min({b0, b1, b2}) < -tolerance)
                  continue;
                const double elevation =
                  b0 * t[0][2] + b1 * t[1][2] + b2 * t[2][2];
                // A point on an edge or a vertex is in several triangles:
                // one elevation if the surface is one sheet over it.
                AssertThrow(
                  !found || std::abs(elevation - z) <= tolerance * size,
                  ExcMessage(where + ": the surface has two elevations, " +
                             number_text(z) + " and " + number_text(elevation) +
                             ", at x = " + number_text(px) +
                             ", y = " + number_text(py) +
                             " (an overhang or a fold); give a "
                             "surface with one elevation "
                             "at each point."));
                found = true;
                z     = elevation;
              }
            AssertThrow(found,
                        ExcMessage(
                          where + ": the surface does not cover x = " +
                          number_text(px) + ", y = " + number_text(py) +
                          " (the surface must cover the rectangle "
                          "of its extent in x and y, " +
                          number_text(x0) + " to " + number_text(x1) + " by " +
                          number_text(y0) + " to " + number_text(y1) + ")."));
            grid.z.push_back(z);
          }
      return grid;
    }
  } // namespace geometry
} // namespace fdem
