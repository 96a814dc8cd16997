// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/parameters/model_parameters.h>

#include <deal.II/base/types.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

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
     * The factorisation of one block's stiffness matrix K by a sparse direct
     * solver: factorised once (the FE part of the method is linear), then
     * solved for any number of right-hand sides, one or many at a time.
     * make_block_factorization() picks the back-end from
     * "Solver/Direct solver":
     * - MumpsSchurSolver: MUMPS_Schur (the interface dofs' Schur complement
     *   kept, so that their flexibility needs no solves) and MUMPS (selected
     *   entries of K^{-1});
     * - CholmodSolver, AmesosSolver (Amesos_Klu, Amesos_Mumps),
     *   UmfpackSolver: solves only.
     *
     * MPI: every call is collective. Right-hand sides and solutions are
     * global-size arrays, the same on every rank.
     */
    class BlockFactorization
    {
    public:
      virtual ~BlockFactorization() = default;

      /**
       * True if factorize() wants the interface dofs, to eliminate them last
       * and keep their Schur complement (MUMPS_Schur).
       */
      virtual bool
      keeps_schur_complement() const
      {
        return false;
      }

      /**
       * Symbolic and numeric factorisation of @p matrix (kept by reference).
       * @p schur_dofs (distinct) must be empty unless
       * keeps_schur_complement().
       */
      virtual void
      factorize(const TrilinosWrappers::SparseMatrix       &matrix,
                const std::vector<types::global_dof_index> &schur_dofs) = 0;

      /**
       * Solves K x = b for the @p n_rhs columns of @p b at once (n x n_rhs,
       * column-major, global size; overwritten with x).
       */
      virtual void
      solve(std::vector<double> &b, const unsigned int n_rhs) const = 0;

      /** Solves K x = b for one right-hand side. */
      Vector<double>
      solve(const Vector<double> &b) const;

      /** The Schur dofs in the order given to factorize(); empty if none. */
      virtual const std::vector<types::global_dof_index> &
      schur_dofs() const;

      /**
       * (K^{-1})_SS on the Schur dofs, n_S x n_S column-major. Only with
       * Schur dofs.
       */
      virtual std::vector<double>
      inverse_on_schur_dofs() const;

      /** True if inverse_entries() is available. */
      virtual bool
      computes_inverse_entries() const
      {
        return false;
      }

      /**
       * Selected entries (K^{-1})_{ij}, one per (i, j) of @p entries, without
       * a solve per column. Only if computes_inverse_entries().
       */
      virtual std::vector<double>
      inverse_entries(
        const std::vector<std::pair<types::global_dof_index,
                                    types::global_dof_index>> &entries) const;

      /**
       * What the back-end reports of its last factorisation (memory, the
       * low-rank compression), one line for the run's log; empty if it
       * reports nothing.
       */
      virtual std::string
      statistics() const
      {
        return "";
      }
    };

    /**
     * A new, not yet factorised, back-end of type @p type; with
     * @p block_low_rank_tolerance > 0 MUMPS's block low-rank factorisation
     * (MUMPS_Schur and MUMPS only; "Solver/Block low-rank tolerance").
     * With @p memory_limit_MiB > 0 MUMPS refuses, after its analysis, a
     * factorisation that would take the process beyond that memory
     * (MumpsSchurSolver); the other back-ends estimate nothing.
     */
    std::unique_ptr<BlockFactorization>
    make_block_factorization(const parameters::DirectSolverType type,
                             const double block_low_rank_tolerance = 0,
                             const double memory_limit_MiB         = 0);

    /**
     * Throws naming Solver/Direct solver = @p type if @p matrix lives on more
     * than one MPI rank: for the serial back-ends (CHOLMOD, UMFPACK).
     */
    void
    assert_one_rank(const TrilinosWrappers::SparseMatrix &matrix,
                    const parameters::DirectSolverType    type);
  } // namespace blocks
} // namespace fdem
