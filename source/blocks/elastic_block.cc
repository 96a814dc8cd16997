// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/blocks/elastic_block.h>
#include <fdem/geometry/block_mesh.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <algorithm>
#include <cmath>

namespace fdem
{
  namespace blocks
  {
    template <int dim>
    ElasticBlock<dim>::ElasticBlock(
      const std::string                                            &name,
      const geometry::MeshDescription<dim>                         &mesh,
      const std::vector<unsigned int>                              &block_ids,
      const std::map<unsigned int, parameters::MaterialParameters> &materials,
      const unsigned int                                            fe_degree)
      : name(name)
      , triangulation(MPI_COMM_WORLD,
                      Triangulation<dim>::none,
                      /*allow_artificial_cells=*/false,
                      parallel::shared::Triangulation<dim>::partition_metis)
      , element_family(mesh, fe_degree)
      , fe(*element_family.scalar_element(), dim)
      , mapping_object(element_family.mapping())
      , mapping(*mapping_object)
      , materials(materials)
    {
      geometry::create_block_triangulation(mesh, block_ids, triangulation);
      // One block, one body: a block in separate parts would need supports
      // for each part, and its rigid modes would not be the body's.
      if (block_ids.size() == 1)
        {
          std::vector<bool> reached(triangulation.n_active_cells(), false);
          std::vector<typename Triangulation<dim>::active_cell_iterator> front{
            triangulation.begin_active()};
          reached[front[0]->active_cell_index()] = true;
          unsigned int n_reached                 = 1;
          while (!front.empty())
            {
              const auto cell = front.back();
              front.pop_back();
              for (const unsigned int f : cell->face_indices())
                if (!cell->at_boundary(f) &&
                    !reached[cell->neighbor(f)->active_cell_index()])
                  {
                    reached[cell->neighbor(f)->active_cell_index()] = true;
                    ++n_reached;
                    front.push_back(cell->neighbor(f));
                  }
            }
          AssertThrow(n_reached == triangulation.n_active_cells(),
                      ExcMessage(mesh.source + ": block '" + name +
                                 "' is not connected; give each separate part "
                                 "its own physical group."));
        }
      dof_handler.reinit(triangulation);
      dof_handler.distribute_dofs(fe);

      // Rigid modes are taken about the centroid, scaled by the block size.
      double volume = 0;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          centre += cell->measure() * cell->center();
          volume += cell->measure();
        }
      centre /= volume;
      length_scale = 0;
      for (const Point<dim> &v : triangulation.get_vertices())
        length_scale = std::max(length_scale, v.distance(centre));

      // By hand: DoFTools::map_dofs_to_support_points() refuses its vector
      // form on a parallel::shared triangulation (9.4); the map form would
      // cost a std::map lookup per dof in every use.
      dof_support_points.resize(dof_handler.n_dofs());
      dof_components.resize(dof_handler.n_dofs());
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              dof_components[dofs[i]] = fe.system_to_component_index(i).first;
              dof_support_points[dofs[i]] = mapping.transform_unit_to_real_cell(
                cell, fe.get_unit_support_points()[i]);
            }
        }
    }

    template <int dim>
    void
    ElasticBlock<dim>::set_surface_loads(
      const std::map<types::boundary_id, std::shared_ptr<const Function<dim>>>
        &pressures,
      const std::map<types::boundary_id, std::shared_ptr<const Function<dim>>>
        &tractions)
    {
      this->pressures = pressures;
      this->tractions = tractions;
    }

    template <int dim>
    ElasticBlock<dim>::CellScratch::CellScratch(
      const Mapping<dim>       &mapping,
      const FiniteElement<dim> &fe,
      const ElementFamily<dim> &family)
      : fe_values(mapping,
                  fe,
                  family.cell_quadrature(fe.degree + 1),
                  update_values | update_gradients | update_quadrature_points |
                    update_JxW_values)
      , fe_face_values(mapping,
                       fe,
                       family.face_quadrature(fe.degree + 2),
                       update_values | update_normal_vectors |
                         update_quadrature_points | update_JxW_values)
      , matrix(fe.n_dofs_per_cell(), fe.n_dofs_per_cell())
      , rhs(fe.n_dofs_per_cell())
      , dofs(fe.n_dofs_per_cell())
    {}

    template <int dim>
    void
    ElasticBlock<dim>::assemble_cell(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      CellScratch                                          &scratch) const
    {
      FEValues<dim>      &fe_values      = scratch.fe_values;
      FEFaceValues<dim>  &fe_face_values = scratch.fe_face_values;
      FullMatrix<double> &cell_matrix    = scratch.matrix;
      Vector<double>     &cell_rhs       = scratch.rhs;
      const parameters::MaterialParameters &material =
        materials.at(cell->material_id());
      const double   E = material.youngs_modulus, nu = material.poissons_ratio;
      const double   lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
      const double   mu     = E / (2 * (1 + nu));
      Tensor<1, dim> body_force, saturated_body_force;
      const double   g = loads.gravitational_acceleration;
      for (unsigned int d = 0; d < dim; ++d)
        {
          body_force[d] = material.weight(g) * loads.gravity_direction[d];
          saturated_body_force[d] =
            material.saturated_weight(g) * loads.gravity_direction[d];
        }
      // Below the water table the saturated weight, point by point: the
      // mesh need not follow the water table.
      const bool saturated_differs =
        water_table && material.saturated_weight(g) != material.weight(g);

      const FEValuesExtractors::Vector displacement(0);
      fe_values.reinit(cell);
      cell_matrix          = 0;
      cell_rhs             = 0;
      const unsigned int n = fe.n_dofs_per_cell();
      // The shape functions' strains once per point, not once per pair
      // (same operations per entry, so the same K bit for bit).
      std::vector<SymmetricTensor<2, dim>> &eps = scratch.strains;
      std::vector<double>                  &div = scratch.divergences;
      eps.resize(n);
      div.resize(n);
      for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          const double          JxW = fe_values.JxW(q);
          const Tensor<1, dim> &weight =
            (saturated_differs &&
             water_table->value(fe_values.quadrature_point(q), material) > 0) ?
              saturated_body_force :
              body_force;
          for (unsigned int j = 0; j < n; ++j)
            {
              eps[j] = fe_values[displacement].symmetric_gradient(j, q);
              div[j] = trace(eps[j]);
            }
          for (unsigned int i = 0; i < n; ++i)
            {
              const SymmetricTensor<2, dim> &eps_i = eps[i];
              const double                   div_i = div[i];
              for (unsigned int j = 0; j < n; ++j)
                cell_matrix(i, j) +=
                  (lambda * div_i * div[j] + 2 * mu * (eps_i * eps[j])) * JxW;
              cell_rhs(i) += fe_values[displacement].value(i, q) * weight * JxW;
            }
        }
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const auto pressure = pressures.find(face->boundary_id());
            const auto given    = tractions.find(face->boundary_id());
            if (pressure == pressures.end() && given == tractions.end())
              continue;
            fe_face_values.reinit(cell, face);
            Vector<double> value(dim);
            for (const unsigned int q :
                 fe_face_values.quadrature_point_indices())
              {
                const Point<dim> &x = fe_face_values.quadrature_point(q);
                Tensor<1, dim>    traction;
                // A pressure pushes against the outward normal.
                if (pressure != pressures.end())
                  traction -= pressure_on_cell(*pressure->second, x, material) *
                              fe_face_values.normal_vector(q);
                if (given != tractions.end())
                  {
                    given->second->vector_value(x, value);
                    for (unsigned int d = 0; d < dim; ++d)
                      traction[d] += value[d];
                  }
                // Where the load is evaluated: a load that is not a number
                // would spread NaN through every result.
                for (unsigned int d = 0; d < dim; ++d)
                  AssertThrow(std::isfinite(traction[d]),
                              ExcMessage("A surface load (Pressure or Traction "
                                         "of a boundary, or a pore pressure) "
                                         "is not a finite number at a point "
                                         "of block '" +
                                         name + "'."));
                for (unsigned int i = 0; i < n; ++i)
                  cell_rhs(i) += fe_face_values[displacement].value(i, q) *
                                 traction * fe_face_values.JxW(q);
              }
          }
    }

    template <int dim>
    void
    ElasticBlock<dim>::assemble_and_factorize(
      const parameters::LoadParameters  &load_parameters,
      const parameters::DirectSolverType solver_type)
    {
      assemble(load_parameters);
      factorize(solver_type);
    }

    template <int dim>
    void
    ElasticBlock<dim>::assemble(
      const parameters::LoadParameters &load_parameters)
    {
      loads                    = load_parameters;
      const auto      start    = std::chrono::steady_clock::now();
      const MPI_Comm  comm     = triangulation.get_communicator();
      const bool      parallel = Utilities::MPI::n_mpi_processes(comm) > 1;
      const IndexSet &owned    = dof_handler.locally_owned_dofs();
      // The pattern of this rank's cells; rows other ranks own go to them.
      DynamicSparsityPattern dsp(dof_handler.n_dofs());
      DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
      if (parallel)
        SparsityTools::distribute_sparsity_pattern(
          dsp, owned, comm, complete_index_set(dof_handler.n_dofs()));
      stiffness_matrix.reinit(owned, owned, dsp, comm);
      load_vector.reinit(dof_handler.n_dofs());

      CellScratch scratch(mapping, fe, element_family);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            assemble_cell(cell, scratch);
            cell->get_dof_indices(scratch.dofs);
            constraints.distribute_local_to_global(scratch.matrix,
                                                   scratch.dofs,
                                                   stiffness_matrix);
            load_vector.add(scratch.dofs, scratch.rhs);
          }
      // F on every rank: the sum of the ranks' cells.
      if (parallel)
        Utilities::MPI::sum(load_vector, comm, load_vector);
      stiffness_matrix.compress(VectorOperation::add);
      assembly_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    }

    template <int dim>
    void
    ElasticBlock<dim>::factorize(const parameters::DirectSolverType solver_type,
                                 const double block_low_rank_tolerance,
                                 const double memory_limit_MiB)
    {
      const auto start = std::chrono::steady_clock::now();
      // A new back-end: the old factors are freed before the new ones exist.
      factorization = make_block_factorization(solver_type,
                                               block_low_rank_tolerance,
                                               memory_limit_MiB);
      factorization->factorize(stiffness_matrix,
                               factorization->keeps_schur_complement() ?
                                 interface_schur_dofs() :
                                 std::vector<types::global_dof_index>());
      factorization_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    }

    template <int dim>
    Vector<double>
    ElasticBlock<dim>::solve(const Vector<double> &nodal_forces) const
    {
      Vector<double> rhs = nodal_forces;
      constraints.condense(rhs);
      Vector<double> u = factorization->solve(rhs);
      constraints.distribute(u);
      return u;
    }

    template <int dim>
    std::vector<Vector<double>>
    ElasticBlock<dim>::solve(
      const std::vector<Vector<double>> &nodal_forces) const
    {
      std::vector<Vector<double>> u(nodal_forces.size());
      solve_blocked(
        nodal_forces.size(),
        [&](const unsigned int c, Vector<double> &f) { f = nodal_forces[c]; },
        [&](const unsigned int c, const Vector<double> &u_c) { u[c] = u_c; });
      return u;
    }

    template <int dim>
    Vector<double>
    ElasticBlock<dim>::nodal_residual(const Vector<double> &u,
                                      const unsigned int    material_id) const
    {
      Vector<double> residual(dof_handler.n_dofs());
      CellScratch    scratch(mapping, fe, element_family);
      Vector<double> cell_u(fe.n_dofs_per_cell()),
        cell_residual(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (material_id == numbers::invalid_unsigned_int ||
            cell->material_id() == material_id)
          {
            assemble_cell(cell, scratch);
            cell->get_dof_indices(scratch.dofs);
            for (unsigned int i = 0; i < scratch.dofs.size(); ++i)
              cell_u[i] = u[scratch.dofs[i]];
            scratch.matrix.vmult(cell_residual, cell_u);
            cell_residual -= scratch.rhs;
            residual.add(scratch.dofs, cell_residual);
          }
      return residual;
    }

    template class ElasticBlock<2>;
    template class ElasticBlock<3>;
  } // namespace blocks
} // namespace fdem
