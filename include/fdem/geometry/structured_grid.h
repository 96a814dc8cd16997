// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/geometry/mesh_description.h>

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/numbers.h>

#include <array>
#include <tuple>
#include <type_traits>

namespace fdem
{
  namespace geometry
  {
    /** The group of a grid face that belongs to no boundary group. */
    constexpr unsigned int no_group = numbers::invalid_unsigned_int;

    /**
     * Adds the quadrilaterals (2D) or hexahedra (3D) of a structured grid of
     * @p n_cells[0] x ... x n_cells[dim-1] cells to @p mesh, with material
     * @p block, and the faces on the grid's boundary. The cells are added in
     * lexicographic order (the first index fastest). @p index(i, j[, k]) is
     * the mesh vertex of grid point (i, j[, k]). Face (d, side) of the grid
     * is normal to direction d at its lower (0) or upper (1) end;
     * @p group_of(d, side, i[, j]) gives the boundary group of the face of
     * the cell with the first dim-1 indices i[, j] there, or no_group. The
     * generators of structured models share it.
     *
     * Hand-written rather than GridGenerator::subdivided_hyper_rectangle:
     * the generators place the grid lines themselves (graded, or split at a
     * block's edge), share vertices between blocks and name face groups,
     * which that function does not do.
     */
    template <int dim, typename Index, typename GroupOf>
    void
    add_structured_grid(
      MeshDescription<dim> &mesh,
      // not deduced: dim comes from the mesh
      const typename std::common_type<std::array<unsigned int, dim>>::type
                              &n_cells,
      const Index             &index,
      const types::material_id block,
      const GroupOf           &group_of)
    {
      unsigned int n_grid_cells = 1;
      for (const unsigned int n : n_cells)
        n_grid_cells *= n;
      for (unsigned int c = 0; c < n_grid_cells; ++c)
        {
          std::array<unsigned int, dim> cell_index;
          for (unsigned int d = 0, rest = c; d < dim; rest /= n_cells[d], ++d)
            cell_index[d] = rest % n_cells[d];

          CellData<dim> cell;
          for (const unsigned int v : GeometryInfo<dim>::vertex_indices())
            {
              std::array<unsigned int, dim> point_index;
              for (unsigned int d = 0; d < dim; ++d)
                point_index[d] = cell_index[d] + ((v >> d) & 1);
              cell.vertices[v] = std::apply(index, point_index);
            }
          cell.material_id = block;
          mesh.cells.push_back(cell);

          for (unsigned int d = 0; d < dim; ++d)
            for (const unsigned int side : {0u, 1u})
              {
                if (cell_index[d] + side != (side ? n_cells[d] : 0))
                  continue;
                std::array<unsigned int, dim + 1> face_of_cell;
                face_of_cell[0] = d;
                face_of_cell[1] = side;
                for (unsigned int e = 0; e + 1 < dim; ++e)
                  face_of_cell[2 + e] = cell_index[e];
                const unsigned int group = std::apply(group_of, face_of_cell);
                if (group == no_group)
                  continue;
                // The face's corners in lexicographic order of the other
                // directions.
                std::array<unsigned int, dim - 1> others;
                for (unsigned int e = 0, m = 0; e < dim; ++e)
                  if (e != d)
                    others[m++] = e;
                CellData<dim - 1> face;
                for (const unsigned int f :
                     GeometryInfo<dim - 1>::vertex_indices())
                  {
                    unsigned int corner = side << d;
                    for (unsigned int m = 0; m + 1 < dim; ++m)
                      corner |= ((f >> m) & 1) << others[m];
                    face.vertices[f] = cell.vertices[corner];
                  }
                face.boundary_id = group;
                mesh.faces.push_back(face);
              }
        }
    }
  } // namespace geometry
} // namespace fdem
