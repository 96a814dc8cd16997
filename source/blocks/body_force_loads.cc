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
                   water_table->value(fe_values.quadrature_point(q), material) >
                     0) ?
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

    template <int dim>
    std::vector<Vector<double>>
    ElasticBlock<dim>::water_loads(
      const PiezometricPressure<dim>     &table,
      const std::set<types::boundary_id> &faces) const
    {
      const MPI_Comm              comm = triangulation.get_communicator();
      std::vector<Vector<double>> result(dim + 1,
                                         Vector<double>(dof_handler.n_dofs()));
      // assemble_cell()'s quadratures.
      FEValues<dim>                        fe_values(mapping,
                              fe,
                              element_family.cell_quadrature(fe.degree + 1),
                              update_values | update_quadrature_points |
                                update_JxW_values);
      FEFaceValues<dim>                    fe_face_values(mapping,
                                       fe,
                                       element_family.face_quadrature(
                                         fe.degree + 2),
                                       update_values | update_normal_vectors |
                                         update_quadrature_points |
                                         update_JxW_values);
      const FEValuesExtractors::Vector     displacement(0);
      const unsigned int                   n = fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dofs(n);
      std::vector<Vector<double>> cell_loads(dim + 1, Vector<double>(n));
      const double                g = loads.gravitational_acceleration;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            for (auto &c : cell_loads)
              c = 0;
            const parameters::MaterialParameters &material =
              materials.at(cell->material_id());
            const double excess =
              material.saturated_weight(g) - material.weight(g);
            if (excess != 0)
              {
                fe_values.reinit(cell);
                for (const unsigned int q :
                     fe_values.quadrature_point_indices())
                  if (table.value(fe_values.quadrature_point(q), material) > 0)
                    for (unsigned int i = 0; i < n; ++i)
                      {
                        const Tensor<1, dim> N_i =
                          fe_values[displacement].value(i, q);
                        for (unsigned int d = 0; d < dim; ++d)
                          cell_loads[1 + d](i) +=
                            N_i[d] * excess * fe_values.JxW(q);
                      }
              }
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary() && faces.count(face->boundary_id()))
                {
                  fe_face_values.reinit(cell, face);
                  for (const unsigned int q :
                       fe_face_values.quadrature_point_indices())
                    {
                      // A pressure pushes against the outward normal.
                      const Tensor<1, dim> traction =
                        -table.value(fe_face_values.quadrature_point(q),
                                     material) *
                        fe_face_values.normal_vector(q);
                      for (unsigned int i = 0; i < n; ++i)
                        cell_loads[0](i) +=
                          fe_face_values[displacement].value(i, q) * traction *
                          fe_face_values.JxW(q);
                    }
                }
            cell->get_dof_indices(dofs);
            for (unsigned int k = 0; k <= dim; ++k)
              result[k].add(dofs, cell_loads[k]);
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
    template std::vector<Vector<double>>
    ElasticBlock<2>::water_loads(const PiezometricPressure<2> &,
                                 const std::set<types::boundary_id> &) const;
    template std::vector<Vector<double>>
    ElasticBlock<3>::water_loads(const PiezometricPressure<3> &,
                                 const std::set<types::boundary_id> &) const;
  } // namespace blocks
} // namespace fdem
