// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/block_factorization.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace fdem
{
  namespace blocks
  {
    using namespace dealii;

    /**
     * MUMPS (through its C interface) for a symmetric positive definite
     * block stiffness K, factorised once as L D L^T with a list of "Schur"
     * dofs eliminated last: MUMPS factorises the rest, K_II, and returns the
     * dense Schur complement S = K_SS - K_SI K_II^{-1} K_IS, which is then
     * Cholesky-factorised here. Together that is a full factorisation of K
     * for the cost of one, and (K^{-1})_SS = S^{-1} follows from the dense
     * factor alone: the interface flexibility needs no sparse solves
     * (MUMPS user's guide, ICNTL(19)).
     *
     * A solve K x = b is y_I = K_II^{-1} b_I, x_S = S^{-1} (b_S - K_SI y_I),
     * x_I = K_II^{-1} (b_I - K_IS x_S): two MUMPS solves of the interior.
     *
     * MPI: MUMPS runs on the matrix's communicator. With one rank it gets
     * the matrix centralised, as always; with more, each rank gives the
     * rows it owns (ICNTL(18) = 3) and MUMPS factorises in parallel. The
     * Schur complement comes back on rank 0 (ICNTL(19) = 1), which
     * Cholesky-factorises it and broadcasts the factor; the rows of K of the
     * Schur dofs are gathered on every rank. Right-hand sides and solutions
     * are global-size arrays, the same on every rank: MUMPS reads rank 0's
     * (ICNTL(20) = 0), and its solution, on rank 0 (ICNTL(21) = 0), is
     * broadcast. Every call is collective.
     *
     * Solver/Direct solver = MUMPS_Schur keeps the Schur complement of the
     * dofs given to factorize(); MUMPS gets none and is the plain L D L^T
     * factorisation, which can compute selected entries of K^{-1}.
     */
    class MumpsSchurSolver : public BlockFactorization
    {
    public:
      /**
       * @p keep_schur_complement: MUMPS_Schur (true) or MUMPS (false).
       * @p block_low_rank_tolerance > 0: MUMPS's block low-rank
       * factorisation with that dropping parameter (CNTL(7)).
       * @p memory_limit_MiB > 0: after the analysis, factorize() throws if
       * the memory MUMPS estimates for the factorisation (INFOG(17), all
       * ranks), the Schur complement's factor and what the process's ranks
       * hold already add up to more.
       */
      explicit MumpsSchurSolver(const bool   keep_schur_complement,
                                const double block_low_rank_tolerance = 0,
                                const double memory_limit_MiB         = 0);
      ~MumpsSchurSolver() override;
      MumpsSchurSolver(const MumpsSchurSolver &) = delete;
      MumpsSchurSolver &
      operator=(const MumpsSchurSolver &) = delete;

      bool
      keeps_schur_complement() const override
      {
        return keep_schur_complement;
      }

      /**
       * Analysis and factorisation of @p matrix (kept by reference; only its
       * upper triangle is read) with @p schur_dofs (distinct) eliminated
       * last, and the Cholesky factorisation of their Schur complement.
       */
      void
      factorize(
        const TrilinosWrappers::SparseMatrix       &matrix,
        const std::vector<types::global_dof_index> &schur_dofs) override;

      /** Solves K x = b for the columns of @p b (n x n_rhs, column-major). */
      using BlockFactorization::solve;
      void
      solve(std::vector<double> &b, const unsigned int n_rhs) const override;

      /** The Schur dofs, in the order given to factorize(). */
      const std::vector<types::global_dof_index> &
      schur_dofs() const override
      {
        return schur;
      }

      /**
       * (K^{-1})_SS = S^{-1} on the Schur dofs, n_S x n_S column-major,
       * from the dense factor (LAPACK potri). Not kept: the flexibility is
       * built once, and in 3D n_S^2 numbers are many.
       */
      std::vector<double>
      inverse_on_schur_dofs() const override;

      /**
       * Without Schur dofs and on one MPI rank: MUMPS's entries of K^{-1}
       * on a distributed matrix stopped with INFOG(1) = -22 in our runs
       * (MUMPS 5.5).
       */
      bool
      computes_inverse_entries() const override
      {
        return matrix != nullptr && schur.empty() && n_ranks == 1;
      }

      /**
       * Selected entries (K^{-1})_{ij}, one per (i, j) of @p entries, from
       * the factors without a solve of all of K^{-1}'s columns: MUMPS
       * computes just those entries, exploiting the sparsity of the
       * right-hand sides (ICNTL(30), "entries of the inverse"). Only
       * without Schur dofs. Collective; the result is on every rank.
       */
      std::vector<double>
      inverse_entries(
        const std::vector<
          std::pair<types::global_dof_index, types::global_dof_index>> &entries)
        const override;

      /**
       * MUMPS's memory (INFOG(16), (21), (22)) and, in low-rank mode, the
       * factors' entries full rank and compressed (INFOG(29), (35)) and the
       * flops (RINFOG(3), (14)), one line.
       */
      std::string
      statistics() const override;

    private:
      const bool   keep_schur_complement;
      const double block_low_rank_tolerance;
      const double memory_limit_MiB;
      /** statistics() of the last factorisation, without "MUMPS: ". */
      std::string report;
      struct Data;
      std::unique_ptr<Data>                 data;
      const TrilinosWrappers::SparseMatrix *matrix = nullptr;
      /** The matrix's communicator and its number of ranks. */
      MPI_Comm                             communicator = MPI_COMM_SELF;
      unsigned int                         n_ranks      = 1;
      std::vector<types::global_dof_index> schur;
      /** Per dof: its index in the Schur list, or -1. */
      std::vector<int> schur_index;
      /**
       * MUMPS factorises s K, with s the power of 2 that brings K's largest
       * entry into [1, 2): exact, and MUMPS's absolute thresholds (null
       * pivots, its scaling) then see the same numbers at every Young's
       * modulus (at 1e-16 Pa, unscaled, K came out 2.4 % low). Every
       * solution, inverse and inverse entry is multiplied by s again.
       */
      double value_scale = 1;
      /** Cholesky factor of s S (lower triangle, column-major). */
      std::vector<double> schur_factor;
      /**
       * The rows of K of the Schur dofs (all columns), in compressed rows:
       * row k holds entries schur_row_start[k] to schur_row_start[k+1].
       */
      std::vector<std::size_t> schur_row_start;
      std::vector<int>         schur_row_columns;
      std::vector<double>      schur_row_values;

      /** Calls f(column, value) for each entry of the row of Schur dof k. */
      template <typename Function>
      void
      for_each_entry_in_schur_row(const unsigned int k, const Function &f) const
      {
        for (std::size_t e = schur_row_start[k]; e < schur_row_start[k + 1];
             ++e)
          f(schur_row_columns[e], schur_row_values[e]);
      }

      /** MUMPS solve of the interior: x_I = K_II^{-1} b_I, x_S = 0. */
      void
      solve_interior(std::vector<double> &b, const unsigned int n_rhs) const;

      /**
       * After the analysis: throws if the factorisation would take the
       * process beyond memory_limit_MiB (when > 0), see the constructor.
       */
      void
      check_memory(unsigned int n_schur) const;

      /** Runs one MUMPS phase and throws with INFOG(1..2) on failure. */
      void
      run(const int job, const char *what) const;
    };
  } // namespace blocks
} // namespace fdem
