// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/blocks/direct_solver.h>

#include <fdem/blocks/crs_rows.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>

#include <algorithm>

namespace fdem
{
  namespace blocks
  {
    DirectSolver::DirectSolver(const std::string &solver_type)
      : solver_type(solver_type)
    {}

    DirectSolver::~DirectSolver() = default;

    void
    DirectSolver::factorize(const TrilinosWrappers::SparseMatrix &A)
    {
      matrix = &A;
      if (solver_type == "UMFPACK")
        {
          AssertThrow(Utilities::MPI::n_mpi_processes(A.get_mpi_communicator()) == 1,
                      ExcMessage("Solver/Direct solver: UMFPACK runs on one MPI "
                                 "rank only; with mpirun use MUMPS_Schur, MUMPS, "
                                 "Amesos_Mumps or Amesos_Klu."));
          const Epetra_CrsMatrix &crs = A.trilinos_matrix();
          DynamicSparsityPattern  dsp(crs.NumMyRows());
          for (int row = 0; row < crs.NumMyRows(); ++row)
            for_each_entry_in_row(crs, row, [&](const int column, double) {
              dsp.add(row, column);
            });
          umfpack_pattern.copy_from(dsp);
          umfpack_matrix.reinit(umfpack_pattern);
          for (int row = 0; row < crs.NumMyRows(); ++row)
            for_each_entry_in_row(crs, row, [&](const int column, const double value) {
              umfpack_matrix.set(row, column, value);
            });
          umfpack = std::make_unique<SparseDirectUMFPACK>();
          umfpack->factorize(umfpack_matrix);
          return;
        }
      problem =
        std::make_unique<Epetra_LinearProblem>(const_cast<Epetra_CrsMatrix *>(
                                                 &A.trilinos_matrix()),
                                               nullptr,
                                               nullptr);
      Amesos factory;
      AssertThrow(factory.Query(solver_type),
                  ExcMessage("Solver/Direct solver: '" + solver_type +
                             "' is not available in this Trilinos build."));
      solver.reset(factory.Create(solver_type, *problem));
      AssertThrow(solver->SymbolicFactorization() == 0,
                  ExcMessage("The symbolic factorisation of a block "
                             "stiffness matrix failed."));
      AssertThrow(solver->NumericFactorization() == 0,
                  ExcMessage("The factorisation of a block stiffness matrix "
                             "failed: the block is not held (check its "
                             "constraints)."));
    }

    void
    DirectSolver::solve(Epetra_MultiVector &x, Epetra_MultiVector &b) const
    {
      if (umfpack)
        {
          Vector<double> column(x.MyLength());
          for (int c = 0; c < b.NumVectors(); ++c)
            {
              for (unsigned int i = 0; i < column.size(); ++i)
                column[i] = b[c][i];
              umfpack->solve(column);
              for (unsigned int i = 0; i < column.size(); ++i)
                x[c][i] = column[i];
            }
          return;
        }
      Assert(solver != nullptr, ExcMessage("factorize() first."));
      problem->SetLHS(&x);
      problem->SetRHS(&b);
      AssertThrow(solver->Solve() == 0,
                  ExcMessage("A direct solve with a factorised block "
                             "stiffness matrix failed."));
    }

    void
    DirectSolver::solve(std::vector<double> &b, const unsigned int n_rhs) const
    {
      const Epetra_Map & map     = matrix->trilinos_matrix().DomainMap();
      const std::size_t  n       = matrix->m();
      const int          n_local = map.NumMyElements();
      Epetra_MultiVector rhs(map, n_rhs), x(map, n_rhs);
      for (unsigned int c = 0; c < n_rhs; ++c)
        for (int i = 0; i < n_local; ++i)
          rhs[c][i] = b[map.GID(i) + c * n];
      solve(x, rhs);
      const MPI_Comm comm = matrix->get_mpi_communicator();
      if (Utilities::MPI::n_mpi_processes(comm) > 1)
        std::fill(b.begin(), b.end(), 0.0);
      for (unsigned int c = 0; c < n_rhs; ++c)
        for (int i = 0; i < n_local; ++i)
          b[map.GID(i) + c * n] = x[c][i];
      // Each entry comes from the one rank that owns it: the sum is exact.
      if (Utilities::MPI::n_mpi_processes(comm) > 1)
        Utilities::MPI::sum(ArrayView<const double>(b), comm, ArrayView<double>(b));
    }

    Vector<double>
    DirectSolver::solve(const Vector<double> &b) const
    {
      std::vector<double> x(b.begin(), b.end());
      solve(x, 1);
      return Vector<double>(x.begin(), x.end());
    }
  } // namespace blocks
} // namespace fdem
