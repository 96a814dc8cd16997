// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// A ground surface from a grid of elevations: read with one-line messages
// for every way the file can be wrong, and evaluated bilinearly, the
// surface the mesh generator's ruled faces make.

#include <fdem/geometry/cases/case_input.h>
#include <fdem/geometry/cases/terrain.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace fdem
{
  namespace geometry
  {
    namespace
    {
      /** The cell [v[k], v[k+1]] holding @p value (clamped to the grid) and
       * the fraction t of the way through it. */
      std::pair<unsigned int, double>
      cell_of(const std::vector<double> &v, const double value)
      {
        const double       clamped = std::clamp(value, v.front(), v.back());
        const unsigned int k =
          std::min<unsigned int>(std::upper_bound(v.begin(), v.end(), clamped) -
                                   v.begin(),
                                 v.size() - 1) -
          1;
        return {k, (clamped - v[k]) / (v[k + 1] - v[k])};
      }

      /** The fields of a line, as read (comments dropped). */
      std::string
      fields_text(const std::vector<std::string> &fields)
      {
        std::string text;
        for (const std::string &f : fields)
          text += (text.empty() ? "" : ", ") + f;
        return text;
      }
    } // namespace



    double
    TerrainGrid::elevation(const double px, const double py) const
    {
      const auto [i, s] = cell_of(x, px);
      const auto [j, t] = cell_of(y, py);
      return (1 - s) * (1 - t) * at(i, j) + s * (1 - t) * at(i + 1, j) +
             (1 - s) * t * at(i, j + 1) + s * t * at(i + 1, j + 1);
    }



    Tensor<1, 2>
    TerrainGrid::gradient(const double px, const double py) const
    {
      const auto [i, s] = cell_of(x, px);
      const auto [j, t] = cell_of(y, py);
      Tensor<1, 2> g;
      g[0] = ((1 - t) * (at(i + 1, j) - at(i, j)) +
              t * (at(i + 1, j + 1) - at(i, j + 1))) /
             (x[i + 1] - x[i]);
      g[1] = ((1 - s) * (at(i, j + 1) - at(i, j)) +
              s * (at(i + 1, j + 1) - at(i + 1, j))) /
             (y[j + 1] - y[j]);
      return g;
    }



    double
    TerrainGrid::min_elevation() const
    {
      return *std::min_element(z.begin(), z.end());
    }



    double
    TerrainGrid::max_elevation() const
    {
      return *std::max_element(z.begin(), z.end());
    }



    std::vector<Point<2>>
    TerrainGrid::lowest_profile() const
    {
      const unsigned int    n = 16;
      std::vector<Point<2>> profile;
      for (unsigned int i = 0; i + 1 < x.size(); ++i)
        for (unsigned int k = 0; k < n + (i + 2 == x.size() ? 1 : 0); ++k)
          {
            const double px     = x[i] + (x[i + 1] - x[i]) * k / n;
            double       lowest = elevation(px, y[0]);
            for (const double py : y)
              lowest = std::min(lowest, elevation(px, py));
            profile.emplace_back(px, lowest);
          }
      return profile;
    }



    double
    TerrainGrid::volume_above(const double z_base) const
    {
      // A bilinear cell's mean height is the mean of its corners'.
      double volume = 0;
      for (unsigned int j = 0; j + 1 < y.size(); ++j)
        for (unsigned int i = 0; i + 1 < x.size(); ++i)
          volume +=
            (x[i + 1] - x[i]) * (y[j + 1] - y[j]) *
            ((at(i, j) + at(i + 1, j) + at(i, j + 1) + at(i + 1, j + 1)) / 4 -
             z_base);
      return volume;
    }



    TerrainGrid
    terrain_grid_from_file(const std::string &file_name,
                           const std::string &entry)
    {
      const std::string where = entry + ": '" + file_name + "'";
      std::map<std::pair<double, double>, double>       points;
      std::map<std::pair<double, double>, unsigned int> line_of;
      case_input::for_each_table_row(
        file_name,
        where,
        [&](const unsigned int              line_number,
            const std::string              &at,
            const std::vector<std::string> &fields) {
          double value[3] = {0, 0, 0};
          bool   numbers  = fields.size() == 3;
          for (unsigned int k = 0; k < fields.size() && k < 3; ++k)
            numbers = case_input::parse_number(fields[k], value[k]) &&
                      std::isfinite(value[k]) && numbers;
          AssertThrow(numbers,
                      ExcMessage(at +
                                 "expected three finite numbers x, y, "
                                 "z (m), got '" +
                                 fields_text(fields) + "'."));
          const std::pair<double, double> xy(value[0], value[1]);
          AssertThrow(points.count(xy) == 0,
                      ExcMessage(at + "the point x = " + fields[0] + ", y = " +
                                 fields[1] + " was given before, on line " +
                                 std::to_string(line_of[xy]) + "."));
          points[xy]  = value[2];
          line_of[xy] = line_number;
        });

      std::set<double> xs, ys;
      for (const auto &[xy, z] : points)
        {
          xs.insert(xy.first);
          ys.insert(xy.second);
        }
      AssertThrow(xs.size() >= 2 && ys.size() >= 2,
                  ExcMessage(where +
                             ": the grid needs at least two "
                             "distinct x and two distinct y, got " +
                             std::to_string(xs.size()) + " and " +
                             std::to_string(ys.size()) + "."));
      TerrainGrid grid;
      grid.x.assign(xs.begin(), xs.end());
      grid.y.assign(ys.begin(), ys.end());
      for (const double py : grid.y)
        for (const double px : grid.x)
          {
            const auto found = points.find({px, py});
            AssertThrow(found != points.end(),
                        ExcMessage(where +
                                   ": the grid has no elevation at "
                                   "x = " +
                                   case_input::number_text(px) +
                                   ", y = " + case_input::number_text(py) +
                                   " (every x of the file with every y, " +
                                   std::to_string(grid.x.size()) + " x " +
                                   std::to_string(grid.y.size()) +
                                   " points, expected)."));
            grid.z.push_back(found->second);
          }
      return grid;
    }
  } // namespace geometry
} // namespace fdem
