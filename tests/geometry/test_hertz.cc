// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Tests of the case "hertz" (2D cylinder on a foundation): blocks and face
// groups, the contact zone's vertices at equal x on both sides, the full
// model as the mirrored half model, and the full model of triangles.

#include "geometry_test_helpers.h"

using namespace geometry_test;

namespace
{
  /** The x coordinates of the listed vertices, sorted. */
  std::vector<double>
  sorted_x_coordinates(const fdem::geometry::MeshDescription<2> &mesh,
                       const std::set<unsigned int>             &vertices)
  {
    std::vector<double> x;
    for (const unsigned int v : vertices)
      x.push_back(mesh.vertices[v][0]);
    std::sort(x.begin(), x.end());
    return x;
  }

  const std::string full_model = "subsection Hertz\n set Full model = true\n";

  /** Minimum and maximum of coordinate @p d over the vertices of @p group. */
  std::pair<double, double>
  coordinate_range(const MeshDescription<2> &mesh,
                   const std::string        &group,
                   const unsigned int        d)
  {
    std::pair<double, double> range(std::numeric_limits<double>::max(),
                                    std::numeric_limits<double>::lowest());
    for (const auto &face : faces_of(mesh, group))
      for (const unsigned int v : face.vertices)
        {
          range.first  = std::min(range.first, mesh.vertices[v][d]);
          range.second = std::max(range.second, mesh.vertices[v][d]);
        }
    return range;
  }
} // namespace



TEST(Hertz, MeshHasTheNamedBlocksAndFaceGroups)
{
  const auto mesh = geometry::make_hertz_mesh(parse("").hertz);
  check_mesh(mesh,
             {"cylinder", "foundation"},
             {"contact surface",
              "load",
              "symmetry",
              "bottom",
              "cylinder surface",
              "foundation surface",
              "foundation side"});
  for (const auto &face : faces_of(mesh, "load"))
    for (const unsigned int v : face.vertices)
      EXPECT_NEAR(mesh.vertices[v][1], 100, 1e-12);
  for (const auto &face : faces_of(mesh, "symmetry"))
    for (const unsigned int v : face.vertices)
      EXPECT_NEAR(mesh.vertices[v][0], 0, 1e-12);
  for (const auto &face : faces_of(mesh, "bottom"))
    for (const unsigned int v : face.vertices)
      EXPECT_NEAR(mesh.vertices[v][1], -500, 1e-12);
  for (const auto &face : faces_of(mesh, "foundation side"))
    for (const unsigned int v : face.vertices)
      EXPECT_NEAR(mesh.vertices[v][0], 500, 1e-12);
  for (const auto &face : faces_of(mesh, "cylinder surface"))
    for (const unsigned int v : face.vertices)
      EXPECT_NEAR(mesh.vertices[v].distance(Point<2>(0, 100)), 100, 1e-9);
}



// Pairs are found along the vertical, so both sides of the contact zone
// must have vertices at the same x_i = i Lc / N.
TEST(Hertz, ContactZoneVerticesMatchInX)
{
  const Parameters::Hertz hertz    = parse("").hertz;
  const auto              mesh     = geometry::make_hertz_mesh(hertz);
  const unsigned int      n        = hertz.n_contact_zone_elements;
  const double            lc       = hertz.contact_zone_width;
  const std::set<Edge>    cylinder = cell_edges(mesh, 0);

  std::set<unsigned int> arc_vertices, top_vertices;
  unsigned int           n_arc_faces = 0;
  for (const auto &face : faces_of(mesh, "contact surface"))
    {
      const bool on_arc =
        cylinder.count(edge(face.vertices[0], face.vertices[1]));
      n_arc_faces += on_arc;
      for (const unsigned int v : face.vertices)
        (on_arc ? arc_vertices : top_vertices).insert(v);
    }
  EXPECT_EQ(n_arc_faces, n);
  ASSERT_EQ(arc_vertices.size(), n + 1);
  ASSERT_EQ(top_vertices.size(), n + 1);

  const std::vector<double> arc_x = sorted_x_coordinates(mesh, arc_vertices),
                            top_x = sorted_x_coordinates(mesh, top_vertices);
  for (unsigned int i = 0; i <= n; ++i)
    {
      EXPECT_NEAR(arc_x[i], top_x[i], 1e-12 * lc);
      EXPECT_NEAR(arc_x[i], lc * i / n, 1e-12 * lc);
    }
  for (const unsigned int v : arc_vertices)
    EXPECT_NEAR(mesh.vertices[v].distance(Point<2>(0, hertz.radius)),
                hertz.radius,
                1e-12 * hertz.radius);
  for (const unsigned int v : top_vertices)
    EXPECT_EQ(mesh.vertices[v][1], 0);
  // The two blocks touch at the origin only, where they share the vertex.
  EXPECT_EQ(*arc_vertices.begin(), *top_vertices.begin());
}



TEST(Hertz, FullModelHasTheNamedBlocksAndFaceGroups)
{
  EXPECT_FALSE(parse("").hertz.full_model);
  const Parameters::Hertz hertz = parse(full_model + "end").hertz;
  ASSERT_TRUE(hertz.full_model);
  const auto mesh = geometry::make_hertz_mesh(hertz);
  check_mesh(mesh,
             {"cylinder", "foundation"},
             {"contact surface",
              "load",
              "bottom",
              "cylinder surface",
              "foundation surface",
              "foundation side"});

  using Range = std::pair<double, double>;
  EXPECT_EQ(coordinate_range(mesh, "load", 1), Range(100, 100));
  EXPECT_EQ(coordinate_range(mesh, "load", 0), Range(-100, 100));
  EXPECT_EQ(coordinate_range(mesh, "bottom", 1), Range(-500, -500));
  EXPECT_EQ(coordinate_range(mesh, "bottom", 0), Range(-500, 500));
  EXPECT_EQ(coordinate_range(mesh, "foundation side", 0), Range(-500, 500));
  EXPECT_EQ(coordinate_range(mesh, "foundation side", 1), Range(-500, 0));
  for (const auto &face : faces_of(mesh, "foundation side"))
    EXPECT_EQ(std::abs(mesh.vertices[face.vertices[0]][0]), 500);
  EXPECT_EQ(coordinate_range(mesh, "foundation surface", 1), Range(0, 0));
  EXPECT_EQ(coordinate_range(mesh, "foundation surface", 0), Range(-500, 500));
  for (const auto &face : faces_of(mesh, "foundation surface"))
    for (const unsigned int v : face.vertices)
      EXPECT_GE(std::abs(mesh.vertices[v][0]), 15);
  EXPECT_EQ(coordinate_range(mesh, "cylinder surface", 0), Range(-100, 100));
  for (const auto &face : faces_of(mesh, "cylinder surface"))
    for (const unsigned int v : face.vertices)
      {
        EXPECT_NEAR(mesh.vertices[v].distance(Point<2>(0, 100)), 100, 1e-9);
        EXPECT_GE(std::abs(mesh.vertices[v][0]), 15);
      }

  // The foundation is a rectangle; the cylinder is the lower half disk less
  // the circular segments cut off by the chords of its arc faces.
  EXPECT_NEAR(block_area(mesh, 1), 1000. * 500, 1e-9 * 1000 * 500);
  const std::set<Edge> cylinder = cell_edges(mesh, 0);
  double               area     = numbers::PI * 100 * 100 / 2;
  for (const std::string group : {"cylinder surface", "contact surface"})
    for (const auto &face : faces_of(mesh, group))
      if (cylinder.count(edge(face.vertices[0], face.vertices[1])))
        {
          const double angle = 2 * std::asin(length(mesh, face) / 200);
          area -= 100 * 100 / 2. * (angle - std::sin(angle));
        }
  EXPECT_NEAR(block_area(mesh, 0), area, 1e-9 * area);
}



// The full model is the half model and its mirror image in x = 0: the mesh
// is symmetric, and the half model is unchanged by the option.
TEST(Hertz, FullModelIsTheMirroredHalfModel)
{
  const auto half = geometry::make_hertz_mesh(parse("").hertz);
  const auto full = geometry::make_hertz_mesh(parse(full_model + "end").hertz);
  std::set<unsigned int> axis;
  for (const auto &face : faces_of(half, "symmetry"))
    axis.insert(face.vertices.begin(), face.vertices.end());
  EXPECT_EQ(full.cells.size(), 2 * half.cells.size());
  EXPECT_EQ(full.vertices.size(), 2 * half.vertices.size() - axis.size());
  EXPECT_EQ(full.faces.size(),
            2 * (half.faces.size() - faces_of(half, "symmetry").size()));

  // Every vertex has its mirror image, exactly.
  std::set<std::pair<double, double>> points;
  for (const Point<2> &p : full.vertices)
    points.emplace(p[0], p[1]);
  EXPECT_EQ(points.size(), full.vertices.size());
  for (const Point<2> &p : full.vertices)
    EXPECT_TRUE(points.count({-p[0], p[1]})) << p;
  for (const unsigned int block : {0u, 1u})
    EXPECT_NEAR(block_area(full, block),
                2 * block_area(half, block),
                1e-12 * block_area(full, block));
}



// As in the half model, both sides of the contact zone have vertices at the
// same x_i = i Lc / N, now for i = -N..N, also when refined.
TEST(Hertz, FullModelContactZoneVerticesMatchInX)
{
  for (const std::string &refinement :
       {std::string(""),
        std::string(" set Elements in contact zone = 120\n"
                    " set Mesh size = 10\n")})
    {
      SCOPED_TRACE(refinement);
      const Parameters::Hertz hertz =
        parse(full_model + refinement + "end").hertz;
      const auto           mesh     = geometry::make_hertz_mesh(hertz);
      const int            n        = hertz.n_contact_zone_elements;
      const double         lc       = hertz.contact_zone_width;
      const std::set<Edge> cylinder = cell_edges(mesh, 0);

      std::set<unsigned int> arc_vertices, top_vertices;
      unsigned int           n_arc_faces = 0, n_top_faces = 0;
      unsigned int           n_left_faces = 0, n_right_faces = 0;
      for (const auto &face : faces_of(mesh, "contact surface"))
        {
          const bool on_arc =
            cylinder.count(edge(face.vertices[0], face.vertices[1]));
          (on_arc ? n_arc_faces : n_top_faces) += 1;
          const double x = mesh.vertices[face.vertices[0]][0] +
                           mesh.vertices[face.vertices[1]][0];
          (x < 0 ? n_left_faces : n_right_faces) += 1;
          for (const unsigned int v : face.vertices)
            (on_arc ? arc_vertices : top_vertices).insert(v);
        }
      EXPECT_EQ(n_arc_faces, 2u * n);
      EXPECT_EQ(n_top_faces, 2u * n);
      EXPECT_EQ(n_left_faces, 2u * n);
      EXPECT_EQ(n_right_faces, 2u * n);
      ASSERT_EQ(arc_vertices.size(), 2u * n + 1);
      ASSERT_EQ(top_vertices.size(), 2u * n + 1);

      const std::vector<double> arc_x =
                                  sorted_x_coordinates(mesh, arc_vertices),
                                top_x =
                                  sorted_x_coordinates(mesh, top_vertices);
      for (int i = -n; i <= n; ++i)
        {
          EXPECT_NEAR(arc_x[i + n], top_x[i + n], 1e-12 * lc);
          EXPECT_NEAR(arc_x[i + n], lc * i / n, 1e-12 * lc);
        }
      const auto count_x = [&](const std::vector<double> &x, const int sign) {
        return std::count_if(x.begin(), x.end(), [&](const double x_i) {
          return sign * x_i > 0;
        });
      };
      EXPECT_EQ(count_x(arc_x, -1), n);
      EXPECT_EQ(count_x(arc_x, 1), n);
      EXPECT_EQ(count_x(top_x, -1), n);
      EXPECT_EQ(count_x(top_x, 1), n);

      for (const unsigned int v : arc_vertices)
        EXPECT_NEAR(mesh.vertices[v].distance(Point<2>(0, hertz.radius)),
                    hertz.radius,
                    1e-12 * hertz.radius);
      for (const unsigned int v : top_vertices)
        EXPECT_EQ(mesh.vertices[v][1], 0);
      // The two blocks touch at the origin only, where they share the
      // vertex.
      std::vector<unsigned int> shared;
      std::set_intersection(arc_vertices.begin(),
                            arc_vertices.end(),
                            top_vertices.begin(),
                            top_vertices.end(),
                            std::back_inserter(shared));
      ASSERT_EQ(shared.size(), 1u);
      EXPECT_EQ(mesh.vertices[shared[0]], Point<2>(0, 0));
    }
}



TEST(Simplices, HertzFullModelOfTriangles)
{
  // Element shape = triangle: the full model of positive triangles, the
  // mirror image included, with the contact zone's nodes at x_i = i Lc / n
  // on both sides of the axis.
  const Parameters geometry =
    parse("set Source = hertz\nsubsection Hertz\nset Element shape = "
          "triangle\nset Full model = true\nend");
  const auto mesh = geometry::make_hertz_mesh(geometry.hertz);
  for (const auto &cell : mesh.cells)
    {
      ASSERT_EQ(cell.vertices.size(), 3u);
      EXPECT_GT(measure(mesh, cell), 0);
    }
  const double       width = geometry.hertz.contact_zone_width;
  const unsigned int n     = geometry.hertz.n_contact_zone_elements;
  std::set<long>     ticks;
  for (const auto &face : faces_of(mesh, "contact surface"))
    for (const unsigned int v : face.vertices)
      {
        const double x = mesh.vertices[v][0] / width * n;
        EXPECT_NEAR(x, std::round(x), 1e-9) << mesh.vertices[v];
        ticks.insert(std::lround(x));
      }
  // -n, ..., n.
  EXPECT_EQ(ticks.size(), 2 * n + 1);
  for (const unsigned int block : {0u, 1u})
    {
      Triangulation<2> triangulation;
      geometry::create_block_triangulation(mesh, {block}, triangulation);
      EXPECT_GT(triangulation.n_active_cells(), 0u);
    }
}
