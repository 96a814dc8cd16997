// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/linear_algebra/reusable_lu.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

// Hand-declared: deal.II 9.4's lapack_templates.h has no lacn2 (the
// estimator inside gecon, here applied to an updated inverse).
extern "C" void
dlacn2_(const int *n,
        double    *v,
        double    *x,
        int       *isgn,
        double    *est,
        int       *kase,
        int       *isave);

namespace fdem
{
  namespace linear_algebra
  {
    namespace
    {
      /**
       * A matrix whose reciprocal condition estimate is at most this is
       * singular to working precision (the unit round-off). Anything above
       * is merely ill-conditioned: solved, refined, and judged by its
       * backward error. The matrices are dimensionless (MixedSystem), so
       * this says the same in any units.
       */
      constexpr double singular_condition =
        std::numeric_limits<double>::epsilon();

      /** Most steps of iterative refinement of one solve (LAPACK's dgerfs: 5).
       */
      constexpr unsigned int max_refinement_steps = 5;

      /**
       * Refinement stops at this componentwise backward error. Measured on
       * the wedges and the paper's slope: a fresh solve starts between 1e-16
       * and 3e-13 (a few up to 5e-7, beside a large rigid motion), one step
       * takes it to 1e-16 to 1e-15, where further steps stagnate. 1e-13
       * refines the few that need it (a fifth of the solves on the lift-off
       * wedge) and keeps each force accurate to far below the 1e-10 of the
       * status tests; 1e-15 refined every solve, for 10 % more contact time
       * and no measurable change in K.
       */
      constexpr double componentwise_target = 1e-13;

      /** The backward errors of a solution y of B y = b. */
      struct BackwardErrors
      {
        /** |b - B y|_inf / (|B|_inf |y|_inf + |b|_inf): judges the solve. */
        double normwise = 0;
        /** max_i |b - B y|_i / (|B| |y| + |b|)_i: drives the refinement. */
        double componentwise = 0;
      };

      /**
       * Solves B y = b, B = diag(s) A diag(s), for @p y (b on entry) by
       * @p apply_inverse (an approximate B^{-1}, in place), with iterative
       * refinement as LAPACK's dgerfs does it: a step while the
       * componentwise backward error is above componentwise_target and has
       * at least halved since the last step, at most @p max_steps. The
       * componentwise error makes each unknown accurate relative to its own
       * size: the accuracy of the small forces beside a large rigid motion
       * then depends neither on the scaling of the unknowns nor on their
       * units (Skeel 1980, Math. Comp. 35, 817-832). Returns both errors
       * (NaN if y is not finite).
       */
      BackwardErrors
      refined_solve(const dealii::FullMatrix<double>    &A,
                    const std::vector<double>           &s,
                    const std::function<void(double *)> &apply_inverse,
                    std::vector<double>                 &y,
                    const unsigned int                   max_steps)
      {
        const unsigned int  n      = A.m();
        std::vector<double> b      = y, r(n), z(n);
        double              b_norm = 0, B_norm = 0;
        for (unsigned int i = 0; i < n; ++i)
          b_norm = std::max(b_norm, std::abs(b[i]));
        // |B|_inf = max_i |s_i| sum_j |A_ij s_j|, summed in the first pass
        // over A of backward_error() (the same sums, in the same order, as a
        // pass of its own).
        bool                B_norm_known = false;
        const double        nan = std::numeric_limits<double>::quiet_NaN();
        std::vector<double> size(n);
        const auto          backward_error = [&]() {
          BackwardErrors errors;
          double         r_norm = 0, y_norm = 0;
          for (unsigned int j = 0; j < n; ++j)
            z[j] = s[j] * y[j];
          for (unsigned int i = 0; i < n; ++i)
            {
              const double *A_i = &A(i, 0);
              double        sum = 0, row = 0;
              if (B_norm_known)
                for (unsigned int j = 0; j < n; ++j)
                  {
                    const double term = A_i[j] * z[j];
                    sum += term;
                    row += std::abs(term);
                  }
              else
                {
                  double B_row = 0;
                  for (unsigned int j = 0; j < n; ++j)
                    {
                      const double term = A_i[j] * z[j];
                      sum += term;
                      row += std::abs(term);
                      B_row += std::abs(A_i[j] * s[j]);
                    }
                  B_norm = std::max(B_norm, std::abs(s[i]) * B_row);
                }
              r[i]    = b[i] - s[i] * sum;
              r_norm  = std::max(r_norm, std::abs(r[i]));
              y_norm  = std::max(y_norm, std::abs(y[i]));
              size[i] = std::abs(s[i]) * row + std::abs(b[i]);
            }
          B_norm_known = true;
          if (!std::isfinite(r_norm) || !std::isfinite(y_norm))
            return BackwardErrors{nan, nan};
          const double scale = B_norm * y_norm + b_norm;
          errors.normwise =
            scale > 0 ? r_norm / scale : (r_norm > 0 ? 1.0 : 0.0);
          // Rows whose whole content is at round-off of the system (e.g.
          // f = 0 of an open pair: B_ii y_i ~ 1e-20) have no relative
          // accuracy to reach; the normwise error covers them.
          const double negligible =
            std::numeric_limits<double>::epsilon() * scale;
          for (unsigned int i = 0; i < n; ++i)
            if (size[i] > negligible)
              errors.componentwise =
                std::max(errors.componentwise, std::abs(r[i]) / size[i]);
          return errors;
        };
        apply_inverse(y.data());
        BackwardErrors      errors = backward_error();
        std::vector<double> previous_y;
        for (unsigned int step = 0;
             step < max_steps && errors.componentwise > componentwise_target;
             ++step)
          {
            previous_y = y;
            apply_inverse(r.data());
            for (unsigned int i = 0; i < n; ++i)
              y[i] += r[i];
            const BackwardErrors next = backward_error();
            if (!(next.componentwise <= 0.5 * errors.componentwise))
              {
                // No longer halving: keep the better of the two.
                if (!(next.componentwise <= errors.componentwise))
                  y = previous_y;
                else
                  errors = next;
                break;
              }
            errors = next;
          }
        return errors;
      }

      /**
       * S_ii = 1/sqrt(max_j max(|A_ij|, |A_ji|)): rows and columns alike,
       * so that S A S stays symmetric where A is.
       */
      std::vector<double>
      row_and_column_scale(const dealii::FullMatrix<double> &matrix)
      {
        // One pass by rows (the matrix is stored by rows): the largest
        // entry of each row and, alongside, of each column. A maximum is
        // exact in any order, so this is the same scale as row i and
        // column i searched together.
        const unsigned int  n = matrix.m();
        std::vector<double> scale(n, 0.0);
        for (unsigned int i = 0; i < n; ++i)
          {
            const double *A_i = &matrix(i, 0);
            double        row = 0;
            for (unsigned int j = 0; j < n; ++j)
              {
                const double a = std::abs(A_i[j]);
                row            = std::max(row, a);
                scale[j]       = std::max(scale[j], a);
              }
            scale[i] = std::max(scale[i], row);
          }
        for (unsigned int i = 0; i < n; ++i)
          scale[i] = scale[i] > 0 ? 1.0 / std::sqrt(scale[i]) : 1.0;
        return scale;
      }
    } // namespace

    void
    ReusableLU::clear()
    {
      lu.reset();
      factorized_matrix.reinit(0, 0);
      factorized_scale.clear();
    }

    namespace
    {
      /** The LU factors of @p matrix scaled by rows and columns by @p scale. */
      std::unique_ptr<DenseLU>
      factorize(const dealii::FullMatrix<double> &matrix,
                const std::vector<double>        &scale)
      {
        const unsigned int  n = matrix.m();
        std::vector<double> column_major(static_cast<std::size_t>(n) * n);
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i < n; ++i)
            column_major[static_cast<std::size_t>(j) * n + i] =
              matrix(i, j) * scale[i] * scale[j];
        return std::make_unique<DenseLU>(n, std::move(column_major));
      }
    } // namespace

    ReusableLU::Result
    ReusableLU::solve(const dealii::FullMatrix<double> &matrix,
                      dealii::Vector<double>           &rhs)
    {
      Assert(matrix.m() == matrix.n(), dealii::ExcInternalError());
      Assert(rhs.size() == matrix.m(), dealii::ExcInternalError());
      const unsigned int n = matrix.m();
      if (!control.reuse || !lu || factorized_matrix.m() != n)
        {
          Result fresh =
            factorize_and_solve(matrix, row_and_column_scale(matrix), rhs);
          fresh.why_factorized = control.reuse ? "first system" : "reuse off";
          return fresh;
        }

      std::vector<unsigned int> changed;
      for (unsigned int i = 0; i < n; ++i)
        {
          const double *A_i = &matrix(i, 0), *F_i = &factorized_matrix(i, 0);
          for (unsigned int j = 0; j < n; ++j)
            if (A_i[j] != F_i[j])
              {
                changed.push_back(i);
                break;
              }
        }

      Result result;
      result.factorized     = false;
      result.n_changed_rows = changed.size();
      if (changed.empty())
        {
          result.method = "same matrix";
          // The very matrix that was factorised (and so the same scaling):
          // the same operations as right after its factorisation.
          result.reciprocal_condition = factorized_condition;
          result.solved =
            factorized_solved &&
            solve_factorized(matrix, factorized_scale, *lu, rhs, result);
          ++n_reused_solves;
          return result;
        }
      // The scaling of the new matrix: its own factorisation's, and that of
      // its condition estimate (not needed for the very same matrix).
      std::vector<double> scale = row_and_column_scale(matrix);
      // The old factors must be a good start: a near-singular one is not.
      const char *why = nullptr;
      if (changed.size() > control.max_changed_fraction * n)
        why = "many rows changed";
      else if (!factorized_solved ||
               factorized_condition < control.min_reused_condition)
        why = "last factorised system ill-conditioned";
      else if (!solve_updated(matrix, scale, changed, rhs, result))
        why = "update inaccurate or ill-conditioned";
      if (why == nullptr)
        {
          ++n_reused_solves;
          return result;
        }
      Result fresh         = factorize_and_solve(matrix, std::move(scale), rhs);
      fresh.n_changed_rows = changed.size();
      fresh.why_factorized = why;
      return fresh;
    }

    ReusableLU::Result
    ReusableLU::factorize_and_solve(const dealii::FullMatrix<double> &matrix,
                                    std::vector<double>               scale,
                                    dealii::Vector<double>           &rhs)
    {
      lu = factorize(matrix, scale);
      ++n_factorizations;
      factorized_matrix    = matrix;
      factorized_scale     = std::move(scale);
      factorized_condition = lu->reciprocal_condition_number();
      factorized_solved =
        lu->factorized() && factorized_condition > singular_condition;

      Result result;
      result.reciprocal_condition = factorized_condition;
      result.solved =
        factorized_solved &&
        solve_factorized(matrix, factorized_scale, *lu, rhs, result);
      return result;
    }

    ReusableLU::Result
    ReusableLU::solve_once(const dealii::FullMatrix<double> &matrix,
                           dealii::Vector<double>           &rhs)
    {
      Assert(matrix.m() == matrix.n(), dealii::ExcInternalError());
      Assert(rhs.size() == matrix.m(), dealii::ExcInternalError());
      const std::vector<double>      scale   = row_and_column_scale(matrix);
      const std::unique_ptr<DenseLU> factors = factorize(matrix, scale);
      ++n_factorizations;
      Result result;
      result.reciprocal_condition = factors->reciprocal_condition_number();
      result.solved               = factors->factorized() &&
                      result.reciprocal_condition > singular_condition &&
                      solve_factorized(matrix, scale, *factors, rhs, result);
      return result;
    }

    bool
    ReusableLU::solve_factorized(const dealii::FullMatrix<double> &matrix,
                                 const std::vector<double>        &scale,
                                 const DenseLU                    &factors,
                                 dealii::Vector<double>           &rhs,
                                 Result                           &result) const
    {
      // The factorised matrix itself: its factors, refined if need be (an
      // ill-conditioned system is refined, not declared singular).
      const unsigned int         n = matrix.m();
      const std::vector<double> &s = scale;
      std::vector<double>        y(n);
      for (unsigned int i = 0; i < n; ++i)
        y[i] = rhs[i] * s[i];
      const BackwardErrors errors = refined_solve(
        matrix,
        s,
        [&factors](double *x) { factors.solve(x, 1); },
        y,
        max_refinement_steps);
      result.backward_error = errors.normwise;
      if (!(errors.normwise <= control.backward_error_tolerance))
        return false;
      for (unsigned int i = 0; i < n; ++i)
        rhs[i] = s[i] * y[i];
      return true;
    }

    bool
    ReusableLU::solve_updated(const dealii::FullMatrix<double> &matrix,
                              const std::vector<double>        &scale,
                              const std::vector<unsigned int>  &changed,
                              dealii::Vector<double>           &rhs,
                              Result                           &result) const
    {
      const unsigned int         n  = matrix.m();
      const unsigned int         k  = changed.size();
      const std::vector<double> &s0 = factorized_scale;
      // B = S_0 A' S_0 = B_0 + P D: D holds the changed rows of B - B_0,
      // each entry formed as the factorised one was (row-major, k x n).
      std::vector<double> D(static_cast<std::size_t>(k) * n);
      for (unsigned int c = 0; c < k; ++c)
        {
          const unsigned int i = changed[c];
          for (unsigned int j = 0; j < n; ++j)
            D[static_cast<std::size_t>(c) * n + j] =
              matrix(i, j) * s0[i] * s0[j] -
              factorized_matrix(i, j) * s0[i] * s0[j];
        }

      // Z = B_0^{-1} P (column-major, n x k) and the capacitance I + D Z.
      std::vector<double> Z(static_cast<std::size_t>(k) * n, 0.0);
      for (unsigned int c = 0; c < k; ++c)
        Z[static_cast<std::size_t>(c) * n + changed[c]] = 1;
      lu->solve(Z.data(), k);
      std::vector<double> capacitance(static_cast<std::size_t>(k) * k);
      for (unsigned int c = 0; c < k; ++c)
        for (unsigned int d = 0; d < k; ++d)
          {
            double sum = c == d ? 1.0 : 0.0;
            for (unsigned int j = 0; j < n; ++j)
              sum += D[static_cast<std::size_t>(c) * n + j] *
                     Z[static_cast<std::size_t>(d) * n + j];
            capacitance[static_cast<std::size_t>(d) * k + c] = sum;
          }
      const DenseLU capacitance_lu(k, std::move(capacitance));
      // A singular capacitance means a singular B: let dgecon judge it.
      if (!capacitance_lu.factorized() ||
          capacitance_lu.reciprocal_condition_number() <
            control.min_reused_condition)
        return false;

      std::vector<double> t(k);
      // x <- B^{-1} x = B_0^{-1} x - Z (I + D Z)^{-1} D B_0^{-1} x
      const auto apply_inverse = [&](double *x) {
        lu->solve(x, 1);
        for (unsigned int c = 0; c < k; ++c)
          {
            double sum = 0;
            for (unsigned int j = 0; j < n; ++j)
              sum += D[static_cast<std::size_t>(c) * n + j] * x[j];
            t[c] = sum;
          }
        capacitance_lu.solve(t.data(), 1);
        for (unsigned int c = 0; c < k; ++c)
          for (unsigned int j = 0; j < n; ++j)
            x[j] -= Z[static_cast<std::size_t>(c) * n + j] * t[c];
      };
      // x <- B^{-T} x = B_0^{-T} (x - D^T (I + D Z)^{-T} Z^T x)
      const auto apply_inverse_transpose = [&](double *x) {
        for (unsigned int c = 0; c < k; ++c)
          {
            double sum = 0;
            for (unsigned int j = 0; j < n; ++j)
              sum += Z[static_cast<std::size_t>(c) * n + j] * x[j];
            t[c] = sum;
          }
        capacitance_lu.solve(t.data(), 1, true);
        for (unsigned int c = 0; c < k; ++c)
          for (unsigned int j = 0; j < n; ++j)
            x[j] -= D[static_cast<std::size_t>(c) * n + j] * t[c];
        lu->solve(x, 1, true);
      };
      result.method = "Woodbury";

      // Solve B y = S_0 b, refine, and judge by the normwise backward error
      // |r|_inf / (|B|_inf |y|_inf + |S_0 b|_inf). Each refinement step
      // costs one solve with the updated factors.
      std::vector<double> y(n);
      for (unsigned int i = 0; i < n; ++i)
        y[i] = rhs[i] * s0[i];
      const BackwardErrors errors =
        refined_solve(matrix, s0, apply_inverse, y, max_refinement_steps);
      const double error = errors.normwise;
      if (!(error <= control.backward_error_tolerance))
        return false;

      // The condition estimate of S' A' S' in its own scaling S', as dgecon
      // makes it: 1 / (|S' A' S'|_1 est|(S' A' S')^{-1}|_1), where
      // (S' A' S')^{-1} = R B^{-1} R with R = S_0 / S'.
      // The column sums by rows (the matrix is stored by rows): each column's
      // terms are added in the same order, top to bottom.
      std::vector<double> columns(n, 0.0);
      for (unsigned int i = 0; i < n; ++i)
        {
          const double *A_i = &matrix(i, 0);
          for (unsigned int j = 0; j < n; ++j)
            columns[j] += std::abs(A_i[j] * scale[i] * scale[j]);
        }
      double A_norm = 0;
      for (unsigned int j = 0; j < n; ++j)
        A_norm = std::max(A_norm, columns[j]);
      std::vector<double> R(n);
      for (unsigned int i = 0; i < n; ++i)
        R[i] = s0[i] / scale[i];
      const int           size = n;
      std::vector<double> v(n), x(n);
      std::vector<int>    signs(n);
      double              inverse_norm = 0;
      int                 kase = 0, isave[3] = {0, 0, 0};
      for (;;)
        {
          dlacn2_(&size,
                  v.data(),
                  x.data(),
                  signs.data(),
                  &inverse_norm,
                  &kase,
                  isave);
          if (kase == 0)
            break;
          for (unsigned int i = 0; i < n; ++i)
            x[i] *= R[i];
          if (kase == 1)
            apply_inverse(x.data());
          else
            apply_inverse_transpose(x.data());
          for (unsigned int i = 0; i < n; ++i)
            x[i] *= R[i];
        }
      if (!std::isfinite(A_norm) || !(inverse_norm > 0) ||
          !std::isfinite(inverse_norm))
        return false;
      const double condition = (1.0 / A_norm) / inverse_norm;
      if (!(condition >= control.min_reused_condition))
        return false;

      result.reciprocal_condition = condition;
      result.solved               = true;
      result.backward_error       = error;
      for (unsigned int i = 0; i < n; ++i)
        rhs[i] = s0[i] * y[i];
      return true;
    }
  } // namespace linear_algebra
} // namespace fdem
