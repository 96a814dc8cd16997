// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/contact/mixed_system.h>

#include <deal.II/lac/lapack_full_matrix.h>

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
    ContactSolution
    MixedSystem<dim>::solve(const std::vector<PairStatus> &statuses) const
    {
      Assert(statuses.size() == pairs.size(), ExcInternalError());
      const unsigned int n_forces = flexibility.m();
      const unsigned int n_rigid  = rigid_loads.size();
      const unsigned int n        = n_forces + n_rigid;

      double max_diagonal = 0;
      for (unsigned int i = 0; i < n_forces; ++i)
        max_diagonal = std::max(max_diagonal, flexibility(i, i));

      LAPACKFullMatrix<double> matrix(n, n);
      Vector<double>           rhs(n);
      for (unsigned int p = 0; p < pairs.size(); ++p)
        for (unsigned int i = 0; i < dim; ++i)
          {
            const unsigned int row = dim * p + i;
            // A direction held by Dirichlet conditions on both sides has no
            // flexibility: its force goes straight into the supports, and
            // f = 0 there is one of the equivalent solutions.
            const bool held = flexibility(row, row) <= 1e-12 * max_diagonal;
            if (statuses[p] == PairStatus::open || held)
              {
                matrix(row, row) = 1; // f = 0
                continue;
              }
            // Stick: g = g_bar - C f + W gamma = 0.
            for (unsigned int j = 0; j < n_forces; ++j)
              matrix(row, j) = flexibility(row, j);
            for (unsigned int j = 0; j < n_rigid; ++j)
              matrix(row, n_forces + j) = -rigid_coupling(row, j);
            rhs[row] = external_gap[row];
          }
      // Equilibrium of the free modes: -W^T f = -omega^T F.
      for (unsigned int r = 0; r < n_rigid; ++r)
        {
          for (unsigned int j = 0; j < n_forces; ++j)
            matrix(n_forces + r, j) = -rigid_coupling(j, r);
          rhs[n_forces + r] = -rigid_loads[r];
        }

      // Scale rows and columns so that forces and rigid motions, whose
      // units differ, weigh alike in the factorisation.
      Vector<double> scale(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          double s = 0;
          for (unsigned int j = 0; j < n; ++j)
            s = std::max(s, std::abs(matrix(i, j)));
          scale[i] = s > 0 ? 1.0 / std::sqrt(s) : 1.0;
        }
      for (unsigned int i = 0; i < n; ++i)
        {
          rhs[i] *= scale[i];
          for (unsigned int j = 0; j < n; ++j)
            matrix(i, j) *= scale[i] * scale[j];
        }
      matrix.compute_lu_factorization();
      matrix.solve(rhs);
      for (unsigned int i = 0; i < n; ++i)
        rhs[i] *= scale[i];

      ContactSolution solution;
      solution.forces.reinit(n_forces);
      solution.rigid_motions.reinit(n_rigid);
      for (unsigned int i = 0; i < n_forces; ++i)
        solution.forces[i] = rhs[i];
      for (unsigned int i = 0; i < n_rigid; ++i)
        solution.rigid_motions[i] = rhs[n_forces + i];

      solution.relative_displacements = external_gap;
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
