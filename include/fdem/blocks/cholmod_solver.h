// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/block_factorization.h>

#include <memory>
#include <vector>

namespace fdem
{
  namespace blocks
  {
    using namespace dealii;

    /**
     * Solver/Direct solver = CHOLMOD: SuiteSparse's supernodal Cholesky of
     * the upper triangle, through its C interface (the long-index one, so
     * that no count of entries can overflow). The block stiffness is
     * symmetric and, with its constraints, positive definite. Serial: more
     * than one MPI rank is an error.
     */
    class CholmodSolver : public BlockFactorization
    {
    public:
      CholmodSolver();
      ~CholmodSolver() override;
      CholmodSolver(const CholmodSolver &) = delete;
      CholmodSolver &
      operator=(const CholmodSolver &) = delete;

      void
      factorize(
        const TrilinosWrappers::SparseMatrix       &matrix,
        const std::vector<types::global_dof_index> &schur_dofs) override;

      using BlockFactorization::solve;
      void
      solve(std::vector<double> &b, const unsigned int n_rhs) const override;

    private:
      /** CHOLMOD's workspace and the factor (defined in the source). */
      struct Data;
      std::unique_ptr<Data> data;
      std::size_t           n = 0;
    };
  } // namespace blocks
} // namespace fdem
