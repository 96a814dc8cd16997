// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The nodes of an ElasticBlock on an interface, with their consistent nodal
// weights (doc/theory.md, "Blocks, pairs and frames").
#include <fdem/blocks/elastic_block.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace fdem
{
  namespace blocks
  {
    template <int dim>
    std::vector<InterfaceNode<dim>>
    ElasticBlock<dim>::interface_nodes(const types::boundary_id group) const
    {
      std::vector<InterfaceNode<dim>>                 nodes;
      std::map<types::global_dof_index, unsigned int> node_of_first_dof;
      FEFaceValues<dim>                               fe_face_values(
        mapping,
        fe,
        element_family.face_quadrature(fe.degree + 1),
        update_values | update_normal_vectors | update_JxW_values);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell()),
        face_dofs;
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == group)
            {
              fe_face_values.reinit(cell, f);
              cell->get_dof_indices(dofs);
              // The face's own dofs: with FE_SimplexP, deal.II 9.4's
              // has_support_on_face() also answered true for dofs off the
              // face (they were listed as unpaired interface nodes).
              face_dofs.resize(fe.n_dofs_per_face(f));
              cell->face(f)->get_dof_indices(face_dofs);
              std::sort(face_dofs.begin(), face_dofs.end());
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                {
                  if (!std::binary_search(face_dofs.begin(),
                                          face_dofs.end(),
                                          dofs[i]))
                    continue;
                  const auto [component, base] =
                    fe.system_to_component_index(i);
                  const types::global_dof_index first =
                    dofs[fe.component_to_system_index(0, base)];
                  const auto [it, is_new] =
                    node_of_first_dof.emplace(first, nodes.size());
                  if (is_new)
                    {
                      nodes.emplace_back();
                      nodes.back().position = dof_support_points[first];
                    }
                  InterfaceNode<dim> &node = nodes[it->second];
                  node.dofs[component]     = dofs[i];
                  if (component != 0)
                    continue;
                  // Consistent nodal weights: int phi dGamma, int phi n dGamma.
                  for (const unsigned int q :
                       fe_face_values.quadrature_point_indices())
                    {
                      const double phi_JxW =
                        fe_face_values.shape_value_component(i, q, 0) *
                        fe_face_values.JxW(q);
                      node.area += phi_JxW;
                      node.area_normal +=
                        phi_JxW * fe_face_values.normal_vector(q);
                      node.adjacent_area += fe_face_values.JxW(q);
                    }
                }
            }
      // The vertices of quadratic triangles have the weight zero: make it
      // exactly zero, not round-off of either sign.
      for (InterfaceNode<dim> &node : nodes)
        if (std::abs(node.area) <= 1e-10 * node.adjacent_area)
          {
            node.area        = 0;
            node.area_normal = 0;
          }
      return nodes;
    }

    template std::vector<InterfaceNode<2>>
    ElasticBlock<2>::interface_nodes(const types::boundary_id) const;
    template std::vector<InterfaceNode<3>>
    ElasticBlock<3>::interface_nodes(const types::boundary_id) const;
  } // namespace blocks
} // namespace fdem
