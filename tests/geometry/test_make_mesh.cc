// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Tests of what every case goes through: the subsection "Geometry" (its
// validation messages), make_mesh() (its dispatch and
// errors) and the transformation x -> R (s x) + t in 2D and 3D.

#include "geometry_test_helpers.h"

using namespace geometry_test;

TEST(Transform, RotationScaleAndTranslationIn2D)
{
  const auto reference =
    geometry::make_mesh<2>(parse("set Source = inclined block"), "");
  const auto moved = geometry::make_mesh<2>(
    parse("set Source = inclined block\nset Scale factor = 2\n"
          "set Rotation angle = 30\nset Translation = 1, -2"),
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



TEST(MakeMesh, MeshFileAndOutput)
{
  const std::string output = temporary_file(".msh");
  const auto        mesh =
    geometry::make_mesh<2>(parse("set Source = mesh file\nset Mesh file = " +
                                 data_directory + "/two_blocks.geo"),
                           output);
  EXPECT_EQ(mesh.cells.size(), 32u);
  EXPECT_EQ(geometry::read_gmsh_file<2>(output).cells.size(), 32u);
  std::filesystem::remove(output);
}



TEST(MakeMesh, Errors)
{
  expect_error([] { geometry::make_mesh<3>(parse(""), ""); },
               "Geometry/Source: the built-in generators slope, hertz and "
               "inclined block are 2D only; in 3D use wedge, block on plane, "
               "hertz sphere, slope 3d or a mesh file.");
  for (const std::string source :
       {"wedge", "block on plane", "hertz sphere", "slope 3d"})
    expect_error(
      [&] { geometry::make_mesh<2>(parse("set Source = " + source), ""); },
      "Geometry/Source: the built-in generators wedge, block on plane, "
      "hertz sphere and slope 3d are 3D only; set Dimension = 3.");
  expect_error(
    [] {
      geometry::make_mesh<2>(parse("set Source = inclined block\n"
                                   "set Translation = 0, 0, 1"),
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
