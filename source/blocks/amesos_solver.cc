// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/blocks/amesos_solver.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

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
    AmesosSolver::AmesosSolver(const std::string &class_name)
      : class_name(class_name)
    {}

    AmesosSolver::~AmesosSolver() = default;

    void
    AmesosSolver::factorize(
      const TrilinosWrappers::SparseMatrix       &A,
      const std::vector<types::global_dof_index> &schur_dofs)
    {
      Assert(schur_dofs.empty(),
             ExcMessage("Amesos keeps no Schur complement."));
      (void)schur_dofs;
      matrix = &A;
      solver.reset();
      problem = std::make_unique<Epetra_LinearProblem>(
        const_cast<Epetra_CrsMatrix *>(&A.trilinos_matrix()), nullptr, nullptr);
      Amesos factory;
      AssertThrow(factory.Query(class_name),
                  ExcMessage("Solver/Direct solver: '" + class_name +
                             "' is not available in this Trilinos build."));
      solver.reset(factory.Create(class_name, *problem));
      AssertThrow(solver->SymbolicFactorization() == 0,
                  ExcMessage("The symbolic factorisation of a block "
                             "stiffness matrix failed."));
      AssertThrow(solver->NumericFactorization() == 0,
                  ExcMessage("The factorisation of a block stiffness matrix "
                             "failed: the block is not held (check its "
                             "constraints)."));
    }

    void
    AmesosSolver::solve(std::vector<double> &b, const unsigned int n_rhs) const
    {
      Assert(solver != nullptr, ExcMessage("factorize() first."));
      const Epetra_Map  &map     = matrix->trilinos_matrix().DomainMap();
      const std::size_t  n       = matrix->m();
      const int          n_local = map.NumMyElements();
      Epetra_MultiVector rhs(map, n_rhs), x(map, n_rhs);
      for (unsigned int c = 0; c < n_rhs; ++c)
        for (int i = 0; i < n_local; ++i)
          rhs[c][i] = b[map.GID(i) + c * n];
      problem->SetLHS(&x);
      problem->SetRHS(&rhs);
      AssertThrow(solver->Solve() == 0,
                  ExcMessage("A direct solve with a factorised block "
                             "stiffness matrix failed."));
      const MPI_Comm comm = matrix->get_mpi_communicator();
      if (Utilities::MPI::n_mpi_processes(comm) > 1)
        std::fill(b.begin(), b.end(), 0.0);
      for (unsigned int c = 0; c < n_rhs; ++c)
        for (int i = 0; i < n_local; ++i)
          b[map.GID(i) + c * n] = x[c][i];
      // Each entry comes from the one rank that owns it: the sum is exact.
      if (Utilities::MPI::n_mpi_processes(comm) > 1)
        Utilities::MPI::sum(ArrayView<const double>(b),
                            comm,
                            ArrayView<double>(b));
    }
  } // namespace blocks
} // namespace fdem
