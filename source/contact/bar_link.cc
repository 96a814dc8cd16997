// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The force law of a passive bar's link: elastic-perfectly-plastic per
// component, in the rows of the mixed system (doc/theory.md, "Passive
// bars").
#include <fdem/contact/bar_link.h>

#include <cmath>

namespace fdem
{
  namespace contact
  {
    namespace
    {
      template <int dim>
      double
      stiffness(const BarLink<dim> &bar, const unsigned int i)
      {
        return i == 0 ? bar.axial_stiffness : bar.shear_stiffness;
      }

      double
      capacity(const PairStrength &strength, const unsigned int i)
      {
        return i == 0 ? strength.bar_axial_capacity :
                        strength.bar_shear_capacity;
      }
    } // namespace

    template <int dim>
    PairRows<dim>
    bar_rows(const PairState<dim> &state,
             const PairStrength   &strength,
             const BarLink<dim>   &bar)
    {
      PairRows<dim> rows;
      for (unsigned int i = 0; i < dim; ++i)
        {
          const double k = stiffness(bar, i);
          if (!(k > 0))
            rows.force[i][i] = 1; // no force across a bar or nail
          else if (state.yield_sign[i] != 0)
            {
              rows.force[i][i] = 1;
              rows.value[i]    = state.yield_sign[i] * capacity(strength, i);
            }
          else
            {
              // g_i = f_i / k: the row G (C f - W gamma) + F f = G g_bar with
              // G = 1 and F = 1/k, the bar in series with the blocks.
              rows.gap[i][i]   = 1;
              rows.force[i][i] = 1 / k;
            }
        }
      return rows;
    }

    template <int dim>
    PairState<dim>
    next_bar_state(const PairState<dim> &state,
                   const PairStrength   &strength,
                   const BarLink<dim>   &bar,
                   const Tensor<1, dim> &forces,
                   const Tensor<1, dim> &gaps,
                   const double          force_tolerance,
                   const bool            hold_yielded)
    {
      PairState<dim> next = state;
      bool           any  = false;
      for (unsigned int i = 0; i < dim; ++i)
        {
          const double k = stiffness(bar, i);
          const double N = capacity(strength, i);
          if (!(k > 0))
            next.yield_sign[i] = 0;
          else if (state.yield_sign[i] == 0)
            {
              if (std::abs(forces[i]) > N + force_tolerance)
                next.yield_sign[i] = forces[i] > 0 ? 1 : -1;
            }
          else if (!hold_yielded &&
                   state.yield_sign[i] * k * gaps[i] < N - force_tolerance)
            // Holonomic: the elastic force of the current stretch is below
            // the capacity, so the component is elastic again.
            next.yield_sign[i] = 0;
          any |= next.yield_sign[i] != 0;
        }
      next.status = any ? PairStatus::slip : PairStatus::stick;
      return next;
    }

    template PairRows<2>
    bar_rows(const PairState<2> &, const PairStrength &, const BarLink<2> &);
    template PairRows<3>
    bar_rows(const PairState<3> &, const PairStrength &, const BarLink<3> &);
    template PairState<2>
    next_bar_state(const PairState<2> &,
                   const PairStrength &,
                   const BarLink<2> &,
                   const Tensor<1, 2> &,
                   const Tensor<1, 2> &,
                   const double,
                   const bool);
    template PairState<3>
    next_bar_state(const PairState<3> &,
                   const PairStrength &,
                   const BarLink<3> &,
                   const Tensor<1, 3> &,
                   const Tensor<1, 3> &,
                   const double,
                   const bool);
  } // namespace contact
} // namespace fdem
