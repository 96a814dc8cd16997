// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/geometry/block_mesh.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <map>

namespace fdem
{
  namespace geometry
  {
    template <int dim>
    void
    create_block_triangulation(const MeshDescription<dim>      &mesh,
                               const std::vector<unsigned int> &blocks,
                               Triangulation<dim>              &triangulation)
    {
      std::vector<unsigned int>  local_index(mesh.vertices.size(),
                                            numbers::invalid_unsigned_int);
      std::vector<unsigned int>  global_index;
      std::vector<Point<dim>>    vertices;
      std::vector<CellData<dim>> cells;
      for (unsigned int c = 0; c < mesh.cells.size(); ++c)
        if (std::find(blocks.begin(),
                      blocks.end(),
                      mesh.cells[c].material_id) != blocks.end())
          {
            CellData<dim> local_cell = mesh.cells[c];
            local_cell.material_id   = mesh.material_key(c);
            for (unsigned int &v : local_cell.vertices)
              {
                if (local_index[v] == numbers::invalid_unsigned_int)
                  {
                    local_index[v] = vertices.size();
                    vertices.push_back(mesh.vertices[v]);
                    global_index.push_back(v);
                  }
                v = local_index[v];
              }
            cells.push_back(local_cell);
          }
      AssertThrow(!cells.empty(),
                  ExcMessage(mesh.source + ": a block has no cells."));

      triangulation.clear();
      triangulation.create_triangulation(vertices, cells, SubCellData());

      // Face groups are identified by their sorted global vertex indices.
      std::map<std::vector<unsigned int>, types::boundary_id> group_of_face;
      for (const CellData<dim - 1> &face : mesh.faces)
        {
          std::vector<unsigned int> key(face.vertices.begin(),
                                        face.vertices.end());
          std::sort(key.begin(), key.end());
          const auto [it, inserted] =
            group_of_face.emplace(key, face.boundary_id);
          (void)inserted;
          AssertThrow(it->second == face.boundary_id,
                      ExcMessage(mesh.source + ": a face belongs to both '" +
                                 mesh.face_group_names[it->second] + "' and '" +
                                 mesh.face_group_names[face.boundary_id] +
                                 "'; a face may belong to one group only."));
        }

      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              std::vector<unsigned int> key;
              for (const unsigned int v : face->vertex_indices())
                key.push_back(global_index[face->vertex_index(v)]);
              std::sort(key.begin(), key.end());
              const auto it = group_of_face.find(key);
              face->set_boundary_id(
                it == group_of_face.end() ? unnamed_boundary_id : it->second);
            }
    }

    template void
    create_block_triangulation(const MeshDescription<2> &,
                               const std::vector<unsigned int> &,
                               Triangulation<2> &);
    template void
    create_block_triangulation(const MeshDescription<3> &,
                               const std::vector<unsigned int> &,
                               Triangulation<3> &);
  } // namespace geometry
} // namespace fdem
