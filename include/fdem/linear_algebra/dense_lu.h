// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_support.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace fdem
{
  /** Dense linear algebra that is not specific to the method. */
  namespace linear_algebra
  {
    /**
     * Dense LU factorisation with partial pivoting (LAPACK getrf) of a
     * square matrix, with an estimate of its reciprocal condition number in
     * the 1-norm (LAPACK gecon). The mixed system is small and dense, and
     * whether it is singular (no static equilibrium) is part of the answer.
     *
     * Not LAPACKFullMatrix: in deal.II 9.4 its compute_lu_factorization()
     * throws on a zero pivot (here a verdict, not an error), its condition
     * estimate needs a Cholesky factor, and it solves only its own types
     * (ReusableLU solves raw columns). The LAPACK calls are deal.II's
     * (lapack_templates.h), but for gecon, which that header lacks.
     */
    class DenseLU
    {
    public:
      /** @p column_major holds the n x n matrix by columns; it is overwritten.
       */
      DenseLU(const unsigned int n, std::vector<double> column_major);

      /** Factorises a copy of the square @p matrix. */
      explicit DenseLU(const dealii::FullMatrix<double> &matrix);

      /** False if a pivot was exactly zero. */
      bool
      factorized() const
      {
        return info == 0;
      }

      /** 1 / (||A||_1 ||A^{-1}||_1), estimated; 0 if singular. */
      double
      reciprocal_condition_number() const
      {
        return rcond;
      }

      /** Solves A x = b in place. */
      void
      solve(dealii::Vector<double> &b) const;

      /**
       * Solves A X = B (or A^T X = B if @p transpose) in place for the
       * @p n_rhs columns of @p columns, stored by columns (n x n_rhs).
       */
      void
      solve(double            *columns,
            const unsigned int n_rhs,
            const bool         transpose = false) const;

      /** Size n of the matrix. */
      unsigned int
      size() const
      {
        return n;
      }

    private:
      dealii::types::blas_int              n;
      std::vector<double>                  lu;
      std::vector<dealii::types::blas_int> pivots;
      dealii::types::blas_int              info  = 0;
      double                               rcond = 0;
    };
  } // namespace linear_algebra
} // namespace fdem
