// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Tests of reading and writing Gmsh files (any case can come from one):
// versions 2 and 4, ASCII and binary, .geo files, hexahedra, higher-order
// and clockwise cells, triangles, and the error messages.

#include "geometry_test_helpers.h"

using namespace geometry_test;

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
               "overlap: element 1 belongs to two blocks, 'a' and 'b' (if one "
               "is a material region, list it in Materials/Names).");
  // Named as a material, 'b' is the material region of block 'a''s cell.
  const auto mesh = geometry::extract_current_gmsh_model<2>("overlap", {"b"});
  EXPECT_EQ(mesh.block_names, std::vector<std::string>{"a"});
  EXPECT_EQ(mesh.material_names, std::vector<std::string>{"b"});
  EXPECT_EQ(mesh.cell_materials, std::vector<unsigned int>{0});
  // Block 0 plus one block times (1 + region 0).
  EXPECT_EQ(mesh.material_key(0), 1u);
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
