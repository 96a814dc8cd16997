// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/block_factorization.h>

#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <vector>

namespace fdem
{
  namespace blocks
  {
    using namespace dealii;

    /**
     * Solver/Direct solver = UMFPACK: deal.II's SparseDirectUMFPACK (LU),
     * one right-hand side at a time. Serial: more than one MPI rank is an
     * error.
     */
    class UmfpackSolver : public BlockFactorization
    {
    public:
      void
      factorize(
        const TrilinosWrappers::SparseMatrix       &matrix,
        const std::vector<types::global_dof_index> &schur_dofs) override;

      using BlockFactorization::solve;
      void
      solve(std::vector<double> &b, const unsigned int n_rhs) const override;

    private:
      /**
       * A copy of the matrix in deal.II's own format: deal.II 9.4's
       * SparseDirectUMFPACK is instantiated for its own sparse matrices only.
       */
      SparsityPattern      pattern;
      SparseMatrix<double> matrix;
      SparseDirectUMFPACK  umfpack;
    };
  } // namespace blocks
} // namespace fdem
