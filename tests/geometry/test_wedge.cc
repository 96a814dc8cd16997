// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Tests of the case "wedge" (3D rock wedge): plane orientations, the
// wedge's corners and volume against the exact ones, other orientations,
// planes that form no wedge, and the wedge of tetrahedra.

#include "geometry_test_helpers.h"

using namespace geometry_test;

namespace
{
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
      expect_error([&] { geometry::make_mesh<3>(geometry, ""); }, message);
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
  const double exact = tetrahedron_volume(exact_wedge_corners(geometry.wedge));
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
          Triangle key = {
            {face.vertices[0], face.vertices[1], face.vertices[2]}};
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
