// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The iterative solver of the mixed system: C is never formed. GMRES works
// on x = [f; gamma / c_mean] (the rigid unknowns as forces, c_mean the mean
// self-flexibility, so that the norm it reduces weighs both alike). Each
// iteration applies C once (one solve of every block a pair touches). The
// preconditioner is the same system with C replaced by the pairs' own
// blocks D_p, solved exactly: per pair M_p = G_p D_p + F_p (dim x dim), and
// the rigid unknowns from a small coarse system S. That coarse system is
// where a free block that nothing holds shows up: S singular means the
// mixed system is too (no static equilibrium).
#include <fdem/contact/dense_lu.h>
#include <fdem/contact/mixed_system.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace fdem
{
  namespace contact
  {
    namespace
    {
      /** A linear operator for deal.II's solvers from a function. */
      struct FunctionOperator
      {
        std::function<void(Vector<double> &, const Vector<double> &)> apply;

        void
        vmult(Vector<double> &dst, const Vector<double> &src) const
        {
          apply(dst, src);
        }
      };
    } // namespace

    template <int dim>
    void
    MixedSystem<dim>::setup_preconditioner()
    {
      const unsigned int n_pairs  = pairs.size();
      const unsigned int n_forces = dim * n_pairs;
      const unsigned int n_rigid  = rigid_loads.size();

      // P C P = C - Pi C - C Pi + Pi C Pi with Pi = W (W^T W)^{-1} W^T, from
      // C W (one product per free mode). On a free block the diagonal of C
      // is several times that of P C P (6.6 times on the block on a plane
      // of prm/, 77 pairs), and its block-Jacobi preconditioner is the
      // worse for it (condition 108 against 25 on ker W^T, computed).
      projected_self_flexibility = self_flexibility;
      if (n_rigid > 0)
        {
          std::vector<double> WW(std::size_t(n_rigid) * n_rigid);
          for (unsigned int r = 0; r < n_rigid; ++r)
            for (unsigned int c = 0; c < n_rigid; ++c)
              for (unsigned int j = 0; j < n_forces; ++j)
                WW[r + std::size_t(c) * n_rigid] += rigid_coupling(j, r) * rigid_coupling(j, c);
          const DenseLU WW_lu(n_rigid, std::move(WW));
          if (WW_lu.reciprocal_condition_number() > 1e-12)
            {
              std::vector<Vector<double>> W(n_rigid, Vector<double>(n_forces));
              for (unsigned int r = 0; r < n_rigid; ++r)
                for (unsigned int j = 0; j < n_forces; ++j)
                  W[r][j] = rigid_coupling(j, r);
              const std::vector<Vector<double>> CW = flexibility_products(W);
              // B = W (W^T W)^{-1} (n_forces x n_rigid), X = W^T C W.
              FullMatrix<double> B(n_forces, n_rigid), X(n_rigid, n_rigid);
              for (unsigned int j = 0; j < n_forces; ++j)
                {
                  Vector<double> row(n_rigid);
                  for (unsigned int r = 0; r < n_rigid; ++r)
                    row[r] = rigid_coupling(j, r);
                  WW_lu.solve(row); // (W^T W) symmetric: row of W (W^T W)^{-1}
                  for (unsigned int r = 0; r < n_rigid; ++r)
                    B(j, r) = row[r];
                }
              for (unsigned int r = 0; r < n_rigid; ++r)
                for (unsigned int c = 0; c < n_rigid; ++c)
                  X(r, c) = W[r] * CW[c];
              for (unsigned int p = 0; p < n_pairs; ++p)
                for (unsigned int i = 0; i < dim; ++i)
                  for (unsigned int k = 0; k < dim; ++k)
                    {
                      const unsigned int a = dim * p + i, b = dim * p + k;
                      double             value = 0;
                      for (unsigned int r = 0; r < n_rigid; ++r)
                        {
                          value -= B(a, r) * CW[r][b] + CW[r][a] * B(b, r);
                          for (unsigned int c = 0; c < n_rigid; ++c)
                            value += B(a, r) * X(r, c) * B(b, c);
                        }
                      projected_self_flexibility[p][i][k] += value;
                    }
            }
        }
    }

    template <int dim>
    ContactSolution
    MixedSystem<dim>::solve_iterative(const std::vector<PairRows<dim>> &rows) const
    {
      const unsigned int n_forces = external_gap.size();
      const unsigned int n_rigid  = rigid_loads.size();
      const unsigned int n        = n_forces + n_rigid;
      const unsigned int n_pairs  = pairs.size();
      const double       scale    = mean_flexibility; // gamma = scale x_r

      ContactSolution solution;
      solution.factorized = false;

      // Right-hand side: G_p g_bar_p + value_p, and -omega^T F.
      Vector<double> rhs(n);
      for (unsigned int p = 0; p < n_pairs; ++p)
        for (unsigned int i = 0; i < dim; ++i)
          {
            double value = rows[p].value[i];
            for (unsigned int k = 0; k < dim; ++k)
              value += rows[p].gap[i][k] * external_gap[dim * p + k];
            rhs[dim * p + i] = value;
          }
      for (unsigned int r = 0; r < n_rigid; ++r)
        rhs[n_forces + r] = -rigid_loads[r];

      const FunctionOperator system{[&](Vector<double> &y, const Vector<double> &x) {
        Vector<double> f(n_forces), gamma(n_rigid), d(n_forces), w(n_forces);
        for (unsigned int i = 0; i < n_forces; ++i)
          f[i] = x[i];
        for (unsigned int r = 0; r < n_rigid; ++r)
          gamma[r] = scale * x[n_forces + r];
        vmult_flexibility(d, f);
        rigid_coupling.vmult(w, gamma);
        d -= w;
        y.reinit(n);
        for (unsigned int p = 0; p < n_pairs; ++p)
          for (unsigned int i = 0; i < dim; ++i)
            {
              double value = 0;
              for (unsigned int k = 0; k < dim; ++k)
                value += rows[p].gap[i][k] * d[dim * p + k] +
                         rows[p].force[i][k] * f[dim * p + k];
              y[dim * p + i] = value;
            }
        if (n_rigid > 0)
          {
            Vector<double> load(n_rigid);
            rigid_coupling.Tvmult(load, f);
            for (unsigned int r = 0; r < n_rigid; ++r)
              y[n_forces + r] = -load[r];
          }
      }};

      // The preconditioner: M_p^{-1}, H_p = M_p^{-1} G_p W'_p (W' = scale W),
      // and S = sum_p W_p^T H_p.
      std::vector<Tensor<2, dim>> M_inverse(n_pairs);
      FullMatrix<double>          H(n_forces, n_rigid);
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          const Tensor<2, dim> M    = rows[p].gap * projected_self_flexibility[p] + rows[p].force;
          const double         size = M.norm();
          // A pair whose block is singular (no such state is known) is
          // preconditioned by the identity: GMRES still solves the true system.
          M_inverse[p] = std::abs(determinant(M)) > 1e-14 * std::pow(size, dim) ?
                           invert(M) :
                           Tensor<2, dim>(unit_symmetric_tensor<dim>());
          const Tensor<2, dim> MG = M_inverse[p] * rows[p].gap;
          for (unsigned int r = 0; r < n_rigid; ++r)
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int k = 0; k < dim; ++k)
                H(dim * p + i, r) += MG[i][k] * scale * rigid_coupling(dim * p + k, r);
        }
      std::unique_ptr<DenseLU> rigid_lu;
      solution.reciprocal_condition = 1;
      if (n_rigid > 0)
        {
          std::vector<double> S(std::size_t(n_rigid) * n_rigid);
          for (unsigned int r = 0; r < n_rigid; ++r)
            for (unsigned int c = 0; c < n_rigid; ++c)
              for (unsigned int j = 0; j < n_forces; ++j)
                S[r + std::size_t(c) * n_rigid] += rigid_coupling(j, r) * H(j, c);
          rigid_lu = std::make_unique<DenseLU>(n_rigid, std::move(S));
          solution.reciprocal_condition = rigid_lu->reciprocal_condition_number();
          // As for the dense solver: below 1e-14 no digit is left, and the
          // free modes are not held by the pairs in these states.
          if (!(solution.reciprocal_condition > 1e-14))
            {
              unsolved(solution);
              return solution;
            }
        }

      const std::function<void(Vector<double> &, const Vector<double> &)> pair_preconditioner =
        [&](Vector<double> &z, const Vector<double> &r) {
        z.reinit(n);
        Vector<double> t(n_forces), coarse_rhs(n_rigid);
        for (unsigned int p = 0; p < n_pairs; ++p)
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int k = 0; k < dim; ++k)
              t[dim * p + i] += M_inverse[p][i][k] * r[dim * p + k];
        if (n_rigid > 0)
          {
            rigid_coupling.Tvmult(coarse_rhs, t);
            for (unsigned int c = 0; c < n_rigid; ++c)
              coarse_rhs[c] = -r[n_forces + c] - coarse_rhs[c];
            rigid_lu->solve(coarse_rhs);
            H.vmult_add(t, coarse_rhs);
            for (unsigned int c = 0; c < n_rigid; ++c)
              z[n_forces + c] = coarse_rhs[c];
          }
        for (unsigned int i = 0; i < n_forces; ++i)
          z[i] = t[i];
      };
      const FunctionOperator preconditioner{pair_preconditioner};

      // Start from the last solution: between status iterations only the
      // pairs that changed move it.
      Vector<double> x(n);
      if (last_iterate.size() == n)
        x = last_iterate;
      Vector<double> preconditioned_rhs(n);
      preconditioner.vmult(preconditioned_rhs, rhs);
      const double target = krylov_control.tolerance * preconditioned_rhs.l2_norm();
      if (target == 0)
        x = 0;
      else
        {
          SolverControl control(krylov_control.max_iterations, target, false, false);
          // Up to 400 Krylov vectors: a restart costs more iterations than
          // the vectors cost memory (n x 400 numbers).
          typename SolverGMRES<Vector<double>>::AdditionalData data(std::min(n, 400u));
          SolverGMRES<Vector<double>> gmres(control, data);
          try
            {
              gmres.solve(system, x, rhs, preconditioner);
            }
          catch (const SolverControl::NoConvergence &)
            {
              solution.n_krylov_iterations = control.last_step();
              n_krylov_iterations += control.last_step();
              solution.reciprocal_condition = 0;
              unsolved(solution);
              return solution;
            }
          solution.n_krylov_iterations = control.last_step();
          n_krylov_iterations += control.last_step();
        }
      last_iterate = x;
      for (unsigned int r = 0; r < n_rigid; ++r)
        x[n_forces + r] *= scale;
      solution.solved = true;
      finish_solution(x, solution);
      return solution;
    }

    template void
    MixedSystem<2>::setup_preconditioner();
    template void
    MixedSystem<3>::setup_preconditioner();
    template ContactSolution
    MixedSystem<2>::solve_iterative(const std::vector<PairRows<2>> &) const;
    template ContactSolution
    MixedSystem<3>::solve_iterative(const std::vector<PairRows<3>> &) const;
  } // namespace contact
} // namespace fdem
