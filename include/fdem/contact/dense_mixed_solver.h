// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/contact/mixed_system.h>
#include <fdem/contact/pair_rows.h>
#include <fdem/linear_algebra/reusable_lu.h>

#include <string>
#include <vector>

namespace fdem
{
  namespace contact
  {
    /**
     * The dense solver of the mixed system (MixedSystemSolver::dense): the
     * rows of every pair over the formed C, W and g_bar as one dense
     * matrix, made dimensionless (SystemScales) and solved by ReusableLU,
     * which reuses the factors of the last factorised matrix while few rows
     * change between solves.
     *
     * In 3D the rows of a slipping pair follow the slip direction of the
     * previous iterate, so that with many pairs slipping every solve changes
     * more rows than the factors can be reused for. Such a system is solved
     * condensed instead: the rows that only fix a pair's own forces (the
     * Mohr-Coulomb limit along the slip direction, open pairs, held
     * directions; condense_force_rows()) are eliminated exactly, which
     * leaves 2 unknowns per slipping pair instead of 3 and none per open
     * pair, and a fresh factorisation of the smaller system (about
     * (2/3)^3 of the flops when all slip). The full factors are kept for a
     * later system that could reuse them.
     */
    template <int dim>
    class DenseMixedSolver
    {
    public:
      /** A solver of @p system, which must have formed C. */
      explicit DenseMixedSolver(const MixedSystem<dim> &system);

      /**
       * The system with the rows @p rows, whose rigid modes can be held
       * (MixedSystem::solve() has tested them). Keeps the factors for the
       * next solve.
       */
      ContactSolution
      solve(const std::vector<PairRows<dim>> &rows);

      /** How @p solution was solved, for the log: rows changed, LU factorised
       * or reused. */
      static std::string
      describe(const ContactSolution &solution);

      /**
       * Forgets the factors and the formed matrix: to be called when C, W or
       * the system's scales change
       * (MixedSystem::set_moving_compliance_scale()).
       */
      void
      clear();

      /**
       * Forgets the factors (not the formed matrix): the next solve is
       * factorised, condensed or whole as if it were the first.
       */
      void
      forget_factors();

      /** The factors of the last factorised system and their counts. */
      linear_algebra::ReusableLU lu;

    private:
      const MixedSystem<dim> &system;

      /**
       * Whether @p rows are solved condensed: in 3D, when they differ from
       * those of the last full factorisation in more rows than ReusableLU
       * reuses its factors for, and the condensed system's factorisation
       * costs at most three quarters of the whole one's (n_condensed^3 <=
       * 0.75 n^3, about a sixth of the pairs slipping; a system of mostly
       * sticking pairs gains little by condensing and keeps its factors
       * for later reuse).
       */
      bool
      solves_condensed(const std::vector<PairRows<dim>> &rows) const;

      /** The whole system, formed from the changed rows, by ReusableLU. */
      ContactSolution
      solve_whole(const std::vector<PairRows<dim>> &rows);

      /** The system with the pairs' force rows eliminated, factorised once. */
      ContactSolution
      solve_condensed(const std::vector<PairRows<dim>> &rows);

      /** The solution of the unknowns [f; gamma] (C f computed here). */
      ContactSolution
      solution_of(const Vector<double> &unknowns) const;

      /** The rows of the last fully factorised system (empty: none). */
      std::vector<PairRows<dim>> factorized_rows;

      /**
       * The dimensionless matrix of the last solve, kept between solves: the
       * rows of a pair whose PairRows did not change are those of the last
       * solve (C, W and the scales are fixed until clear()), so only the
       * changed pairs' rows are formed again, each from zero by the same
       * operations as a whole new matrix: the matrix is the same, bit for
       * bit, whatever was solved before (as the samples of a probabilistic
       * analysis need, on any number of ranks).
       */
      FullMatrix<double> matrix;
      /** The pair rows each pair's rows of #matrix were formed from. */
      std::vector<PairRows<dim>> formed_rows;
      /** Whether #matrix holds the rigid rows and #formed_rows is valid. */
      bool formed = false;
      /** The scales #matrix was formed with (compared at every solve). */
      SystemScales formed_scales;
      /** Work arrays of a solve: right-hand side and solution, row scales. */
      Vector<double>      rhs;
      std::vector<double> row_scale, column_scale;
    };
  } // namespace contact
} // namespace fdem
