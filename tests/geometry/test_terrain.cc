// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Tests of the terrain grid (Geometry/Slope 3D/Terrain file): read in any
// order with a header and comments, evaluated exactly on a bilinear
// function, and each way a file can be wrong named on one line.

#include "geometry_test_helpers.h"

#include <fdem/geometry/cases/terrain.h>

#include <cmath>
#include <fstream>

using namespace geometry_test;

namespace
{
  /** A bilinear function: the grid's surface must be it exactly. */
  double
  bilinear(const double x, const double y)
  {
    return 100 + 0.2 * x - 0.1 * y + 0.01 * x * y;
  }

  std::string
  write_file(const std::string &text)
  {
    const std::string name = temporary_file(".csv");
    std::ofstream(name) << text;
    return name;
  }
} // namespace



// An uneven grid (x: 0, 1, 4, 10; y: -2, 3, 5), its lines shuffled, with a
// header, comments, blank lines and mixed separators.
TEST(TerrainGrid, ReadsAGridInAnyOrderAndIsBilinear)
{
  const std::vector<double> xs = {4, 0, 10, 1}, ys = {5, -2, 3};
  std::string               text = "# elevations\nx; y; z\n\n";
  for (const double y : ys)
    for (const double x : xs)
      text += std::to_string(x) + ", " + std::to_string(y) + "\t" +
              std::to_string(bilinear(x, y)) + "  # a point\n";
  const std::string           name = write_file(text);
  const geometry::TerrainGrid grid =
    geometry::terrain_grid_from_file(name, "Terrain file");
  std::filesystem::remove(name);
  EXPECT_EQ(grid.x, (std::vector<double>{0, 1, 4, 10}));
  EXPECT_EQ(grid.y, (std::vector<double>{-2, 3, 5}));
  for (const double x : {0., 0.5, 2.7, 9.99, 10.})
    for (const double y : {-2., 0., 3., 4.2, 5.})
      {
        EXPECT_NEAR(grid.elevation(x, y), bilinear(x, y), 1e-9);
        const Tensor<1, 2> g = grid.gradient(x, y);
        EXPECT_NEAR(g[0], 0.2 + 0.01 * y, 1e-9);
        EXPECT_NEAR(g[1], -0.1 + 0.01 * x, 1e-9);
      }
  // Outside the grid: the nearest edge's value.
  EXPECT_NEAR(grid.elevation(-5, 7), bilinear(0, 5), 1e-9);
  // The volume over the rectangle [0, 10] x [-2, 5] above z = 90:
  // integral of 10 + 0.2 x - 0.1 y + 0.01 x y = 700 + 70 - 10.5 + 5.25.
  EXPECT_NEAR(grid.volume_above(90), 764.75, 1e-9);
  // The lowest profile: along y the function is linear with slope
  // -0.1 + 0.01 x < 0, lowest at y = 5.
  for (const Point<2> &p : grid.lowest_profile())
    EXPECT_NEAR(p[1], bilinear(p[0], 5), 1e-9) << p;
  EXPECT_EQ(grid.min_elevation(), bilinear(0, 5));
  EXPECT_EQ(grid.max_elevation(), bilinear(10, 5));
}



TEST(TerrainGrid, EachWrongFileIsNamedOnOneLine)
{
  const std::string entry = "Geometry/Slope 3D/Terrain file";
  expect_error(
    [&] {
      geometry::terrain_grid_from_file("/nonexistent/terrain.csv", entry);
    },
    entry + ": '/nonexistent/terrain.csv' cannot be read");
  const auto wrong = [&](const std::string &text, const std::string &message) {
    const std::string name = write_file(text);
    expect_error([&] { geometry::terrain_grid_from_file(name, entry); },
                 message);
    std::filesystem::remove(name);
  };
  wrong("0 0 1\n1 0 1\n0 1 1\n1 1 nan\n",
        "line 4: expected three finite numbers x, y, z (m)");
  wrong("0 0 1\n1 0 1\n0 1 1\n1 1\n",
        "line 4: expected three finite numbers x, y, z (m)");
  wrong("0 0 1\n1 0 1\n0 1 1\n1 1 1 7\n",
        "line 4: expected three finite numbers x, y, z (m)");
  wrong("x y z\n0 0 1\n1 0 1\n0 1 1\n1 1 1\nx y z\n",
        "line 6: expected three finite numbers x, y, z (m)");
  wrong("0 0 1\n1 0 1\n0 1 1\n", "no elevation at x = 1, y = 1");
  wrong("0 0 1\n1 0 1\n0 1 1\n1 1 1\n1 0 2\n",
        "line 5: the point x = 1, y = 0 was given before, on line 2");
  wrong("0 0 1\n1 0 1\n2 0 1\n", "at least two distinct x and two distinct y");
  wrong("", "at least two distinct x and two distinct y, got 0 and 0");
}
