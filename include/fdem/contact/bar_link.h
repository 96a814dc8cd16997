// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/contact/contact_law.h>
#include <fdem/contact/interface_pairs.h>
#include <fdem/contact/pair_rows.h>

#include <deal.II/base/tensor.h>

namespace fdem
{
  namespace contact
  {
    using namespace dealii;

    /**
     * A passive reinforcement bar (a bar, nail or pile) where it crosses a
     * sliding surface, as one more kind of row in the mixed system of eq.
     * (9) (doc/theory.md, "Passive bars"): a link between the two nodes of
     * the node pair nearest to the crossing, with its own force law instead
     * of the contact law. Its dim unknowns are the force that block I
     * exerts on block J through the bar, in the bar's frame: the axial
     * force N first (positive in tension, as f_n of a pair), then the shear
     * force(s) across the bar. Each component is elastic, with stiffness k
     * (the relative displacement of the two sides along it is f / k), or
     * yielded at plus or minus its capacity; a component with zero
     * stiffness carries no force (a bar or nail in shear).
     */
    template <int dim>
    struct BarLink
    {
      /**
       * The two nodes the bar joins (those of the nearest node pair of the
       * sliding surface), with the bar's frame: row 0 the bar's axis
       * pointing from block J's side into block I's (so that f_0 > 0 is
       * tension), then the directions across the bar. area and
       * initial_gap are 0.
       */
      NodePair<dim> link;
      /** The blocks of the pair's interface (I: the one that moves). */
      unsigned int block_I = 0, block_J = 0;
      /** The frame of the sliding surface at the crossing (that pair's). */
      Tensor<2, dim> surface_frame;
      /** Axial stiffness k_a (force per length, per unit width in 2D), > 0. */
      double axial_stiffness = 0;
      /** Shear stiffness k_s across the bar; 0: the bar carries no shear. */
      double shear_stiffness = 0;
    };

    /**
     * The rows of @p bar in @p state (the form of PairRows): an elastic
     * component i reads g_i = f_i / k, a yielded one f_i = s_i N_y (V_y
     * across) with s_i its state's yield_sign, and a component without
     * stiffness f_i = 0. The capacities are @p strength's bar capacities.
     */
    template <int dim>
    PairRows<dim>
    bar_rows(const PairState<dim> &state,
             const PairStrength   &strength,
             const BarLink<dim>   &bar);

    /**
     * The next state of @p bar from its @p forces and relative
     * displacements @p gaps (local, its dim components): an elastic
     * component whose force exceeds its capacity by more than @p
     * force_tolerance yields with the sign of the force; a yielded one
     * whose elastic force k g would be below its capacity by more than
     * that unloads back to elastic, unless @p hold_yielded (a cycle was
     * broken). The status follows: stick if all elastic, slip otherwise.
     */
    template <int dim>
    PairState<dim>
    next_bar_state(const PairState<dim> &state,
                   const PairStrength   &strength,
                   const BarLink<dim>   &bar,
                   const Tensor<1, dim> &forces,
                   const Tensor<1, dim> &gaps,
                   const double          force_tolerance,
                   const bool            hold_yielded);
  } // namespace contact
} // namespace fdem
