// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

// The model's mesh written back as a Gmsh file (mesh.msh of a run): what
// the program meshed, with its blocks, material regions and face groups.
#include <fdem/geometry/gmsh_mesh.h>

#include <gmsh.h>

#include <string>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    template <int dim>
    void
    write_gmsh_file(const MeshDescription<dim> &mesh,
                    const std::string          &file_name)
    {
      GmshSession session;
      gmsh::model::add("fdem");

      // Gmsh keeps elements by entity and physical groups are sets of
      // entities: one discrete entity per block and per face group. All
      // nodes go to the first block's entity; elements refer to node tags
      // of any entity.
      // A cell's entity is that of its material key (block and material
      // region), so that both kinds of group are sets of entities.
      std::vector<int>   block_entities, face_entities;
      const unsigned int n_keys =
        mesh.block_names.size() * (1 + mesh.material_names.size());
      for (unsigned int k = 0; k < n_keys; ++k)
        block_entities.push_back(gmsh::model::addDiscreteEntity(dim));
      for (unsigned int g = 0; g < mesh.face_group_names.size(); ++g)
        face_entities.push_back(gmsh::model::addDiscreteEntity(dim - 1));

      std::vector<std::size_t> node_tags(mesh.vertices.size());
      std::vector<double>      coordinates(3 * mesh.vertices.size(), 0.);
      for (unsigned int v = 0; v < mesh.vertices.size(); ++v)
        {
          node_tags[v] = v + 1;
          for (unsigned int d = 0; d < dim; ++d)
            coordinates[3 * v + d] = mesh.vertices[v][d];
        }
      if (!block_entities.empty())
        gmsh::model::mesh::addNodes(dim,
                                    block_entities[0],
                                    node_tags,
                                    coordinates);

      std::size_t element_tag  = 0;
      const auto  add_elements = [&](const auto             &objects,
                                    const std::vector<int> &entities,
                                    const int               structdim,
                                    const int               gmsh_type,
                                    const auto             &entity_index) {
        std::vector<std::vector<std::size_t>> tags(entities.size()),
          nodes(entities.size());
        for (const auto &object : objects)
          {
            const unsigned int e = entity_index(object);
            tags[e].push_back(++element_tag);
            const unsigned int n_corners = object.vertices.size();
            for (unsigned int i = 0; i < n_corners; ++i)
              nodes[e].push_back(
                object
                  .vertices[internal::gmsh_corner(structdim, n_corners, i)] +
                1);
          }
        for (unsigned int e = 0; e < entities.size(); ++e)
          if (!tags[e].empty())
            gmsh::model::mesh::addElementsByType(entities[e],
                                                 gmsh_type,
                                                 tags[e],
                                                 nodes[e]);
      };
      // Gmsh element types: 1 line, 2 triangle, 3 quadrilateral,
      // 4 tetrahedron, 5 hexahedron.
      const bool simplex =
        !mesh.cells.empty() && mesh.cells[0].vertices.size() == dim + 1;
      std::vector<CellData<dim>> keyed_cells = mesh.cells;
      for (unsigned int c = 0; c < keyed_cells.size(); ++c)
        keyed_cells[c].material_id = mesh.material_key(c);
      add_elements(keyed_cells,
                   block_entities,
                   dim,
                   (dim == 2) ? (simplex ? 2 : 3) : (simplex ? 4 : 5),
                   [](const CellData<dim> &cell) { return cell.material_id; });
      add_elements(mesh.faces,
                   face_entities,
                   dim - 1,
                   (dim == 2) ? 1 : (simplex ? 2 : 3),
                   [](const CellData<dim - 1> &face) {
                     return face.boundary_id;
                   });
      gmsh::model::mesh::reclassifyNodes();

      // Physical groups of entities without elements are left out.
      std::vector<std::vector<int>> block_groups(mesh.block_names.size()),
        material_groups(mesh.material_names.size());
      std::vector<bool> used(n_keys, false);
      for (unsigned int c = 0; c < keyed_cells.size(); ++c)
        used[keyed_cells[c].material_id] = true;
      for (unsigned int k = 0; k < n_keys; ++k)
        if (used[k])
          {
            block_groups[mesh.block_of_key(k)].push_back(block_entities[k]);
            if (mesh.material_of_key(k) != mesh.no_material)
              material_groups[mesh.material_of_key(k)].push_back(
                block_entities[k]);
          }
      for (unsigned int b = 0; b < block_groups.size(); ++b)
        gmsh::model::setPhysicalName(
          dim,
          gmsh::model::addPhysicalGroup(dim, block_groups[b], b + 1),
          mesh.block_names[b]);
      for (unsigned int m = 0; m < material_groups.size(); ++m)
        gmsh::model::setPhysicalName(
          dim,
          gmsh::model::addPhysicalGroup(dim,
                                        material_groups[m],
                                        block_groups.size() + m + 1),
          mesh.material_names[m]);
      for (unsigned int g = 0; g < face_entities.size(); ++g)
        gmsh::model::setPhysicalName(
          dim - 1,
          gmsh::model::addPhysicalGroup(dim - 1, {face_entities[g]}, g + 1),
          mesh.face_group_names[g]);

      gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
      gmsh::option::setNumber("Mesh.Binary", 0);
      GmshSession::run("Gmsh could not write '" + file_name + "'",
                       [&]() { gmsh::write(file_name); });
    }



    template void
    write_gmsh_file<2>(const MeshDescription<2> &, const std::string &);
    template void
    write_gmsh_file<3>(const MeshDescription<3> &, const std::string &);
  } // namespace geometry
} // namespace fdem
