// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// What the geometry tests share: parsing a subsection "Geometry", temporary
// files, expected error messages, and the checks that every generated mesh
// must pass.
#pragma once

#include "../source_dir.h"

#include <fdem/geometry/block_mesh.h>
#include <fdem/geometry/cases/block_on_plane.h>
#include <fdem/geometry/cases/hertz.h>
#include <fdem/geometry/cases/hertz_sphere.h>
#include <fdem/geometry/cases/slope.h>
#include <fdem/geometry/cases/wedge.h>
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

namespace geometry_test
{
  using namespace dealii;
  using namespace fdem;
  using fdem::geometry::MeshDescription;
  using Parameters = parameters::GeometryParameters;
  using Edge       = std::pair<unsigned int, unsigned int>;

  inline const std::string data_directory =
    fdem::test_support::source_dir() + "/tests/geometry/data";

  /** Geometry parameters from the entries of the subsection "Geometry". */
  inline Parameters
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
  inline std::string
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

  inline unsigned int
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

  inline Edge
  edge(const unsigned int a, const unsigned int b)
  {
    return {std::min(a, b), std::max(a, b)};
  }

  /** Edges of the cells of @p block (all blocks if it is invalid). */
  inline std::set<Edge>
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

  inline double
  length(const MeshDescription<2> &mesh, const CellData<1> &face)
  {
    return mesh.vertices[face.vertices[0]].distance(
      mesh.vertices[face.vertices[1]]);
  }

  using Face3 = std::array<unsigned int, 4>;

  inline Face3
  sorted_face(const CellData<2> &face)
  {
    Face3 key = {
      {face.vertices[0], face.vertices[1], face.vertices[2], face.vertices[3]}};
    std::sort(key.begin(), key.end());
    return key;
  }

  /** The faces of the cells of @p block (all blocks if it is invalid). */
  inline std::set<Face3>
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
  inline std::set<Edge>
  cell_boundaries(const MeshDescription<2> &mesh)
  {
    return cell_edges(mesh);
  }

  inline std::set<Face3>
  cell_boundaries(const MeshDescription<3> &mesh)
  {
    return cell_faces(mesh);
  }

  inline Edge
  boundary_key(const CellData<1> &face)
  {
    return edge(face.vertices[0], face.vertices[1]);
  }

  inline Face3
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

  /** Area of a plane quadrilateral face (two triangles). */
  inline double
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
  inline void
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
  inline void
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
  inline Tensor<1, 3>
  normal(const double dip, const double dip_direction)
  {
    const double psi   = dip * numbers::PI / 180,
                 alpha = dip_direction * numbers::PI / 180;
    return Tensor<1, 3>({std::sin(psi) * std::sin(alpha),
                         std::sin(psi) * std::cos(alpha),
                         std::cos(psi)});
  }
} // namespace geometry_test
