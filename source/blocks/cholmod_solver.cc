// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/blocks/cholmod_solver.h>
#include <fdem/blocks/crs_rows.h>

#include <deal.II/base/exceptions.h>

#include <Epetra_CrsMatrix.h>
#include <cholmod.h>

#include <algorithm>
#include <string>

namespace fdem
{
  namespace blocks
  {
    struct CholmodSolver::Data
    {
      cholmod_common  common;
      cholmod_factor *factor = nullptr;

      Data()
      {
        cholmod_l_start(&common);
      }

      ~Data()
      {
        if (factor != nullptr)
          cholmod_l_free_factor(&factor, &common);
        cholmod_l_finish(&common);
      }

      Data(const Data &) = delete;
      Data &
      operator=(const Data &) = delete;
    };

    CholmodSolver::CholmodSolver()
      : data(std::make_unique<Data>())
    {}

    CholmodSolver::~CholmodSolver() = default;

    void
    CholmodSolver::factorize(
      const TrilinosWrappers::SparseMatrix       &matrix,
      const std::vector<types::global_dof_index> &schur_dofs)
    {
      Assert(schur_dofs.empty(),
             ExcMessage("CHOLMOD keeps no Schur complement."));
      (void)schur_dofs;
      assert_one_rank(matrix, parameters::DirectSolverType::cholmod);
      data                           = std::make_unique<Data>();
      cholmod_common         &common = data->common;
      const Epetra_CrsMatrix &crs    = matrix.trilinos_matrix();
      n                              = matrix.m();
      const SuiteSparse_long n_rows  = crs.NumMyRows();
      // Column j of the upper triangle is row j's entries left of and on
      // the diagonal (the matrix is symmetric).
      std::vector<SuiteSparse_long> column_start(n_rows + 1, 0);
      for (SuiteSparse_long j = 0; j < n_rows; ++j)
        {
          column_start[j + 1] = column_start[j];
          for_each_entry_in_row(crs, j, [&](const int i, double) {
            if (i <= j)
              ++column_start[j + 1];
          });
        }
      cholmod_sparse *A = cholmod_l_allocate_sparse(n_rows,
                                                    n_rows,
                                                    column_start[n_rows],
                                                    /*sorted=*/0,
                                                    /*packed=*/1,
                                                    /*stype=*/1,
                                                    CHOLMOD_REAL,
                                                    &common);
      AssertThrow(A != nullptr,
                  ExcMessage(
                    "CHOLMOD could not allocate a block stiffness matrix."));
      auto *p = static_cast<SuiteSparse_long *>(A->p);
      auto *i = static_cast<SuiteSparse_long *>(A->i);
      auto *x = static_cast<double *>(A->x);
      std::copy(column_start.begin(), column_start.end(), p);
      for (SuiteSparse_long j = 0; j < n_rows; ++j)
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
      data->factor = cholmod_l_analyze(A, &common);
      const bool analysed =
        data->factor != nullptr && common.status == CHOLMOD_OK;
      const bool factorised =
        analysed && cholmod_l_factorize(A, data->factor, &common) != 0 &&
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

    void
    CholmodSolver::solve(std::vector<double> &b, const unsigned int n_rhs) const
    {
      Assert(data->factor != nullptr, ExcMessage("factorize() first."));
      cholmod_dense rhs;
      rhs.nrow  = n;
      rhs.ncol  = n_rhs;
      rhs.nzmax = n * n_rhs;
      rhs.d     = n;
      rhs.x     = b.data();
      rhs.z     = nullptr;
      rhs.xtype = CHOLMOD_REAL;
      rhs.dtype = CHOLMOD_DOUBLE;
      cholmod_dense *x =
        cholmod_l_solve(CHOLMOD_A, data->factor, &rhs, &data->common);
      AssertThrow(x != nullptr,
                  ExcMessage("A direct solve with a factorised block "
                             "stiffness matrix failed (CHOLMOD status " +
                             std::to_string(data->common.status) + ")."));
      const double *values = static_cast<const double *>(x->x);
      std::copy(values, values + n * n_rhs, b.begin());
      cholmod_l_free_dense(&x, &data->common);
    }
  } // namespace blocks
} // namespace fdem
