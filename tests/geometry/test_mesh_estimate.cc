// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The estimate of a built-in mesh made before meshing (mesh_estimate.h)
// against the mesh itself, for every generator, and its refusal beyond
// Geometry/Memory limit.

#include "geometry_test_helpers.h"

#include <fdem/geometry/mesh_estimate.h>

using namespace geometry_test;

namespace
{
  // The estimate only has to tell a mesh that fits from one that is orders
  // of magnitude too large: within a factor of 3 of the real counts.
  constexpr double factor = 3;

  template <int dim>
  void
  expect_close_estimate(const std::string &entries)
  {
    SCOPED_TRACE(entries);
    const Parameters geometry = parse(entries);
    const auto       estimate = geometry::estimate_mesh(geometry);
    const auto       mesh     = geometry::make_mesh<dim>(geometry, "", "");
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
