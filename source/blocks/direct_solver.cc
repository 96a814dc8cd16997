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
#include <cholmod.h>

#include <algorithm>

namespace fdem
{
  namespace blocks
  {
    /**
     * CHOLMOD's workspace and factor (the long-index interface, so that no
     * count of entries can overflow). It factorises the upper triangle: the
     * block stiffness is symmetric and, with its constraints, positive
     * definite, as MUMPS (sym = 1) assumes too.
     */
    struct DirectSolver::Cholmod
    {
      cholmod_common  common;
      cholmod_factor *factor = nullptr;

      Cholmod()
      {
        cholmod_l_start(&common);
      }

      ~Cholmod()
      {
        if (factor != nullptr)
          cholmod_l_free_factor(&factor, &common);
        cholmod_l_finish(&common);
      }

      Cholmod(const Cholmod &) = delete;
      Cholmod &
      operator=(const Cholmod &) = delete;

      void
      factorize(const Epetra_CrsMatrix &crs)
      {
        const SuiteSparse_long n = crs.NumMyRows();
        // Column j of the upper triangle is row j's entries left of and on
        // the diagonal (the matrix is symmetric).
        std::vector<SuiteSparse_long> column_start(n + 1, 0);
        for (SuiteSparse_long j = 0; j < n; ++j)
          {
            column_start[j + 1] = column_start[j];
            for_each_entry_in_row(crs, j, [&](const int i, double) {
              if (i <= j)
                ++column_start[j + 1];
            });
          }
        cholmod_sparse *A = cholmod_l_allocate_sparse(
          n, n, column_start[n], /*sorted=*/0, /*packed=*/1, /*stype=*/1, CHOLMOD_REAL, &common);
        AssertThrow(A != nullptr,
                    ExcMessage("CHOLMOD could not allocate a block stiffness matrix."));
        auto *p = static_cast<SuiteSparse_long *>(A->p);
        auto *i = static_cast<SuiteSparse_long *>(A->i);
        auto *x = static_cast<double *>(A->x);
        std::copy(column_start.begin(), column_start.end(), p);
        for (SuiteSparse_long j = 0; j < n; ++j)
          {
            SuiteSparse_long k = column_start[j];
            for_each_entry_in_row(crs, j, [&](const int row, const double value) {
              if (row <= j)
                {
                  i[k] = row;
                  x[k] = value;
                  ++k;
                }
            });
          }
        factor = cholmod_l_analyze(A, &common);
        const bool analysed = factor != nullptr && common.status == CHOLMOD_OK;
        const bool factorised = analysed && cholmod_l_factorize(A, factor, &common) != 0 &&
                                common.status == CHOLMOD_OK;
        cholmod_l_free_sparse(&A, &common);
        AssertThrow(analysed,
                    ExcMessage("The symbolic factorisation of a block stiffness "
                               "matrix failed (CHOLMOD status " +
                               std::to_string(common.status) + ")."));
        AssertThrow(factorised,
                    ExcMessage("The factorisation of a block stiffness matrix "
                               "failed: the block is not held (check its "
                               "constraints); CHOLMOD status " +
                               std::to_string(common.status) + "."));
      }

      /** Solves for the @p n_rhs columns of @p b (n x n_rhs, column-major). */
      void
      solve(std::vector<double> &b, const std::size_t n, const unsigned int n_rhs)
      {
        cholmod_dense rhs;
        rhs.nrow  = n;
        rhs.ncol  = n_rhs;
        rhs.nzmax = n * n_rhs;
        rhs.d     = n;
        rhs.x     = b.data();
        rhs.z     = nullptr;
        rhs.xtype = CHOLMOD_REAL;
        rhs.dtype = CHOLMOD_DOUBLE;
        cholmod_dense *x = cholmod_l_solve(CHOLMOD_A, factor, &rhs, &common);
        AssertThrow(x != nullptr,
                    ExcMessage("A direct solve with a factorised block "
                               "stiffness matrix failed (CHOLMOD status " +
                               std::to_string(common.status) + ")."));
        const double *values = static_cast<const double *>(x->x);
        std::copy(values, values + n * n_rhs, b.begin());
        cholmod_l_free_dense(&x, &common);
      }
    };

    DirectSolver::DirectSolver(const std::string &solver_type)
      : solver_type(solver_type)
    {}

    DirectSolver::~DirectSolver() = default;

    void
    DirectSolver::factorize(const TrilinosWrappers::SparseMatrix &A)
    {
      matrix = &A;
      if (solver_type == "UMFPACK" || solver_type == "CHOLMOD")
        AssertThrow(Utilities::MPI::n_mpi_processes(A.get_mpi_communicator()) == 1,
                    ExcMessage("Solver/Direct solver: " + solver_type +
                               " runs on one MPI rank only; with mpirun use "
                               "MUMPS_Schur, MUMPS, Amesos_Mumps or Amesos_Klu."));
      if (solver_type == "CHOLMOD")
        {
          cholmod = std::make_unique<Cholmod>();
          cholmod->factorize(A.trilinos_matrix());
          return;
        }
      if (solver_type == "UMFPACK")
        {
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
      if (cholmod)
        {
          cholmod->solve(b, matrix->m(), n_rhs);
          return;
        }
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
