// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/linear_algebra/dense_lu.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_templates.h>

#include <cmath>

// Hand-declared: deal.II 9.4's lapack_templates.h has no gecon.
extern "C" void
dgecon_(const char                    *norm,
        const dealii::types::blas_int *n,
        const double                  *a,
        const dealii::types::blas_int *lda,
        const double                  *anorm,
        double                        *rcond,
        double                        *work,
        dealii::types::blas_int       *iwork,
        dealii::types::blas_int       *info);

namespace fdem
{
  namespace linear_algebra
  {
    namespace
    {
      std::vector<double>
      by_columns(const dealii::FullMatrix<double> &matrix)
      {
        Assert(matrix.m() == matrix.n(), dealii::ExcInternalError());
        std::vector<double> columns(std::size_t(matrix.m()) * matrix.n());
        for (unsigned int c = 0; c < matrix.n(); ++c)
          for (unsigned int r = 0; r < matrix.m(); ++r)
            columns[r + std::size_t(c) * matrix.m()] = matrix(r, c);
        return columns;
      }
    } // namespace

    DenseLU::DenseLU(const dealii::FullMatrix<double> &matrix)
      : DenseLU(matrix.m(), by_columns(matrix))
    {}

    DenseLU::DenseLU(const unsigned int size, std::vector<double> column_major)
      : n(size)
      , lu(std::move(column_major))
      , pivots(size)
    {
      Assert(lu.size() == static_cast<std::size_t>(n) * n,
             dealii::ExcInternalError());
      if (n == 0)
        {
          rcond = 1;
          return;
        }
      // The 1-norm (largest column sum), which gecon needs of the matrix
      // before its factorisation: LAPACK's dlange("1") written out, the
      // same sums in the same order (a NaN sum is the norm), without the
      // call (the reference dlange was 1 % of a probabilistic run).
      double norm = 0;
      for (dealii::types::blas_int j = 0; j < n; ++j)
        {
          const double *column = lu.data() + static_cast<std::size_t>(j) * n;
          double        sum    = 0;
          for (dealii::types::blas_int i = 0; i < n; ++i)
            sum += std::abs(column[i]);
          if (norm < sum || std::isnan(sum))
            norm = sum;
        }
      dealii::getrf(&n, &n, lu.data(), &n, pivots.data(), &info);
      if (info != 0 || !std::isfinite(norm))
        {
          info  = info != 0 ? info : -1;
          rcond = 0;
          return;
        }
      std::vector<double>                  work(4 * n);
      std::vector<dealii::types::blas_int> iwork(n);
      dealii::types::blas_int              condition_info = 0;
      dgecon_("1",
              &n,
              lu.data(),
              &n,
              &norm,
              &rcond,
              work.data(),
              iwork.data(),
              &condition_info);
      if (condition_info != 0)
        rcond = 0;
    }

    void
    DenseLU::solve(dealii::Vector<double> &b) const
    {
      Assert(b.size() == static_cast<std::size_t>(n),
             dealii::ExcInternalError());
      solve(b.data(), 1);
    }

    void
    DenseLU::solve(double            *columns,
                   const unsigned int n_rhs,
                   const bool         transpose) const
    {
      Assert(factorized(), dealii::ExcInternalError());
      if (n == 0 || n_rhs == 0)
        return;
      const dealii::types::blas_int nrhs       = n_rhs;
      dealii::types::blas_int       solve_info = 0;
      dealii::getrs(transpose ? "T" : "N",
                    &n,
                    &nrhs,
                    lu.data(),
                    &n,
                    pivots.data(),
                    columns,
                    &n,
                    &solve_info);
      AssertThrow(solve_info == 0, dealii::ExcInternalError());
    }
  } // namespace linear_algebra
} // namespace fdem
