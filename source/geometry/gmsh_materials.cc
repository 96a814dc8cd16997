// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Material regions of a Gmsh model: physical groups of dimension dim that
// overlap the blocks. The .prm file says which groups they are
// (Materials/Names); the rest are blocks.

#include <fdem/geometry/gmsh_mesh.h>

#include <deal.II/base/exceptions.h>

#include <gmsh.h>

#include <algorithm>
#include <unordered_map>

namespace fdem
{
  namespace geometry
  {
    template <int dim>
    void
    split_block_and_material_groups(
      const std::vector<std::string>   &material_names,
      std::vector<std::pair<int, int>> &block_groups,
      std::vector<std::pair<int, int>> &material_groups)
    {
      gmsh::vectorpair groups;
      gmsh::model::getPhysicalGroups(groups, dim);
      block_groups.clear();
      material_groups.clear();
      for (const auto &group : groups)
        {
          std::string name;
          gmsh::model::getPhysicalName(dim, group.second, name);
          const bool material =
            !name.empty() &&
            std::find(material_names.begin(), material_names.end(), name) !=
              material_names.end();
          (material ? material_groups : block_groups).push_back(group);
        }
    }

    template <int dim>
    void
    read_material_groups(
      const std::string                      &source,
      const std::vector<std::pair<int, int>> &material_groups,
      const std::vector<std::size_t>         &cell_element_tags,
      MeshDescription<dim>                   &mesh)
    {
      mesh.material_names.clear();
      mesh.cell_materials.clear();
      if (material_groups.empty())
        return;
      std::unordered_map<std::size_t, unsigned int> cell_of_element;
      for (unsigned int c = 0; c < cell_element_tags.size(); ++c)
        cell_of_element.emplace(cell_element_tags[c], c);
      mesh.cell_materials.assign(cell_element_tags.size(), mesh.no_material);
      for (const auto &group : material_groups)
        {
          const unsigned int m = mesh.material_names.size();
          std::string        name;
          gmsh::model::getPhysicalName(dim, group.second, name);
          mesh.material_names.push_back(name);
          std::vector<int> entities;
          gmsh::model::getEntitiesForPhysicalGroup(dim, group.second, entities);
          for (const int entity : entities)
            {
              std::vector<int>                      types;
              std::vector<std::vector<std::size_t>> tags, nodes;
              gmsh::model::mesh::getElements(types, tags, nodes, dim, entity);
              for (const auto &tags_of_type : tags)
                for (const std::size_t tag : tags_of_type)
                  {
                    const auto cell = cell_of_element.find(tag);
                    AssertThrow(cell != cell_of_element.end(),
                                ExcMessage(source + ": material '" + name +
                                           "' has element " +
                                           std::to_string(tag) +
                                           ", which belongs to no block; a "
                                           "material region lies inside the "
                                           "blocks."));
                    unsigned int &material = mesh.cell_materials[cell->second];
                    AssertThrow(material == mesh.no_material || material == m,
                                ExcMessage(source + ": element " +
                                           std::to_string(tag) +
                                           " belongs to two materials, '" +
                                           mesh.material_names[material] +
                                           "' and '" + name + "'."));
                    material = m;
                  }
            }
        }
    }

    template void
    split_block_and_material_groups<2>(const std::vector<std::string> &,
                                       std::vector<std::pair<int, int>> &,
                                       std::vector<std::pair<int, int>> &);
    template void
    split_block_and_material_groups<3>(const std::vector<std::string> &,
                                       std::vector<std::pair<int, int>> &,
                                       std::vector<std::pair<int, int>> &);
    template void
    read_material_groups<2>(const std::string &,
                            const std::vector<std::pair<int, int>> &,
                            const std::vector<std::size_t> &,
                            MeshDescription<2> &);
    template void
    read_material_groups<3>(const std::string &,
                            const std::vector<std::pair<int, int>> &,
                            const std::vector<std::size_t> &,
                            MeshDescription<3> &);
  } // namespace geometry
} // namespace fdem
