// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/blocks/crs_rows.h>
#include <fdem/blocks/umfpack_solver.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>

namespace fdem
{
  namespace blocks
  {
    void
    UmfpackSolver::factorize(
      const TrilinosWrappers::SparseMatrix       &A,
      const std::vector<types::global_dof_index> &schur_dofs)
    {
      Assert(schur_dofs.empty(),
             ExcMessage("UMFPACK keeps no Schur complement."));
      (void)schur_dofs;
      assert_one_rank(A, parameters::DirectSolverType::umfpack);
      const Epetra_CrsMatrix &crs = A.trilinos_matrix();
      DynamicSparsityPattern  dsp(crs.NumMyRows());
      for (int row = 0; row < crs.NumMyRows(); ++row)
        for_each_entry_in_row(crs, row, [&](const int column, double) {
          dsp.add(row, column);
        });
      matrix.clear();
      pattern.copy_from(dsp);
      matrix.reinit(pattern);
      for (int row = 0; row < crs.NumMyRows(); ++row)
        for_each_entry_in_row(crs,
                              row,
                              [&](const int column, const double value) {
                                matrix.set(row, column, value);
                              });
      umfpack.factorize(matrix);
    }

    void
    UmfpackSolver::solve(std::vector<double> &b, const unsigned int n_rhs) const
    {
      const std::size_t n = matrix.m();
      Vector<double>    column(n);
      for (unsigned int c = 0; c < n_rhs; ++c)
        {
          std::copy(b.begin() + c * n, b.begin() + (c + 1) * n, column.begin());
          umfpack.solve(column);
          std::copy(column.begin(), column.end(), b.begin() + c * n);
        }
    }
  } // namespace blocks
} // namespace fdem
