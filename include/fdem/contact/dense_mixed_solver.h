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

      /** The factors of the last factorised system and their counts. */
      linear_algebra::ReusableLU lu;

    private:
      const MixedSystem<dim> &system;
    };
  } // namespace contact
} // namespace fdem
