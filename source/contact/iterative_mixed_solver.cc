// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The iterative solver of the mixed system: C is never formed. GMRES works
// on x = [f; gamma w / c_0] (the rigid unknowns as forces: w_m the largest
// relative motion of mode m, c_0 the mean self-flexibility, so that the
// norm it reduces weighs both alike in any units). Each
// iteration applies C once (one solve of every block a pair touches). The
// preconditioner is the same system with C replaced by the pairs' own
// blocks of P C P (P onto ker W^T), solved exactly: per pair
// M_p = G_p D_p + F_p (dim x dim), and the rigid unknowns from a small
// system S. Whether the free blocks can be held at all is decided before,
// on the rigid modes (MixedSystem::solve, RigidModeTest). A coarse
// correction on groups of neighbouring pairs takes care of the smooth force
// patterns, which the pairs' blocks precondition worst.
#include <fdem/contact/dirichlet_preconditioner.h>
#include <fdem/contact/iterative_mixed_solver.h>
#include <fdem/linear_algebra/dense_lu.h>

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
    IterativeMixedSolver<dim>::IterativeMixedSolver(MixedSystem<dim> &system)
      : system(system)
    {
      setup_preconditioner();
    }

    template <int dim>
    IterativeMixedSolver<dim>::~IterativeMixedSolver() = default;

    template <int dim>
    std::string
    IterativeMixedSolver<dim>::describe(const ContactSolution &solution)
    {
      return std::to_string(solution.n_krylov_iterations) + " GMRES iterations";
    }

    template <int dim>
    ContactSolution
    IterativeMixedSolver<dim>::solve(const std::vector<PairRows<dim>> &rows)
    {
      const Vector<double>     &external_gap   = system.external_gap;
      const Vector<double>     &rigid_loads    = system.rigid_loads;
      const FullMatrix<double> &rigid_coupling = system.rigid_coupling;
      const SystemScales       &scales         = system.scales;
      const double       mean_flexibility      = system.mean_self_flexibility();
      const unsigned int n_forces              = external_gap.size();
      const unsigned int n_rigid               = rigid_loads.size();
      const unsigned int n                     = n_forces + n_rigid;
      const unsigned int n_pairs               = system.n_pairs();
      // gamma_r = rigid_scale[r] x_r: x_r = gamma_r w_r / c_0 is a force.
      std::vector<double> rigid_scale(n_rigid);
      for (unsigned int r = 0; r < n_rigid; ++r)
        rigid_scale[r] = mean_flexibility / scales.rigid[r];

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

      const FunctionOperator mixed_operator{
        [&](Vector<double> &y, const Vector<double> &x) {
          Vector<double> f(n_forces), gamma(n_rigid), d(n_forces), w(n_forces);
          for (unsigned int i = 0; i < n_forces; ++i)
            f[i] = x[i];
          for (unsigned int r = 0; r < n_rigid; ++r)
            gamma[r] = rigid_scale[r] * x[n_forces + r];
          d = system.flexibility_products({f})[0];
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

      // The preconditioner: M_p^{-1}, H_p = M_p^{-1} G_p W'_p (W' = W
      // diag(rigid_scale)), and S = diag(1/w) sum_p W_p^T H_p (dimensionless).
      // M_p's invertibility is judged on its rows over their magnitudes
      // (row_magnitudes), which are dimensionless.
      std::vector<Tensor<2, dim>> M_inverse(n_pairs);
      FullMatrix<double>          H(n_forces, n_rigid);
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          const Tensor<2, dim> M =
            rows[p].gap * projected_self_flexibility[p] + rows[p].force;
          const Tensor<1, dim> rho = row_magnitudes(rows[p], scales);
          Tensor<2, dim>       M_scaled; // rows over rho, columns times F_0
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int k = 0; k < dim; ++k)
              M_scaled[i][k] = M[i][k] * scales.force / rho[i];
          const double size = M_scaled.norm();
          // A pair whose block is singular (no such state is known) is
          // preconditioned by the identity: GMRES still solves the true system.
          M_inverse[p] =
            std::abs(determinant(M_scaled)) > 1e-14 * std::pow(size, dim) ?
              invert(M) :
              Tensor<2, dim>(unit_symmetric_tensor<dim>());
          if (dirichlet)
            continue;
          const Tensor<2, dim> MG = M_inverse[p] * rows[p].gap;
          for (unsigned int r = 0; r < n_rigid; ++r)
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int k = 0; k < dim; ++k)
                H(dim * p + i, r) +=
                  MG[i][k] * rigid_scale[r] * rigid_coupling(dim * p + k, r);
        }

      // The pairs' part of the preconditioner: t = M_p^{-1} r_p per pair,
      // which solves the pairs' rows with C replaced by its pairs' blocks
      // D_p. With the Dirichlet preconditioner H ~ C^{-1} (FETI's), t is
      // corrected once: the local solution (f = t, displacement u = D t)
      // satisfies the rows but not the global law f = H u; its mismatch
      // e = H D t - t, taken up by the rows with the local law
      // (G dU + F df = 0, df - D^{-1} dU = e), gives f = t + M^{-1} G D e.
      // For a sticking pair (G = I, F = 0) that is f = H r, FETI's
      // preconditioner; rows that fix forces (open, a slip limit, a held
      // direction) stay satisfied exactly, and the 3D slip's row across the
      // slip takes the correction by its weight on the gap. (Replacing f by
      // H u along the directions that the force rows leave free instead
      // needed twice the iterations once pairs slipped: 21.8 GMRES
      // iterations per solve against 9.5 at 121 pairs.)
      const auto local_solve = [&](const std::vector<Vector<double>> &r) {
        std::vector<Vector<double>> t(r.size(), Vector<double>(n_forces));
        for (unsigned int c = 0; c < r.size(); ++c)
          for (unsigned int p = 0; p < n_pairs; ++p)
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int k = 0; k < dim; ++k)
                t[c][dim * p + i] += M_inverse[p][i][k] * r[c][dim * p + k];
        if (!dirichlet)
          return t;
        std::vector<Vector<double>> u(r.size(), Vector<double>(n_forces));
        for (unsigned int c = 0; c < r.size(); ++c)
          for (unsigned int p = 0; p < n_pairs; ++p)
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int k = 0; k < dim; ++k)
                u[c][dim * p + i] +=
                  projected_self_flexibility[p][i][k] * t[c][dim * p + k];
        const std::vector<Vector<double>> h = dirichlet->apply(u);
        for (unsigned int c = 0; c < r.size(); ++c)
          for (unsigned int p = 0; p < n_pairs; ++p)
            {
              Tensor<1, dim> e, t_p;
              for (unsigned int i = 0; i < dim; ++i)
                {
                  e[i]   = h[c][dim * p + i] - t[c][dim * p + i];
                  t_p[i] = t[c][dim * p + i];
                }
              const Tensor<1, dim> correction =
                M_inverse[p] *
                (rows[p].gap * (projected_self_flexibility[p] * e));
              for (unsigned int i = 0; i < dim; ++i)
                t[c][dim * p + i] = t_p[i] + correction[i];
            }
        return t;
      };
      if (dirichlet && n_rigid > 0)
        {
          // H = L(G W'), L the map above: its columns by one product each.
          std::vector<Vector<double>> GW(n_rigid, Vector<double>(n_forces));
          for (unsigned int r = 0; r < n_rigid; ++r)
            for (unsigned int p = 0; p < n_pairs; ++p)
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int k = 0; k < dim; ++k)
                  GW[r][dim * p + i] += rows[p].gap[i][k] * rigid_scale[r] *
                                        rigid_coupling(dim * p + k, r);
          const std::vector<Vector<double>> LGW = local_solve(GW);
          for (unsigned int r = 0; r < n_rigid; ++r)
            for (unsigned int j = 0; j < n_forces; ++j)
              H(j, r) = LGW[r][j];
        }
      std::unique_ptr<linear_algebra::DenseLU> rigid_lu;
      solution.reciprocal_condition = 1;
      if (n_rigid > 0)
        {
          FullMatrix<double> S(n_rigid, n_rigid);
          rigid_coupling.Tmmult(S, H);
          for (unsigned int r = 0; r < n_rigid; ++r)
            for (unsigned int c = 0; c < n_rigid; ++c)
              S(r, c) /= scales.rigid[r];
          rigid_lu = std::make_unique<linear_algebra::DenseLU>(S);
          solution.reciprocal_condition =
            rigid_lu->reciprocal_condition_number();
          // The rigid modes can be held (RigidModeTest): a preconditioner
          // whose rigid part has no inverse is a numerical breakdown.
          if (!rigid_lu->factorized())
            {
              const double condition = solution.reciprocal_condition;
              solution               = system.unsolved(SolveFailure::numerical);
              solution.factorized    = false;
              solution.reciprocal_condition = condition;
              return solution;
            }
        }

      const std::function<void(Vector<double> &, const Vector<double> &)>
        pair_preconditioner = [&](Vector<double> &z, const Vector<double> &r) {
          z.reinit(n);
          Vector<double> r_forces(n_forces), coarse_rhs(n_rigid);
          for (unsigned int j = 0; j < n_forces; ++j)
            r_forces[j] = r[j];
          Vector<double> t = local_solve({r_forces})[0];
          if (n_rigid > 0)
            {
              rigid_coupling.Tvmult(coarse_rhs, t);
              for (unsigned int c = 0; c < n_rigid; ++c)
                coarse_rhs[c] =
                  (-r[n_forces + c] - coarse_rhs[c]) / scales.rigid[c];
              rigid_lu->solve(coarse_rhs);
              H.vmult_add(t, coarse_rhs);
              for (unsigned int c = 0; c < n_rigid; ++c)
                z[n_forces + c] = coarse_rhs[c];
            }
          for (unsigned int i = 0; i < n_forces; ++i)
            z[i] = t[i];
        };

      // The coarse correction (A-DEF1, e.g. Tang et al. 2009, J Sci Comput
      // 39, 340-370): with Q = Z E^{-1} Z^T R and E = Z^T R A Z, the
      // preconditioner is z = Q r + M^{-1} (r - A Q r), M^{-1} the pairs'
      // preconditioner above. Z holds the smooth force patterns, along which
      // C has its largest eigenvalues and the pairs' blocks say least. R
      // turns rows that fix forces into displacements (times the mean
      // flexibility), so that all rows weigh alike in Z^T R. A Z comes from
      // the stored C Z, and its rigid rows, -W^T Z, vanish (Z is in ker W^T):
      // the correction costs no product with C. (Deflating the system
      // instead, P_D A x = P_D b, halved the iterations of all-stick solves
      // too, but GMRES stalled on that singular system once pairs slipped.)
      const unsigned int n_coarse = coarse_basis.n();
      FullMatrix<double> AZ(n_forces, n_coarse), RZ(n_forces, n_coarse);
      for (unsigned int p = 0; p < n_pairs; ++p)
        for (unsigned int i = 0; i < dim; ++i)
          {
            const unsigned int row = dim * p + i;
            bool               gap = false;
            for (unsigned int k = 0; k < dim; ++k)
              {
                const double a = rows[p].gap[i][k], b = rows[p].force[i][k];
                gap |= a != 0;
                if (a != 0 || b != 0)
                  for (unsigned int c = 0; c < n_coarse; ++c)
                    AZ(row, c) += a * coarse_flexibility(dim * p + k, c) +
                                  b * coarse_basis(dim * p + k, c);
              }
            const double scale_row = gap ? 1.0 : mean_flexibility;
            for (unsigned int c = 0; c < n_coarse; ++c)
              RZ(row, c) = scale_row * coarse_basis(row, c);
          }
      FullMatrix<double> E(n_coarse, n_coarse);
      if (n_coarse > 0)
        RZ.Tmmult(E, AZ);
      const linear_algebra::DenseLU coarse_lu(E);
      // A coarse problem without a digit left (no such state is known) is
      // left out: the pairs' preconditioner alone is still a preconditioner.
      const bool coarse =
        n_coarse > 0 && coarse_lu.reciprocal_condition_number() > 1e-14;
      const FunctionOperator preconditioner{
        [&](Vector<double> &z, const Vector<double> &r) {
          if (!coarse)
            {
              pair_preconditioner(z, r);
              return;
            }
          Vector<double> r_forces(n_forces), y(n_coarse), Ay(n_forces);
          for (unsigned int j = 0; j < n_forces; ++j)
            r_forces[j] = r[j];
          RZ.Tvmult(y, r_forces);
          coarse_lu.solve(y);
          AZ.vmult(Ay, y);
          Vector<double> left = r;
          for (unsigned int j = 0; j < n_forces; ++j)
            left[j] -= Ay[j];
          pair_preconditioner(z, left);
          Vector<double> Zy(n_forces);
          coarse_basis.vmult(Zy, y);
          for (unsigned int j = 0; j < n_forces; ++j)
            z[j] += Zy[j];
        }};

      // Start from the last solution: between status iterations only the
      // pairs that changed move it.
      unsigned int   n_iterations = 0;
      Vector<double> x(n);
      if (last_iterate.size() == n)
        x = last_iterate;
      Vector<double> preconditioned_rhs(n);
      preconditioner.vmult(preconditioned_rhs, rhs);
      const double target =
        system.krylov_control.tolerance * preconditioned_rhs.l2_norm();
      if (target == 0)
        x = 0;
      else
        {
          SolverControl control(system.krylov_control.max_iterations,
                                target,
                                false,
                                false);
          // Up to 400 Krylov vectors: a restart costs more iterations than
          // the vectors cost memory (n x 400 numbers).
          typename SolverGMRES<Vector<double>>::AdditionalData data(
            std::min(n, 400u));
          SolverGMRES<Vector<double>> gmres(control, data);
          try
            {
              gmres.solve(mixed_operator, x, rhs, preconditioner);
            }
          catch (const SolverControl::NoConvergence &)
            {
              solution            = system.unsolved(SolveFailure::numerical);
              solution.factorized = false;
              solution.reciprocal_condition = 0;
              solution.n_krylov_iterations  = control.last_step();
              return solution;
            }
          n_iterations = control.last_step();
        }
      last_iterate = x;
      for (unsigned int r = 0; r < n_rigid; ++r)
        x[n_forces + r] *= rigid_scale[r];
      Vector<double> forces(n_forces);
      for (unsigned int i = 0; i < n_forces; ++i)
        forces[i] = x[i];
      const double condition = solution.reciprocal_condition;
      solution =
        system.solution_from(x, system.flexibility_products({forces})[0]);
      solution.factorized           = false;
      solution.reciprocal_condition = condition;
      solution.n_krylov_iterations  = n_iterations;
      return solution;
    }

    template class IterativeMixedSolver<2>;
    template class IterativeMixedSolver<3>;
  } // namespace contact
} // namespace fdem
