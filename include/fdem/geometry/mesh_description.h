// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    using namespace dealii;

    /**
     * The one representation of a model's geometry, whatever made it: a Gmsh
     * file (.msh or .geo) or one of the built-in generators. It is a plain
     * unstructured mesh of quadrilaterals or triangles (2D), hexahedra or
     * tetrahedra (3D), all of one shape, in which
     * every cell carries the index of its block and every named face group
     * (a Gmsh physical group of dimension dim-1) lists its faces.
     *
     * A face group is either a boundary part (Dirichlet conditions, pressures)
     * or an interface between two blocks; the .prm file says which. The
     * vertices are shared between blocks here: the program duplicates the
     * nodes along each interface when it splits the mesh into blocks.
     */
    template <int dim>
    struct MeshDescription
    {
      /** Vertex coordinates (model length units). */
      std::vector<Point<dim>> vertices;

      /**
       * Cells in deal.II's vertex ordering (lexicographic for quadrilaterals
       * and hexahedra, consistently oriented), with positive measure: 2^dim
       * vertices for hypercubes, dim + 1 for simplices. `material_id` is
       * the block index into block_names.
       */
      std::vector<CellData<dim>> cells;

      /** Block names (Gmsh physical groups of dimension dim), by index. */
      std::vector<std::string> block_names;

      /**
       * Faces of named groups: `vertices` are indices into `vertices`,
       * `boundary_id` is the group index into face_group_names. A face that
       * belongs to several groups appears once per group.
       */
      std::vector<CellData<dim - 1>> faces;

      /** Names of the face groups (Gmsh physical groups of dimension dim-1). */
      std::vector<std::string> face_group_names;

      /** Where the description came from (file name or generator), for messages. */
      std::string source;
    };
  } // namespace geometry
} // namespace fdem
