// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/geometry/mesh_description.h>

#include <deal.II/base/numbers.h>

#include <array>

namespace fdem
{
  namespace geometry
  {
    /** The group of a grid face that belongs to no boundary group. */
    constexpr unsigned int no_group = numbers::invalid_unsigned_int;

    /**
     * Adds the hexahedra of a structured grid of @p n_cells[0] x n_cells[1]
     * x n_cells[2] cells to @p mesh, with material @p block, and the faces
     * on the grid's boundary. @p index(i, j, k) is the mesh vertex of grid
     * point (i, j, k). Face (d, side) of the grid is normal to direction d at
     * its lower (0) or upper (1) end; @p group_of(d, side, i, j) gives the
     * boundary group of the face of cell (i, j, ...) there, or no_group.
     * The generators of structured 3D models share it.
     */
    template <typename Index, typename GroupOf>
    void
    add_structured_grid(MeshDescription<3> &                mesh,
                        const std::array<unsigned int, 3> &n_cells,
                        const Index &                       index,
                        const types::material_id            block,
                        const GroupOf &                     group_of)
    {
      for (unsigned int k = 0; k < n_cells[2]; ++k)
        for (unsigned int j = 0; j < n_cells[1]; ++j)
          for (unsigned int i = 0; i < n_cells[0]; ++i)
            {
              CellData<3> cell;
              for (unsigned int v = 0; v < 8; ++v)
                cell.vertices[v] = index(i + (v & 1), j + ((v >> 1) & 1), k + (v >> 2));
              cell.material_id = block;
              mesh.cells.push_back(cell);

              const std::array<unsigned int, 3> ijk = {{i, j, k}};
              for (unsigned int d = 0; d < 3; ++d)
                for (const unsigned int side : {0u, 1u})
                  {
                    if (ijk[d] + side != (side ? n_cells[d] : 0))
                      continue;
                    const unsigned int group = group_of(d, side, i, j);
                    if (group == no_group)
                      continue;
                    // The face's corners in lexicographic order of the other
                    // two directions.
                    const unsigned int a = (d == 0) ? 1 : 0;
                    const unsigned int c = (d == 2) ? 1 : 2;
                    CellData<2>        face;
                    for (unsigned int f = 0; f < 4; ++f)
                      face.vertices[f] =
                        cell.vertices[(side << d) | ((f & 1) << a) | (((f >> 1) & 1) << c)];
                    face.boundary_id = group;
                    mesh.faces.push_back(face);
                  }
            }
    }
  } // namespace geometry
} // namespace fdem
