// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/contact/dense_mixed_solver.h>
#include <fdem/contact/iterative_mixed_solver.h>
#include <fdem/contact/mixed_system.h>

#include <algorithm>
#include <cmath>

namespace fdem
{
  namespace contact
  {
    template <int dim>
    MixedSystem<dim>::MixedSystem(
      const std::vector<std::unique_ptr<blocks::ElasticBlock<dim>>> &blocks,
      const std::vector<Vector<double>> &external_displacements,
      const std::vector<Interface<dim>> &interfaces,
      const MixedSystemSolver            solver,
      const bool                         keep_moving_part,
      const std::vector<BarLink<dim>>   &bars,
      const KrylovControl               &krylov)
      : krylov_control(krylov)
      , blocks(blocks)
      , solver_type(solver)
      , bar_links(bars)
    {
      for (const Interface<dim> &interface : interfaces)
        for (const NodePair<dim> &pair : interface.pairs)
          {
            pairs.push_back(&pair);
            pair_block_I.push_back(interface.block_I);
            pair_block_J.push_back(interface.block_J);
          }
      // A bar's link is a pair of the same two nodes as a contact pair, in
      // its own frame: C, g_bar and W follow for it as for any pair.
      for (const BarLink<dim> &bar : bar_links)
        {
          pairs.push_back(&bar.link);
          pair_block_I.push_back(bar.block_I);
          pair_block_J.push_back(bar.block_J);
        }
      const unsigned int n_forces = dim * pairs.size();

      unsigned int n_rigid = 0;
      for (const auto &block : blocks)
        {
          first_rigid_unknown.push_back(n_rigid);
          n_rigid += block->n_free_rigid_modes();
        }

      if (solver_type == MixedSystemSolver::dense)
        flexibility.reinit(n_forces, n_forces);
      const bool keep_moving =
        keep_moving_part && solver_type == MixedSystemSolver::dense;
      if (keep_moving)
        {
          moving_flexibility.reinit(n_forces, n_forces);
          moving_external_gap.reinit(n_forces);
        }
      self_flexibility.assign(pairs.size(), Tensor<2, dim>());
      external_gap.reinit(n_forces);
      rigid_coupling.reinit(n_forces, n_rigid);
      rigid_loads.reinit(n_rigid);

      for (unsigned int b = 0; b < blocks.size(); ++b)
        {
          BlockTouch touch;
          touch.block = b;
          for (unsigned int p = 0; p < pairs.size(); ++p)
            for (const bool on_I : {true, false})
              if ((on_I ? pair_block_I[p] : pair_block_J[p]) == b)
                {
                  touch.pairs.push_back(p);
                  touch.signs.push_back(on_I ? -1.0 : 1.0);
                  const auto &pair_dofs =
                    on_I ? pairs[p]->dofs_I : pairs[p]->dofs_J;
                  touch.dofs.insert(touch.dofs.end(),
                                    pair_dofs.begin(),
                                    pair_dofs.end());
                }
          if (touch.pairs.empty())
            continue;
          const std::vector<unsigned int> &touching = touch.pairs;
          const std::vector<double>       &sign     = touch.signs;
          const auto                      &dofs     = touch.dofs;
          const auto local_tensor = [](const FullMatrix<double> &C_b,
                                       const unsigned int        k,
                                       const unsigned int        l,
                                       const unsigned int        offset_k,
                                       const unsigned int        offset_l) {
            Tensor<2, dim> C_kl;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                C_kl[i][j] =
                  C_b(offset_k + dim * k + i, offset_l + dim * l + j);
            return C_kl;
          };

          if (solver_type == MixedSystemSolver::dense)
            {
              // g = u_I - u_J: C += s_k s_l T_k C_b T_l^T (eq. 6).
              const FullMatrix<double> C_b = blocks[b]->flexibility(dofs);
              for (unsigned int k = 0; k < touching.size(); ++k)
                for (unsigned int l = 0; l < touching.size(); ++l)
                  {
                    const Tensor<2, dim> local =
                      sign[k] * sign[l] * pairs[touching[k]]->frame *
                      local_tensor(C_b, k, l, 0, 0) *
                      transpose(pairs[touching[l]]->frame);
                    for (unsigned int i = 0; i < dim; ++i)
                      for (unsigned int j = 0; j < dim; ++j)
                        flexibility(dim * touching[k] + i,
                                    dim * touching[l] + j) += local[i][j];
                    if (keep_moving && blocks[b]->n_free_rigid_modes() > 0)
                      for (unsigned int i = 0; i < dim; ++i)
                        for (unsigned int j = 0; j < dim; ++j)
                          moving_flexibility(dim * touching[k] + i,
                                             dim * touching[l] + j) +=
                            local[i][j];
                  }
            }
          else
            {
              // Only the pairs' own blocks: T_k C_b,kk T_k^T (s_k^2 = 1).
              std::vector<std::array<types::global_dof_index, dim>> nodes(
                touching.size());
              for (unsigned int k = 0; k < touching.size(); ++k)
                for (unsigned int i = 0; i < dim; ++i)
                  nodes[k][i] = dofs[dim * k + i];
              const std::vector<FullMatrix<double>> C_kk =
                blocks[b]->flexibility_diagonal_blocks(nodes);
              for (unsigned int k = 0; k < touching.size(); ++k)
                self_flexibility[touching[k]] +=
                  pairs[touching[k]]->frame *
                  local_tensor(C_kk[k], 0, 0, 0, 0) *
                  transpose(pairs[touching[k]]->frame);
            }

          // g_bar: the relative displacement under the external loads.
          const Vector<double> &u_bar = external_displacements[b];
          for (unsigned int k = 0; k < touching.size(); ++k)
            {
              Tensor<1, dim> u;
              for (unsigned int i = 0; i < dim; ++i)
                u[i] = u_bar[dofs[dim * k + i]];
              const Tensor<1, dim> local =
                -sign[k] * (pairs[touching[k]]->frame * u);
              for (unsigned int i = 0; i < dim; ++i)
                external_gap[dim * touching[k] + i] += local[i];
              if (keep_moving && blocks[b]->n_free_rigid_modes() > 0)
                for (unsigned int i = 0; i < dim; ++i)
                  moving_external_gap[dim * touching[k] + i] += local[i];
            }

          // W and omega^T F for the free modes of block b (eqs. 1, 7, 8).
          for (unsigned int m = 0; m < blocks[b]->n_free_rigid_modes(); ++m)
            {
              const unsigned int column = first_rigid_unknown[b] + m;
              rigid_loads[column]       = blocks[b]->free_mode_load(m);
              for (unsigned int k = 0; k < touching.size(); ++k)
                {
                  const NodePair<dim> &pair = *pairs[touching[k]];
                  const Point<dim>    &x =
                    sign[k] < 0 ? pair.position_I : pair.position_J;
                  const Tensor<1, dim> local =
                    -sign[k] *
                    (pair.frame * blocks[b]->free_mode_displacement(m, x));
                  for (unsigned int i = 0; i < dim; ++i)
                    rigid_coupling(dim * touching[k] + i, column) += local[i];
                }
            }
          touches.push_back(std::move(touch));
        }
      initial_gaps.reinit(n_forces);
      for (unsigned int p = 0; p < pairs.size(); ++p)
        {
          external_gap[dim * p] += pairs[p]->initial_gap;
          initial_gaps[dim * p] = pairs[p]->initial_gap;
        }
      base_external_gap = external_gap;
      base_rigid_loads  = rigid_loads;

      set_diagonal_scales();
      check_within_range();
      if (solver_type == MixedSystemSolver::dense)
        dense = std::make_unique<DenseMixedSolver<dim>>(*this);
      else
        iterative = std::make_unique<IterativeMixedSolver<dim>>(*this);
    }

    template <int dim>
    MixedSystem<dim>::~MixedSystem() = default;

    template <int dim>
    const linear_algebra::ReusableLU &
    MixedSystem<dim>::dense_solver() const
    {
      static const linear_algebra::ReusableLU unused;
      return dense ? dense->lu : unused;
    }

    template <int dim>
    const IterativeMixedSolver<dim> &
    MixedSystem<dim>::iterative_solver() const
    {
      AssertThrow(iterative,
                  ExcMessage("This mixed system uses the dense solver."));
      return *iterative;
    }

    template <int dim>
    void
    MixedSystem<dim>::check_within_range() const
    {
      // K does not depend on a common modulus, but C and g_bar scale with
      // its inverse: from about E = 1e-300 (kN loads) they are no numbers.
      bool finite =
        std::all_of(external_gap.begin(),
                    external_gap.end(),
                    [](const double g) { return std::isfinite(g); });
      for (const Tensor<2, dim> &C_pp : self_flexibility)
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            finite = finite && std::isfinite(C_pp[i][j]);
      if (solver_type == MixedSystemSolver::dense)
        for (unsigned int i = 0; i < flexibility.m(); ++i)
          for (unsigned int j = 0; j < flexibility.n(); ++j)
            finite = finite && std::isfinite(flexibility(i, j));
      AssertThrow(finite,
                  ExcMessage(
                    "Interfaces: the flexibilities or the relative "
                    "displacements under the loads exceed the range of a "
                    "double (above 1e308): the Young's moduli are too small "
                    "for the loads; give the moduli and the loads in one set "
                    "of units."));
    }

    template <int dim>
    void
    MixedSystem<dim>::set_diagonal_scales()
    {
      // Also after set_moving_compliance_scale(): the scales are then those
      // of a model whose moving blocks have the scaled moduli.
      if (solver_type == MixedSystemSolver::dense)
        for (unsigned int p = 0; p < pairs.size(); ++p)
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              self_flexibility[p][i][j] = flexibility(dim * p + i, dim * p + j);
      double max_diagonal = 0, sum_diagonal = 0;
      for (const Tensor<2, dim> &C_pp : self_flexibility)
        for (unsigned int i = 0; i < dim; ++i)
          {
            max_diagonal = std::max(max_diagonal, C_pp[i][i]);
            sum_diagonal += C_pp[i][i];
          }
      // A direction whose flexibility is 1e-12 of the largest is held: a
      // ratio of flexibilities, the same in any units and for any E.
      held_flexibility            = 1e-12 * max_diagonal;
      const unsigned int n_forces = dim * pairs.size();
      const unsigned int n_rigid  = rigid_loads.size();
      if (sum_diagonal > 0)
        mean_flexibility = sum_diagonal / n_forces;

      // The scales of the dimensionless system (doc/theory.md, "Scale-free
      // decisions"). F_0: the largest total load of a block, a force that
      // no modulus enters (the 1-norm of the nodal loads: the load's
      // magnitude however it is directed). Without any load (only gaps or
      // prescribed displacements drive the model) the force that closes
      // the largest relative displacement elastically.
      scales.flexibility = mean_flexibility;
      // The assembled load's, computed once: a load combination
      // (set_load_coefficients()) changes the blocks' load vectors, not the
      // reference force.
      if (base_force_scale < 0)
        {
          base_force_scale = 0;
          for (const auto &block : blocks)
            base_force_scale =
              std::max(base_force_scale, block->load_vector.l1_norm());
        }
      scales.force = base_force_scale;
      if (!(scales.force > 0))
        scales.force = external_gap.linfty_norm() / scales.flexibility;
      if (!(scales.force > 0) || !std::isfinite(scales.force))
        scales.force = 1; // nothing loads the model: every force is zero
      scales.displacement = scales.flexibility * scales.force;
      scales.rigid.assign(n_rigid, 1.0);
      for (unsigned int m = 0; m < n_rigid; ++m)
        {
          double largest = 0;
          for (unsigned int j = 0; j < n_forces; ++j)
            largest = std::max(largest, std::abs(rigid_coupling(j, m)));
          if (largest > 0)
            scales.rigid[m] = largest;
        }
    }

    template <int dim>
    void
    MixedSystem<dim>::set_moving_compliance_scale(const double scale)
    {
      AssertThrow(
        can_scale_moving_compliance(),
        ExcMessage(
          "The moving blocks' compliance can be scaled only in a dense "
          "mixed system that kept its moving part."));
      const double change = scale - moving_compliance_scale;
      flexibility.add(change, moving_flexibility);
      base_external_gap.add(change, moving_external_gap);
      moving_compliance_scale = scale;
      combine_loads();
      set_diagonal_scales();
      dense->clear(); // the factors and the formed matrix are of the old C
    }

    template <int dim>
    typename MixedSystem<dim>::LoadCase
    MixedSystem<dim>::load_case(
      const std::vector<Vector<double>> &displacements,
      const std::vector<Vector<double>> &loads) const
    {
      AssertDimension(displacements.size(), blocks.size());
      AssertDimension(loads.size(), blocks.size());
      const bool     keep_moving = moving_external_gap.size() > 0;
      Vector<double> gap(external_gap.size()),
        moving_gap(keep_moving ? external_gap.size() : 0);
      Vector<double> loads_on_modes(rigid_loads.size());
      // The same sums as the constructor's g_bar and omega^T F, for this load.
      for (const BlockTouch &touch : touches)
        {
          const unsigned int b = touch.block;
          for (unsigned int k = 0; k < touch.pairs.size(); ++k)
            {
              Tensor<1, dim> u;
              for (unsigned int i = 0; i < dim; ++i)
                u[i] = displacements[b][touch.dofs[dim * k + i]];
              const Tensor<1, dim> local =
                -touch.signs[k] * (pairs[touch.pairs[k]]->frame * u);
              for (unsigned int i = 0; i < dim; ++i)
                {
                  gap[dim * touch.pairs[k] + i] += local[i];
                  if (keep_moving && blocks[b]->n_free_rigid_modes() > 0)
                    moving_gap[dim * touch.pairs[k] + i] += local[i];
                }
            }
          for (unsigned int m = 0; m < blocks[b]->n_free_rigid_modes(); ++m)
            loads_on_modes[first_rigid_unknown[b] + m] =
              blocks[b]->free_mode_load(m, loads[b]);
        }
      return {std::move(gap), std::move(moving_gap), std::move(loads_on_modes)};
    }

    template <int dim>
    unsigned int
    MixedSystem<dim>::add_load_case(
      const std::vector<Vector<double>> &displacements,
      const std::vector<Vector<double>> &loads)
    {
      LoadCase parts = load_case(displacements, loads);
      case_gaps.push_back(std::move(parts.gap));
      case_moving_gaps.push_back(std::move(parts.moving_gap));
      case_rigid_loads.push_back(std::move(parts.rigid_loads));
      return case_gaps.size() - 1;
    }

    template <int dim>
    void
    MixedSystem<dim>::replace_load_case(const unsigned int index,
                                        const LoadCase    &parts)
    {
      AssertIndexRange(index, case_gaps.size());
      AssertDimension(parts.gap.size(), case_gaps[index].size());
      case_gaps[index]        = parts.gap;
      case_moving_gaps[index] = parts.moving_gap;
      case_rigid_loads[index] = parts.rigid_loads;
      combine_loads();
    }

    template <int dim>
    void
    MixedSystem<dim>::set_load_coefficients(
      const double               base_factor,
      const std::vector<double> &coefficients)
    {
      AssertThrow(coefficients.size() <= case_gaps.size(),
                  ExcMessage("More load coefficients than load cases."));
      base_load_factor  = base_factor;
      load_coefficients = coefficients;
      combine_loads();
    }

    template <int dim>
    void
    MixedSystem<dim>::combine_loads()
    {
      external_gap = base_external_gap;
      rigid_loads  = base_rigid_loads;
      if (base_load_factor != 1)
        {
          Vector<double> load_gap = base_external_gap;
          load_gap -= initial_gaps;
          external_gap.add(base_load_factor - 1, load_gap);
          rigid_loads *= base_load_factor;
        }
      for (unsigned int k = 0; k < load_coefficients.size(); ++k)
        if (load_coefficients[k] != 0)
          {
            const double c = load_coefficients[k];
            external_gap.add(c, case_gaps[k]);
            // A case's g_bar was computed at compliance scale 1.
            if (case_moving_gaps[k].size() > 0 && moving_compliance_scale != 1)
              external_gap.add(c * (moving_compliance_scale - 1),
                               case_moving_gaps[k]);
            rigid_loads.add(c, case_rigid_loads[k]);
          }
    }

    template <int dim>
    void
    MixedSystem<dim>::forget_factorization()
    {
      if (dense)
        dense->forget_factors();
    }

    template <int dim>
    std::vector<Vector<double>>
    MixedSystem<dim>::flexibility_products(
      const std::vector<Vector<double>> &sources)
    {
      // C f = sum_b s_k T_k K_b^{-1} (sum_l s_l T_l^T f_l): the load of the
      // pair forces on each block, one solve, its displacements at the pairs.
      std::vector<Vector<double>> products(sources.size(),
                                           Vector<double>(external_gap.size()));
      for (const BlockTouch &touch : touches)
        blocks[touch.block]->solve_blocked(
          sources.size(),
          [&](const unsigned int c, Vector<double> &load) {
            for (unsigned int k = 0; k < touch.pairs.size(); ++k)
              {
                const unsigned int p = touch.pairs[k];
                Tensor<1, dim>     f;
                for (unsigned int i = 0; i < dim; ++i)
                  f[i] = sources[c][dim * p + i];
                const Tensor<1, dim> global =
                  touch.signs[k] * (transpose(pairs[p]->frame) * f);
                for (unsigned int i = 0; i < dim; ++i)
                  load[touch.dofs[dim * k + i]] += global[i];
              }
          },
          [&](const unsigned int c, const Vector<double> &u) {
            for (unsigned int k = 0; k < touch.pairs.size(); ++k)
              {
                const unsigned int p = touch.pairs[k];
                Tensor<1, dim>     u_k;
                for (unsigned int i = 0; i < dim; ++i)
                  u_k[i] = u[touch.dofs[dim * k + i]];
                const Tensor<1, dim> local =
                  touch.signs[k] * (pairs[p]->frame * u_k);
                for (unsigned int i = 0; i < dim; ++i)
                  products[c][dim * p + i] += local[i];
              }
          });
      n_flexibility_products += sources.size();
      return products;
    }

    template <int dim>
    ContactSolution
    MixedSystem<dim>::solve_all_stick()
    {
      return solve(std::vector<PairState<dim>>(pairs.size()),
                   std::vector<PairStrength>(pairs.size()));
    }

    template <int dim>
    ContactSolution
    MixedSystem<dim>::solve(const std::vector<PairState<dim>> &states,
                            const std::vector<PairStrength>   &strengths)
    {
      Assert(states.size() == pairs.size(), ExcInternalError());
      Assert(strengths.size() == pairs.size(), ExcInternalError());
      std::vector<PairRows<dim>> rows(pairs.size());
      for (unsigned int p = 0; p < pairs.size(); ++p)
        rows[p] = is_bar(p) ? bar_rows(states[p], strengths[p], bar(p)) :
                              pair_rows(states[p],
                                        strengths[p],
                                        self_flexibility[p],
                                        held_flexibility);
      // Whether the free modes can be held at all is a question of
      // mechanics, answered on the small dimensionless rigid-mode system
      // before any factorisation: a mechanism is never left to the
      // condition number of the whole system (doc/theory.md).
      const RigidModeTest test = rigid_mode_test(
        rigid_coupling, rigid_loads, rows, scales, rigid_mode_tolerance);
      ContactSolution solution;
      if (!test.holds)
        {
          solution                      = unsolved(SolveFailure::mechanism);
          solution.reciprocal_condition = 0;
          solution.factorized           = false;
        }
      else if (dense)
        solution = dense->solve(rows);
      else
        {
          solution = iterative->solve(rows);
          n_krylov_iterations += solution.n_krylov_iterations;
        }
      solution.rigid_modes = test;
      return solution;
    }

    template <int dim>
    std::string
    MixedSystem<dim>::describe_solve(const ContactSolution &solution) const
    {
      return dense ? DenseMixedSolver<dim>::describe(solution) :
                     IterativeMixedSolver<dim>::describe(solution);
    }

    template <int dim>
    ContactSolution
    MixedSystem<dim>::unsolved(const SolveFailure failure) const
    {
      ContactSolution solution;
      solution.solved  = false;
      solution.failure = failure;
      solution.forces.reinit(external_gap.size());
      solution.rigid_motions.reinit(rigid_loads.size());
      solution.elastic_displacements.reinit(external_gap.size());
      solution.relative_displacements = external_gap;
      return solution;
    }

    template <int dim>
    ContactSolution
    MixedSystem<dim>::solution_from(const Vector<double> &x,
                                    Vector<double>        elastic) const
    {
      const unsigned int n_forces = external_gap.size();
      const unsigned int n_rigid  = rigid_loads.size();
      ContactSolution    solution;
      solution.forces.reinit(n_forces);
      solution.rigid_motions.reinit(n_rigid);
      for (unsigned int i = 0; i < n_forces; ++i)
        solution.forces[i] = x[i];
      for (unsigned int i = 0; i < n_rigid; ++i)
        solution.rigid_motions[i] = x[n_forces + i];

      solution.elastic_displacements  = std::move(elastic);
      solution.relative_displacements = external_gap;
      solution.relative_displacements -= solution.elastic_displacements;
      // No rigid motions (every block held): deal.II's vmult asserts on
      // the empty coupling matrix in a Debug build.
      if (n_rigid > 0)
        {
          Vector<double> product(n_forces);
          rigid_coupling.vmult(product, solution.rigid_motions);
          solution.relative_displacements += product;
        }
      return solution;
    }

    template <int dim>
    Vector<double>
    MixedSystem<dim>::block_nodal_forces(const unsigned int     b,
                                         const ContactSolution &solution) const
    {
      Vector<double> forces = blocks[b]->load_vector;
      for (unsigned int p = 0; p < pairs.size(); ++p)
        for (const bool on_I : {true, false})
          if ((on_I ? pair_block_I[p] : pair_block_J[p]) == b)
            {
              Tensor<1, dim> local;
              for (unsigned int i = 0; i < dim; ++i)
                local[i] = solution.forces[dim * p + i];
              const Tensor<1, dim> global =
                (on_I ? -1.0 : 1.0) * (transpose(pairs[p]->frame) * local);
              const auto &dofs = on_I ? pairs[p]->dofs_I : pairs[p]->dofs_J;
              for (unsigned int i = 0; i < dim; ++i)
                forces[dofs[i]] += global[i];
            }
      return forces;
    }

    template class MixedSystem<2>;
    template class MixedSystem<3>;
  } // namespace contact
} // namespace fdem
