// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/blocks/elastic_block.h>
#include <fdem/blocks/rigid_modes.h>
#include <fdem/geometry/block_mesh.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace fdem
{
  namespace blocks
  {
    template <int dim>
    ElasticBlock<dim>::ElasticBlock(
      const std::string &                                             name,
      const geometry::MeshDescription<dim> &                          mesh,
      const std::vector<unsigned int> &                               block_ids,
      const std::map<unsigned int, parameters::MaterialParameters> &materials,
      const unsigned int                                              fe_degree)
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
          unsigned int n_reached                  = 1;
          while (!front.empty())
            {
              const auto cell = front.back();
              front.pop_back();
              for (const unsigned int f : cell->face_indices())
                if (!cell->at_boundary(f) && !reached[cell->neighbor(f)->active_cell_index()])
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
    ElasticBlock<dim>::setup_constraints(
      const std::map<types::boundary_id, parameters::BoundaryParameters>
        &                                    boundary_conditions,
      const std::vector<types::boundary_id> &interface_group_ids)
    {
      interface_ids = interface_group_ids;
      AffineConstraints<double> fixed, normal, plate;
      std::set<types::boundary_id> normal_ids;
      for (const auto &[id, condition] : boundary_conditions)
        {
          if (condition.constraint == parameters::Constraint::fixed)
            VectorTools::interpolate_boundary_values(
              mapping, dof_handler, id, Functions::ZeroFunction<dim>(dim), fixed);
          else if (condition.constraint == parameters::Constraint::normal)
            normal_ids.insert(id);
          else if (condition.constraint == parameters::Constraint::plate)
            add_plate_constraints(id, plate);

        }
      if (!normal_ids.empty())
        VectorTools::compute_no_normal_flux_constraints(
          dof_handler, 0, normal_ids, normal, mapping);

      // Where a fixed part meets a roller or a plate, the fixed condition
      // wins; where a roller meets a plate, the roller.
      dirichlet_constraints.clear();
      dirichlet_constraints.merge(plate);
      dirichlet_constraints.merge(
        normal, AffineConstraints<double>::MergeConflictBehavior::right_object_wins);
      dirichlet_constraints.merge(
        fixed, AffineConstraints<double>::MergeConflictBehavior::right_object_wins);
      dirichlet_constraints.close();
      constraints.copy_from(dirichlet_constraints);
    }

    template <int dim>
    void
    ElasticBlock<dim>::set_surface_loads(
      const std::map<types::boundary_id, std::shared_ptr<const Function<dim>>> &pressures,
      const std::map<types::boundary_id, std::shared_ptr<const Function<dim>>> &tractions)
    {
      this->pressures = pressures;
      this->tractions = tractions;
    }

    template <int dim>
    void
    ElasticBlock<dim>::add_plate_constraints(const types::boundary_id   id,
                                             AffineConstraints<double> &plate) const
    {
      // The part's normal must be one coordinate axis: its dofs along that
      // axis all follow the first one.
      int                                  axis = -1;
      std::set<types::global_dof_index>    dofs;
      std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == id)
            {
              const Tensor<1, dim> n = cell->face(f)->center() - cell->center();
              int                  face_axis = 0;
              for (unsigned int d = 1; d < dim; ++d)
                if (std::abs(n[d]) > std::abs(n[face_axis]))
                  face_axis = d;
              AssertThrow(axis < 0 || axis == face_axis,
                          ExcMessage("Block '" + name +
                                     "': a boundary part with Constraint = plate "
                                     "must be flat and normal to a coordinate axis."));
              axis = face_axis;
              cell->face(f)->get_dof_indices(face_dofs);
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                if (fe.face_system_to_component_index(i).first ==
                    static_cast<unsigned int>(axis))
                  dofs.insert(face_dofs[i]);
            }
      if (dofs.size() < 2)
        return;
      const types::global_dof_index master = *dofs.begin();
      for (const types::global_dof_index dof : dofs)
        if (dof != master)
          {
            plate.add_line(dof);
            plate.add_entry(dof, master, 1.0);
          }
    }

    template <int dim>
    FullMatrix<double>
    ElasticBlock<dim>::rigid_modes_at_dofs() const
    {
      FullMatrix<double> modes(dof_handler.n_dofs(), n_rigid_modes<dim>);
      for (unsigned int i = 0; i < dof_handler.n_dofs(); ++i)
        for (unsigned int m = 0; m < n_rigid_modes<dim>; ++m)
          modes(i, m) = rigid_mode(m,
                                   dof_support_points[i],
                                   centre,
                                   length_scale)[dof_components[i]];
      return modes;
    }

    template <int dim>
    void
    ElasticBlock<dim>::find_free_rigid_modes()
    {
      const FullMatrix<double> modes = rigid_modes_at_dofs();
      free_modes = free_rigid_modes(dirichlet_constraints, modes);
      support_dofs.clear();
      constraints.clear();
      constraints.copy_from(dirichlet_constraints);
      if (free_modes.n() == 0)
        return;

      // Candidate support dofs: neither constrained nor on an interface,
      // starting at the node nearest the centroid, then the farthest ones,
      // which gives a well-conditioned pin-and-roller support.
      const std::set<types::boundary_id> interfaces(interface_ids.begin(),
                                                    interface_ids.end());
      const IndexSet on_interface =
        interfaces.empty() ?
          IndexSet(dof_handler.n_dofs()) :
          DoFTools::extract_boundary_dofs(dof_handler, ComponentMask(), interfaces);
      std::vector<types::global_dof_index> candidates;
      for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
        if (!dirichlet_constraints.is_constrained(i) &&
            !on_interface.is_element(i))
          candidates.push_back(i);
      AssertThrow(!candidates.empty(),
                  ExcMessage("Block '" + name +
                             "': no node is free to hold its rigid modes."));
      const auto nearest =
        *std::min_element(candidates.begin(),
                          candidates.end(),
                          [&](const auto a, const auto b) {
                            return dof_support_points[a].distance(centre) <
                                   dof_support_points[b].distance(centre);
                          });
      const Point<dim> pin = dof_support_points[nearest];
      std::stable_sort(candidates.begin(),
                       candidates.end(),
                       [&](const auto a, const auto b) {
                         const bool a_pin = dof_support_points[a] == pin;
                         const bool b_pin = dof_support_points[b] == pin;
                         if (a_pin != b_pin)
                           return a_pin;
                         return dof_support_points[a].distance(pin) >
                                dof_support_points[b].distance(pin);
                       });
      support_dofs = minimal_support_dofs(free_modes, modes, candidates);
      AssertThrow(support_dofs.size() == free_modes.n(),
                  ExcMessage("Block '" + name +
                             "': cannot find a support that holds its free "
                             "rigid modes."));
      // constraints is a copy of the closed Dirichlet constraints: lines
      // cannot be added to it (close() would return at once and leave them
      // unsorted; deal.II's debug library stops there). Merge them instead.
      AffineConstraints<double> support;
      for (const types::global_dof_index dof : support_dofs)
        support.add_line(dof);
      support.close();
      constraints.merge(support);
    }

    template <int dim>
    ElasticBlock<dim>::CellScratch::CellScratch(const Mapping<dim> &       mapping,
                                                const FiniteElement<dim> & fe,
                                                const ElementFamily<dim> & family)
      : fe_values(mapping,
                  fe,
                  family.cell_quadrature(fe.degree + 1),
                  update_values | update_gradients | update_JxW_values)
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
      CellScratch &                                         scratch) const
    {
      FEValues<dim> &     fe_values      = scratch.fe_values;
      FEFaceValues<dim> & fe_face_values = scratch.fe_face_values;
      FullMatrix<double> &cell_matrix    = scratch.matrix;
      Vector<double> &    cell_rhs       = scratch.rhs;
      const parameters::MaterialParameters &material =
        materials.at(cell->material_id());
      const double E = material.youngs_modulus, nu = material.poissons_ratio;
      const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
      const double mu     = E / (2 * (1 + nu));
      Tensor<1, dim> body_force;
      for (unsigned int d = 0; d < dim; ++d)
        body_force[d] = (material.unit_weight +
                         material.density * loads.gravitational_acceleration) *
                        loads.gravity_direction[d];

      const FEValuesExtractors::Vector displacement(0);
      fe_values.reinit(cell);
      cell_matrix = 0;
      cell_rhs    = 0;
      const unsigned int n = fe.n_dofs_per_cell();
      // The shape functions' strains once per point, not once per pair
      // (same operations per entry, so the same K bit for bit).
      std::vector<SymmetricTensor<2, dim>> &eps = scratch.strains;
      std::vector<double> &                 div = scratch.divergences;
      eps.resize(n);
      div.resize(n);
      for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          const double JxW = fe_values.JxW(q);
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
              cell_rhs(i) +=
                fe_values[displacement].value(i, q) * body_force * JxW;
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
            for (const unsigned int q : fe_face_values.quadrature_point_indices())
              {
                const Point<dim> &x = fe_face_values.quadrature_point(q);
                Tensor<1, dim>    traction;
                // A pressure pushes against the outward normal.
                if (pressure != pressures.end())
                  traction -= pressure->second->value(x) * fe_face_values.normal_vector(q);
                if (given != tractions.end())
                  {
                    given->second->vector_value(x, value);
                    for (unsigned int d = 0; d < dim; ++d)
                      traction[d] += value[d];
                  }
                for (unsigned int i = 0; i < n; ++i)
                  cell_rhs(i) += fe_face_values[displacement].value(i, q) *
                                 traction * fe_face_values.JxW(q);
              }
          }
    }

    template <int dim>
    void
    ElasticBlock<dim>::assemble_and_factorize(
      const parameters::LoadParameters &load_parameters,
      const std::string &               solver_type)
    {
      assemble(load_parameters);
      factorize(solver_type);
    }

    template <int dim>
    void
    ElasticBlock<dim>::assemble(const parameters::LoadParameters &load_parameters)
    {
      loads = load_parameters;
      const auto     start    = std::chrono::steady_clock::now();
      const MPI_Comm comm     = triangulation.get_communicator();
      const bool     parallel = Utilities::MPI::n_mpi_processes(comm) > 1;
      const IndexSet &owned   = dof_handler.locally_owned_dofs();
      // The pattern of this rank's cells; rows other ranks own go to them.
      DynamicSparsityPattern dsp(dof_handler.n_dofs());
      DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
      if (parallel)
        SparsityTools::distribute_sparsity_pattern(dsp, owned, comm,
                                                   complete_index_set(dof_handler.n_dofs()));
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
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    template <int dim>
    void
    ElasticBlock<dim>::factorize(const std::string &solver_type)
    {
      const auto start = std::chrono::steady_clock::now();
      direct_solver.reset();
      mumps_solver.reset();
      if (solver_type == "MUMPS" || solver_type == "MUMPS_Schur")
        {
          mumps_solver = std::make_unique<MumpsSchurSolver>();
          mumps_solver->factorize(stiffness_matrix,
                                  solver_type == "MUMPS_Schur" ?
                                    interface_schur_dofs() :
                                    std::vector<types::global_dof_index>());
        }
      else
        {
          direct_solver = std::make_unique<DirectSolver>(solver_type);
          direct_solver->factorize(stiffness_matrix);
        }
      factorization_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    template <int dim>
    std::vector<types::global_dof_index>
    ElasticBlock<dim>::interface_schur_dofs() const
    {
      if (interface_ids.empty())
        return {};
      const std::set<types::boundary_id> interfaces(interface_ids.begin(),
                                                    interface_ids.end());
      const IndexSet on_interface =
        DoFTools::extract_boundary_dofs(dof_handler, ComponentMask(), interfaces);
      std::set<types::global_dof_index> schur;
      for (const types::global_dof_index dof : on_interface)
        if (!constraints.is_constrained(dof))
          schur.insert(dof);
        else
          for (const auto &[master, weight] : *constraints.get_constraint_entries(dof))
            schur.insert(master);
      return {schur.begin(), schur.end()};
    }

    template <int dim>
    Vector<double>
    ElasticBlock<dim>::solve(const Vector<double> &nodal_forces) const
    {
      Vector<double> rhs = nodal_forces;
      constraints.condense(rhs);
      Vector<double> u = mumps_solver ? mumps_solver->solve(rhs) :
                                        direct_solver->solve(rhs);
      constraints.distribute(u);
      return u;
    }

    template <int dim>
    std::vector<Vector<double>>
    ElasticBlock<dim>::solve(const std::vector<Vector<double>> &nodal_forces) const
    {
      if (nodal_forces.size() == 1)
        return {solve(nodal_forces[0])};
      const unsigned int          block_size = 64;
      const std::size_t           n_dofs     = dof_handler.n_dofs();
      std::vector<Vector<double>> u(nodal_forces.size());
      std::vector<double>         columns;
      for (unsigned int first = 0; first < nodal_forces.size(); first += block_size)
        {
          const unsigned int n_columns =
            std::min<unsigned int>(block_size, nodal_forces.size() - first);
          columns.resize(n_dofs * n_columns);
          for (unsigned int c = 0; c < n_columns; ++c)
            {
              Vector<double> rhs = nodal_forces[first + c];
              constraints.condense(rhs);
              std::copy(rhs.begin(), rhs.end(), columns.begin() + c * n_dofs);
            }
          solve_columns(columns, n_columns);
          for (unsigned int c = 0; c < n_columns; ++c)
            {
              Vector<double> &column = u[first + c];
              column.reinit(n_dofs);
              std::copy(columns.begin() + c * n_dofs,
                        columns.begin() + (c + 1) * n_dofs,
                        column.begin());
              constraints.distribute(column);
            }
        }
      return u;
    }

    template <int dim>
    void
    ElasticBlock<dim>::solve_columns(std::vector<double> &b,
                                     const unsigned int   n_rhs) const
    {
      if (mumps_solver)
        mumps_solver->solve(b, n_rhs);
      else
        direct_solver->solve(b, n_rhs);
    }

    template <int dim>
    bool
    ElasticBlock<dim>::flexibility_from_schur(
      const std::vector<types::global_dof_index> &dofs,
      FullMatrix<double> &                        C) const
    {
      if (!mumps_solver || mumps_solver->schur_dofs().empty())
        return false;
      // Row r of the constraint map P (u = P u_free): the unconstrained
      // dofs dof r follows, as positions in the Schur list, with weights.
      const auto &                                   schur = mumps_solver->schur_dofs();
      std::vector<std::vector<std::pair<unsigned int, double>>> rows(dofs.size());
      for (unsigned int r = 0; r < dofs.size(); ++r)
        {
          const auto entry = [&](const types::global_dof_index dof, const double w) {
            const auto it = std::lower_bound(schur.begin(), schur.end(), dof);
            if (it == schur.end() || *it != dof)
              return false;
            rows[r].emplace_back(it - schur.begin(), w);
            return true;
          };
          if (!constraints.is_constrained(dofs[r]))
            {
              if (!entry(dofs[r], 1.0))
                return false;
            }
          else
            for (const auto &[master, weight] :
                 *constraints.get_constraint_entries(dofs[r]))
              if (!entry(master, weight))
                return false;
        }
      // C = P (K^{-1})_SS P^T; a fixed dof has an empty row, so zero.
      const std::vector<double> inverse = mumps_solver->inverse_on_schur_dofs();
      const std::size_t          n_s     = schur.size();
      for (unsigned int r = 0; r < dofs.size(); ++r)
        for (unsigned int c = 0; c < dofs.size(); ++c)
          {
            double value = 0;
            for (const auto &[i, wi] : rows[r])
              for (const auto &[j, wj] : rows[c])
                value += wi * wj * inverse[i + j * n_s];
            C(r, c) = value;
          }
      return true;
    }

    template <int dim>
    FullMatrix<double>
    ElasticBlock<dim>::flexibility(
      const std::vector<types::global_dof_index> &dofs) const
    {
      const unsigned int n = dofs.size();
      FullMatrix<double> C(n, n);
      if (flexibility_from_schur(dofs, C))
        return C;
      // Unit loads on the dofs, 64 at a time: one pass through the factors
      // for many, and memory for 64 solutions only.
      const unsigned int block_size = 64;
      for (unsigned int first = 0; first < n; first += block_size)
        {
          const unsigned int          n_columns = std::min(block_size, n - first);
          std::vector<Vector<double>> loads(n_columns, Vector<double>(dof_handler.n_dofs()));
          for (unsigned int c = 0; c < n_columns; ++c)
            loads[c][dofs[first + c]] = 1;
          const std::vector<Vector<double>> u = solve(loads);
          for (unsigned int c = 0; c < n_columns; ++c)
            for (unsigned int r = 0; r < n; ++r)
              C(r, first + c) = u[c][dofs[r]];
        }
      return C;
    }

    template <int dim>
    std::vector<FullMatrix<double>>
    ElasticBlock<dim>::flexibility_diagonal_blocks(
      const std::vector<std::array<types::global_dof_index, dim>> &nodes) const
    {
      std::vector<FullMatrix<double>> blocks(nodes.size(), FullMatrix<double>(dim, dim));
      // MUMPS's entries of K^{-1} on a distributed matrix stopped with
      // INFOG(1) = -22 in our runs (MUMPS 5.5): with more than one rank, and
      // with the other solvers, the columns of the nodes' dofs are solved
      // in blocks of right-hand sides and only their own blocks kept.
      if (!mumps_solver || !mumps_solver->schur_dofs().empty() ||
          Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
        {
          const unsigned int nodes_per_pass = 64 / dim;
          for (unsigned int first = 0; first < nodes.size(); first += nodes_per_pass)
            {
              const unsigned int last =
                std::min<unsigned int>(nodes.size(), first + nodes_per_pass);
              std::vector<Vector<double>> loads;
              for (unsigned int k = first; k < last; ++k)
                for (unsigned int j = 0; j < dim; ++j)
                  {
                    loads.emplace_back(dof_handler.n_dofs());
                    loads.back()[nodes[k][j]] = 1;
                  }
              const std::vector<Vector<double>> u = solve(loads);
              for (unsigned int k = first; k < last; ++k)
                for (unsigned int i = 0; i < dim; ++i)
                  for (unsigned int j = 0; j < dim; ++j)
                    blocks[k](i, j) = u[dim * (k - first) + j][nodes[k][i]];
            }
          return blocks;
        }
      // C = P K^{-1} P^T with P the constraints (u = P u_free, a fixed dof
      // has an empty row): the entries of K^{-1} between the dofs that a
      // node's dofs follow, each asked for once.
      using Weights = std::vector<std::pair<types::global_dof_index, double>>;
      const auto follows = [&](const types::global_dof_index dof) {
        if (!constraints.is_constrained(dof))
          return Weights{{dof, 1.0}};
        return Weights(constraints.get_constraint_entries(dof)->begin(),
                       constraints.get_constraint_entries(dof)->end());
      };
      std::map<std::pair<types::global_dof_index, types::global_dof_index>, std::size_t>
        entry_index;
      std::vector<std::pair<types::global_dof_index, types::global_dof_index>> entries;
      std::vector<std::array<Weights, dim>> weights(nodes.size());
      for (unsigned int k = 0; k < nodes.size(); ++k)
        for (unsigned int i = 0; i < dim; ++i)
          weights[k][i] = follows(nodes[k][i]);
      for (unsigned int k = 0; k < nodes.size(); ++k)
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            for (const auto &[a, wa] : weights[k][i])
              for (const auto &[b, wb] : weights[k][j])
                if (entry_index.emplace(std::make_pair(a, b), entries.size()).second)
                  entries.emplace_back(a, b);
      const std::vector<double> values = mumps_solver->inverse_entries(entries);
      for (unsigned int k = 0; k < nodes.size(); ++k)
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            for (const auto &[a, wa] : weights[k][i])
              for (const auto &[b, wb] : weights[k][j])
                blocks[k](i, j) += wa * wb * values[entry_index.at({a, b})];
      return blocks;
    }

    template <int dim>
    std::vector<InterfaceNode<dim>>
    ElasticBlock<dim>::interface_nodes(const types::boundary_id group) const
    {
      std::vector<InterfaceNode<dim>>               nodes;
      std::map<types::global_dof_index, unsigned int> node_of_first_dof;
      FEFaceValues<dim> fe_face_values(mapping,
                                       fe,
                                       element_family.face_quadrature(fe.degree + 1),
                                       update_values | update_normal_vectors |
                                         update_JxW_values);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell()), face_dofs;
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
                  if (!std::binary_search(face_dofs.begin(), face_dofs.end(), dofs[i]))
                    continue;
                  const auto [component, base] = fe.system_to_component_index(i);
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
                      node.area_normal += phi_JxW * fe_face_values.normal_vector(q);
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

    template <int dim>
    Vector<double>
    ElasticBlock<dim>::nodal_residual(const Vector<double> &u,
                                      const unsigned int    material_id) const
    {
      Vector<double> residual(dof_handler.n_dofs());
      CellScratch    scratch(mapping, fe, element_family);
      Vector<double> cell_u(fe.n_dofs_per_cell()), cell_residual(fe.n_dofs_per_cell());
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

    template <int dim>
    Tensor<1, dim>
    ElasticBlock<dim>::free_mode_displacement(const unsigned int k,
                                              const Point<dim> & x) const
    {
      Tensor<1, dim> u;
      for (unsigned int m = 0; m < n_rigid_modes<dim>; ++m)
        u += free_modes(m, k) * rigid_mode(m, x, centre, length_scale);
      return u;
    }

    template <int dim>
    void
    ElasticBlock<dim>::add_rigid_motion(const Vector<double> &gamma,
                                        Vector<double> &      u) const
    {
      for (unsigned int i = 0; i < dof_handler.n_dofs(); ++i)
        for (unsigned int k = 0; k < gamma.size(); ++k)
          u[i] += gamma[k] *
                  free_mode_displacement(k, dof_support_points[i])[dof_components[i]];
    }

    template <int dim>
    double
    ElasticBlock<dim>::free_mode_load(const unsigned int k) const
    {
      double work = 0;
      for (unsigned int i = 0; i < dof_handler.n_dofs(); ++i)
        work += load_vector[i] *
                free_mode_displacement(k, dof_support_points[i])[dof_components[i]];
      return work;
    }

    template class ElasticBlock<2>;
    template class ElasticBlock<3>;
  } // namespace blocks
} // namespace fdem
