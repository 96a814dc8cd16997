// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>
#include <string>

class Amesos_BaseSolver;
class Epetra_LinearProblem;
class Epetra_MultiVector;

namespace fdem
{
  namespace blocks
  {
    using namespace dealii;

    /**
     * A sparse direct solver from Trilinos Amesos, UMFPACK through deal.II's
     * SparseDirectUMFPACK (on a copy of the matrix), or SuiteSparse's
     * CHOLMOD (supernodal Cholesky of the upper triangle, through its C
     * interface), that
     * factorises a matrix once and then solves for any number of
     * right-hand sides, one or many at a time. The FE part of the method is
     * linear, so each block's stiffness is factorised exactly once per run.
     *
     * MPI: Amesos works on the matrix's distribution (Amesos_Klu gathers it
     * on one rank, Amesos_Mumps factorises in parallel). Right-hand sides and
     * solutions here are global-size arrays, the same on every rank; each
     * rank gives the entries of its rows and the solution is gathered on
     * all. UMFPACK and CHOLMOD are serial: with more than one rank they are
     * an error. Every
     * call is collective.
     */
    class DirectSolver
    {
    public:
      /**
       * @p solver_type is an Amesos class name, e.g. "Amesos_Klu", "UMFPACK"
       * or "CHOLMOD".
       */
      explicit DirectSolver(const std::string &solver_type);
      ~DirectSolver();

      /** Symbolic and numeric factorisation of @p matrix (kept by reference). */
      void
      factorize(const TrilinosWrappers::SparseMatrix &matrix);

      /**
       * Solves A x = b for the @p n_rhs columns of @p b at once (n x n_rhs,
       * column-major, global size; overwritten with x).
       */
      void
      solve(std::vector<double> &b, const unsigned int n_rhs) const;

      /** Solves A x = b for one right-hand side. */
      Vector<double>
      solve(const Vector<double> &b) const;

    private:
      /** Solves A x = b for all columns of @p b at once (distributed). */
      void
      solve(Epetra_MultiVector &x, Epetra_MultiVector &b) const;

      const std::string                     solver_type;
      const TrilinosWrappers::SparseMatrix *matrix = nullptr;
      std::unique_ptr<Epetra_LinearProblem> problem;
      std::unique_ptr<Amesos_BaseSolver>    solver;
      /** UMFPACK: deal.II's copy of the matrix and its factorisation. */
      SparsityPattern                       umfpack_pattern;
      SparseMatrix<double>                  umfpack_matrix;
      std::unique_ptr<SparseDirectUMFPACK>  umfpack;
      /** CHOLMOD: its workspace and the factor (defined in the source). */
      struct Cholmod;
      std::unique_ptr<Cholmod> cholmod;
    };
  } // namespace blocks
} // namespace fdem
