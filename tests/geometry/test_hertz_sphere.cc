// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Tests of the case "hertz sphere" (3D quarter model): the sphere's nodes
// straight above the foundation's in the contact zone, and bad input.

#include "geometry_test_helpers.h"

using namespace geometry_test;

TEST(HertzSphere, QuarterModelWithTheSphereAboveTheFoundationNodes)
{
  const Parameters               geometry = parse("set Source = hertz sphere");
  const Parameters::HertzSphere &p        = geometry.hertz_sphere;
  EXPECT_EQ(p.radius, 100);
  EXPECT_EQ(p.n_contact_zone_elements, 6u);
  const auto mesh = geometry::make_mesh<3>(geometry, "");
  check_mesh(mesh,
             {"sphere", "foundation"},
             {"contact surface",
              "load",
              "symmetry",
              "bottom",
              "sphere surface",
              "foundation surface",
              "foundation side"});
  // The two blocks touch only at the origin: every face group is on the
  // boundary of the whole mesh.
  expect_conforming_mesh(mesh, {});

  // The foundation is the box [0, W]^2 x [-D, 0].
  const double W = p.foundation_width, D = p.foundation_depth;
  EXPECT_NEAR(block_area(mesh, 1), W * W * D, 1e-9 * W * W * D);

  // Every vertex of the sphere lies in the ball, in [0, S]^2, below H.
  const double           R = p.radius, S = p.cap_half_width, H = p.load_height;
  const Point<3>         centre(0, 0, R);
  std::set<unsigned int> sphere_vertices;
  for (const auto &cell : mesh.cells)
    if (cell.material_id == 0)
      sphere_vertices.insert(cell.vertices.begin(), cell.vertices.end());
  for (const unsigned int v : sphere_vertices)
    {
      const Point<3> &x = mesh.vertices[v];
      EXPECT_LE(x.distance(centre), R * (1 + 1e-12));
      EXPECT_GE(x[0], 0);
      EXPECT_GE(x[1], 0);
      EXPECT_LE(x[0], S * (1 + 1e-12));
      EXPECT_LE(x[1], S * (1 + 1e-12));
      EXPECT_LE(x[2], H * (1 + 1e-12));
    }
  // Its volume is that of the truncated ball, up to the chords of the
  // spherical surface (sag h^2/(8R) over faces of size h <= 25: < 1 %).
  double             exact        = 0;
  const unsigned int n_quadrature = 400;
  for (unsigned int i = 0; i < n_quadrature; ++i)
    for (unsigned int j = 0; j < n_quadrature; ++j)
      {
        const double x = S * (i + 0.5) / n_quadrature,
                     y = S * (j + 0.5) / n_quadrature;
        exact += (H - (R - std::sqrt(R * R - x * x - y * y))) * S * S /
                 (n_quadrature * n_quadrature);
      }
  EXPECT_NEAR(block_area(mesh, 0), exact, 0.01 * exact);

  // The contact surface: n x n faces on each side, the sphere's vertices on
  // the sphere straight above the foundation's, on the grid (i, j) Lc/n.
  const unsigned int n       = p.n_contact_zone_elements;
  const double       lc      = p.contact_zone_width;
  const auto         contact = faces_of(mesh, "contact surface");
  EXPECT_EQ(contact.size(), 2u * n * n);
  std::set<std::pair<long, long>> on_sphere, on_foundation;
  for (const auto &face : contact)
    for (const unsigned int v : face.vertices)
      {
        const Point<3> &x = mesh.vertices[v];
        const long      i = std::lround(x[0] / lc * n);
        const long      j = std::lround(x[1] / lc * n);
        EXPECT_NEAR(x[0], lc * i / n, 1e-12 * lc);
        EXPECT_NEAR(x[1], lc * j / n, 1e-12 * lc);
        EXPECT_LE(i, static_cast<long>(n));
        EXPECT_LE(j, static_cast<long>(n));
        if (sphere_vertices.count(v))
          {
            EXPECT_NEAR(x.distance(centre), R, 1e-12 * R);
            on_sphere.insert({i, j});
          }
        if (!sphere_vertices.count(v) || x.norm() == 0)
          {
            EXPECT_EQ(x[2], 0);
            on_foundation.insert({i, j});
          }
      }
  EXPECT_EQ(on_sphere.size(), (n + 1) * (n + 1));
  EXPECT_TRUE(on_sphere == on_foundation);

  // Graded mesh: edges of Lc/n in the contact zone, none longer than the
  // mesh size (the last element of a range may be stretched to fill it by
  // at most half the growth ratio).
  double longest = 0;
  for (const auto &cell : mesh.cells)
    for (unsigned int l = 0; l < GeometryInfo<3>::lines_per_cell; ++l)
      longest = std::max(
        longest,
        mesh
          .vertices[cell.vertices[GeometryInfo<3>::line_to_cell_vertices(l, 0)]]
          .distance(
            mesh.vertices
              [cell.vertices[GeometryInfo<3>::line_to_cell_vertices(l, 1)]]));
  EXPECT_LE(longest, 1.7 * p.mesh_size);
}



TEST(HertzSphere, BadInputs)
{
  const std::string prefix =
    "set Source = hertz sphere\nsubsection Hertz sphere\n";
  expect_error([&] { parse(prefix + " set Contact zone width = 60\nend"); },
               "Geometry/Hertz sphere/Contact zone width: must be positive "
               "and smaller than Cap half width.");
  expect_error([&] { parse(prefix + " set Cap half width = 75\nend"); },
               "Geometry/Hertz sphere/Cap half width: S sqrt(2) must be "
               "smaller than Radius");
  expect_error([&] { parse(prefix + " set Load height = 30\nend"); },
               "Geometry/Hertz sphere/Load height: must be at most Radius");
  expect_error([&] { parse(prefix + " set Foundation width = 40\nend"); },
               "Geometry/Hertz sphere/Foundation width: must be larger");
}
