// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/blocks/elastic_block.h>

#include <deal.II/base/mpi.h>

namespace fdem
{
  namespace blocks
  {
    template <int dim>
    std::vector<Vector<double>>
    ElasticBlock<dim>::unit_body_force_loads(const bool saturated) const
    {
      // The same quadrature and the same choice of weight, point by point,
      // as assemble_cell(): the gravity load is then sum_d g_d B_d to
      // round-off, and a combination of these cases adds to it exactly what
      // a change of the body force would have assembled.
      const MPI_Comm                   comm = triangulation.get_communicator();
      std::vector<Vector<double>>      result(dim,
                                         Vector<double>(dof_handler.n_dofs()));
      FEValues<dim>                    fe_values(mapping,
                              fe,
                              element_family.cell_quadrature(fe.degree + 1),
                              update_values | update_quadrature_points |
                                update_JxW_values);
      const FEValuesExtractors::Vector displacement(0);
      const unsigned int               n = fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dofs(n);
      std::vector<Vector<double>>          cell_loads(dim, Vector<double>(n));
      const double                         g = loads.gravitational_acceleration;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const parameters::MaterialParameters &material =
              materials.at(cell->material_id());
            const double weight           = material.weight(g),
                         saturated_weight = material.saturated_weight(g);
            const bool saturated_differs =
              saturated && water_table && saturated_weight != weight;
            fe_values.reinit(cell);
            for (auto &c : cell_loads)
              c = 0;
            for (const unsigned int q : fe_values.quadrature_point_indices())
              {
                const double gamma =
                  (saturated_differs &&
                   water_table->value(fe_values.quadrature_point(q)) > 0) ?
                    saturated_weight :
                    weight;
                const double JxW = fe_values.JxW(q);
                for (unsigned int i = 0; i < n; ++i)
                  {
                    const Tensor<1, dim> N_i =
                      fe_values[displacement].value(i, q);
                    for (unsigned int d = 0; d < dim; ++d)
                      cell_loads[d](i) += N_i[d] * gamma * JxW;
                  }
              }
            cell->get_dof_indices(dofs);
            for (unsigned int d = 0; d < dim; ++d)
              result[d].add(dofs, cell_loads[d]);
          }
      if (Utilities::MPI::n_mpi_processes(comm) > 1)
        for (auto &load : result)
          Utilities::MPI::sum(load, comm, load);
      return result;
    }

    template std::vector<Vector<double>>
    ElasticBlock<2>::unit_body_force_loads(const bool) const;
    template std::vector<Vector<double>>
    ElasticBlock<3>::unit_body_force_loads(const bool) const;
  } // namespace blocks
} // namespace fdem
