// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/contact/contact_law.h>
#include <fdem/contact/mixed_system.h>
#include <fdem/model.h>

#include <limits>
#include <string>
#include <vector>

namespace fdem
{
  namespace analyses
  {
    /**
     * The FE-stress factor of the sliding surface (Kulhawy's, as computed from
     * finite-element stresses by stress-based slope programs): the elastic
     * state with every pair stuck, the strengths unreduced, and
     * F = sum (c A - mu f_n) / F_tau over the pairs of the sliding surface,
     * F_tau as in eq. (11). When the iteration's first step at K0 ends with
     * every pair stuck, its K* is this factor exactly (doc/theory.md).
     */
    struct FeStressFactor
    {
      bool computed = false;
      /** Why not computed (empty if computed). */
      std::string not_computed;
      double      factor          = std::numeric_limits<double>::quiet_NaN();
      double      resisting_force = 0;
      double      sliding_force   = 0;
      /** Pairs of the sliding surface in tension in the all-stick state. */
      unsigned int n_pairs_in_tension = 0;
      /**
       * The all-stick state itself (if solved): the elastic state from
       * which the output's mechanism displacement is measured.
       */
      contact::ContactSolution all_stick;
    };

    /**
     * Solves the model's mixed system with every pair stuck, at its current
     * load, and sums the sliding surface's forces with the full strengths;
     * the model's contact state does not change.
     */
    template <int dim>
    FeStressFactor
    fe_stress_factor(Model<dim> &model);
  } // namespace analyses
} // namespace fdem
