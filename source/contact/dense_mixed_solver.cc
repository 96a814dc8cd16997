// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The dense solver of the mixed system: the rows of every pair over the
// formed C as one dense, dimensionless matrix, solved by ReusableLU.
#include <fdem/contact/dense_mixed_solver.h>

#include <algorithm>
#include <limits>

namespace fdem
{
  namespace contact
  {
    template <int dim>
    DenseMixedSolver<dim>::DenseMixedSolver(const MixedSystem<dim> &system)
      : system(system)
    {
      Assert(system.flexibility.m() == dim * system.n_pairs(),
             ExcInternalError());
    }

    namespace
    {
      /** Whether two pairs' rows have the same coefficients (not values). */
      template <int dim>
      bool
      same_coefficients(const PairRows<dim> &a, const PairRows<dim> &b)
      {
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int k = 0; k < dim; ++k)
            if (!(a.gap[i][k] == b.gap[i][k]) ||
                !(a.force[i][k] == b.force[i][k]))
              return false;
        return true;
      }

      bool
      same_scales(const SystemScales &a, const SystemScales &b)
      {
        return a.force == b.force && a.flexibility == b.flexibility &&
               a.displacement == b.displacement && a.rigid == b.rigid;
      }
    } // namespace

    template <int dim>
    void
    DenseMixedSolver<dim>::clear()
    {
      lu.clear();
      formed = false;
    }

    template <int dim>
    ContactSolution
    DenseMixedSolver<dim>::solve(const std::vector<PairRows<dim>> &rows)
    {
      const FullMatrix<double> &flexibility    = system.flexibility;
      const FullMatrix<double> &rigid_coupling = system.rigid_coupling;
      const Vector<double>     &rigid_loads    = system.rigid_loads;
      const Vector<double>     &external_gap   = system.external_gap;
      const SystemScales       &scales         = system.scales;
      const unsigned int        n_pairs        = system.n_pairs();
      const unsigned int        n_forces       = flexibility.m();
      const unsigned int        n_rigid        = rigid_loads.size();
      const unsigned int        n              = n_forces + n_rigid;

      // The dimensionless system D_r A D_c (D_c x~) = D_r b: unknowns f / F_0
      // and gamma_m w_m / u_0, pair rows over their magnitudes, rigid rows
      // over w_m F_0 (doc/theory.md, "Scale-free decisions"). Its entries
      // are the same in any units and for any common E, so that what the
      // factorisation decides (pivots, reuse, refinement) is too.
      // ReusableLU equilibrates it further and reuses the factors of an
      // earlier system while few rows have changed.
      rhs.reinit(n, true);
      row_scale.resize(n);
      column_scale.resize(n);
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          const Tensor<1, dim> rho = row_magnitudes(rows[p], scales);
          for (unsigned int i = 0; i < dim; ++i)
            {
              row_scale[dim * p + i]    = 1.0 / rho[i];
              column_scale[dim * p + i] = scales.force;
            }
        }
      for (unsigned int r = 0; r < n_rigid; ++r)
        {
          row_scale[n_forces + r]    = 1.0 / (scales.rigid[r] * scales.force);
          column_scale[n_forces + r] = scales.displacement / scales.rigid[r];
        }
      // Rows of the matrix, scaled: entry (i, j) times row_scale[i]
      // column_scale[j].
      const auto scale_row = [&](const unsigned int i) {
        double *A_i = &matrix(i, 0);
        for (unsigned int j = 0; j < n; ++j)
          A_i[j] *= row_scale[i] * column_scale[j];
      };

      if (!formed || matrix.m() != n || formed_rows.size() != n_pairs ||
          !same_scales(scales, formed_scales))
        {
          matrix.reinit(n, n);
          // Equilibrium of the free modes: -W^T f = -omega^T F.
          for (unsigned int r = 0; r < n_rigid; ++r)
            {
              for (unsigned int j = 0; j < n_forces; ++j)
                matrix(n_forces + r, j) = -rigid_coupling(j, r);
              scale_row(n_forces + r);
            }
          formed_rows.assign(n_pairs, PairRows<dim>());
          formed_scales = scales;
          formed        = true;
          for (unsigned int p = 0; p < n_pairs; ++p)
            // Not equal to any rows: every pair's rows are formed below.
            formed_rows[p].gap[0][0] = std::numeric_limits<double>::quiet_NaN();
        }
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          const bool form = !same_coefficients(rows[p], formed_rows[p]);
          for (unsigned int i = 0; i < dim; ++i)
            {
              const unsigned int row = dim * p + i;
              rhs[row]               = rows[p].value[i];
              if (form)
                std::fill(&matrix(row, 0), &matrix(row, 0) + n, 0.0);
              // sum_k gap[i][k] (C f - W gamma - g_bar)_k
              for (unsigned int k = 0; k < dim; ++k)
                {
                  const double a = rows[p].gap[i][k];
                  if (a == 0)
                    continue;
                  const unsigned int source = dim * p + k;
                  if (form)
                    {
                      for (unsigned int j = 0; j < n_forces; ++j)
                        matrix(row, j) += a * flexibility(source, j);
                      for (unsigned int j = 0; j < n_rigid; ++j)
                        matrix(row, n_forces + j) -=
                          a * rigid_coupling(source, j);
                    }
                  rhs[row] += a * external_gap[source];
                }
              if (form)
                {
                  for (unsigned int k = 0; k < dim; ++k)
                    matrix(row, dim * p + k) += rows[p].force[i][k];
                  scale_row(row);
                }
            }
          if (form)
            formed_rows[p] = rows[p];
        }
      for (unsigned int r = 0; r < n_rigid; ++r)
        rhs[n_forces + r] = -rigid_loads[r];
      for (unsigned int i = 0; i < n; ++i)
        rhs[i] *= row_scale[i];
      const linear_algebra::ReusableLU::Result result = lu.solve(matrix, rhs);
      for (unsigned int i = 0; i < n; ++i)
        rhs[i] *= column_scale[i];

      // The rigid modes can be held (MixedSystem::solve()): a system
      // ReusableLU could not solve to its backward error is a numerical
      // breakdown.
      ContactSolution solution;
      if (result.solved)
        {
          Vector<double> forces(n_forces), elastic(n_forces);
          for (unsigned int i = 0; i < n_forces; ++i)
            forces[i] = rhs[i];
          flexibility.vmult(elastic, forces);
          solution = system.solution_from(rhs, std::move(elastic));
        }
      else
        solution = system.unsolved(SolveFailure::numerical);
      solution.reciprocal_condition = result.reciprocal_condition;
      solution.factorized           = result.factorized;
      solution.n_changed_rows       = result.n_changed_rows;
      solution.why_factorized       = result.why_factorized;
      solution.reuse_method = result.method != nullptr ? result.method : "";
      return solution;
    }

    template <int dim>
    std::string
    DenseMixedSolver<dim>::describe(const ContactSolution &solution)
    {
      return std::to_string(solution.n_changed_rows) + " rows changed, LU " +
             (solution.factorized ?
                std::string("factorised: ") + solution.why_factorized :
                std::string("reused: ") + solution.reuse_method);
    }

    template class DenseMixedSolver<2>;
    template class DenseMixedSolver<3>;
  } // namespace contact
} // namespace fdem
