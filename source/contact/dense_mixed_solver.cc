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
      forget_factors();
      formed = false;
    }

    template <int dim>
    void
    DenseMixedSolver<dim>::forget_factors()
    {
      lu.clear();
      factorized_rows.clear();
    }

    template <int dim>
    ContactSolution
    DenseMixedSolver<dim>::solve(const std::vector<PairRows<dim>> &rows)
    {
      return solves_condensed(rows) ? solve_condensed(rows) : solve_whole(rows);
    }

    template <int dim>
    bool
    DenseMixedSolver<dim>::solves_condensed(
      const std::vector<PairRows<dim>> &rows) const
    {
      if (dim != 3 || !system.condensed_solves)
        // 2D slip rows stay the same between iterations: the whole
        // system's factors are reused (the paper's slope: 1 to 4
        // factorisations in up to 34 solves per K).
        return false;
      const unsigned int n_pairs   = rows.size();
      const unsigned int n         = dim * n_pairs + system.rigid_loads.size();
      unsigned int       n_changed = 0, n_condensed = n - dim * n_pairs;
      for (unsigned int p = 0; p < n_pairs; ++p)
        for (unsigned int i = 0; i < dim; ++i)
          {
            if (rows[p].is_gap_row(i))
              ++n_condensed;
            if (factorized_rows.size() != n_pairs ||
                !(rows[p].gap[i] == factorized_rows[p].gap[i]) ||
                !(rows[p].force[i] == factorized_rows[p].force[i]))
              ++n_changed;
          }
      const double ratio = static_cast<double>(n_condensed) / n;
      return n_changed > lu.control.max_changed_fraction * n &&
             ratio * ratio * ratio <= 0.75;
    }

    template <int dim>
    ContactSolution
    DenseMixedSolver<dim>::solve_whole(const std::vector<PairRows<dim>> &rows)
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
      if (result.factorized)
        factorized_rows = rows;
      for (unsigned int i = 0; i < n; ++i)
        rhs[i] *= column_scale[i];

      // The rigid modes can be held (MixedSystem::solve()): a system
      // ReusableLU could not solve to its backward error is a numerical
      // breakdown.
      ContactSolution solution      = result.solved ?
                                        solution_of(rhs) :
                                        system.unsolved(SolveFailure::numerical);
      solution.reciprocal_condition = result.reciprocal_condition;
      solution.factorized           = result.factorized;
      solution.n_changed_rows       = result.n_changed_rows;
      solution.why_factorized       = result.why_factorized;
      solution.reuse_method = result.method != nullptr ? result.method : "";
      return solution;
    }

    template <int dim>
    ContactSolution
    DenseMixedSolver<dim>::solve_condensed(
      const std::vector<PairRows<dim>> &rows)
    {
      const FullMatrix<double> &flexibility    = system.flexibility;
      const FullMatrix<double> &rigid_coupling = system.rigid_coupling;
      const Vector<double>     &rigid_loads    = system.rigid_loads;
      const Vector<double>     &external_gap   = system.external_gap;
      const SystemScales       &scales         = system.scales;
      const unsigned int        n_pairs        = system.n_pairs();
      const unsigned int        n_forces       = flexibility.m();
      const unsigned int        n_rigid        = rigid_loads.size();

      // Each pair's forces f_p = particular_p + N_p y_p; y numbered pair by
      // pair, the pair's kept rows likewise (as many as its y).
      std::vector<CondensedPair<dim>> pairs(n_pairs);
      std::vector<unsigned int>       first(n_pairs + 1, 0);
      Vector<double>                  particular(n_forces);
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          pairs[p]     = condense_force_rows(rows[p]);
          first[p + 1] = first[p] + pairs[p].n_free;
          for (unsigned int k = 0; k < dim; ++k)
            particular[dim * p + k] = pairs[p].particular[k];
        }
      const unsigned int n_free = first[n_pairs], n = n_free + n_rigid;
      Vector<double>     flexible_particular(n_forces);
      flexibility.vmult(flexible_particular, particular);

      // The same dimensionless form as the whole system (solve_whole()):
      // a kept row over its magnitude, y in units of the force scale (N is
      // orthonormal), rigid rows and unknowns as there.
      FullMatrix<double>  condensed(n, n);
      Vector<double>      x(n);
      std::vector<double> combined_row(n_forces);
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          const Tensor<1, dim> rho = row_magnitudes(rows[p], scales);
          for (unsigned int m = 0; m < pairs[p].n_free; ++m)
            {
              const unsigned int i   = pairs[p].kept_rows[m];
              const unsigned int row = first[p] + m;
              // sum_k gap[i][k] (C f - W gamma - g_bar)_k + force[i] . f_p
              //   = value[i], with f = particular + N y.
              std::fill(combined_row.begin(), combined_row.end(), 0.0);
              double rhs = rows[p].value[i];
              for (unsigned int k = 0; k < dim; ++k)
                {
                  const double a = rows[p].gap[i][k];
                  if (a == 0)
                    continue;
                  const unsigned int source = dim * p + k;
                  const double      *C_row  = &flexibility(source, 0);
                  for (unsigned int j = 0; j < n_forces; ++j)
                    combined_row[j] += a * C_row[j];
                  for (unsigned int r = 0; r < n_rigid; ++r)
                    condensed(row, n_free + r) -= a * rigid_coupling(source, r);
                  rhs +=
                    a * (external_gap[source] - flexible_particular[source]);
                }
              for (unsigned int k = 0; k < dim; ++k)
                {
                  combined_row[dim * p + k] += rows[p].force[i][k];
                  rhs -= rows[p].force[i][k] * pairs[p].particular[k];
                }
              const double row_scale = 1.0 / rho[i];
              for (unsigned int q = 0; q < n_pairs; ++q)
                for (unsigned int t = 0; t < pairs[q].n_free; ++t)
                  {
                    double entry = 0;
                    for (unsigned int l = 0; l < dim; ++l)
                      entry += combined_row[dim * q + l] * pairs[q].basis[l][t];
                    condensed(row, first[q] + t) =
                      entry * row_scale * scales.force;
                  }
              for (unsigned int r = 0; r < n_rigid; ++r)
                condensed(row, n_free + r) *=
                  row_scale * scales.displacement / scales.rigid[r];
              x[row] = rhs * row_scale;
            }
        }
      // Equilibrium of the free modes: -W^T f = -omega^T F.
      for (unsigned int r = 0; r < n_rigid; ++r)
        {
          const double row_scale = 1.0 / (scales.rigid[r] * scales.force);
          double       rhs       = -rigid_loads[r];
          for (unsigned int j = 0; j < n_forces; ++j)
            rhs += rigid_coupling(j, r) * particular[j];
          for (unsigned int q = 0; q < n_pairs; ++q)
            for (unsigned int t = 0; t < pairs[q].n_free; ++t)
              {
                double entry = 0;
                for (unsigned int l = 0; l < dim; ++l)
                  entry -=
                    rigid_coupling(dim * q + l, r) * pairs[q].basis[l][t];
                condensed(n_free + r, first[q] + t) =
                  entry * row_scale * scales.force;
              }
          x[n_free + r] = rhs * row_scale;
        }

      const linear_algebra::ReusableLU::Result result =
        lu.solve_once(condensed, x);
      condensed = FullMatrix<double>(); // its memory, before C f below

      ContactSolution solution;
      if (result.solved)
        {
          Vector<double> unknowns(n_forces + n_rigid);
          for (unsigned int p = 0; p < n_pairs; ++p)
            for (unsigned int l = 0; l < dim; ++l)
              {
                double force = pairs[p].particular[l];
                for (unsigned int t = 0; t < pairs[p].n_free; ++t)
                  force +=
                    pairs[p].basis[l][t] * x[first[p] + t] * scales.force;
                unknowns[dim * p + l] = force;
              }
          for (unsigned int r = 0; r < n_rigid; ++r)
            unknowns[n_forces + r] =
              x[n_free + r] * scales.displacement / scales.rigid[r];
          solution = solution_of(unknowns);
        }
      else
        solution = system.unsolved(SolveFailure::numerical);
      solution.reciprocal_condition = result.reciprocal_condition;
      solution.factorized           = true;
      solution.n_condensed_unknowns = n;
      solution.why_factorized       = "condensed";
      return solution;
    }

    template <int dim>
    ContactSolution
    DenseMixedSolver<dim>::solution_of(const Vector<double> &unknowns) const
    {
      const unsigned int n_forces = system.flexibility.m();
      Vector<double>     forces(n_forces), elastic(n_forces);
      for (unsigned int i = 0; i < n_forces; ++i)
        forces[i] = unknowns[i];
      system.flexibility.vmult(elastic, forces);
      return system.solution_from(unknowns, std::move(elastic));
    }

    template <int dim>
    std::string
    DenseMixedSolver<dim>::describe(const ContactSolution &solution)
    {
      if (solution.n_condensed_unknowns > 0)
        return "slip rows changed, condensed system of " +
               std::to_string(solution.n_condensed_unknowns) +
               " unknowns factorised";
      return std::to_string(solution.n_changed_rows) + " rows changed, LU " +
             (solution.factorized ?
                std::string("factorised: ") + solution.why_factorized :
                std::string("reused: ") + solution.reuse_method);
    }

    template class DenseMixedSolver<2>;
    template class DenseMixedSolver<3>;
  } // namespace contact
} // namespace fdem
