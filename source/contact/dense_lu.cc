// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/contact/dense_lu.h>

#include <deal.II/base/exceptions.h>

#include <cmath>

extern "C"
{
  void
  dgetrf_(const int *m, const int *n, double *a, const int *lda, int *ipiv, int *info);
  void
  dgetrs_(const char *trans, const int *n, const int *nrhs, const double *a,
          const int *lda, const int *ipiv, double *b, const int *ldb, int *info);
  void
  dgecon_(const char *norm, const int *n, const double *a, const int *lda,
          const double *anorm, double *rcond, double *work, int *iwork, int *info);
}

namespace fdem
{
  namespace contact
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
      Assert(lu.size() == static_cast<std::size_t>(n) * n, dealii::ExcInternalError());
      if (n == 0)
        {
          rcond = 1;
          return;
        }
      double norm = 0; // 1-norm: largest column sum
      for (int j = 0; j < n; ++j)
        {
          double column = 0;
          for (int i = 0; i < n; ++i)
            column += std::abs(lu[j * n + i]);
          norm = std::max(norm, column);
        }
      dgetrf_(&n, &n, lu.data(), &n, pivots.data(), &info);
      if (info != 0 || !std::isfinite(norm))
        {
          info  = info != 0 ? info : -1;
          rcond = 0;
          return;
        }
      std::vector<double> work(4 * n);
      std::vector<int>    iwork(n);
      int                 condition_info = 0;
      const char          one            = '1';
      dgecon_(&one, &n, lu.data(), &n, &norm, &rcond, work.data(), iwork.data(), &condition_info);
      if (condition_info != 0)
        rcond = 0;
    }

    void
    DenseLU::solve(dealii::Vector<double> &b) const
    {
      Assert(factorized(), dealii::ExcInternalError());
      if (n == 0)
        return;
      const char no_transpose = 'N';
      const int  one          = 1;
      int        solve_info   = 0;
      dgetrs_(&no_transpose, &n, &one, lu.data(), &n, pivots.data(), b.data(), &n, &solve_info);
      AssertThrow(solve_info == 0, dealii::ExcInternalError());
    }

    void
    DenseLU::solve(double *columns, const unsigned int n_rhs, const bool transpose) const
    {
      Assert(factorized(), dealii::ExcInternalError());
      if (n == 0 || n_rhs == 0)
        return;
      const char trans      = transpose ? 'T' : 'N';
      const int  nrhs       = n_rhs;
      int        solve_info = 0;
      dgetrs_(&trans, &n, &nrhs, lu.data(), &n, pivots.data(), columns, &n, &solve_info);
      AssertThrow(solve_info == 0, dealii::ExcInternalError());
    }
  } // namespace contact
} // namespace fdem
