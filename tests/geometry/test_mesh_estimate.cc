// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The estimate of a built-in mesh made before meshing (mesh_estimate.h)
// against the mesh itself, for every generator, and its refusal beyond
// Geometry/Memory limit.

#include "geometry_test_helpers.h"

#include <fdem/geometry/mesh_estimate.h>

#include <set>

using namespace geometry_test;

namespace
{
  // The estimate only has to tell a mesh that fits from one that is orders
  // of magnitude too large: within a factor of 3 of the real counts.
  constexpr double factor = 3;

  /** prm/slope_3d.prm's model with another element shape, mesh size or
   * surface. */
  std::string
  slope_3d_entries(const std::string &shape,
                   const double       mesh_size,
                   const std::string &surface = "sphere",
                   const std::string &centre  = "19.61, 20, 46.32",
                   const double       width   = 40)
  {
    return "set Source = slope 3d\nsubsection Slope 3D\nset Sliding surface "
           "= " +
           surface + "\nset Surface centre = " + centre +
           "\nset Surface radius = 21.32\nset Width = " +
           std::to_string(width) + "\nset Element shape = " + shape +
           "\nset Mesh size = " + std::to_string(mesh_size) + "\nend";
  }

  template <int dim>
  void
  expect_close_estimate(const std::string &entries)
  {
    SCOPED_TRACE(entries);
    const Parameters geometry = parse(entries);
    const auto       estimate = geometry::estimate_mesh(geometry);
    const auto       mesh     = geometry::make_mesh<dim>(geometry, "");
    const double     cells    = mesh.cells.size();
    const double     vertices = mesh.vertices.size();
    std::cout << entries << ": " << cells << " cells (estimate "
              << estimate.n_cells << "), " << vertices << " vertices (estimate "
              << estimate.n_vertices << ")" << std::endl;
    EXPECT_FALSE(estimate.entry.empty());
    EXPECT_LT(estimate.n_cells, factor * cells);
    EXPECT_GT(estimate.n_cells, cells / factor);
    EXPECT_LT(estimate.n_vertices, factor * vertices);
    EXPECT_GT(estimate.n_vertices, vertices / factor);
  }
} // namespace



TEST(MeshEstimate, WithinAFactorOfTheMeshIn2D)
{
  expect_close_estimate<2>("set Source = slope");
  expect_close_estimate<2>(
    "set Source = slope\nsubsection Slope\nset Mesh size = 0.25\nend");
  expect_close_estimate<2>("set Source = hertz");
  expect_close_estimate<2>(
    "set Source = hertz\nsubsection Hertz\nset Full model = true\n"
    "set Element shape = triangle\nend");
  expect_close_estimate<2>("set Source = inclined block");
}



TEST(MeshEstimate, WithinAFactorOfTheMeshIn3D)
{
  expect_close_estimate<3>("set Source = block on plane");
  expect_close_estimate<3>("set Source = hertz sphere");
  expect_close_estimate<3>("set Source = wedge");
  expect_close_estimate<3>(
    "set Source = wedge\nsubsection Wedge\nset Element shape = "
    "tetrahedron\nend");
  expect_close_estimate<3>(slope_3d_entries("tetrahedron", 2));
  expect_close_estimate<3>(slope_3d_entries("hexahedron", 2));
}



TEST(MeshEstimate, PairsOfTheSlope3DAnUpperBoundWithin30Percent)
{
  // The pairs enter the memory estimate squared (the dense interface
  // parts): an upper bound, but not by so much that a model that fits is
  // refused. A pair per vertex of the sliding surface.
  const auto check = [](const std::string &entries) {
    SCOPED_TRACE(entries);
    const Parameters       geometry = parse(entries);
    const auto             estimate = geometry::estimate_mesh(geometry);
    const auto             mesh     = geometry::make_mesh<3>(geometry, "");
    std::set<unsigned int> vertices;
    for (const auto &face : faces_of(mesh, "sliding surface"))
      vertices.insert(face.vertices.begin(), face.vertices.end());
    const double pairs = vertices.size();
    std::cout << entries << ": " << pairs << " pairs (estimate "
              << estimate.n_pairs << ")" << std::endl;
    EXPECT_GT(estimate.n_pairs, pairs);
    EXPECT_LT(estimate.n_pairs, 1.3 * pairs);
  };
  check(slope_3d_entries("tetrahedron", 2));
  check(slope_3d_entries("tetrahedron", 1.5));
  check(slope_3d_entries("hexahedron", 2));
  check(slope_3d_entries("tetrahedron", 2, "cylinder", "19.61, 0, 46.32", 6));
}



TEST(MeshEstimate, RefusedBeyondTheLimitWithTheEntry)
{
  // The default hertz mesh fits in 100 MiB, not in 1 MiB.
  EXPECT_NO_THROW(geometry::check_mesh_estimate(
    parse("set Source = hertz\nset Memory limit = 100"), 2, 1));
  expect_error(
    [] {
      geometry::check_mesh_estimate(
        parse("set Source = hertz\nset Memory limit = 1"), 2, 1);
    },
    "Geometry/Hertz/Mesh size, Elements in contact zone and the lengths: "
    "about");
  // Not a number of elements that can be counted: refused at any limit.
  expect_error(
    [] {
      geometry::check_mesh_estimate(
        parse(
          "set Source = hertz\nset Memory limit = 1e300\nsubsection Hertz\n"
          "set Foundation width = 1e308\nset Foundation depth = 1e308\nend"),
        2,
        1);
    },
    "Geometry/Memory limit");
  // Without a limit: this machine's memory, or less under ulimit -v.
  EXPECT_GT(geometry::memory_limit_MiB(parse("")), 0);
  EXPECT_EQ(geometry::memory_limit_MiB(parse("set Memory limit = 123")), 123);
  // A mesh file is not estimated.
  EXPECT_TRUE(geometry::estimate_mesh(
                parse("set Source = mesh file\nset Mesh file = x.msh"))
                .entry.empty());
}



TEST(MeshEstimate, GeoFilesFromTheirBoundaryMesh)
{
  // An upper bound by design (the roundest shape of that boundary), but
  // not by more than a factor 5 on these blocks (squares, a box).
  const auto check = [](const std::string &name, auto dimension) {
    constexpr int          dim  = decltype(dimension)::value;
    const std::string      file = data_directory + "/" + name;
    geometry::MeshEstimate estimate;
    const auto             mesh = geometry::read_gmsh_file<dim>(file, [&]() {
      estimate = geometry::estimate_gmsh_geometry(dim, file);
    });
    std::cout << name << ": " << mesh.cells.size() << " cells (estimate "
              << estimate.n_cells << "), " << mesh.vertices.size()
              << " vertices (estimate " << estimate.n_vertices << ")"
              << std::endl;
    EXPECT_GT(estimate.n_cells, mesh.cells.size() / 1.5) << name;
    EXPECT_LT(estimate.n_cells, 5.0 * mesh.cells.size()) << name;
  };
  check("triangles.geo", std::integral_constant<int, 2>());
  check("two_blocks.geo", std::integral_constant<int, 2>());
  check("box.geo", std::integral_constant<int, 3>());
}



TEST(MeshEstimate, IterativeMixedSystemNeedsNoSquareOfThePairs)
{
  // prm/block_on_plane_3d.prm with 99 x 99 elements along the plane: 10^4
  // pairs. The dense interface parts alone would be about 15 matrices of
  // (3 x 10^4)^2 doubles (over 100 GiB): refused within 24 GiB, with the
  // hint that the iterative mixed system, which never forms them, fits
  // (its peak was 2.8 GiB, doc/scaling.md).
  const std::string entries =
    "set Source = block on plane\nset Memory limit = 24576\n"
    "subsection Block on plane\nset Dip = 30\nset Dip direction = 120\n"
    "set Elements along length = 99\nset Elements along width = 99\n"
    "set Elements across height = 2\nend";
  const auto estimate = geometry::estimate_mesh(parse(entries));
  EXPECT_NEAR(estimate.n_pairs, 1e4, 1);
  EXPECT_GT(estimate.memory_MiB(3, 1, true), 100 * 1024);
  EXPECT_LT(estimate.memory_MiB(3, 1, false), 24 * 1024);
  expect_error(
    [&] { geometry::check_mesh_estimate(parse(entries), 3, 1, true); },
    "or set Solver/Mixed system = iterative (about");
  EXPECT_NO_THROW(geometry::check_mesh_estimate(parse(entries), 3, 1, false));
}
