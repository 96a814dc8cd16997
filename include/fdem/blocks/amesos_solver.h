// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/block_factorization.h>

#include <memory>
#include <string>
#include <vector>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace fdem
{
  namespace blocks
  {
    using namespace dealii;

    /**
     * Solver/Direct solver = Amesos_Klu or Amesos_Mumps: a Trilinos Amesos
     * solver (LU) on the distributed Epetra matrix (Amesos_Klu gathers it on
     * one rank, Amesos_Mumps factorises in parallel). Each rank gives the
     * entries of its rows and the solution is summed into a global-size
     * array on all.
     */
    class AmesosSolver : public BlockFactorization
    {
    public:
      /** @p class_name: an Amesos class, "Amesos_Klu" or "Amesos_Mumps". */
      explicit AmesosSolver(const std::string &class_name);
      ~AmesosSolver() override;

      void
      factorize(
        const TrilinosWrappers::SparseMatrix       &matrix,
        const std::vector<types::global_dof_index> &schur_dofs) override;

      using BlockFactorization::solve;
      void
      solve(std::vector<double> &b, const unsigned int n_rhs) const override;

    private:
      const std::string                     class_name;
      const TrilinosWrappers::SparseMatrix *matrix = nullptr;
      std::unique_ptr<Epetra_LinearProblem> problem;
      std::unique_ptr<Amesos_BaseSolver>    solver;
    };
  } // namespace blocks
} // namespace fdem
