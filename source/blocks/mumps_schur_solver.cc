// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/blocks/crs_rows.h>
#include <fdem/blocks/mumps_schur_solver.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/lapack_templates.h>

#include <Epetra_CrsMatrix.h>
#include <dmumps_c.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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

      MUMPS_INT
      infog(const DMUMPS_STRUC_C &id, const int i)
      {
        return id.infog[i - 1];
      }

      /** A count of INFOG: negative values are millions (MUMPS's overflow). */
      double
      infog_count(const DMUMPS_STRUC_C &id, const int i)
      {
        const MUMPS_INT value = infog(id, i);
        return value < 0 ? -1e6 * value : value;
      }

      std::string
      format(const char *pattern, const double value)
      {
        char text[32];
        std::snprintf(text, sizeof(text), pattern, value);
        return text;
      }

      /**
       * What MUMPS reports of a factorisation, read right after it (the
       * solves overwrite some of INFOG): the entries of the factors
       * (INFOG(29)) and the flops of the elimination (RINFOG(3)), in
       * low-rank mode also after the compression (INFOG(35), RINFOG(14)),
       * and the memory MUMPS used (INFOG(22), the sum over the ranks) and
       * had estimated in the analysis (INFOG(17)), in MB of 10^6 bytes as
       * MUMPS counts them.
       */
      std::string
      describe_factorization(const DMUMPS_STRUC_C &id, const double tolerance)
      {
        std::string text =
          "factors " + format("%.3g", infog_count(id, 29)) + " entries";
        if (tolerance > 0)
          text += " (" + format("%.3g", infog_count(id, 35)) +
                  " after low-rank compression at " + format("%g", tolerance) +
                  ", " +
                  format("%.1f",
                         100 * infog_count(id, 35) /
                           std::max(1.0, infog_count(id, 29))) +
                  " %)";
        text += ", " + format("%.3g", id.rinfog[2]) + " flops";
        if (tolerance > 0)
          text += " (" + format("%.3g", id.rinfog[13]) + " low-rank)";
        return text + ", memory " + std::to_string(infog(id, 22)) +
               " MB (estimated " + std::to_string(infog(id, 17)) + " MB)";
      }
    } // namespace

    struct MumpsSchurSolver::Data
    {
      DMUMPS_STRUC_C         id{};
      std::vector<MUMPS_INT> rows, columns, schur_list;
      std::vector<double>    values, schur;
      bool                   initialized = false;
    };

    MumpsSchurSolver::MumpsSchurSolver(const bool   keep_schur_complement,
                                       const double block_low_rank_tolerance,
                                       const double memory_limit_MiB)
      : keep_schur_complement(keep_schur_complement)
      , block_low_rank_tolerance(block_low_rank_tolerance)
      , memory_limit_MiB(memory_limit_MiB)
      , data(std::make_unique<Data>())
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
                  ExcMessage(
                    std::string("MUMPS failed in the ") + what +
                    " of a block stiffness matrix (INFOG(1) = " +
                    std::to_string(id.infog[0]) +
                    ", INFOG(2) = " + std::to_string(id.infog[1]) +
                    (id.infog[0] == -10 ?
                       "): the block is not held (check its constraints)." :
                       ").")));
    }

    void
    MumpsSchurSolver::check_memory(const unsigned int n_schur) const
    {
      if (memory_limit_MiB <= 0)
        return;
      const DMUMPS_STRUC_C &id = data->id;
      // INFOG(17): the in-core factorisation's estimated work space, summed
      // over the ranks, in MB of 10^6 bytes. MUMPS 5.5 allocates it from the
      // full-rank estimate also in low-rank mode (doc/scaling.md). The
      // Cholesky factor of the Schur complement takes MUMPS's n_S^2 array
      // over, which the process already holds; its broadcast adds one per
      // further rank. The message also gives the elimination's flops
      // estimated by the analysis (RINFOG(1)): the time the refused
      // factorisation would have taken.
      const double mumps_MiB = infog(id, 17) * 1e6 / (1 << 20);
      const double schur_MiB =
        (n_ranks - 1) * 8.0 * n_schur * n_schur / (1 << 20);
      Utilities::System::MemoryStats stats;
      Utilities::System::get_memory_stats(stats);
      const double held_MiB =
        Utilities::MPI::sum(stats.VmRSS / 1024.0, communicator);
      AssertThrow(
        held_MiB + mumps_MiB + schur_MiB <= memory_limit_MiB,
        ExcMessage(
          "Geometry/Memory limit: the factorisation of a block stiffness "
          "matrix of " +
          std::to_string(id.n) + " dofs would need about " +
          format("%.0f", mumps_MiB + schur_MiB) + " MiB (MUMPS's analysis; " +
          format("%.2g", id.rinfog[0]) + " flops) beside the " +
          format("%.0f", held_MiB) +
          " MiB the run holds already, more than the " +
          format("%.0f", memory_limit_MiB) +
          " MiB allowed (0 is this machine's memory or ulimit -v). Use a "
          "coarser mesh or raise the limit; a block low-rank tolerance does "
          "not lower this need."));
    }

    namespace
    {
      /**
       * The concatenation over the ranks of @p comm of each rank's @p local
       * (rank 0's first), on every rank.
       */
      template <typename T>
      std::vector<T>
      all_gather_concatenated(const MPI_Comm comm, const std::vector<T> &local)
      {
        const int        n_ranks = Utilities::MPI::n_mpi_processes(comm);
        const int        size    = local.size();
        std::vector<int> sizes(n_ranks), offsets(n_ranks, 0);
        int              ierr =
          MPI_Allgather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, comm);
        AssertThrowMPI(ierr);
        for (int r = 1; r < n_ranks; ++r)
          offsets[r] = offsets[r - 1] + sizes[r - 1];
        std::vector<T>     all(offsets.back() + sizes.back());
        const MPI_Datatype type =
          Utilities::MPI::internal::MPIDataTypes::mpi_type_id(
            static_cast<const T *>(nullptr));
        ierr = MPI_Allgatherv(local.data(),
                              size,
                              type,
                              all.data(),
                              sizes.data(),
                              offsets.data(),
                              type,
                              comm);
        AssertThrowMPI(ierr);
        return all;
      }

      /** Broadcasts @p data (same size on every rank) from rank 0. */
      void
      broadcast_from_host(const MPI_Comm    comm,
                          double           *data,
                          const std::size_t size)
      {
        Utilities::MPI::broadcast(data, size, 0, comm);
      }
    } // namespace

    void
    MumpsSchurSolver::factorize(
      const TrilinosWrappers::SparseMatrix       &A,
      const std::vector<types::global_dof_index> &schur_dofs)
    {
      Assert(keep_schur_complement || schur_dofs.empty(),
             ExcMessage("MUMPS without Schur complement got Schur dofs."));
      matrix          = &A;
      schur           = schur_dofs;
      communicator    = A.get_mpi_communicator();
      n_ranks         = Utilities::MPI::n_mpi_processes(communicator);
      const bool host = Utilities::MPI::this_mpi_process(communicator) == 0;
      const Epetra_CrsMatrix &crs = A.trilinos_matrix();
      const int               n   = A.m();
      schur_index.assign(n, -1);
      for (unsigned int k = 0; k < schur.size(); ++k)
        {
          Assert(schur_index[schur[k]] < 0,
                 ExcMessage("Schur dofs must be distinct."));
          schur_index[schur[k]] = k;
        }

      // The upper triangle of the rows this rank owns in coordinates
      // (1-based): MUMPS sums duplicates, so a symmetric matrix is given
      // once. With one rank, all rows, in the order of the rows.
      data->rows.clear();
      data->columns.clear();
      data->values.clear();
      for (int local_row = 0; local_row < crs.NumMyRows(); ++local_row)
        {
          const int row = crs.GRID(local_row);
          int       n_entries;
          double   *values;
          int      *indices;
          crs.ExtractMyRowView(local_row, n_entries, values, indices);
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

      {
        double largest = 0;
        for (const double a : data->values)
          largest = std::max(largest, std::abs(a));
        if (n_ranks > 1)
          largest = Utilities::MPI::max(largest, communicator);
        value_scale = largest > 0 && std::isfinite(largest) ?
                        std::ldexp(1.0, -std::ilogb(largest)) :
                        1.0;
        for (double &a : data->values)
          a *= value_scale;
      }

      // The rows of the Schur dofs, on every rank: the solves need K_SI
      // (unscaled: the solves scale their results back).
      {
        std::vector<int>    local_rows, local_columns;
        std::vector<double> local_values;
        for (unsigned int k = 0; k < schur.size(); ++k)
          if (crs.MyGRID(static_cast<int>(schur[k])))
            for_each_entry_in_row(crs,
                                  crs.LRID(static_cast<int>(schur[k])),
                                  [&](const int column, const double value) {
                                    local_rows.push_back(k);
                                    local_columns.push_back(column);
                                    local_values.push_back(value);
                                  });
        std::vector<int> all_rows = local_rows;
        if (n_ranks > 1)
          {
            all_rows = all_gather_concatenated(communicator, local_rows);
            local_columns =
              all_gather_concatenated(communicator, local_columns);
            local_values = all_gather_concatenated(communicator, local_values);
          }
        // Counting sort by row, keeping each row's entries in their order.
        schur_row_start.assign(schur.size() + 1, 0);
        for (const int k : all_rows)
          ++schur_row_start[k + 1];
        for (unsigned int k = 0; k < schur.size(); ++k)
          schur_row_start[k + 1] += schur_row_start[k];
        std::vector<std::size_t> next(schur_row_start.begin(),
                                      schur_row_start.end() - 1);
        schur_row_columns.resize(all_rows.size());
        schur_row_values.resize(all_rows.size());
        for (std::size_t e = 0; e < all_rows.size(); ++e)
          {
            const std::size_t position  = next[all_rows[e]]++;
            schur_row_columns[position] = local_columns[e];
            schur_row_values[position]  = local_values[e];
          }
      }

      DMUMPS_STRUC_C &id = data->id;
      if (data->initialized)
        {
          id.job = -2;
          dmumps_c(&id);
        }
      id              = DMUMPS_STRUC_C{};
      id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(communicator));
      id.par          = 1; // the host works too
      id.sym          = 1; // symmetric positive definite: L D L^T, no pivoting
      run(-1, "initialisation");
      data->initialized = true;
      // No output from MUMPS.
      icntl(id, 1) = -1;
      icntl(id, 2) = -1;
      icntl(id, 3) = -1;
      icntl(id, 4) = 0;

      id.n = n;
      if (n_ranks == 1)
        {
          id.nnz = data->values.size();
          id.irn = data->rows.data();
          id.jcn = data->columns.data();
          id.a   = data->values.data();
        }
      else
        {
          // Distributed assembled matrix: each rank its own entries.
          icntl(id, 18) = 3;
          id.nnz_loc    = data->values.size();
          id.irn_loc    = data->rows.data();
          id.jcn_loc    = data->columns.data();
          id.a_loc      = data->values.data();
        }

      if (block_low_rank_tolerance > 0)
        {
          // Set before the analysis, which clusters the fronts' variables
          // into the blocks that the factorisation compresses.
          // ICNTL(35) = 2: low-rank in the factorisation and the solves,
          // the factors stored compressed (3 would keep them full rank for
          // the solves; 1, MUMPS's automatic choice, and compressing the
          // contribution blocks too, ICNTL(37) = 1, gave the same factors,
          // time and memory on a 85000-dof block: doc/scaling.md).
          icntl(id, 35) = 2;
          id.cntl[6]    = block_low_rank_tolerance;
        }

      const unsigned int n_schur = schur.size();
      if (n_schur > 0)
        {
          data->schur_list.resize(n_schur);
          for (unsigned int k = 0; k < n_schur; ++k)
            data->schur_list[k] = schur[k] + 1;
          if (host)
            data->schur.assign(static_cast<std::size_t>(n_schur) * n_schur,
                               0.0);
          // Centralised Schur complement on the host, n_S x n_S.
          icntl(id, 19)    = 1;
          id.size_schur    = n_schur;
          id.listvar_schur = data->schur_list.data();
          id.schur         = host ? data->schur.data() : nullptr;
        }
      // Analysis, then the factorisation, once the analysis's estimate of
      // its memory is known to fit.
      run(1, "analysis");
      check_memory(n_schur);
      run(2, "factorisation");
      report = describe_factorization(id, block_low_rank_tolerance);

      // For a symmetric matrix MUMPS returns the lower triangle of S by rows
      // (ICNTL(19) = 1); the other triangle is workspace, not zero, on
      // larger problems. Read column-major, the array holds S^T: keep its
      // upper triangle and mirror it.
      if (n_schur > 0)
        {
          types::blas_int info = 0;
          if (host)
            {
              std::vector<double> &S = data->schur;
              for (unsigned int j = 0; j < n_schur; ++j)
                for (unsigned int i = 0; i < j; ++i)
                  S[j + std::size_t(i) * n_schur] =
                    S[i + std::size_t(j) * n_schur];
              // Cholesky factor of S: with MUMPS's factor of K_II, a complete
              // factorisation of K. LAPACK in place on MUMPS's array, not
              // LAPACKFullMatrix: that would copy n_S^2 numbers (many in 3D).
              schur_factor.swap(S);
              std::vector<double>().swap(S);
              const types::blas_int n_s = n_schur;
              potrf("L", &n_s, schur_factor.data(), &n_s, &info);
            }
          if (n_ranks > 1)
            {
              info = Utilities::MPI::broadcast(communicator, info, 0);
              schur_factor.resize(std::size_t(n_schur) * n_schur);
              broadcast_from_host(communicator,
                                  schur_factor.data(),
                                  schur_factor.size());
            }
          // With low-rank factors S is approximate too: at a coarse
          // tolerance (1e-2 on prm/slope_3d.prm) it lost its definiteness
          // although the block was held.
          AssertThrow(info == 0,
                      ExcMessage(
                        "The Schur complement of a block stiffness matrix "
                        "on its interface dofs is not positive definite: " +
                        (block_low_rank_tolerance > 0 ?
                           "Solver/Block low-rank tolerance = " +
                             format("%g", block_low_rank_tolerance) +
                             " approximates the factors too coarsely "
                             "(lower it), or the block is not held." :
                           std::string("the block is not held (check its "
                                       "constraints)."))));
        }
    }

    void
    MumpsSchurSolver::solve_interior(std::vector<double> &b,
                                     const unsigned int   n_rhs) const
    {
      DMUMPS_STRUC_C &id = data->id;
      const auto      n  = static_cast<std::size_t>(id.n);
      for (unsigned int c = 0; c < n_rhs; ++c)
        for (const auto dof : schur)
          b[dof + c * n] = 0;
      id.rhs        = b.data();
      id.nrhs       = n_rhs;
      id.lrhs       = id.n;
      icntl(id, 26) = 0; // the interior problem only, x_S = 0
      // Rank 0's right-hand sides in, the solutions out on rank 0.
      run(3, "solution");
      if (n_ranks > 1)
        broadcast_from_host(communicator, b.data(), n * n_rhs);
      for (double &x : b)
        x *= value_scale;
      for (unsigned int c = 0; c < n_rhs; ++c)
        for (const auto dof : schur)
          b[dof + c * n] = 0;
    }

    void
    MumpsSchurSolver::solve(std::vector<double> &b,
                            const unsigned int   n_rhs) const
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
      for (unsigned int k = 0; k < n_schur; ++k)
        for_each_entry_in_schur_row(k,
                                    [&](const int column, const double value) {
                                      if (schur_index[column] < 0)
                                        for (unsigned int c = 0; c < n_rhs; ++c)
                                          r[k + c * n_schur] -=
                                            value * b[column + c * n];
                                    });
      // x_S = S^{-1} r_S with the Cholesky factor.
      const types::blas_int n_s = n_schur, n_r = n_rhs;
      types::blas_int       info = 0;
      potrs("L", &n_s, &n_r, schur_factor.data(), &n_s, r.data(), &n_s, &info);
      Assert(info == 0, ExcInternalError());
      for (double &x : r)
        x *= value_scale;

      // x_I = y_I - K_II^{-1} K_IS x_S: solve with rhs -K_IS x_S, using
      // the symmetry K_IS = K_SI^T (the rows of the Schur dofs again).
      std::vector<double> correction(n * n_rhs, 0.0);
      for (unsigned int k = 0; k < n_schur; ++k)
        for_each_entry_in_schur_row(k,
                                    [&](const int column, const double value) {
                                      if (schur_index[column] < 0)
                                        for (unsigned int c = 0; c < n_rhs; ++c)
                                          correction[column + c * n] -=
                                            value * r[k + c * n_schur];
                                    });
      solve_interior(correction, n_rhs);
      for (std::size_t i = 0; i < n * n_rhs; ++i)
        b[i] += correction[i];
      for (unsigned int c = 0; c < n_rhs; ++c)
        for (unsigned int k = 0; k < n_schur; ++k)
          b[schur[k] + c * n] = r[k + c * n_schur];
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
          AssertThrow(info == 0,
                      ExcMessage("Inverting the Schur complement of a "
                                 "block stiffness matrix failed."));
          for (types::blas_int j = 0; j < n_s; ++j)
            for (types::blas_int i = 0; i < j; ++i)
              inverse[i + std::size_t(j) * n_s] =
                inverse[j + std::size_t(i) * n_s];
          for (double &x : inverse)
            x *= value_scale;
        }
      return inverse;
    }

    std::vector<double>
    MumpsSchurSolver::inverse_entries(
      const std::vector<std::pair<types::global_dof_index,
                                  types::global_dof_index>> &entries) const
    {
      Assert(matrix != nullptr, ExcMessage("factorize() first."));
      Assert(schur.empty(),
             ExcMessage("Entries of the inverse need a factorisation "
                        "without Schur dofs."));
      DMUMPS_STRUC_C &id = data->id;
      const auto      n  = static_cast<std::size_t>(id.n);
      // The requested entries as a sparse matrix by columns (1-based): MUMPS
      // returns (K^{-1})_{ij} in the place of each (i, j).
      std::vector<std::size_t> order(entries.size());
      for (std::size_t e = 0; e < order.size(); ++e)
        order[e] = e;
      std::stable_sort(order.begin(),
                       order.end(),
                       [&](const std::size_t a, const std::size_t b) {
                         return entries[a].second < entries[b].second;
                       });
      std::vector<MUMPS_INT> column_start(n + 1, 0), rows(entries.size());
      for (const auto &[i, j] : entries)
        ++column_start[j + 1];
      for (std::size_t j = 0; j < n; ++j)
        column_start[j + 1] += column_start[j];
      for (std::size_t k = 0; k < order.size(); ++k)
        rows[k] = entries[order[k]].first + 1;
      for (MUMPS_INT &start : column_start)
        ++start;
      std::vector<double> values(entries.size(), 0.0);

      // The requests live on the host only: MUMPS refuses arrays on the
      // other ranks (INFOG(1) = -22), and the dense pointer of the last
      // solve is stale.
      const bool host = Utilities::MPI::this_mpi_process(communicator) == 0;
      id.rhs          = nullptr;
      icntl(id, 30)   = 1;
      id.nrhs         = n;
      id.lrhs         = n;
      id.nz_rhs       = entries.size();
      id.irhs_ptr     = host ? column_start.data() : nullptr;
      id.irhs_sparse  = host ? rows.data() : nullptr;
      id.rhs_sparse   = host ? values.data() : nullptr;
      run(3, "computation of entries of the inverse");
      icntl(id, 30)  = 0;
      id.irhs_ptr    = nullptr;
      id.irhs_sparse = nullptr;
      id.rhs_sparse  = nullptr;
      id.nz_rhs      = 0;
      if (n_ranks > 1)
        broadcast_from_host(communicator, values.data(), values.size());

      std::vector<double> result(entries.size());
      for (std::size_t k = 0; k < order.size(); ++k)
        result[order[k]] = values[k] * value_scale;
      return result;
    }

    std::string
    MumpsSchurSolver::statistics() const
    {
      return "MUMPS: " + report;
    }
  } // namespace blocks
} // namespace fdem
