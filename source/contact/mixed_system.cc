// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
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
      const std::vector<Interface<dim>> &interfaces)
      : blocks(blocks)
    {
      for (const Interface<dim> &interface : interfaces)
        for (const NodePair<dim> &pair : interface.pairs)
          {
            pairs.push_back(&pair);
            pair_block_I.push_back(interface.block_I);
            pair_block_J.push_back(interface.block_J);
          }
      const unsigned int n_forces = dim * pairs.size();

      unsigned int n_rigid = 0;
      for (const auto &block : blocks)
        {
          first_rigid_unknown.push_back(n_rigid);
          n_rigid += block->n_free_rigid_modes();
        }

      flexibility.reinit(n_forces, n_forces);
      external_gap.reinit(n_forces);
      rigid_coupling.reinit(n_forces, n_rigid);
      rigid_loads.reinit(n_rigid);

      for (unsigned int b = 0; b < blocks.size(); ++b)
        {
          // The pairs that touch block b, the sign of the load they put on
          // it (I receives -f, J receives +f), and their dofs on b.
          std::vector<unsigned int>            touching;
          std::vector<double>                  sign;
          std::vector<types::global_dof_index> dofs;
          for (unsigned int p = 0; p < pairs.size(); ++p)
            for (const bool on_I : {true, false})
              if ((on_I ? pair_block_I[p] : pair_block_J[p]) == b)
                {
                  touching.push_back(p);
                  sign.push_back(on_I ? -1.0 : 1.0);
                  const auto &pair_dofs = on_I ? pairs[p]->dofs_I : pairs[p]->dofs_J;
                  dofs.insert(dofs.end(), pair_dofs.begin(), pair_dofs.end());
                }
          if (touching.empty())
            continue;

          // g = u_I - u_J: C += s_k s_l T_k C_b T_l^T (eq. 6).
          const FullMatrix<double> C_b = blocks[b]->flexibility(dofs);
          for (unsigned int k = 0; k < touching.size(); ++k)
            for (unsigned int l = 0; l < touching.size(); ++l)
              {
                Tensor<2, dim> C_kl;
                for (unsigned int i = 0; i < dim; ++i)
                  for (unsigned int j = 0; j < dim; ++j)
                    C_kl[i][j] = C_b(dim * k + i, dim * l + j);
                const Tensor<2, dim> local = sign[k] * sign[l] *
                                             pairs[touching[k]]->frame * C_kl *
                                             transpose(pairs[touching[l]]->frame);
                for (unsigned int i = 0; i < dim; ++i)
                  for (unsigned int j = 0; j < dim; ++j)
                    flexibility(dim * touching[k] + i, dim * touching[l] + j) +=
                      local[i][j];
              }

          // g_bar: the relative displacement under the external loads.
          const Vector<double> &u_bar = external_displacements[b];
          for (unsigned int k = 0; k < touching.size(); ++k)
            {
              Tensor<1, dim> u;
              for (unsigned int i = 0; i < dim; ++i)
                u[i] = u_bar[dofs[dim * k + i]];
              const Tensor<1, dim> local = -sign[k] * (pairs[touching[k]]->frame * u);
              for (unsigned int i = 0; i < dim; ++i)
                external_gap[dim * touching[k] + i] += local[i];
            }

          // W and omega^T F for the free modes of block b (eqs. 1, 7, 8).
          for (unsigned int m = 0; m < blocks[b]->n_free_rigid_modes(); ++m)
            {
              const unsigned int column = first_rigid_unknown[b] + m;
              rigid_loads[column]      = blocks[b]->free_mode_load(m);
              for (unsigned int k = 0; k < touching.size(); ++k)
                {
                  const NodePair<dim> &pair = *pairs[touching[k]];
                  const Point<dim> &x = sign[k] < 0 ? pair.position_I : pair.position_J;
                  const Tensor<1, dim> local =
                    -sign[k] * (pair.frame * blocks[b]->free_mode_displacement(m, x));
                  for (unsigned int i = 0; i < dim; ++i)
                    rigid_coupling(dim * touching[k] + i, column) += local[i];
                }
            }
        }
      for (unsigned int p = 0; p < pairs.size(); ++p)
        external_gap[dim * p] += pairs[p]->initial_gap;
    }

    template <int dim>
    double
    MixedSystem<dim>::tangential_stiffness(const unsigned int p) const
    {
      double sum = 0;
      for (unsigned int i = 1; i < dim; ++i)
        sum += flexibility(dim * p + i, dim * p + i);
      return sum > 0 ? (dim - 1) / sum : 0.0;
    }

    template <int dim>
    ContactSolution
    MixedSystem<dim>::solve_all_stick() const
    {
      return solve(std::vector<PairState<dim>>(pairs.size()),
                   std::vector<PairStrength>(pairs.size()));
    }

    template <int dim>
    ContactSolution
    MixedSystem<dim>::solve(const std::vector<PairState<dim>> &states,
                            const std::vector<PairStrength> &  strengths) const
    {
      Assert(states.size() == pairs.size(), ExcInternalError());
      Assert(strengths.size() == pairs.size(), ExcInternalError());
      const unsigned int n_forces = flexibility.m();
      const unsigned int n_rigid  = rigid_loads.size();
      const unsigned int n        = n_forces + n_rigid;

      double max_diagonal = 0;
      for (unsigned int i = 0; i < n_forces; ++i)
        max_diagonal = std::max(max_diagonal, flexibility(i, i));

      FullMatrix<double> matrix(n, n);
      Vector<double>     rhs(n);
      // Row "g_i = 0": g = g_bar - C f + W gamma.
      const auto gap_row = [&](const unsigned int row) {
        for (unsigned int j = 0; j < n_forces; ++j)
          matrix(row, j) = flexibility(row, j);
        for (unsigned int j = 0; j < n_rigid; ++j)
          matrix(row, n_forces + j) = -rigid_coupling(row, j);
        rhs[row] = external_gap[row];
      };
      // A slipping pair in 3D: with d the slip direction of the previous
      // iterate, e the tangent normal to it, alpha = s/|z| and r the pair's
      // augmentation, the linearised f_t = s z/|z| reads
      //   d . f_t + mu f_n = c A                 (the limit along d)
      //   (1 - alpha) e . f_t - alpha r e . g_t = 0  (turning towards g_t).
      // At a fixed point e . f_t = e . g_t = 0: force and slip are parallel.
      const auto slip_rows_3d = [&](const unsigned int    normal,
                                    const PairState<dim> &state,
                                    const PairStrength &  strength) {
        const double d1 = state.slip_direction[0];
        const double d2 = dim == 3 ? state.slip_direction[dim - 2] : 0.0;
        const double e1 = -d2, e2 = d1;
        const unsigned int along = normal + 1, across = normal + dim - 1;
        matrix(along, along)  = d1;
        matrix(along, across) = d2;
        matrix(along, normal) = strength.friction_coefficient;
        rhs[along]            = strength.cohesion_force;

        const double alpha = state.direction_weight;
        const double ar    = alpha * tangential_stiffness(normal / dim);
        // - alpha r e . g_t = alpha r e . (C f - W gamma - g_bar)
        for (unsigned int j = 0; j < n_forces; ++j)
          matrix(across, j) =
            ar * (e1 * flexibility(along, j) + e2 * flexibility(across, j));
        for (unsigned int j = 0; j < n_rigid; ++j)
          matrix(across, n_forces + j) =
            -ar * (e1 * rigid_coupling(along, j) + e2 * rigid_coupling(across, j));
        matrix(across, along) += (1 - alpha) * e1;
        matrix(across, across) += (1 - alpha) * e2;
        rhs[across] = ar * (e1 * external_gap[along] + e2 * external_gap[across]);
      };
      for (unsigned int p = 0; p < pairs.size(); ++p)
        {
          const PairState<dim> &state    = states[p];
          const PairStrength &  strength = strengths[p];
          const unsigned int    normal   = dim * p;
          // A direction held by Dirichlet conditions on both sides has no
          // flexibility: its force goes straight into the supports, and
          // f = 0 there is one of the equivalent solutions.
          const auto held = [&](const unsigned int row) {
            return flexibility(row, row) <= 1e-12 * max_diagonal;
          };
          if (state.status == PairStatus::open)
            {
              for (unsigned int i = 0; i < dim; ++i)
                matrix(normal + i, normal + i) = 1; // f = 0
              continue;
            }
          // Normal row: closed (g_n = 0), or held at the tension cut-off.
          if (state.at_cutoff || held(normal))
            {
              matrix(normal, normal) = 1;
              rhs[normal]            = state.at_cutoff ? strength.tensile_force : 0;
            }
          else
            gap_row(normal);
          if (dim == 3 && state.status == PairStatus::slip)
            {
              slip_rows_3d(normal, state, strength);
              continue;
            }
          for (unsigned int i = 1; i < dim; ++i)
            {
              const unsigned int row = normal + i;
              if (state.status == PairStatus::slip)
                {
                  // f_t = d (c A - mu f_n): the force at the Mohr-Coulomb
                  // limit along the slip direction d (a vector in 3D).
                  const double d   = state.slip_direction[i - 1];
                  matrix(row, row) = 1;
                  matrix(row, normal) = d * strength.friction_coefficient;
                  rhs[row]            = d * strength.cohesion_force;
                }
              else if (held(row))
                matrix(row, row) = 1;
              else
                gap_row(row);
            }
        }
      // Equilibrium of the free modes: -W^T f = -omega^T F.
      for (unsigned int r = 0; r < n_rigid; ++r)
        {
          for (unsigned int j = 0; j < n_forces; ++j)
            matrix(n_forces + r, j) = -rigid_coupling(j, r);
          rhs[n_forces + r] = -rigid_loads[r];
        }

      // The rows and columns are scaled so that forces and rigid motions,
      // whose units differ, weigh alike in the factorisation and in the
      // condition estimate; the factors of an earlier system are reused
      // while few rows have changed (ReusableLU).
      const ReusableLU::Result result = lu.solve(matrix, rhs);

      ContactSolution solution;
      solution.forces.reinit(n_forces);
      solution.rigid_motions.reinit(n_rigid);
      solution.relative_displacements = external_gap;
      solution.reciprocal_condition   = result.reciprocal_condition;
      solution.factorized             = result.factorized;
      solution.n_changed_rows         = result.n_changed_rows;
      solution.why_factorized         = result.why_factorized;
      solution.reuse_method           = result.method != nullptr ? result.method : "";
      // Below rcond = 1e-14 the solution has no correct digit left.
      solution.solved = result.solved;
      if (!solution.solved)
        return solution;

      for (unsigned int i = 0; i < n_forces; ++i)
        solution.forces[i] = rhs[i];
      for (unsigned int i = 0; i < n_rigid; ++i)
        solution.rigid_motions[i] = rhs[n_forces + i];

      Vector<double> product(n_forces);
      flexibility.vmult(product, solution.forces);
      solution.relative_displacements -= product;
      rigid_coupling.vmult(product, solution.rigid_motions);
      solution.relative_displacements += product;
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
