// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/blocks/mumps_schur_solver.h>

#include <fdem/blocks/crs_rows.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_templates.h>

#include <Epetra_CrsMatrix.h>
#include <dmumps_c.h>
#include <mpi.h>

#include <string>

namespace fdem
{
  namespace blocks
  {
    namespace
    {
      // MUMPS's ICNTL(i) and INFOG(i) with the 1-based numbers of its guide.
      MUMPS_INT &
      icntl(DMUMPS_STRUC_C &id, const int i)
      {
        return id.icntl[i - 1];
      }
    } // namespace

    struct MumpsSchurSolver::Data
    {
      DMUMPS_STRUC_C         id{};
      std::vector<MUMPS_INT> rows, columns, schur_list;
      std::vector<double>    values, schur;
      bool                   initialized = false;
    };

    MumpsSchurSolver::MumpsSchurSolver()
      : data(std::make_unique<Data>())
    {}

    MumpsSchurSolver::~MumpsSchurSolver()
    {
      if (data->initialized)
        {
          data->id.job = -2;
          dmumps_c(&data->id);
        }
    }

    void
    MumpsSchurSolver::run(const int job, const char *what) const
    {
      DMUMPS_STRUC_C &id = data->id;
      id.job             = job;
      dmumps_c(&id);
      AssertThrow(id.infog[0] >= 0,
                  ExcMessage(std::string("MUMPS failed in the ") + what +
                             " of a block stiffness matrix (INFOG(1) = " +
                             std::to_string(id.infog[0]) + ", INFOG(2) = " +
                             std::to_string(id.infog[1]) +
                             (id.infog[0] == -10 ?
                                "): the block is not held (check its constraints)." :
                                ").")));
    }

    void
    MumpsSchurSolver::factorize(const TrilinosWrappers::SparseMatrix &A,
                                const std::vector<types::global_dof_index> &schur_dofs)
    {
      matrix = &A;
      schur  = schur_dofs;
      const Epetra_CrsMatrix &crs = A.trilinos_matrix();
      const int               n   = crs.NumMyRows();
      schur_index.assign(n, -1);
      for (unsigned int k = 0; k < schur.size(); ++k)
        {
          Assert(schur_index[schur[k]] < 0, ExcMessage("Schur dofs must be distinct."));
          schur_index[schur[k]] = k;
        }

      // The upper triangle in coordinates (1-based): MUMPS sums duplicates,
      // so a symmetric matrix is given once.
      data->rows.clear();
      data->columns.clear();
      data->values.clear();
      for (int row = 0; row < n; ++row)
        {
          int     n_entries;
          double *values;
          int *   indices;
          crs.ExtractMyRowView(row, n_entries, values, indices);
          for (int e = 0; e < n_entries; ++e)
            {
              const int column = crs.GCID(indices[e]);
              if (column >= row)
                {
                  data->rows.push_back(row + 1);
                  data->columns.push_back(column + 1);
                  data->values.push_back(values[e]);
                }
            }
        }

      DMUMPS_STRUC_C &id = data->id;
      if (data->initialized)
        {
          id.job = -2;
          dmumps_c(&id);
        }
      id              = DMUMPS_STRUC_C{};
      id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(MPI_COMM_SELF));
      id.par          = 1;
      id.sym          = 1; // symmetric positive definite: L D L^T, no pivoting
      run(-1, "initialisation");
      data->initialized = true;
      // No output from MUMPS.
      icntl(id, 1) = -1;
      icntl(id, 2) = -1;
      icntl(id, 3) = -1;
      icntl(id, 4) = 0;

      id.n   = n;
      id.nnz = data->values.size();
      id.irn = data->rows.data();
      id.jcn = data->columns.data();
      id.a   = data->values.data();

      const unsigned int n_schur = schur.size();
      if (n_schur > 0)
        {
          data->schur_list.resize(n_schur);
          for (unsigned int k = 0; k < n_schur; ++k)
            data->schur_list[k] = schur[k] + 1;
          data->schur.assign(static_cast<std::size_t>(n_schur) * n_schur, 0.0);
          // Centralised Schur complement on the host, n_S x n_S.
          icntl(id, 19)    = 1;
          id.size_schur    = n_schur;
          id.listvar_schur = data->schur_list.data();
          id.schur         = data->schur.data();
        }
      run(4, "analysis and factorisation");

      // For a symmetric matrix MUMPS returns the lower triangle of S by rows
      // (ICNTL(19) = 1); the other triangle is workspace, not zero, on
      // larger problems. Read column-major, the array holds S^T: keep its
      // upper triangle and mirror it.
      if (n_schur > 0)
        {
          std::vector<double> &S = data->schur;
          for (unsigned int j = 0; j < n_schur; ++j)
            for (unsigned int i = 0; i < j; ++i)
              S[j + std::size_t(i) * n_schur] = S[i + std::size_t(j) * n_schur];
          // Cholesky factor of S: with MUMPS's factor of K_II, a complete
          // factorisation of K.
          schur_factor.swap(S);
          std::vector<double>().swap(S);
          const types::blas_int n_s = n_schur;
          types::blas_int       info = 0;
          potrf("L", &n_s, schur_factor.data(), &n_s, &info);
          AssertThrow(info == 0,
                      ExcMessage("The Schur complement of a block stiffness matrix "
                                 "on its interface dofs is not positive definite: "
                                 "the block is not held (check its constraints)."));
        }
    }

    void
    MumpsSchurSolver::solve_interior(std::vector<double> &b, const unsigned int n_rhs) const
    {
      DMUMPS_STRUC_C &id = data->id;
      const auto      n  = static_cast<std::size_t>(id.n);
      for (unsigned int c = 0; c < n_rhs; ++c)
        for (const auto dof : schur)
          b[dof + c * n] = 0;
      id.rhs          = b.data();
      id.nrhs         = n_rhs;
      id.lrhs         = id.n;
      icntl(id, 26)   = 0; // the interior problem only, x_S = 0
      run(3, "solution");
      for (unsigned int c = 0; c < n_rhs; ++c)
        for (const auto dof : schur)
          b[dof + c * n] = 0;
    }

    void
    MumpsSchurSolver::solve(std::vector<double> &b, const unsigned int n_rhs) const
    {
      Assert(matrix != nullptr, ExcMessage("factorize() first."));
      const std::size_t  n       = data->id.n;
      const unsigned int n_schur = schur.size();
      if (n_schur == 0)
        {
          solve_interior(b, n_rhs);
          return;
        }
      // r_S = b_S, then y_I = K_II^{-1} b_I.
      std::vector<double> r(std::size_t(n_schur) * n_rhs);
      for (unsigned int c = 0; c < n_rhs; ++c)
        for (unsigned int k = 0; k < n_schur; ++k)
          r[k + c * n_schur] = b[schur[k] + c * n];
      solve_interior(b, n_rhs);

      // r_S -= K_SI y_I: the rows of the Schur dofs, interior columns.
      const Epetra_CrsMatrix &crs = matrix->trilinos_matrix();
      for (unsigned int k = 0; k < n_schur; ++k)
        for_each_entry_in_row(crs, schur[k], [&](const int column, const double value) {
          if (schur_index[column] < 0)
            for (unsigned int c = 0; c < n_rhs; ++c)
              r[k + c * n_schur] -= value * b[column + c * n];
        });
      // x_S = S^{-1} r_S with the Cholesky factor.
      const types::blas_int n_s = n_schur, n_r = n_rhs;
      types::blas_int       info = 0;
      potrs("L", &n_s, &n_r, schur_factor.data(), &n_s, r.data(), &n_s, &info);
      Assert(info == 0, ExcInternalError());

      // x_I = y_I - K_II^{-1} K_IS x_S: solve with rhs -K_IS x_S, using
      // the symmetry K_IS = K_SI^T (the rows of the Schur dofs again).
      std::vector<double> correction(n * n_rhs, 0.0);
      for (unsigned int k = 0; k < n_schur; ++k)
        for_each_entry_in_row(crs, schur[k], [&](const int column, const double value) {
          if (schur_index[column] < 0)
            for (unsigned int c = 0; c < n_rhs; ++c)
              correction[column + c * n] -= value * r[k + c * n_schur];
        });
      solve_interior(correction, n_rhs);
      for (std::size_t i = 0; i < n * n_rhs; ++i)
        b[i] += correction[i];
      for (unsigned int c = 0; c < n_rhs; ++c)
        for (unsigned int k = 0; k < n_schur; ++k)
          b[schur[k] + c * n] = r[k + c * n_schur];
    }

    Vector<double>
    MumpsSchurSolver::solve(const Vector<double> &b) const
    {
      std::vector<double> x(b.begin(), b.end());
      solve(x, 1);
      return Vector<double>(x.begin(), x.end());
    }

    std::vector<double>
    MumpsSchurSolver::inverse_on_schur_dofs() const
    {
      std::vector<double> inverse = schur_factor;
      if (!schur.empty())
        {
          const types::blas_int n_s  = schur.size();
          types::blas_int       info = 0;
          potri("L", &n_s, inverse.data(), &n_s, &info);
          AssertThrow(info == 0, ExcMessage("Inverting the Schur complement of a "
                                            "block stiffness matrix failed."));
          for (types::blas_int j = 0; j < n_s; ++j)
            for (types::blas_int i = 0; i < j; ++i)
              inverse[i + std::size_t(j) * n_s] = inverse[j + std::size_t(i) * n_s];
        }
      return inverse;
    }
  } // namespace blocks
} // namespace fdem
