// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/linear_algebra/dense_lu.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace fdem
{
  namespace linear_algebra
  {
    /**
     * Solves a sequence of dense systems A x = b whose matrices differ from
     * one to the next in a few rows, as the mixed system does between status
     * iterations (a pair that changes status changes its dim rows). The
     * system is scaled, S A S y = S b with x = S y, by rows and columns alike
     * (S_ii = 1/sqrt of the largest |entry| of row and column i) so that
     * forces and rigid motions, whose units differ, weigh alike.
     *
     * The first matrix is scaled and LU-factorised (DenseLU); the solution
     * and the reciprocal condition estimate are then exactly those of a
     * fresh factorisation. A later matrix A' that differs from the factorised
     * A_0 in k rows is A' = A_0 + P D (P selects the k rows, D their change),
     * and its scaled form B = S_0 A' S_0 = B_0 + P D' is solved by the
     * Sherman-Morrison-Woodbury formula
     *
     *   B^{-1} = B_0^{-1} - Z (I_k + D' Z)^{-1} D' B_0^{-1},   Z = B_0^{-1} P,
     *
     * which is exact: it costs k + 2 solves with the old factors and a k x k
     * factorisation instead of a new n x n one. The solution is checked by
     * its residual (normwise backward error), with up to two steps of
     * iterative refinement; the condition estimate of the new matrix, in its
     * own scaling S', is LAPACK's 1-norm estimator (dlacn2, the one dgecon
     * uses) applied to (S' A' S')^{-1} through the same formula. The matrix
     * is factorised afresh instead when k exceeds max_changed_fraction n,
     * when the backward error stays above its tolerance, when the
     * capacitance matrix I_k + D' Z is singular, or when the estimate (or
     * that of the factorised matrix) falls below min_reused_condition: a
     * system near singularity is judged on a fresh factorisation, exactly
     * as without reuse. That judgement: singular to working precision
     * (dgecon's estimate at most the unit round-off, or a zero pivot), or
     * a solution that iterative refinement (three steps) cannot bring to the
     * backward error tolerance; a system that is merely ill-conditioned is
     * solved. MixedSystem hands it dimensionless matrices, so that none of
     * these verdicts depends on units; whether the system is singular for a
     * mechanical reason is decided before, on the rigid modes
     * (RigidModeTest).
     *
     * (GMRES right-preconditioned by the old factors, for many rows changed
     * by little as 3D slip rows are, was tried and measured slower than a
     * fresh factorisation on the rock wedge, n = 573: about 21 iterations
     * per solve with the condition estimate; see the branch history.)
     */
    class ReusableLU
    {
    public:
      /** When to factorise afresh instead of reusing the factors. */
      struct Control
      {
        /**
         * Largest number of changed rows solved with the old factors, as a
         * fraction of n. The update costs about 2 k n^2 + k^2 n flops plus
         * the condition estimate, a factorisation 2/3 n^3 with faster
         * (blocked) kernels: measured with OpenBLAS for n = 285 to 936, a
         * reused solve took 5-50 % of a fresh one for k < 0.05 n and as
         * long near k = 0.12-0.15 n.
         */
        double max_changed_fraction = 0.1;
        /**
         * Largest normwise backward error accepted from any solve, after
         * iterative refinement (up to two steps for a reused solve, three
         * for the factorised matrix itself).
         */
        double backward_error_tolerance = 1e-14;
        /**
         * Below this reciprocal condition estimate a reused solve is
         * replaced by a fresh factorisation, so that an ill-conditioned
         * system is always solved from its own factors: two estimates by the
         * same estimator (dlacn2) of the same number differ by far less than
         * the factor left here. (The rock wedge's systems have rcond ~ 1e-10.)
         */
        double min_reused_condition = 1e-12;
        /** False: factorise every matrix (the behaviour without reuse). */
        bool reuse = true;
      };

      /** The outcome of one solve. */
      struct Result
      {
        /** Reciprocal condition estimate (1-norm) of S A S. */
        double reciprocal_condition = 1;
        /**
         * False if A is singular to working precision (reciprocal condition
         * at most the unit round-off, or a zero pivot) or if no solution
         * reached the backward error tolerance after refinement.
         */
        bool solved = true;
        /** True if A was factorised for this solve. */
        bool factorized = true;
        /** Rows of A that differ from the factorised matrix. */
        unsigned int n_changed_rows = 0;
        /** Normwise backward error of a reused solve (0 if factorised). */
        double backward_error = 0;
        /** Why the matrix was factorised (for the log); empty if reused. */
        const char *why_factorized = "";
        /** How the old factors were reused: "Woodbury", "same matrix", or none.
         */
        const char *method = nullptr;
      };

      ReusableLU() = default;
      explicit ReusableLU(const Control &control)
        : control(control)
      {}

      /**
       * Solves @p matrix x = @p rhs; @p rhs is overwritten with x if the
       * result says solved (and left as it is otherwise).
       */
      Result
      solve(const dealii::FullMatrix<double> &matrix,
            dealii::Vector<double>           &rhs);

      /**
       * Solves @p matrix x = @p rhs from a factorisation of its own, with the
       * same scaling, refinement and verdict as a fresh factorisation in
       * solve(), but neither stores it nor drops the stored factors (of
       * another matrix) that later solves may reuse. For a matrix that will
       * not be seen again: DenseMixedSolver's condensed systems. Counted in
       * n_factorizations.
       */
      Result
      solve_once(const dealii::FullMatrix<double> &matrix,
                 dealii::Vector<double>           &rhs);

      /** Drops the stored factors: the next solve factorises. */
      void
      clear();

      /** Matrices factorised so far. */
      unsigned int n_factorizations = 0;
      /** Solves that reused the factors of an earlier matrix. */
      unsigned int n_reused_solves = 0;

      Control control;

    private:
      /** Factorises @p matrix (scaled by @p scale), stores it, and solves. */
      Result
      factorize_and_solve(const dealii::FullMatrix<double> &matrix,
                          std::vector<double>               scale,
                          dealii::Vector<double>           &rhs);

      /**
       * Solves @p matrix (scaled by @p scale, factorised as @p factors) with
       * those factors and iterative refinement; false if the backward error
       * stays above its tolerance.
       */
      bool
      solve_factorized(const dealii::FullMatrix<double> &matrix,
                       const std::vector<double>        &scale,
                       const DenseLU                    &factors,
                       dealii::Vector<double>           &rhs,
                       Result                           &result) const;

      /** Solves with the stored factors updated by k changed rows; false if not
       * accurate. */
      bool
      solve_updated(const dealii::FullMatrix<double> &matrix,
                    const std::vector<double>        &scale,
                    const std::vector<unsigned int>  &changed,
                    dealii::Vector<double>           &rhs,
                    Result                           &result) const;

      /** The factorised matrix, unscaled, its scaling, and its factors. */
      dealii::FullMatrix<double> factorized_matrix;
      std::vector<double>        factorized_scale;
      std::unique_ptr<DenseLU>   lu;
      /** The verdict of the factorisation: its condition estimate and solved
       * flag. */
      double factorized_condition = 0;
      bool   factorized_solved    = false;
    };
  } // namespace linear_algebra
} // namespace fdem
