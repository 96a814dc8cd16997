// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Tests of the case "slope": blocks and face groups, a conforming sliding
// surface, the sliding mass's area against the exact area, the finer mesh
// on the sliding surface, polyline surfaces, surfaces that separate nothing.

#include "geometry_test_helpers.h"

using namespace geometry_test;

namespace
{
  /**
   * Signed area of the intersection of the polygon @p corners with the disk
   * of centre @p centre and radius @p radius: the sum over the edges of the
   * intersection of the disk with the triangle (centre, edge), where each
   * piece of an edge contributes a triangle inside the circle and a sector
   * outside it.
   */
  double
  polygon_disk_area(const std::vector<Point<2>> &corners,
                    const Point<2>              &centre,
                    const double                 radius)
  {
    const auto cross = [](const Tensor<1, 2> &a, const Tensor<1, 2> &b) {
      return a[0] * b[1] - a[1] * b[0];
    };
    double area = 0;
    for (unsigned int i = 0; i < corners.size(); ++i)
      {
        const Tensor<1, 2>  a = corners[i] - centre;
        const Tensor<1, 2>  d = corners[(i + 1) % corners.size()] - corners[i];
        std::vector<double> t = {0, 1};
        const double qa = d * d, qb = 2 * (a * d), qc = a * a - radius * radius;
        const double discriminant = qb * qb - 4 * qa * qc;
        if (discriminant > 0)
          for (const double sign : {-1., 1.})
            {
              const double root =
                (-qb + sign * std::sqrt(discriminant)) / (2 * qa);
              if (root > 0 && root < 1)
                t.push_back(root);
            }
        std::sort(t.begin(), t.end());
        for (unsigned int k = 0; k + 1 < t.size(); ++k)
          {
            const Tensor<1, 2> p = a + t[k] * d, q = a + t[k + 1] * d;
            if ((0.5 * (p + q)).norm() < radius)
              area += 0.5 * cross(p, q);
            else
              area += 0.5 * radius * radius * std::atan2(cross(p, q), p * q);
          }
      }
    return area;
  }

  /** Piecewise linear interpolation in a polyline with increasing x. */
  double
  polyline_y(const std::vector<Point<2>> &line, const double x)
  {
    for (unsigned int i = 1; i < line.size(); ++i)
      if (x <= line[i][0])
        return line[i - 1][1] + (x - line[i - 1][0]) /
                                  (line[i][0] - line[i - 1][0]) *
                                  (line[i][1] - line[i - 1][1]);
    return line.back()[1];
  }

  /** Exact area between @p upper and @p lower where upper lies above. */
  double
  area_between(const std::vector<Point<2>> &upper,
               const std::vector<Point<2>> &lower)
  {
    std::vector<double> x;
    const double        x_begin = std::max(upper.front()[0], lower.front()[0]);
    const double        x_end   = std::min(upper.back()[0], lower.back()[0]);
    for (const auto *line : {&upper, &lower})
      for (const Point<2> &p : *line)
        if (p[0] > x_begin && p[0] < x_end)
          x.push_back(p[0]);
    x.push_back(x_begin);
    x.push_back(x_end);
    std::sort(x.begin(), x.end());
    double area = 0;
    for (unsigned int i = 0; i + 1 < x.size(); ++i)
      {
        // The difference is linear on each interval: integrate its positive
        // part.
        const double da = polyline_y(upper, x[i]) - polyline_y(lower, x[i]);
        const double db =
          polyline_y(upper, x[i + 1]) - polyline_y(lower, x[i + 1]);
        const double dx = x[i + 1] - x[i];
        if (da >= 0 && db >= 0)
          area += 0.5 * (da + db) * dx;
        else if (da > 0 || db > 0)
          area +=
            0.5 * std::max(da, db) * dx * std::max(da, db) / std::abs(da - db);
      }
    return area;
  }

  const std::vector<std::string> slope_blocks = {"sliding mass", "foundation"};
  const std::vector<std::string> slope_groups = {"sliding surface",
                                                 "ground",
                                                 "left",
                                                 "right",
                                                 "bottom"};
} // namespace



TEST(Slope, DefaultMeshHasTheNamedBlocksAndFaceGroups)
{
  const auto mesh = geometry::make_slope_mesh(parse("").slope);
  check_mesh(mesh, slope_blocks, slope_groups);
  for (const auto &face : faces_of(mesh, "left"))
    for (const unsigned int v : face.vertices)
      EXPECT_NEAR(mesh.vertices[v][0], 0, 1e-12);
  for (const auto &face : faces_of(mesh, "right"))
    for (const unsigned int v : face.vertices)
      EXPECT_NEAR(mesh.vertices[v][0], 50, 1e-12);
  for (const auto &face : faces_of(mesh, "bottom"))
    for (const unsigned int v : face.vertices)
      EXPECT_NEAR(mesh.vertices[v][1], 20, 1e-12);
  const std::set<Edge> mass       = cell_edges(mesh, 0),
                       foundation = cell_edges(mesh, 1);
  // With the paper's data the circle stays clear of the sides and the base.
  for (const std::string group : {"left", "right", "bottom"})
    for (const auto &face : faces_of(mesh, group))
      EXPECT_FALSE(mass.count(edge(face.vertices[0], face.vertices[1])));
  // The ground is the top of both blocks.
  unsigned int n_on_mass = 0, n_on_foundation = 0;
  for (const auto &face : faces_of(mesh, "ground"))
    {
      n_on_mass += mass.count(edge(face.vertices[0], face.vertices[1]));
      n_on_foundation +=
        foundation.count(edge(face.vertices[0], face.vertices[1]));
    }
  EXPECT_GT(n_on_mass, 0u);
  EXPECT_GT(n_on_foundation, 0u);
}



TEST(Slope, SlidingSurfaceIsConforming)
{
  const auto           mesh       = geometry::make_slope_mesh(parse("").slope);
  const std::set<Edge> mass       = cell_edges(mesh, 0),
                       foundation = cell_edges(mesh, 1);
  std::vector<std::set<unsigned int>> blocks_of_vertex(mesh.vertices.size());
  for (const auto &cell : mesh.cells)
    for (const unsigned int v : cell.vertices)
      blocks_of_vertex[v].insert(cell.material_id);
  const auto sliding = faces_of(mesh, "sliding surface");
  ASSERT_FALSE(sliding.empty());
  for (const auto &face : sliding)
    {
      // The same two vertices bound a cell edge on each side.
      EXPECT_TRUE(mass.count(edge(face.vertices[0], face.vertices[1])));
      EXPECT_TRUE(foundation.count(edge(face.vertices[0], face.vertices[1])));
      for (const unsigned int v : face.vertices)
        EXPECT_EQ(blocks_of_vertex[v].size(), 2u);
    }
}



// The sliding mass is the polygon of the ground closed to the base, cut by
// the disk. Its mesh replaces the arc by chords, all with their ends on the
// circle, so the mesh area plus the circular segments cut off by the chords,
// (r^2/2)(theta - sin theta) each, equals the exact area to round-off (1e-9
// relative leaves ample room). The segments themselves bound the difference
// a priori: c^3/(12 r) for a chord c to leading order (the next term is
// smaller by theta^2/10 < 1e-3 here), so at most L h_max^2 / (12 r) with L
// the arc length, plus 1% for that term: 0.08% of the area for h = 1 m.
TEST(Slope, SlidingMassAreaMatchesDomainInsideDisk)
{
  const Parameters geometry = parse("");
  const auto      &slope    = geometry.slope;
  const auto       mesh     = geometry::make_slope_mesh(slope);

  std::vector<Point<2>> domain = slope.ground_surface;
  domain.emplace_back(50, slope.base_elevation);
  domain.emplace_back(0, slope.base_elevation);
  const double r = slope.circle_radius;
  const double exact =
    std::abs(polygon_disk_area(domain, slope.circle_centre, r));
  const double meshed = block_area(mesh, 0);

  double segments = 0, arc_length = 0, h_max = 0;
  for (const auto &face : faces_of(mesh, "sliding surface"))
    {
      const double chord = length(mesh, face);
      const double theta = 2 * std::asin(chord / (2 * r));
      segments += 0.5 * r * r * (theta - std::sin(theta));
      arc_length += r * theta;
      h_max = std::max(h_max, chord);
    }
  EXPECT_NEAR(meshed + segments, exact, 1e-9 * exact);
  EXPECT_GT(exact - meshed, 0);
  EXPECT_LT(exact - meshed, 1.01 * arc_length * h_max * h_max / (12 * r));
  EXPECT_LT(exact - meshed, 1e-3 * exact);
  // The whole slope: the integral of the ground elevation above the base.
  EXPECT_NEAR(meshed + block_area(mesh, 1), 550, 1e-9 * 550);
}



TEST(Slope, MeshIsFinerOnTheSlidingSurface)
{
  const auto mesh = geometry::make_slope_mesh(
    parse("subsection Slope\n set Mesh size = 2\n"
          " set Mesh size on sliding surface = 0.5\nend")
      .slope);
  check_mesh(mesh, slope_blocks, slope_groups);
  // The right side is more than 9 m from the circle: there the size is 2 m.
  double sliding_max = 0, right_min = 1e10, right_max = 0;
  for (const auto &face : faces_of(mesh, "sliding surface"))
    sliding_max = std::max(sliding_max, length(mesh, face));
  for (const auto &face : faces_of(mesh, "right"))
    {
      right_min = std::min(right_min, length(mesh, face));
      right_max = std::max(right_max, length(mesh, face));
    }
  EXPECT_LT(sliding_max, 1.3 * 0.5);
  EXPECT_GT(right_min, 0.7 * 2);
  EXPECT_LT(right_max, 1.3 * 2);
}



TEST(Slope, PolylineSlidingSurface)
{
  const Parameters geometry =
    parse("subsection Slope\n set Sliding surface = polyline\n"
          " set Sliding surface polyline = 5,26; 15,22; 35,30; 45,36\nend");
  const auto mesh = geometry::make_slope_mesh(geometry.slope);
  check_mesh(mesh, slope_blocks, slope_groups);
  // Everything is straight, so the areas are exact up to round-off.
  const double exact = area_between(geometry.slope.ground_surface,
                                    geometry.slope.sliding_surface_polyline);
  EXPECT_NEAR(block_area(mesh, 0), exact, 1e-9 * exact);
  for (const auto &face : faces_of(mesh, "sliding surface"))
    for (const unsigned int v : face.vertices)
      EXPECT_NEAR(mesh.vertices[v][1],
                  polyline_y(geometry.slope.sliding_surface_polyline,
                             mesh.vertices[v][0]),
                  1e-9);
}



// Interslices from the polyline's interior vertices (15, 22) and (35, 30):
// three blocks, left to right, whose areas are those between the ground and
// the polyline over each block's x range (vertical cuts: exact up to
// round-off), interslice faces on the verticals, and a tension crack 3 m
// deep with a node at its water level.
TEST(Slope, InterslicesAndTensionCrackCutTheSlidingMass)
{
  const std::string polyline =
    "subsection Slope\n set Sliding surface = polyline\n"
    " set Sliding surface polyline = 5,26; 15,22; 35,30; 45,36\n"
    " set Interslice surfaces = vertical\n";
  const Parameters geometry = parse(polyline + "end");
  const auto       mesh     = geometry::make_slope_mesh(geometry.slope);
  check_mesh(
    mesh,
    {"sliding mass 1", "sliding mass 2", "sliding mass 3", "foundation"},
    {"sliding surface 1",
     "sliding surface 2",
     "sliding surface 3",
     "interslice 1",
     "interslice 2",
     "ground",
     "left",
     "right",
     "bottom"});
  const auto  &ground  = geometry.slope.ground_surface;
  const auto  &line    = geometry.slope.sliding_surface_polyline;
  const double x_cut[] = {15, 35};
  for (unsigned int i = 0; i < 3; ++i)
    {
      const std::vector<Point<2>> piece(line.begin() + i, line.begin() + i + 2);
      const double                exact = area_between(ground, piece);
      EXPECT_NEAR(block_area(mesh, i), exact, 1e-9 * exact) << i;
    }
  for (unsigned int i = 0; i < 2; ++i)
    for (const auto &face :
         faces_of(mesh, "interslice " + std::to_string(i + 1)))
      for (const unsigned int v : face.vertices)
        EXPECT_NEAR(mesh.vertices[v][0], x_cut[i], 1e-9);

  // The crack: the surface 3 m below the ground on 35,30 - 45,36, where
  // the ground is 35: y = 32 at x = 35 + 2 / 0.6; water 1 m deep.
  const auto cracked = geometry::make_slope_mesh(
    parse(polyline + " set Tension crack depth = 3\n"
                     " set Tension crack water depth = 1\nend")
      .slope);
  const double x_crack    = 35 + 2 / 0.6;
  bool         water_node = false;
  for (const auto &face : faces_of(cracked, "tension crack"))
    for (const unsigned int v : face.vertices)
      {
        EXPECT_NEAR(cracked.vertices[v][0], x_crack, 1e-9);
        EXPECT_GE(cracked.vertices[v][1], 32 - 1e-9);
        water_node |= std::abs(cracked.vertices[v][1] - 33) < 1e-9;
      }
  EXPECT_TRUE(water_node);
  const std::vector<Point<2>> last  = {line[2], Point<2>(x_crack, 32)};
  const double                exact = area_between(ground, last);
  EXPECT_NEAR(block_area(cracked, 2), exact, 1e-9 * exact);
}



TEST(Slope, SurfaceThatDoesNotSeparateIsRejected)
{
  const std::string message = "Geometry/Slope: the sliding surface does not "
                              "separate a sliding mass from the foundation.";
  // A circle inside the slope, and one that cuts through the base.
  expect_error(
    [] {
      geometry::make_slope_mesh(
        parse("subsection Slope\n set Circle centre = 25, 25\n"
              " set Circle radius = 3\nend")
          .slope);
    },
    message);
  expect_error(
    [] {
      geometry::make_slope_mesh(
        parse("subsection Slope\n set Circle centre = 25, 45\n"
              " set Circle radius = 30\nend")
          .slope);
    },
    message);
  expect_error(
    [] {
      geometry::make_slope_mesh(
        parse("subsection Slope\n set Circle centre = 100, 100\n"
              " set Circle radius = 3\nend")
          .slope);
    },
    message);
}
