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



// A Gmsh surface as the ground (Terrain file = .geo, .msh or .stl): the
// paper's straight slope as three planes (toe z = 25 to x = 10, the face
// rising 1:2 to the crest at x = 30, z = 35), meshed by Gmsh into
// triangles, or quadrangles (Recombine), sampled on a grid. Every surface
// element lies in one of the planes, so each sample is exact: on the
// grid through the kinks (spacing 10) and on one that misses them
// (spacing 7: steps of 6.25 m in x, 40/6 m in y).
TEST(TerrainGrid, SamplesAGmshSurfaceExactlyOnItsPlanes)
{
  const auto slope = [](const double x) {
    return x <= 10 ? 25 : x <= 30 ? 25 + 0.5 * (x - 10) : 35;
  };
  const std::string planes =
    "lc = 5;\n"
    "Point(1) = {0, 0, 25, lc}; Point(2) = {10, 0, 25, lc};\n"
    "Point(3) = {30, 0, 35, lc}; Point(4) = {50, 0, 35, lc};\n"
    "Point(5) = {0, 40, 25, lc}; Point(6) = {10, 40, 25, lc};\n"
    "Point(7) = {30, 40, 35, lc}; Point(8) = {50, 40, 35, lc};\n"
    "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};\n"
    "Line(4) = {5, 6}; Line(5) = {6, 7}; Line(6) = {7, 8};\n"
    "Line(7) = {1, 5}; Line(8) = {2, 6}; Line(9) = {3, 7}; Line(10) = {4, 8};\n"
    "Curve Loop(1) = {1, 8, -4, -7}; Plane Surface(1) = {1};\n"
    "Curve Loop(2) = {2, 9, -5, -8}; Plane Surface(2) = {2};\n"
    "Curve Loop(3) = {3, 10, -6, -9}; Plane Surface(3) = {3};\n";
  for (const std::string extra : {"", "Recombine Surface{1, 2, 3};\n"})
    {
      const std::string name = temporary_file(".geo");
      std::ofstream(name) << planes << extra;
      for (const double spacing : {10.0, 7.0})
        {
          const geometry::TerrainGrid grid =
            geometry::terrain_grid_from_surface(name, "Terrain file", spacing);
          const unsigned int n_x = spacing == 10 ? 6 : 9,
                             n_y = spacing == 10 ? 5 : 7;
          ASSERT_EQ(grid.x.size(), n_x) << spacing;
          ASSERT_EQ(grid.y.size(), n_y) << spacing;
          EXPECT_EQ(grid.x.front(), 0);
          EXPECT_EQ(grid.x.back(), 50);
          EXPECT_EQ(grid.y.front(), 0);
          EXPECT_EQ(grid.y.back(), 40);
          for (unsigned int j = 0; j < n_y; ++j)
            for (unsigned int i = 0; i < n_x; ++i)
              {
                EXPECT_NEAR(grid.x[i], 50.0 * i / (n_x - 1), 1e-12);
                EXPECT_NEAR(grid.at(i, j), slope(grid.x[i]), 1e-9)
                  << grid.x[i] << ", " << grid.y[j] << extra;
              }
        }
      std::filesystem::remove(name);
    }
  EXPECT_TRUE(geometry::is_surface_mesh_file("ground.MSH"));
  EXPECT_TRUE(geometry::is_surface_mesh_file("dir.v2/ground.stl"));
  EXPECT_FALSE(geometry::is_surface_mesh_file("ground.csv"));
}



// A Gmsh surface that leaves part of its rectangle uncovered, or has two
// sheets over part of it: one line naming the entry, the file and a point.
TEST(TerrainGrid, GmshSurfaceWithAGapOrAnOverhangIsNamed)
{
  const std::string entry = "Geometry/Slope 3D/Terrain file";
  const auto wrong = [&](const std::string &geo, const std::string &message) {
    const std::string name = temporary_file(".geo");
    std::ofstream(name) << geo;
    expect_error([&] { geometry::terrain_grid_from_surface(name, entry, 10); },
                 entry + ": '" + name + "': " + message);
    std::filesystem::remove(name);
  };
  wrong("Point(1) = {0, 0, 25, 10}; Point(2) = {50, 0, 35, 10};\n"
        "Point(3) = {0, 40, 30, 10};\n"
        "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};\n"
        "Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};\n",
        "the surface does not cover x = 40, y = 10");
  wrong("Point(1) = {0, 0, 25, 10}; Point(2) = {50, 0, 25, 10};\n"
        "Point(3) = {50, 40, 25, 10}; Point(4) = {0, 40, 25, 10};\n"
        "Point(5) = {20, 0, 30, 10}; Point(6) = {40, 0, 30, 10};\n"
        "Point(7) = {40, 40, 30, 10}; Point(8) = {20, 40, 30, 10};\n"
        "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};\n"
        "Line(4) = {4, 1}; Line(5) = {5, 6}; Line(6) = {6, 7};\n"
        "Line(7) = {7, 8}; Line(8) = {8, 5};\n"
        "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
        "Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};\n",
        "the surface has two elevations");
}
