// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Tests of the case "slope 3d": the sliding mass's volume and the sliding
// surface's area against integrals of the exact shapes, every vertex of the
// sliding surface on the quadric (but the few whose move onto it would
// twist a cell), the blocks and face groups, and surfaces that do not cut
// the ground, leave the model or do not daylight on the slope.

#include "geometry_test_helpers.h"

#include <fdem/geometry/cases/slope_3d.h>

#include <filesystem>
#include <fstream>
#include <set>

using namespace geometry_test;

namespace
{
  /** The entries of tests/three_d/slope_3d.prm with another surface. */
  std::string
  slope_entries(const std::string &surface,
                const std::string &centre,
                const double       radius,
                const double       half_length,
                const double       width,
                const double       mesh_size,
                const double       straight = 20)
  {
    return "set Source = slope 3d\nsubsection Slope 3D\n"
           "set Sliding surface = " +
           surface + "\nset Surface centre = " + centre +
           "\nset Surface radius = " + std::to_string(radius) +
           "\nset Surface half length = " + std::to_string(half_length) +
           "\nset Surface straight length = " + std::to_string(straight) +
           "\nset Width = " + std::to_string(width) +
           "\nset Mesh size = " + std::to_string(mesh_size) + "\nend";
  }

  /**
   * The sliding mass's volume and the sliding surface's area, integrated
   * by the midpoint rule on an n x n grid in plan (x, y) over the box of
   * the surface: the thickness between the lower sheet of the quadric
   * z_c - R sqrt(1 - u^2 - v^2) and the ground (or the upper sheet), and
   * the lower sheet's area element sqrt(1 + |grad z|^2) where the sheet is
   * below the ground. The sheet's rim lies above the ground in the cases
   * tested, so the integrands are bounded.
   */
  std::pair<double, double>
  exact_volume_and_area(const geometry::Slope3D &s, const unsigned int n)
  {
    const bool   cylinder = s.surface == geometry::Slope3D::Surface::cylinder;
    const double r = s.radius, b = s.half_length;
    const double x0 = s.centre[0] - r, dx = 2 * r / n;
    // The capsule's straight part lies between its ends.
    const double half = s.straight_length / 2;
    const double y0   = cylinder ? s.y_min() : s.centre[1] - b - half;
    const double dy =
      cylinder ? (s.y_max() - s.y_min()) / n : 2 * (b + half) / n;
    double volume = 0, area = 0;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          const double x = x0 + (i + 0.5) * dx, y = y0 + (j + 0.5) * dy;
          const double u = (x - s.centre[0]) / r;
          const double v = s.axial_offset(y) / b;
          const double q = 1 - u * u - v * v;
          if (q <= 0)
            continue;
          const double z      = s.centre[2] - r * std::sqrt(q);
          const double ground = s.ground(x, y);
          if (z >= ground)
            continue;
          volume +=
            (std::min(ground, s.centre[2] + r * std::sqrt(q)) - z) * dx * dy;
          // z = z_c - R sqrt(q): dz/dx = u / sqrt(q), dz/dy = (R/b) v/sqrt(q).
          const double zx = u / std::sqrt(q), zy = r / b * v / std::sqrt(q);
          area += std::sqrt(1 + zx * zx + zy * zy) * dx * dy;
        }
    return {volume, area};
  }

  double
  face_area(const MeshDescription<3> &mesh, const CellData<2> &face)
  {
    // Two triangles of the (possibly warped) quadrilateral 0 1 3 2.
    const auto &p  = mesh.vertices;
    const auto &v  = face.vertices;
    const auto  tr = [&](unsigned a, unsigned b, unsigned c) {
      return 0.5 *
             cross_product_3d(p[v[b]] - p[v[a]], p[v[c]] - p[v[a]]).norm();
    };
    return tr(0, 1, 3) + tr(0, 3, 2);
  }

  void
  check_slope(const Parameters  &geometry,
              const double       volume_tolerance,
              const unsigned int max_off_surface)
  {
    const geometry::Slope3D &s    = geometry.slope_3d;
    const MeshDescription<3> mesh = geometry::make_slope_3d_mesh(s);
    EXPECT_EQ(mesh.block_names,
              (std::vector<std::string>{"sliding mass", "foundation"}));
    for (const std::string group :
         {"sliding surface", "ground", "base", "sides"})
      EXPECT_FALSE(faces_of(mesh, group).empty()) << group;

    // Every vertex of the sliding surface on the quadric (the generator
    // moves the split elements' new vertices onto it), but for those a
    // move would twist a cell: they stay on the tetrahedra's flat faces
    // and edges, inside the surface, no deeper than the middle of a chord
    // or a triangle of chords: with Q(d) = (d_x/R)^2 + (d_y/b)^2 +
    // (d_z/R)^2 <= (|d| / min(R, b))^2 the quadric is -Q(d)/4 at the
    // middle of a chord d and -(Q(d_1) + Q(d_2) + Q(d_3))/9 at the
    // centroid of a triangle of chords: -0.053 for edges up to 6 m (the
    // tetrahedra are of 2 h = 4 m) against b = 15 m. Measured -0.027.
    double                 area = 0, worst = 0, deepest = 0;
    unsigned int           n_off = 0;
    std::set<unsigned int> vertices;
    for (const auto &face : faces_of(mesh, "sliding surface"))
      {
        area += face_area(mesh, face);
        vertices.insert(face.vertices.begin(), face.vertices.end());
      }
    for (const unsigned int v : vertices)
      {
        const double q = s.quadric(mesh.vertices[v]);
        if (std::abs(q) < 1e-6)
          worst = std::max(worst, std::abs(q));
        else
          {
            ++n_off;
            deepest = std::min(deepest, q);
            EXPECT_LT(q, 0) << mesh.vertices[v];
          }
      }
    std::cout << vertices.size() << " vertices on the sliding surface, "
              << n_off << " left on the facets (quadric down to " << deepest
              << "), the others on it to " << worst << "\n";
    EXPECT_LE(n_off, max_off_surface);
    EXPECT_GT(deepest, -0.053);

    const auto [exact_volume, exact_area] = exact_volume_and_area(s, 2000);
    const double volume =
      block_area(mesh, index_of(mesh.block_names, "sliding mass"));
    std::cout << "sliding mass " << volume << " (exact " << exact_volume
              << "), surface " << area << " (exact " << exact_area << ")\n";
    // Flat facets inscribed in the curved surface cut off a sliver of the
    // mass and a little of the area: 2 % at these sizes (brief, issue 22).
    EXPECT_NEAR(volume / exact_volume, 1, volume_tolerance);
    EXPECT_NEAR(area / exact_area, 1, 0.02);
  }
} // namespace



// The default ellipsoid (its hexahedra were twisted before the split's
// vertices were moved onto the surface by the generator, keeping those
// whose move twists a cell: 7 of 313 measured; at most 5 %).
TEST(Slope3D, EllipsoidMassAndSurfaceMatchTheExactShape)
{
  check_slope(
    parse(slope_entries("ellipsoid", "19.61, 20, 46.32", 21.32, 15, 40, 2)),
    0.02,
    16);
}



TEST(Slope3D, SphereMassAndSurfaceMatchTheExactShape)
{
  check_slope(parse(
                slope_entries("sphere", "19.61, 20, 46.32", 21.32, 0, 50, 2)),
              0.02,
              0);
}



TEST(Slope3D, CylinderMassAndSurfaceMatchTheExactShape)
{
  check_slope(parse(
                slope_entries("cylinder", "19.61, 0, 46.32", 21.32, 15, 6, 2)),
              0.02,
              0);
}



// The capsule: a cylinder 10 m long closed by half-ellipsoids of 10 m
// along y (the shape of three_d.undrained_capsule): the surface's three
// faces, the mass one block, the split's vertices moved onto the piece
// they reach (measured: all 409 of them; at most 16 as the ellipsoid).
TEST(Slope3D, CapsuleMassAndSurfaceMatchTheExactShape)
{
  check_slope(
    parse(slope_entries("capsule", "19.61, 20, 46.32", 21.32, 10, 40, 2, 10)),
    0.02,
    16);
}



// A capsule whose ends reach beyond the model's sides (from y = -5 to 45
// in a width of 40 m), and one without a straight part.
TEST(Slope3D, CapsulesThatLeaveTheModelAreRejected)
{
  expect_error(
    [] {
      parse(slope_entries("capsule", "19.61, 20, 46.32", 21.32, 10, 40, 2, 30));
    },
    "Geometry/Slope 3D/Surface centre: the sliding surface leaves the model");
  expect_error(
    [] {
      parse(slope_entries("capsule", "19.61, 20, 46.32", 21.32, 10, 40, 2, 0));
    },
    "Geometry/Slope 3D/Surface straight length: must be positive for a "
    "capsule");
}



TEST(Slope3D, SurfacesThatCutNoSlopeAreRejected)
{
  expect_error(
    [] {
      parse(slope_entries("ellipsoid", "19.61, 20, 70", 21.32, 15, 40, 2));
    },
    "Geometry/Slope 3D/Surface centre: the sliding surface does not cut the "
    "ground surface");
  expect_error(
    [] { parse(slope_entries("sphere", "19.61, 20, 46.32", 30, 0, 40, 2)); },
    "Geometry/Slope 3D/Surface centre: the sliding surface leaves the model");
  expect_error(
    [] {
      parse(slope_entries("ellipsoid", "19.61, 5, 46.32", 21.32, 15, 40, 2));
    },
    "Geometry/Slope 3D/Surface centre: the sliding surface leaves the model");
  expect_error(
    [] { parse(slope_entries("ellipsoid", "42, 20, 38", 6, 15, 40, 2)); },
    "Geometry/Slope 3D/Surface centre: the sliding surface does not daylight "
    "on the slope face");
}



namespace
{
  /**
   * The surface @p surface (the paper's circle: a sphere, or a cylinder
   * along y) under the uneven terrain of three_d.undrained_sphere_terrain
   * (tests/three_d/data/uneven_terrain.csv), meshed with tetrahedra: every
   * vertex of the ground on the terrain's bilinear surface (the ruled faces
   * between the grid's sections are that surface), the sides at the grid's
   * edges, the mass's volume and the surface's area against their
   * integrals over the terrain (the facets inscribed in the surface: within
   * 2 %, as the straight slope's).
   */
  void
  check_under_terrain(const std::string &surface)
  {
    std::string entries =
      slope_entries(surface, "19.61, 20, 46.32", 21.32, 15, 40, 2);
    entries.insert(entries.rfind("end"),
                   "set Element shape = tetrahedron\nset Terrain file = " +
                     fdem::test_support::source_dir() + "/tests/geometry/data" +
                     "/../../three_d/data/uneven_terrain.csv\n");
    const Parameters         geometry = parse(entries);
    const geometry::Slope3D &s        = geometry.slope_3d;
    EXPECT_EQ(s.x_min(), 0);
    EXPECT_EQ(s.x_max(), 50);
    EXPECT_EQ(s.y_max(), 40);
    const MeshDescription<3> mesh  = geometry::make_slope_3d_mesh(s);
    double                   worst = 0;
    for (const auto &face : faces_of(mesh, "ground"))
      for (const unsigned int v : face.vertices)
        {
          const Point<3> &p = mesh.vertices[v];
          worst = std::max(worst, std::abs(p[2] - s.ground(p[0], p[1])));
        }
    std::cout << "ground vertices off the terrain by up to " << worst << " m\n";
    EXPECT_LT(worst, 1e-6);
    for (const auto &face : faces_of(mesh, "sides"))
      for (const unsigned int v : face.vertices)
        {
          const Point<3> &p = mesh.vertices[v];
          EXPECT_LT(std::min({std::abs(p[0]),
                              std::abs(p[0] - 50),
                              std::abs(p[1]),
                              std::abs(p[1] - 40)}),
                    1e-6)
            << p;
        }
    double area = 0;
    for (const auto &face : faces_of(mesh, "sliding surface"))
      area += 0.5 * cross_product_3d(mesh.vertices[face.vertices[1]] -
                                       mesh.vertices[face.vertices[0]],
                                     mesh.vertices[face.vertices[2]] -
                                       mesh.vertices[face.vertices[0]])
                      .norm();
    const auto [exact_volume, exact_area] = exact_volume_and_area(s, 2000);
    const double volume =
      block_area(mesh, index_of(mesh.block_names, "sliding mass"));
    std::cout << "sliding mass " << volume << " (exact " << exact_volume
              << "), surface " << area << " (exact " << exact_area << ")\n";
    EXPECT_NEAR(volume / exact_volume, 1, 0.02);
    EXPECT_NEAR(area / exact_area, 1, 0.02);
  }
} // namespace



TEST(Slope3D, TerrainGroundAndMassMatchTheGrid)
{
  check_under_terrain("sphere");
}



// The cylinder runs across the whole grid; under this terrain each of its
// sections meets another ground.
TEST(Slope3D, CylinderUnderATerrainMatchesTheGrid)
{
  check_under_terrain("cylinder");
}



// A terrain whose grid is narrower than the sphere's part below the
// ground: the sliding surface leaves the model at its sides.
TEST(Slope3D, TerrainTooNarrowForTheSurfaceIsRejected)
{
  const std::string name = temporary_file(".csv");
  std::ofstream(name) << "0 10 25\n10 10 25\n30 10 35\n50 10 35\n"
                         "0 30 25\n10 30 25\n30 30 35\n50 30 35\n";
  std::string entries =
    slope_entries("sphere", "19.61, 20, 46.32", 21.32, 0, 40, 2);
  entries.insert(entries.rfind("end"), "set Terrain file = " + name + "\n");
  expect_error([&] { parse(entries); },
               "Geometry/Slope 3D/Surface centre: the sliding surface leaves "
               "the model");
  std::filesystem::remove(name);
}
