// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/contact/pair_rows.h>

namespace fdem
{
  namespace contact
  {
    template <int dim>
    double
    tangential_stiffness(const Tensor<2, dim> &self_flexibility)
    {
      double sum = 0;
      for (unsigned int i = 1; i < dim; ++i)
        sum += self_flexibility[i][i];
      return sum > 0 ? (dim - 1) / sum : 0.0;
    }

    template <int dim>
    PairRows<dim>
    pair_rows(const PairState<dim> &state,
              const PairStrength   &strength,
              const Tensor<2, dim> &self_flexibility,
              const double          held_flexibility)
    {
      PairRows<dim> rows;
      const auto    held = [&](const unsigned int i) {
        return self_flexibility[i][i] <= held_flexibility;
      };
      if (state.status == PairStatus::open)
        {
          for (unsigned int i = 0; i < dim; ++i)
            rows.force[i][i] = 1; // f = 0
          return rows;
        }
      // Normal row: closed (g_n = 0), or held at the tension cut-off.
      if (state.at_cutoff || held(0))
        {
          rows.force[0][0] = 1;
          rows.value[0]    = state.at_cutoff ? strength.tensile_force : 0;
        }
      else
        rows.gap[0][0] = 1;

      if (dim == 3 && state.status == PairStatus::slip)
        {
          // With d the slip direction of the previous iterate, e the tangent
          // normal to it, alpha = s/|z| and r the pair's augmentation, the
          // linearised f_t = s z/|z| reads
          //   d . f_t + mu f_n = c A                     (the limit along d)
          //   (1 - alpha) e . f_t - alpha r e . g_t = 0  (turning towards g_t).
          // At a fixed point e . f_t = e . g_t = 0: force and slip are
          // parallel.
          const double       d1 = state.slip_direction[0];
          const double       d2 = state.slip_direction[dim - 2];
          const double       e1 = -d2, e2 = d1;
          const unsigned int along = 1, across = dim - 1;
          rows.force[along][along]  = d1;
          rows.force[along][across] = d2;
          rows.force[along][0]      = strength.friction_coefficient;
          rows.value[along]         = strength.cohesion_force;

          const double alpha = state.direction_weight;
          const double ar    = alpha * tangential_stiffness(self_flexibility);
          // - alpha r e . g_t = alpha r e . (d - g_bar)
          rows.gap[across][along]    = ar * e1;
          rows.gap[across][across]   = ar * e2;
          rows.force[across][along]  = (1 - alpha) * e1;
          rows.force[across][across] = (1 - alpha) * e2;
          return rows;
        }
      for (unsigned int i = 1; i < dim; ++i)
        if (state.status == PairStatus::slip)
          {
            // f_t = d (c A - mu f_n): the force at the Mohr-Coulomb limit
            // along the slip direction d.
            const double d   = state.slip_direction[i - 1];
            rows.force[i][i] = 1;
            rows.force[i][0] = d * strength.friction_coefficient;
            rows.value[i]    = d * strength.cohesion_force;
          }
        else if (held(i))
          rows.force[i][i] = 1;
        else
          rows.gap[i][i] = 1;
      return rows;
    }

    template double
    tangential_stiffness(const Tensor<2, 2> &);
    template double
    tangential_stiffness(const Tensor<2, 3> &);
    template PairRows<2>
    pair_rows(const PairState<2> &,
              const PairStrength &,
              const Tensor<2, 2> &,
              const double);
    template PairRows<3>
    pair_rows(const PairState<3> &,
              const PairStrength &,
              const Tensor<2, 3> &,
              const double);
  } // namespace contact
} // namespace fdem
