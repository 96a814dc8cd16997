// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Tests of the case block on plane, 2D (source "inclined block") and 3D
// (source "block on plane"): structured meshes on the rotated plane, the
// sliding surface shared by both blocks, the transformation, bad input.

#include "geometry_test_helpers.h"

using namespace geometry_test;

namespace
{
  const std::vector<std::string> block_on_plane_blocks = {"block",
                                                          "foundation"};
  const std::vector<std::string> block_on_plane_groups = {"sliding surface",
                                                          "block surface",
                                                          "foundation surface",
                                                          "foundation base",
                                                          "foundation ends"};
} // namespace



TEST(InclinedBlock, StructuredMeshOnThePlane)
{
  const Parameters::InclinedBlock block = parse("").inclined_block;
  const auto mesh = geometry::make_block_on_plane_mesh(block);
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



// With Element shape = triangle, the 2D case splits each quadrilateral of
// the same structured grid into two triangles: the same vertices and face
// groups, twice the cells, each of half the area, and the sliding surface
// an edge of a triangle on both sides.
TEST(InclinedBlock, TrianglesSplitEachQuadrilateralInTwo)
{
  const Parameters::InclinedBlock quadrilaterals = parse("").inclined_block;
  Parameters::InclinedBlock       triangles      = quadrilaterals;
  triangles.element_shape = Parameters::ElementShape::simplex;
  const auto quad_mesh    = geometry::make_block_on_plane_mesh(quadrilaterals);
  const auto mesh         = geometry::make_block_on_plane_mesh(triangles);

  EXPECT_EQ(mesh.vertices, quad_mesh.vertices);
  EXPECT_EQ(mesh.face_group_names, quad_mesh.face_group_names);
  EXPECT_EQ(mesh.faces.size(), quad_mesh.faces.size());
  ASSERT_EQ(mesh.cells.size(), 2 * quad_mesh.cells.size());
  for (const auto &cell : mesh.cells)
    {
      ASSERT_EQ(cell.vertices.size(), 3u);
      EXPECT_NEAR(measure(mesh, cell), 0.5, 1e-10); // 1 m x 1 m halved
    }
  EXPECT_NEAR(block_area(mesh, 0), 50, 1e-9);
  EXPECT_NEAR(block_area(mesh, 1), 100, 1e-9);

  // Each face of the sliding surface is an edge of a triangle of the block
  // and of one of the foundation.
  const auto has_edge = [&](const CellData<1> &face, const unsigned int block) {
    for (const auto &cell : mesh.cells)
      if (cell.material_id == block &&
          std::count(cell.vertices.begin(),
                     cell.vertices.end(),
                     face.vertices[0]) == 1 &&
          std::count(cell.vertices.begin(),
                     cell.vertices.end(),
                     face.vertices[1]) == 1)
        return true;
    return false;
  };
  const auto sliding = faces_of(mesh, "sliding surface");
  EXPECT_EQ(sliding.size(), 10u);
  for (const auto &face : sliding)
    {
      EXPECT_TRUE(has_edge(face, 0));
      EXPECT_TRUE(has_edge(face, 1));
    }

  Triangulation<2> triangulation;
  EXPECT_NO_THROW(triangulation.create_triangulation(mesh.vertices,
                                                     mesh.cells,
                                                     SubCellData()));
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
  const auto       mesh     = geometry::make_mesh<3>(geometry, "");
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
    parse(entries + "set Scale factor = 2\nset Translation = 1, 2, 3"), "");
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
