// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Unit tests of the geometry module: the built-in generators, Gmsh files,
// the transforms and the error messages.

#include <fdem/geometry/block_mesh.h>
#include <fdem/geometry/generators.h>
#include <fdem/geometry/generators_3d.h>
#include <fdem/geometry/gmsh_mesh.h>
#include <fdem/geometry/make_mesh.h>
#include <fdem/parameters/geometry_parameters.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <gmsh.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <regex>
#include <set>

namespace
{
  /** The x coordinates of the listed vertices, sorted. */
  std::vector<double>
  sorted_x_coordinates(const fdem::geometry::MeshDescription<2> &mesh,
                       const std::set<unsigned int> &            vertices)
  {
    std::vector<double> x;
    for (const unsigned int v : vertices)
      x.push_back(mesh.vertices[v][0]);
    std::sort(x.begin(), x.end());
    return x;
  }

  using namespace dealii;
  using namespace fdem;
  using fdem::geometry::MeshDescription;
  using Parameters = parameters::GeometryParameters;
  using Edge       = std::pair<unsigned int, unsigned int>;

  const std::string data_directory = FDEM_GEOMETRY_TEST_DATA;

  /** Geometry parameters from the entries of the subsection "Geometry". */
  Parameters
  parse(const std::string &entries)
  {
    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    prm.parse_input_from_string("subsection Geometry\n" + entries + "\nend\n");
    Parameters geometry;
    geometry.parse_parameters(prm);
    return geometry;
  }

  /** A file name in the temporary directory, unique to the running test. */
  std::string
  temporary_file(const std::string &extension)
  {
    const auto *test = ::testing::UnitTest::GetInstance()->current_test_info();
    return (std::filesystem::temp_directory_path() /
            ("fdem_" + std::string(test->test_suite_name()) + "_" +
             test->name() + "_" + std::to_string(getpid()) + extension))
      .string();
  }

  /**
   * Expect @p function to throw a message that contains @p text. deal.II
   * wraps its messages, so whitespace is compared as single spaces.
   */
  template <typename Function>
  void
  expect_error(const Function &function, const std::string &text)
  {
    try
      {
        function();
        ADD_FAILURE() << "no exception; expected one saying: " << text;
      }
    catch (const std::exception &error)
      {
        const std::string message =
          std::regex_replace(error.what(), std::regex("\\s+"), " ");
        EXPECT_NE(message.find(text), std::string::npos) << message;
      }
  }

  template <int dim>
  double
  measure(const MeshDescription<dim> &mesh, const CellData<dim> &cell)
  {
    const std::vector<unsigned int> vertices(cell.vertices.begin(),
                                             cell.vertices.end());
    return GridTools::cell_measure<dim>(mesh.vertices, vertices);
  }

  template <int dim>
  double
  block_area(const MeshDescription<dim> &mesh, const unsigned int block)
  {
    double area = 0;
    for (const auto &cell : mesh.cells)
      if (cell.material_id == block)
        area += measure(mesh, cell);
    return area;
  }

  unsigned int
  index_of(const std::vector<std::string> &names, const std::string &name)
  {
    const auto found = std::find(names.begin(), names.end(), name);
    EXPECT_NE(found, names.end()) << "no group '" << name << "'";
    return found - names.begin();
  }

  /** The faces of group @p group. */
  template <int dim>
  std::vector<CellData<dim - 1>>
  faces_of(const MeshDescription<dim> &mesh, const std::string &group)
  {
    const unsigned int             id = index_of(mesh.face_group_names, group);
    std::vector<CellData<dim - 1>> faces;
    for (const auto &face : mesh.faces)
      if (face.boundary_id == id)
        faces.push_back(face);
    return faces;
  }

  Edge
  edge(const unsigned int a, const unsigned int b)
  {
    return {std::min(a, b), std::max(a, b)};
  }

  /** Edges of the cells of @p block (all blocks if it is invalid). */
  std::set<Edge>
  cell_edges(const MeshDescription<2> &mesh,
             const unsigned int        block = numbers::invalid_unsigned_int)
  {
    std::set<Edge> edges;
    for (const auto &cell : mesh.cells)
      if (block == numbers::invalid_unsigned_int || cell.material_id == block)
        for (const auto &[a, b] :
             {Edge{0, 1}, Edge{2, 3}, Edge{0, 2}, Edge{1, 3}})
          edges.insert(edge(cell.vertices[a], cell.vertices[b]));
    return edges;
  }

  double
  length(const MeshDescription<2> &mesh, const CellData<1> &face)
  {
    return mesh.vertices[face.vertices[0]].distance(
      mesh.vertices[face.vertices[1]]);
  }

  using Face3 = std::array<unsigned int, 4>;

  Face3
  sorted_face(const CellData<2> &face)
  {
    Face3 key = {
      {face.vertices[0], face.vertices[1], face.vertices[2], face.vertices[3]}};
    std::sort(key.begin(), key.end());
    return key;
  }

  /** The faces of the cells of @p block (all blocks if it is invalid). */
  std::set<Face3>
  cell_faces(const MeshDescription<3> &mesh,
             const unsigned int        block = numbers::invalid_unsigned_int)
  {
    std::set<Face3> faces;
    for (const auto &cell : mesh.cells)
      if (block == numbers::invalid_unsigned_int || cell.material_id == block)
        for (const unsigned int f : GeometryInfo<3>::face_indices())
          {
            Face3 key;
            for (unsigned int v = 0; v < 4; ++v)
              key[v] =
                cell.vertices[GeometryInfo<3>::face_to_cell_vertices(f, v)];
            std::sort(key.begin(), key.end());
            faces.insert(key);
          }
    return faces;
  }

  /** The cell boundaries of a mesh: edges in 2D, faces in 3D. */
  std::set<Edge>
  cell_boundaries(const MeshDescription<2> &mesh)
  {
    return cell_edges(mesh);
  }

  std::set<Face3>
  cell_boundaries(const MeshDescription<3> &mesh)
  {
    return cell_faces(mesh);
  }

  Edge
  boundary_key(const CellData<1> &face)
  {
    return edge(face.vertices[0], face.vertices[1]);
  }

  Face3
  boundary_key(const CellData<2> &face)
  {
    return sorted_face(face);
  }

  /**
   * What every generated mesh must satisfy: the given names in order,
   * quadrilaterals (2D) or hexahedra (3D) of positive measure, every block
   * and face group non-empty, every face a face of a cell, every vertex
   * used, and deal.II accepts it as a triangulation.
   */
  template <int dim>
  void
  check_mesh(const MeshDescription<dim>     &mesh,
             const std::vector<std::string> &blocks,
             const std::vector<std::string> &face_groups)
  {
    EXPECT_EQ(mesh.block_names, blocks);
    EXPECT_EQ(mesh.face_group_names, face_groups);
    std::vector<unsigned int> n_cells(blocks.size()),
      n_faces(face_groups.size());
    std::vector<bool> used(mesh.vertices.size());
    for (const auto &cell : mesh.cells)
      {
        ASSERT_EQ(cell.vertices.size(), GeometryInfo<dim>::vertices_per_cell);
        ASSERT_LT(cell.material_id, blocks.size());
        EXPECT_GT(measure(mesh, cell), 0);
        ++n_cells[cell.material_id];
        for (const unsigned int v : cell.vertices)
          used[v] = true;
      }
    const auto boundaries = cell_boundaries(mesh);
    for (const auto &face : mesh.faces)
      {
        if constexpr (dim == 3)
          {
            ASSERT_EQ(face.vertices.size(), 4u);
          }
        ASSERT_LT(face.boundary_id, face_groups.size());
        ++n_faces[face.boundary_id];
        EXPECT_TRUE(boundaries.count(boundary_key(face)));
      }
    for (unsigned int b = 0; b < blocks.size(); ++b)
      EXPECT_GT(n_cells[b], 0u) << blocks[b];
    for (unsigned int g = 0; g < face_groups.size(); ++g)
      EXPECT_GT(n_faces[g], 0u) << face_groups[g];
    EXPECT_EQ(std::count(used.begin(), used.end(), false), 0);

    Triangulation<dim> triangulation;
    EXPECT_NO_THROW(triangulation.create_triangulation(mesh.vertices,
                                                       mesh.cells,
                                                       SubCellData()));
    if constexpr (dim == 3)
      {
        EXPECT_EQ(triangulation.n_active_cells(), mesh.cells.size());
      }
  }

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

      const std::vector<double> arc_x = sorted_x_coordinates(mesh, arc_vertices),
                                top_x = sorted_x_coordinates(mesh, top_vertices);
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



TEST(InclinedBlock, StructuredMeshOnThePlane)
{
  const Parameters::InclinedBlock block = parse("").inclined_block;
  const auto mesh = geometry::make_inclined_block_mesh(block);
  check_mesh(mesh,
             {"block", "foundation"},
             {"sliding surface",
              "block surface",
              "foundation surface",
              "foundation base",
              "foundation ends"});
  // Element size 1 m x 1 m: 10 x 5 in the block, 20 x 5 in the foundation.
  unsigned int n_block_cells = 0;
  for (const auto &cell : mesh.cells)
    {
      n_block_cells += (cell.material_id == 0);
      EXPECT_NEAR(measure(mesh, cell), 1, 1e-10);
    }
  EXPECT_EQ(n_block_cells, 50u);
  EXPECT_EQ(mesh.cells.size(), 150u);

  const double         angle      = block.inclination * numbers::PI / 180;
  const std::set<Edge> foundation = cell_edges(mesh, 1);
  const auto           sliding    = faces_of(mesh, "sliding surface");
  EXPECT_EQ(sliding.size(), 10u);
  for (const auto &face : sliding)
    {
      EXPECT_TRUE(foundation.count(edge(face.vertices[0], face.vertices[1])));
      for (const unsigned int v : face.vertices)
        {
          const Point<2> &p = mesh.vertices[v];
          const double    s = p[0] * std::cos(angle) + p[1] * std::sin(angle);
          EXPECT_NEAR(-p[0] * std::sin(angle) + p[1] * std::cos(angle),
                      0,
                      1e-10);
          EXPECT_GT(s, -1e-10);
          EXPECT_LT(s, block.block_length + 1e-10);
        }
    }
}



TEST(GmshFile, WrittenMeshReadsBack)
{
  const auto        mesh = geometry::make_slope_mesh(parse("").slope);
  const std::string file = temporary_file(".msh");
  geometry::write_gmsh_file(mesh, file);
  const auto read = geometry::read_gmsh_file<2>(file);
  std::filesystem::remove(file);
  EXPECT_EQ(read.cells.size(), mesh.cells.size());
  EXPECT_EQ(read.vertices.size(), mesh.vertices.size());
  EXPECT_EQ(read.faces.size(), mesh.faces.size());
  EXPECT_EQ(read.block_names, mesh.block_names);
  EXPECT_EQ(read.face_group_names, mesh.face_group_names);
  EXPECT_NEAR(block_area(read, 0),
              block_area(mesh, 0),
              1e-12 * block_area(mesh, 0));
}



TEST(GmshFile, GeoFileIsMeshed)
{
  const auto mesh =
    geometry::read_gmsh_file<2>(data_directory + "/two_blocks.geo");
  std::vector<std::string> groups = mesh.face_group_names;
  std::sort(groups.begin(), groups.end());
  EXPECT_EQ(mesh.block_names,
            (std::vector<std::string>{"left block", "block 7"}));
  EXPECT_EQ(groups, (std::vector<std::string>{"bottom", "interface"}));
  EXPECT_EQ(mesh.cells.size(), 32u);
  EXPECT_EQ(mesh.vertices.size(), 45u);
  EXPECT_EQ(faces_of(mesh, "interface").size(), 4u);
  EXPECT_EQ(faces_of(mesh, "bottom").size(), 8u);
  check_mesh(mesh, mesh.block_names, mesh.face_group_names);
  EXPECT_NEAR(block_area(mesh, 0), 1, 1e-12);
}



TEST(GmshFile, Version2WithAClockwiseCell)
{
  const auto mesh =
    geometry::read_gmsh_file<2>(data_directory + "/two_quads_v2.msh");
  check_mesh(mesh, {"rock"}, {"base"});
  EXPECT_EQ(mesh.cells.size(), 2u);
  EXPECT_EQ(mesh.vertices.size(), 6u);
}



TEST(GmshFile, BinaryFilesOfBothVersions)
{
  for (const double version : {2.2, 4.1})
    {
      const std::string file = temporary_file(".msh");
      {
        geometry::GmshSession session;
        gmsh::open(data_directory + "/two_blocks.geo");
        gmsh::model::mesh::generate(2);
        gmsh::option::setNumber("Mesh.Binary", 1);
        gmsh::option::setNumber("Mesh.MshFileVersion", version);
        gmsh::write(file);
      }
      const auto mesh = geometry::read_gmsh_file<2>(file);
      std::filesystem::remove(file);
      EXPECT_EQ(mesh.cells.size(), 32u) << "version " << version;
      EXPECT_EQ(mesh.faces.size(), 12u) << "version " << version;
    }
}



TEST(GmshFile, HexahedraIn3D)
{
  const auto mesh = geometry::read_gmsh_file<3>(data_directory + "/box.geo");
  EXPECT_EQ(mesh.block_names, std::vector<std::string>{"box"});
  EXPECT_EQ(mesh.cells.size(), 8u);
  EXPECT_EQ(mesh.vertices.size(), 27u);
  EXPECT_EQ(mesh.faces.size(), 8u);
  double volume = 0;
  for (const auto &cell : mesh.cells)
    {
      EXPECT_GT(measure(mesh, cell), 0);
      volume += measure(mesh, cell);
    }
  EXPECT_NEAR(volume, 1, 1e-12);
  for (const auto &face : mesh.faces)
    {
      const double z =
        (mesh.face_group_names[face.boundary_id] == "base") ? 0 : 1;
      for (const unsigned int v : face.vertices)
        EXPECT_EQ(mesh.vertices[v][2], z);
    }
  Triangulation<3> triangulation;
  EXPECT_NO_THROW(triangulation.create_triangulation(mesh.vertices,
                                                     mesh.cells,
                                                     SubCellData()));
}



TEST(GmshFile, HigherOrderElementsGiveTheirCorners)
{
  geometry::GmshSession session;
  gmsh::open(data_directory + "/two_blocks.geo");
  gmsh::model::mesh::generate(2);
  gmsh::model::mesh::setOrder(2);
  const auto mesh = geometry::extract_current_gmsh_model<2>("quadratic");
  EXPECT_EQ(mesh.cells.size(), 32u);
  EXPECT_EQ(mesh.vertices.size(), 45u);
  EXPECT_EQ(mesh.faces.size(), 12u);
  EXPECT_NEAR(block_area(mesh, 0) + block_area(mesh, 1), 2, 1e-12);
}



TEST(GmshFile, CellInTwoBlocksIsRejected)
{
  geometry::GmshSession session;
  gmsh::model::add("overlap");
  const int surface = gmsh::model::addDiscreteEntity(2);
  gmsh::model::mesh::addNodes(2,
                              surface,
                              {1, 2, 3, 4},
                              {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  gmsh::model::mesh::addElementsByType(surface, 3, {1}, {1, 2, 3, 4});
  gmsh::model::setPhysicalName(2,
                               gmsh::model::addPhysicalGroup(2, {surface}),
                               "a");
  gmsh::model::setPhysicalName(2,
                               gmsh::model::addPhysicalGroup(2, {surface}),
                               "b");
  expect_error([] { geometry::extract_current_gmsh_model<2>("overlap"); },
               "overlap: element 1 belongs to two blocks, 'a' and 'b'.");
}



TEST(GmshFile, Errors)
{
  const std::string missing = data_directory + "/does_not_exist.msh";
  expect_error([&] { geometry::read_gmsh_file<2>(missing); },
               "Gmsh file '" + missing + "': is missing or cannot be read.");
  expect_error(
    [] { geometry::read_gmsh_file<2>(data_directory + "/mixed.geo"); },
    "the mesh mixes triangles and quadrilaterals (block 'rock'); mixed "
    "meshes are not supported");
  expect_error(
    [] { geometry::read_gmsh_file<2>(data_directory + "/no_groups.geo"); },
    "no_groups.geo': there is no physical group of dimension 2");
  expect_error(
    [] { geometry::read_gmsh_file<3>(data_directory + "/two_blocks.geo"); },
    "the model is 2-dimensional, but a 3-dimensional mesh was asked for");
  expect_error(
    [] { geometry::read_gmsh_file<2>(data_directory + "/box.geo"); },
    "the model is 3-dimensional, but a 2-dimensional mesh was asked for");
  expect_error(
    [] {
      geometry::read_gmsh_file<2>(data_directory + "/twisted_quad_v2.msh");
    },
    "of block 'rock' near (0 0) is degenerate or twisted");
  expect_error(
    [] { geometry::read_gmsh_file<2>(data_directory + "/algorithm_8.geo"); },
    "Mesh.Algorithm = 8 (Frontal-Delaunay for quads) crashes Gmsh 4.8.4");
  expect_error(
    [] { geometry::read_gmsh_file<2>(data_directory + "/syntax_error.geo"); },
    "Gmsh could not read '" + data_directory + "/syntax_error.geo': Unknown");
  // Gmsh stays locked after an error inside a file; a new session recovers.
  EXPECT_EQ(geometry::read_gmsh_file<2>(data_directory + "/two_blocks.geo")
              .cells.size(),
            32u);
  expect_error([] { geometry::GmshSession first, second; },
               "Only one GmshSession may exist at a time");
}



TEST(Transform, RotationScaleAndTranslationIn2D)
{
  const auto reference =
    geometry::make_mesh<2>(parse("set Source = inclined block"), "", "");
  const auto moved = geometry::make_mesh<2>(
    parse("set Source = inclined block\nset Scale factor = 2\n"
          "set Rotation angle = 30\nset Translation = 1, -2"),
    "",
    "");
  ASSERT_EQ(moved.vertices.size(), reference.vertices.size());
  const double c = std::cos(numbers::PI / 6), s = std::sin(numbers::PI / 6);
  for (unsigned int v = 0; v < reference.vertices.size(); ++v)
    {
      const Point<2> &x = reference.vertices[v];
      const Point<2>  expected(2 * (c * x[0] - s * x[1]) + 1,
                              2 * (s * x[0] + c * x[1]) - 2);
      EXPECT_LT(moved.vertices[v].distance(expected), 1e-12 * 30);
    }
  for (unsigned int i = 0; i < moved.cells.size(); ++i)
    EXPECT_NEAR(measure(moved, moved.cells[i]),
                4 * measure(reference, reference.cells[i]),
                1e-12);
}



TEST(Transform, RotationAboutAnAxisIn3D)
{
  // 120 degrees about (1, 1, 1) maps x to y, y to z, z to x.
  MeshDescription<3> mesh;
  mesh.vertices = {Point<3>(1, 2, 3), Point<3>(-4, 0.5, 7)};
  geometry::apply_transformation(
    parse("set Rotation axis = 1, 1, 1\nset Rotation angle = 120\n"
          "set Translation = 0, 0, 10"),
    mesh);
  EXPECT_LT(mesh.vertices[0].distance(Point<3>(3, 1, 12)), 1e-14 * 20);
  EXPECT_LT(mesh.vertices[1].distance(Point<3>(7, -4, 10.5)), 1e-14 * 20);
}



TEST(MakeMesh, MeshFileRelativeToThePrmDirectoryAndOutput)
{
  const std::string output = temporary_file(".msh");
  const auto        mesh   = geometry::make_mesh<2>(
    parse("set Source = mesh file\nset Mesh file = two_blocks.geo"),
    data_directory,
    output);
  EXPECT_EQ(mesh.cells.size(), 32u);
  EXPECT_EQ(geometry::read_gmsh_file<2>(output).cells.size(), 32u);
  std::filesystem::remove(output);
}



TEST(MakeMesh, Errors)
{
  expect_error([] { geometry::make_mesh<3>(parse(""), "", ""); },
               "Geometry/Source: the built-in generators slope, hertz and "
               "inclined block are 2D only; in 3D use wedge, block on plane, "
               "hertz sphere or a mesh file.");
  for (const std::string source : {"wedge", "block on plane", "hertz sphere"})
    expect_error(
      [&] { geometry::make_mesh<2>(parse("set Source = " + source), "", ""); },
      "Geometry/Source: the built-in generators wedge, block on plane and "
      "hertz sphere are 3D only; set Dimension = 3.");
  expect_error(
    [] {
      geometry::make_mesh<2>(parse("set Source = inclined block\n"
                                   "set Translation = 0, 0, 1"),
                             "",
                             "");
    },
    "Geometry/Translation: a 2D model has no z component");
}



TEST(GeometryParameters, ValidationMessages)
{
  expect_error(
    [] { parse("subsection Slope\n set Base elevation = 30\nend"); },
    "Geometry/Slope/Base elevation: must lie below every point of the "
    "ground surface.");
  expect_error(
    [] { parse("subsection Slope\n set Ground surface = 0,25; 0,30\nend"); },
    "Geometry/Slope/Ground surface: the x coordinates must increase");
  expect_error(
    [] { parse("subsection Slope\n set Sliding surface = polyline\nend"); },
    "Geometry/Slope/Sliding surface polyline: needs at least two points");
  expect_error(
    [] {
      parse("subsection Slope\n set Sliding surface = polyline\n"
            " set Sliding surface polyline = 5,20; 45,40\nend");
    },
    "Geometry/Slope/Sliding surface polyline: its first and last points");
  expect_error(
    [] {
      parse("set Source = hertz\nsubsection Hertz\n"
            " set Contact zone width = 150\nend");
    },
    "Geometry/Hertz/Contact zone width: must be positive and smaller");
  expect_error(
    [] {
      parse("set Source = hertz\nsubsection Hertz\n"
            " set Elements in contact zone = 61\nend");
    },
    "Geometry/Hertz/Elements in contact zone: must be even");
  expect_error([] { parse("set Source = mesh file"); },
               "Geometry/Mesh file: must be given");
  expect_error([] { parse("set Scale factor = 0"); },
               "Geometry/Scale factor: must be positive.");
  // Only the selected source is validated.
  EXPECT_NO_THROW(parse(
    "set Source = hertz\nsubsection Slope\n set Base elevation = 30\nend"));
}



TEST(GeometryParameters, MeshFilePath)
{
  Parameters geometry =
    parse("set Source = mesh file\nset Mesh file = meshes/a.msh");
  EXPECT_EQ(geometry.mesh_file_path("/work/case"), "/work/case/meshes/a.msh");
  EXPECT_EQ(geometry.mesh_file_path(""), "meshes/a.msh");
  geometry.mesh_file = "/data/b.msh";
  EXPECT_EQ(geometry.mesh_file_path("/work/case"), "/data/b.msh");
}



// ---------------------------------------------------------------------------
// The 3D generators
// ---------------------------------------------------------------------------

namespace
{
  /** Area of a plane quadrilateral face (two triangles). */
  double
  area(const MeshDescription<3> &mesh, const CellData<2> &face)
  {
    const Point<3> &p0 = mesh.vertices[face.vertices[0]],
                   &p1 = mesh.vertices[face.vertices[1]],
                   &p2 = mesh.vertices[face.vertices[2]],
                   &p3 = mesh.vertices[face.vertices[3]];
    return 0.5 * cross_product_3d(p1 - p0, p3 - p0).norm() +
           0.5 * cross_product_3d(p3 - p0, p2 - p0).norm();
  }

  /**
   * The mesh is conforming everywhere: in deal.II's triangulation of the
   * whole mesh, the boundary faces are exactly the faces of the groups
   * other than @p interfaces (which lie inside). Each block alone is a
   * triangulation whose boundary faces all carry a group.
   */
  void
  expect_conforming_mesh(const MeshDescription<3>       &mesh,
                         const std::vector<std::string> &interfaces)
  {
    std::set<unsigned int> interface_ids;
    for (const std::string &name : interfaces)
      interface_ids.insert(index_of(mesh.face_group_names, name));
    std::set<Face3> outer;
    for (const auto &face : mesh.faces)
      if (!interface_ids.count(face.boundary_id))
        outer.insert(sorted_face(face));

    Triangulation<3> triangulation;
    triangulation.create_triangulation(mesh.vertices,
                                       mesh.cells,
                                       SubCellData());
    std::set<Face3> boundary;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            Face3 key;
            for (unsigned int v = 0; v < 4; ++v)
              key[v] = face->vertex_index(v);
            std::sort(key.begin(), key.end());
            boundary.insert(key);
          }
    EXPECT_EQ(boundary.size(), outer.size());
    EXPECT_TRUE(boundary == outer);

    for (unsigned int b = 0; b < mesh.block_names.size(); ++b)
      {
        Triangulation<3> block;
        geometry::create_block_triangulation(mesh, {b}, block);
        for (const auto &cell : block.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                EXPECT_NE(face->boundary_id(), geometry::unnamed_boundary_id)
                  << mesh.block_names[b] << " " << face->center();
              }
      }
  }

  /**
   * Every vertex of every face of @p group belongs to cells of both blocks,
   * and every face is a face of a cell of each block: the interface is
   * conforming.
   */
  void
  expect_conforming_interface(const MeshDescription<3> &mesh,
                              const std::string        &group)
  {
    std::vector<std::set<unsigned int>> blocks_of_vertex(mesh.vertices.size());
    for (const auto &cell : mesh.cells)
      for (const unsigned int v : cell.vertices)
        blocks_of_vertex[v].insert(cell.material_id);
    const std::set<Face3> faces_0 = cell_faces(mesh, 0),
                          faces_1 = cell_faces(mesh, 1);
    const auto interface          = faces_of(mesh, group);
    ASSERT_FALSE(interface.empty()) << group;
    for (const auto &face : interface)
      {
        EXPECT_TRUE(faces_0.count(sorted_face(face))) << group;
        EXPECT_TRUE(faces_1.count(sorted_face(face))) << group;
        for (const unsigned int v : face.vertices)
          EXPECT_EQ(blocks_of_vertex[v].size(), 2u) << group;
      }
  }

  /** Upward unit normal of a plane of dip psi and dip direction alpha. */
  Tensor<1, 3>
  normal(const double dip, const double dip_direction)
  {
    const double psi   = dip * numbers::PI / 180,
                 alpha = dip_direction * numbers::PI / 180;
    return Tensor<1, 3>({std::sin(psi) * std::sin(alpha),
                         std::sin(psi) * std::cos(alpha),
                         std::cos(psi)});
  }

  /** The point on the three planes n_i . x = d_i, by Cramer's rule. */
  Point<3>
  meet(const std::array<Tensor<1, 3>, 3> &n, const std::array<double, 3> &d)
  {
    const auto det =
      [](const Tensor<1, 3> &a, const Tensor<1, 3> &b, const Tensor<1, 3> &c) {
        return a * cross_product_3d(b, c);
      };
    // Columns of the matrix with rows n_i.
    std::array<Tensor<1, 3>, 3> column;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        column[j][i] = n[i][j];
    const Tensor<1, 3> rhs({d[0], d[1], d[2]});
    const double       denominator = det(column[0], column[1], column[2]);
    return Point<3>(det(rhs, column[1], column[2]) / denominator,
                    det(column[0], rhs, column[2]) / denominator,
                    det(column[0], column[1], rhs) / denominator);
  }

  /** Smallest and largest edge length and smallest corner sine of a mesh. */
  struct Quality
  {
    double min_edge = std::numeric_limits<double>::max(), max_edge = 0;
    double min_sine = 1;
  };

  Quality
  quality(const MeshDescription<3> &mesh)
  {
    Quality q;
    for (const auto &cell : mesh.cells)
      for (unsigned int v = 0; v < 8; ++v)
        {
          Tensor<2, 3> edges;
          for (unsigned int d = 0; d < 3; ++d)
            {
              Tensor<1, 3> edge = mesh.vertices[cell.vertices[v ^ (1u << d)]] -
                                  mesh.vertices[cell.vertices[v]];
              if ((v >> d) & 1u)
                edge *= -1;
              q.min_edge = std::min(q.min_edge, edge.norm());
              q.max_edge = std::max(q.max_edge, edge.norm());
              edges[d]   = edge / edge.norm();
            }
          q.min_sine = std::min(q.min_sine, determinant(edges));
        }
    return q;
  }

  const std::vector<std::string> wedge_blocks = {"wedge", "rock"};
  const std::vector<std::string> wedge_groups =
    {"plane A", "plane B", "slope face", "upper slope", "base", "sides"};
  const std::vector<std::string> block_on_plane_blocks = {"block",
                                                          "foundation"};
  const std::vector<std::string> block_on_plane_groups = {"sliding surface",
                                                          "block surface",
                                                          "foundation surface",
                                                          "foundation base",
                                                          "foundation ends"};

  /** The wedge's corners from the planes of @p wedge, as in the docs. */
  std::array<Point<3>, 4>
  exact_wedge_corners(const Parameters::Wedge &wedge)
  {
    const double   psi   = wedge.slope_face.dip * numbers::PI / 180;
    const double   alpha = wedge.slope_face.dip_direction * numbers::PI / 180;
    const double   h     = wedge.slope_height;
    const Point<3> crest(-h / std::tan(psi) * std::sin(alpha),
                         -h / std::tan(psi) * std::cos(alpha),
                         h);
    const auto     n = [](const parameters::PlaneOrientation &o) {
      return normal(o.dip, o.dip_direction);
    };
    const Tensor<1, 3> face = n(wedge.slope_face), upper = n(wedge.upper_slope),
                       a = n(wedge.plane_a), b = n(wedge.plane_b);
    const double d = upper * crest;
    return {{Point<3>(),
             meet({{a, b, upper}}, {{0, 0, d}}),
             meet({{face, upper, a}}, {{0, d, 0}}),
             meet({{face, upper, b}}, {{0, d, 0}})}};
  }

  double
  tetrahedron_volume(const std::array<Point<3>, 4> &p)
  {
    return std::abs((p[1] - p[0]) *
                    cross_product_3d(p[2] - p[0], p[3] - p[0])) /
           6;
  }

  /** The checks of a wedge mesh; returns it. */
  MeshDescription<3>
  check_wedge(const Parameters::Wedge &wedge)
  {
    const auto mesh = geometry::make_wedge_mesh(wedge);
    check_mesh(mesh, wedge_blocks, wedge_groups);
    const double h = wedge.slope_height;

    for (const std::string group : {"plane A", "plane B"})
      expect_conforming_interface(mesh, group);
    expect_conforming_mesh(mesh, {"plane A", "plane B"});
    const Tensor<1, 3> n_a =
      normal(wedge.plane_a.dip, wedge.plane_a.dip_direction);
    const Tensor<1, 3> n_b =
      normal(wedge.plane_b.dip, wedge.plane_b.dip_direction);
    for (const auto &[group, n] :
         {std::make_pair("plane A", n_a), std::make_pair("plane B", n_b)})
      for (const auto &face : faces_of(mesh, group))
        for (const unsigned int v : face.vertices)
          EXPECT_LT(std::abs(n * mesh.vertices[v]), 1e-9 * h) << group;

    // Flat faces: the hexahedra fill the tetrahedron exactly.
    const std::array<Point<3>, 4> corners = exact_wedge_corners(wedge);
    const double                  exact   = tetrahedron_volume(corners);
    EXPECT_NEAR(block_area(mesh, 0), exact, 1e-9 * exact);
    // The mesh's corners are the wedge's.
    for (const Point<3> &corner : corners)
      {
        double distance = std::numeric_limits<double>::max();
        for (const auto &cell : mesh.cells)
          if (cell.material_id == 0)
            for (const unsigned int v : cell.vertices)
              distance = std::min(distance, mesh.vertices[v].distance(corner));
        EXPECT_LT(distance, 1e-9 * h) << corner;
      }

    // Only the rock reaches the base and the sides; the free surfaces are
    // on both blocks.
    const std::set<Face3> wedge_faces = cell_faces(mesh, 0),
                          rock_faces  = cell_faces(mesh, 1);
    for (const std::string group : {"base", "sides"})
      for (const auto &face : faces_of(mesh, group))
        {
          EXPECT_FALSE(wedge_faces.count(sorted_face(face))) << group;
          EXPECT_TRUE(rock_faces.count(sorted_face(face))) << group;
        }
    for (const std::string group : {"slope face", "upper slope"})
      {
        unsigned int n_wedge = 0, n_rock = 0;
        for (const auto &face : faces_of(mesh, group))
          {
            n_wedge += wedge_faces.count(sorted_face(face));
            n_rock += rock_faces.count(sorted_face(face));
          }
        EXPECT_GT(n_wedge, 0u) << group;
        EXPECT_GT(n_rock, 0u) << group;
      }
    return mesh;
  }
} // namespace



TEST(PlaneOrientation, NormalAndDownDipDirection)
{
  parameters::PlaneOrientation plane;
  plane.dip            = 30;
  plane.dip_direction  = 120;
  const Tensor<1, 3> n = plane.upward_normal(), d = plane.down_dip_direction();
  EXPECT_LT((n - normal(30, 120)).norm(), 1e-15);
  // Dipping to the east-south-east: the normal leans that way.
  EXPECT_GT(n[0], 0);
  EXPECT_LT(n[1], 0);
  EXPECT_NEAR(n.norm(), 1, 1e-15);
  EXPECT_NEAR(d.norm(), 1, 1e-15);
  EXPECT_NEAR(n * d, 0, 1e-15);
  EXPECT_NEAR(d[2], -0.5, 1e-15);
  EXPECT_NEAR(std::atan2(d[0], d[1]) * 180 / numbers::PI, 120, 1e-12);
  // Dip direction 0 is north, 90 east.
  plane.dip_direction = 0;
  EXPECT_GT(plane.down_dip_direction()[1], 0);
  plane.dip_direction = 90;
  EXPECT_GT(plane.down_dip_direction()[0], 0);
}



TEST(Wedge, DefaultMeshHasTheNamedBlocksAndFaceGroups)
{
  const Parameters geometry = parse("set Source = wedge");
  const auto      &wedge    = geometry.wedge;
  EXPECT_EQ(wedge.slope_height, 20);
  EXPECT_EQ(wedge.rock_extent, 40);
  EXPECT_EQ(wedge.mesh_size, 2);
  EXPECT_EQ(wedge.plane_a.dip, 50);
  EXPECT_EQ(wedge.plane_a.dip_direction, 140);
  const auto mesh = check_wedge(wedge);

  // The apex at the origin, the crest at z = H above it on the face.
  const std::array<Point<3>, 4> corners = wedge.corners();
  const std::array<Point<3>, 4> exact   = exact_wedge_corners(wedge);
  for (unsigned int i = 0; i < 4; ++i)
    EXPECT_LT(corners[i].distance(exact[i]), 1e-12 * 20);
  EXPECT_EQ(corners[0], Point<3>());
  const Point<3> crest = wedge.crest_point();
  EXPECT_NEAR(crest[0], 0, 1e-12);
  EXPECT_NEAR(crest[1], 20 / std::tan(65 * numbers::PI / 180), 1e-12);
  EXPECT_NEAR(crest[2], 20, 1e-12);
  for (const unsigned int i : {1u, 2u, 3u})
    EXPECT_NEAR(corners[i][2], 20, 1e-12);

  // The planes of the outer faces; the box reaches the rock extent below
  // the apex.
  const Tensor<1, 3> n_face = normal(65, 180);
  for (const auto &face : faces_of(mesh, "upper slope"))
    for (const unsigned int v : face.vertices)
      EXPECT_NEAR(mesh.vertices[v][2], 20, 1e-9);
  for (const auto &face : faces_of(mesh, "base"))
    for (const unsigned int v : face.vertices)
      EXPECT_NEAR(mesh.vertices[v][2], -40, 1e-9);
  for (const auto &face : faces_of(mesh, "slope face"))
    {
      // The face itself, or the ground in front of the toe.
      bool on_face = true, on_ground = true;
      for (const unsigned int v : face.vertices)
        {
          on_face &= std::abs(n_face * mesh.vertices[v]) < 1e-9;
          on_ground &=
            std::abs(mesh.vertices[v][2]) < 1e-9 && mesh.vertices[v][1] < 1e-9;
        }
      EXPECT_TRUE(on_face || on_ground);
    }
  double x_min = 0, x_max = 0, y_min = 0, y_max = 0, z_min = 0;
  for (const Point<3> &p : mesh.vertices)
    {
      x_min = std::min(x_min, p[0]);
      x_max = std::max(x_max, p[0]);
      y_min = std::min(y_min, p[1]);
      y_max = std::max(y_max, p[1]);
      z_min = std::min(z_min, p[2]);
    }
  double wedge_x_min = 0, wedge_x_max = 0, wedge_y_max = 0;
  for (const Point<3> &p : corners)
    {
      wedge_x_min = std::min(wedge_x_min, p[0]);
      wedge_x_max = std::max(wedge_x_max, p[0]);
      wedge_y_max = std::max(wedge_y_max, p[1]);
    }
  // Dip direction 180: the face looks south (-y), the strike is along x.
  EXPECT_NEAR(x_min, wedge_x_min - 40, 1e-9);
  EXPECT_NEAR(x_max, wedge_x_max + 40, 1e-9);
  EXPECT_NEAR(y_max, wedge_y_max + 40, 1e-9);
  EXPECT_NEAR(y_min, -40, 1e-9);
  EXPECT_NEAR(z_min, -40, 1e-9);

  const Quality q             = quality(mesh);
  unsigned int  n_wedge_cells = 0;
  for (const auto &cell : mesh.cells)
    n_wedge_cells += (cell.material_id == 0);
  std::cout << "wedge: " << mesh.cells.size() << " cells (" << n_wedge_cells
            << " in the wedge), " << mesh.vertices.size() << " vertices, edges "
            << q.min_edge << " to " << q.max_edge << " m, smallest corner sine "
            << q.min_sine << std::endl;
  EXPECT_GT(q.min_sine, 0.05);
}



TEST(Wedge, OtherOrientationsAndSizes)
{
  // An inclined upper slope, a steeper face looking north-east, unequal
  // planes, a finer mesh and a smaller rock extent.
  const Parameters geometry =
    parse("set Source = wedge\nsubsection Wedge\n"
          " set Slope height = 12\n set Slope face = 75, 40\n"
          " set Upper slope = 10, 60\n set Plane A = 45, 5\n"
          " set Plane B = 60, 85\n set Mesh size = 1.5\n"
          " set Rock extent = 10\nend");
  const auto mesh = check_wedge(geometry.wedge);
  for (const auto &face : faces_of(mesh, "base"))
    for (const unsigned int v : face.vertices)
      EXPECT_NEAR(mesh.vertices[v][2], -10, 1e-9);
  const Tensor<1, 3> n_upper = normal(10, 60);
  const Point<3>     crest   = geometry.wedge.crest_point();
  for (const auto &face : faces_of(mesh, "upper slope"))
    for (const unsigned int v : face.vertices)
      EXPECT_NEAR(n_upper * (mesh.vertices[v] - crest), 0, 1e-9);
}



TEST(Wedge, PlanesThatFormNoWedgeAreRejected)
{
  const std::string message = "Geometry/Wedge: the planes do not form a "
                              "wedge that daylights in the slope face.";
  for (const std::string &planes :
       {// The line of intersection plunges more steeply than the face.
        std::string(" set Plane A = 80, 140\n set Plane B = 80, 220\n"),
        // Parallel planes.
        std::string(" set Plane A = 50, 140\n set Plane B = 50, 140\n"),
        // Dipping into the slope: the line rises out of the face.
        std::string(" set Plane A = 50, 320\n set Plane B = 50, 40\n")})
    {
      SCOPED_TRACE(planes);
      expect_error(
        [&] {
          parse("set Source = wedge\nsubsection Wedge\n" + planes + "end");
        },
        message);
      // The generator checks too, and make_mesh in 3D.
      Parameters geometry = parse("subsection Wedge\n" + planes + "end");
      expect_error([&] { geometry::make_wedge_mesh(geometry.wedge); }, message);
      geometry.source = Parameters::Source::wedge;
      expect_error([&] { geometry::make_mesh<3>(geometry, "", ""); }, message);
    }
  expect_error(
    [] {
      parse("set Source = wedge\nsubsection Wedge\n"
            " set Upper slope = 70, 180\nend");
    },
    "Geometry/Wedge/Upper slope: must dip less steeply than the slope face");
  expect_error(
    [] {
      parse(
        "set Source = wedge\nsubsection Wedge\n set Plane A = 95, 140\nend");
    },
    "Geometry/Wedge/Plane A: the dip must lie in [0, 90] and the dip "
    "direction in [0, 360] degrees.");
  expect_error(
    [] {
      parse("set Source = wedge\nsubsection Wedge\n set Mesh size = 0\nend");
    },
    "Geometry/Wedge/Mesh size: must be positive.");
}



TEST(BlockOnPlane, StructuredMeshOnTheRotatedPlane)
{
  const Parameters geometry             = parse("set Source = block on plane");
  const Parameters::BlockOnPlane &block = geometry.block_on_plane;
  EXPECT_EQ(block.plane.dip, 30);
  EXPECT_EQ(block.plane.dip_direction, 120);
  EXPECT_EQ(block.foundation_overhang, 3);
  const auto mesh = geometry::make_block_on_plane_mesh(block);
  check_mesh(mesh, block_on_plane_blocks, block_on_plane_groups);
  expect_conforming_interface(mesh, "sliding surface");
  expect_conforming_mesh(mesh, {"sliding surface"});

  // Elements of 1 m: 10 x 6 x 5 in the block, 16 x 12 x 5 in the slab.
  unsigned int n_block_cells = 0;
  for (const auto &cell : mesh.cells)
    {
      n_block_cells += (cell.material_id == 0);
      EXPECT_NEAR(measure(mesh, cell), 1, 1e-12);
    }
  EXPECT_EQ(n_block_cells, 300u);
  EXPECT_EQ(mesh.cells.size(), 300u + 960u);
  EXPECT_EQ(mesh.vertices.size(), 11u * 7 * 6 + 17u * 13 * 6 - 11 * 7);
  EXPECT_NEAR(block_area(mesh, 0), 10. * 6 * 5, 1e-9 * 300);
  EXPECT_NEAR(block_area(mesh, 1), 16. * 12 * 5, 1e-9 * 960);
  EXPECT_EQ(faces_of(mesh, "sliding surface").size(), 60u);
  EXPECT_EQ(faces_of(mesh, "block surface").size(), 60u + 2 * 50 + 2 * 30);
  EXPECT_EQ(faces_of(mesh, "foundation surface").size(), 16u * 12 - 60);
  EXPECT_EQ(faces_of(mesh, "foundation base").size(), 16u * 12);
  EXPECT_EQ(faces_of(mesh, "foundation ends").size(), 2u * 80 + 2 * 60);

  // The sliding surface lies on the plane through the origin with the
  // given normal and covers L x B; the block lies above it, down the dip
  // from the origin and centred on it along the strike.
  const Tensor<1, 3> n = normal(30, 120);
  const Tensor<1, 3> down_dip(
    {std::cos(numbers::PI / 6) * std::sin(2 * numbers::PI / 3),
     std::cos(numbers::PI / 6) * std::cos(2 * numbers::PI / 3),
     -0.5});
  const Tensor<1, 3> strike       = cross_product_3d(n, down_dip);
  double             sliding_area = 0;
  for (const auto &face : faces_of(mesh, "sliding surface"))
    {
      sliding_area += area(mesh, face);
      for (const unsigned int v : face.vertices)
        EXPECT_NEAR(n * mesh.vertices[v], 0, 1e-12);
    }
  EXPECT_NEAR(sliding_area, 60, 1e-9 * 60);
  for (const auto &cell : mesh.cells)
    for (const unsigned int v : cell.vertices)
      {
        const Point<3> &p = mesh.vertices[v];
        if (cell.material_id == 0)
          {
            EXPECT_GT(n * p, -1e-12);
            EXPECT_LT(n * p, 5 + 1e-12);
            EXPECT_GT(down_dip * p, -1e-12);
            EXPECT_LT(down_dip * p, 10 + 1e-12);
            EXPECT_LT(std::abs(strike * p), 3 + 1e-12);
          }
        else
          {
            EXPECT_LT(n * p, 1e-12);
            EXPECT_GT(n * p, -5 - 1e-12);
          }
      }
  for (const auto &face : faces_of(mesh, "foundation base"))
    for (const unsigned int v : face.vertices)
      EXPECT_NEAR(n * mesh.vertices[v], -5, 1e-12);
  for (const auto &face : faces_of(mesh, "foundation surface"))
    for (const unsigned int v : face.vertices)
      EXPECT_NEAR(n * mesh.vertices[v], 0, 1e-12);
  for (const auto &face : faces_of(mesh, "foundation ends"))
    {
      double along = 0, across = 0;
      for (const unsigned int v : face.vertices)
        {
          along  = std::max(along, std::abs(down_dip * mesh.vertices[v] - 5));
          across = std::max(across, std::abs(strike * mesh.vertices[v]));
        }
      EXPECT_TRUE(std::abs(along - 8) < 1e-12 || std::abs(across - 6) < 1e-12);
    }
  // The block's faces other than the sliding surface are not on the
  // foundation.
  const std::set<Face3> foundation = cell_faces(mesh, 1);
  for (const auto &face : faces_of(mesh, "block surface"))
    EXPECT_FALSE(foundation.count(sorted_face(face)));
}



TEST(BlockOnPlane, OtherSizesAndTheTransformation)
{
  const std::string entries =
    "set Source = block on plane\nsubsection Block on plane\n"
    " set Dip = 47\n set Dip direction = 301\n set Block length = 4\n"
    " set Block width = 3\n set Block height = 2\n"
    " set Foundation thickness = 1.5\n set Foundation overhang = 0.4\n"
    " set Elements along length = 8\n set Elements along width = 3\n"
    " set Elements across height = 4\nend\n";
  const Parameters geometry = parse(entries);
  const auto       mesh     = geometry::make_mesh<3>(geometry, "", "");
  check_mesh(mesh, block_on_plane_blocks, block_on_plane_groups);
  expect_conforming_interface(mesh, "sliding surface");
  expect_conforming_mesh(mesh, {"sliding surface"});
  EXPECT_NEAR(block_area(mesh, 0), 4. * 3 * 2, 1e-9 * 24);
  EXPECT_NEAR(block_area(mesh, 1), 4.8 * 3.8 * 1.5, 1e-9 * 27);
  // 8 x 3 x 4 in the block; the slab has one element across the overhang
  // in both directions and 3 across the thickness.
  EXPECT_EQ(mesh.cells.size(), 8u * 3 * 4 + 10u * 5 * 3);
  const Tensor<1, 3> n            = normal(47, 301);
  double             sliding_area = 0;
  for (const auto &face : faces_of(mesh, "sliding surface"))
    {
      sliding_area += area(mesh, face);
      for (const unsigned int v : face.vertices)
        EXPECT_NEAR(n * mesh.vertices[v], 0, 1e-12);
    }
  EXPECT_NEAR(sliding_area, 12, 1e-9 * 12);

  // make_mesh applies the transformation to the 3D generators too.
  const auto moved = geometry::make_mesh<3>(
    parse(entries + "set Scale factor = 2\nset Translation = 1, 2, 3"), "", "");
  ASSERT_EQ(moved.vertices.size(), mesh.vertices.size());
  for (unsigned int v = 0; v < mesh.vertices.size(); ++v)
    EXPECT_LT(moved.vertices[v].distance(
                Point<3>(2 * mesh.vertices[v] + Tensor<1, 3>({1., 2., 3.}))),
              1e-12 * 10);
}



TEST(BlockOnPlane, WrittenMeshReadsBack)
{
  const auto mesh = geometry::make_block_on_plane_mesh(
    parse("set Source = block on plane").block_on_plane);
  const std::string file = temporary_file(".msh");
  geometry::write_gmsh_file(mesh, file);
  const auto read = geometry::read_gmsh_file<3>(file);
  std::filesystem::remove(file);
  EXPECT_EQ(read.cells.size(), mesh.cells.size());
  EXPECT_EQ(read.vertices.size(), mesh.vertices.size());
  EXPECT_EQ(read.faces.size(), mesh.faces.size());
  EXPECT_EQ(read.block_names, mesh.block_names);
  EXPECT_EQ(read.face_group_names, mesh.face_group_names);
  EXPECT_NEAR(block_area(read, 0), 300, 1e-9 * 300);
}



TEST(BlockOnPlane, BadInputs)
{
  expect_error(
    [] {
      parse("set Source = block on plane\nsubsection Block on plane\n"
            " set Block width = 0\nend");
    },
    "Geometry/Block on plane/Block length, width and height: must be "
    "positive.");
  expect_error(
    [] {
      parse("set Source = block on plane\nsubsection Block on plane\n"
            " set Foundation overhang = 0\nend");
    },
    "Geometry/Block on plane/Foundation thickness and overhang: must be "
    "positive.");
}



// ---------------------------------------------------------------------------
// Hertz sphere (3D quarter model)
// ---------------------------------------------------------------------------

TEST(HertzSphere, QuarterModelWithTheSphereAboveTheFoundationNodes)
{
  const Parameters geometry = parse("set Source = hertz sphere");
  const Parameters::HertzSphere &p = geometry.hertz_sphere;
  EXPECT_EQ(p.radius, 100);
  EXPECT_EQ(p.n_contact_zone_elements, 6u);
  const auto mesh = geometry::make_mesh<3>(geometry, "", "");
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
  const double   R = p.radius, S = p.cap_half_width, H = p.load_height;
  const Point<3> centre(0, 0, R);
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
  double exact = 0;
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
  const unsigned int n  = p.n_contact_zone_elements;
  const double       lc = p.contact_zone_width;
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
      longest = std::max(longest,
                         mesh.vertices[cell.vertices[GeometryInfo<3>::line_to_cell_vertices(l, 0)]]
                           .distance(mesh.vertices[cell.vertices[GeometryInfo<3>::line_to_cell_vertices(l, 1)]]));
  EXPECT_LE(longest, 1.7 * p.mesh_size);
}



TEST(HertzSphere, BadInputs)
{
  const std::string prefix = "set Source = hertz sphere\nsubsection Hertz sphere\n";
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



TEST(Simplices, GmshTrianglesAreTurnedToPositiveOrientation)
{
  // triangles.geo: the unit square, its triangles clockwise in Gmsh.
  const auto mesh =
    geometry::read_gmsh_file<2>(data_directory + "/triangles.geo");
  ASSERT_FALSE(mesh.cells.empty());
  double area = 0;
  for (const auto &cell : mesh.cells)
    {
      ASSERT_EQ(cell.vertices.size(), 3u);
      EXPECT_GT(measure(mesh, cell), 0);
      area += measure(mesh, cell);
    }
  EXPECT_NEAR(area, 1, 1e-12);
  Triangulation<2> triangulation;
  geometry::create_block_triangulation(mesh, {0}, triangulation);
  EXPECT_EQ(triangulation.n_active_cells(), mesh.cells.size());
  EXPECT_FALSE(triangulation.all_reference_cells_are_hyper_cube());
}



TEST(Simplices, WedgeOfTetrahedra)
{
  // Element shape = tetrahedron keeps Gmsh's tetrahedra: positive volumes,
  // the wedge filled exactly, triangles on the planes shared by a wedge
  // cell and a rock cell, and deal.II takes both blocks.
  const Parameters geometry =
    parse("set Source = wedge\nsubsection Wedge\nset Mesh size = 4\n"
          "set Element shape = tetrahedron\nend");
  const auto mesh = geometry::make_wedge_mesh(geometry.wedge);
  EXPECT_EQ(mesh.block_names, wedge_blocks);
  EXPECT_EQ(mesh.face_group_names, wedge_groups);
  for (const auto &cell : mesh.cells)
    {
      ASSERT_EQ(cell.vertices.size(), 4u);
      EXPECT_GT(measure(mesh, cell), 0);
    }
  const double exact =
    tetrahedron_volume(exact_wedge_corners(geometry.wedge));
  EXPECT_NEAR(block_area(mesh, 0), exact, 1e-9 * exact);

  using Triangle = std::array<unsigned int, 3>;
  std::array<std::set<Triangle>, 2> block_faces;
  for (const auto &cell : mesh.cells)
    for (unsigned int skip = 0; skip < 4; ++skip)
      {
        Triangle     face;
        unsigned int k = 0;
        for (unsigned int v = 0; v < 4; ++v)
          if (v != skip)
            face[k++] = cell.vertices[v];
        std::sort(face.begin(), face.end());
        block_faces[cell.material_id].insert(face);
      }
  const double h = geometry.wedge.slope_height;
  for (const auto &[group, plane] :
       {std::make_pair("plane A", geometry.wedge.plane_a),
        std::make_pair("plane B", geometry.wedge.plane_b)})
    {
      const auto faces = faces_of(mesh, group);
      EXPECT_FALSE(faces.empty());
      const Tensor<1, 3> n = plane.upward_normal();
      for (const auto &face : faces)
        {
          ASSERT_EQ(face.vertices.size(), 3u);
          Triangle key = {{face.vertices[0], face.vertices[1], face.vertices[2]}};
          std::sort(key.begin(), key.end());
          EXPECT_TRUE(block_faces[0].count(key)) << group;
          EXPECT_TRUE(block_faces[1].count(key)) << group;
          for (const unsigned int v : face.vertices)
            EXPECT_LT(std::abs(n * mesh.vertices[v]), 1e-9 * h) << group;
        }
    }
  for (const unsigned int block : {0u, 1u})
    {
      Triangulation<3> triangulation;
      geometry::create_block_triangulation(mesh, {block}, triangulation);
      EXPECT_GT(triangulation.n_active_cells(), 0u);
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
