// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/contact/contact_law.h>

#include <deal.II/base/tensor.h>

#include <array>

namespace fdem
{
  namespace contact
  {
    using namespace dealii;

    /**
     * The dim rows of one pair in the mixed system (eq. 9 with the
     * conditions of Table 1, doc/theory.md), set by the
     * pair's state. With d = C f - W gamma the elastic-minus-rigid part of
     * the pair's relative displacement (g = g_bar - d), row i reads
     *
     *   sum_k gap[i][k] d_k + sum_k force[i][k] f_k = sum_k gap[i][k] g_bar_k +
     * value[i],
     *
     * so that a row of gap coefficients asks g = 0 along them, and a row of
     * force coefficients fixes a combination of the pair's own forces. The
     * dense and the iterative solvers build their systems from these rows.
     */
    template <int dim>
    struct PairRows
    {
      Tensor<2, dim> gap;
      Tensor<2, dim> force;
      Tensor<1, dim> value;

      /**
       * Whether row @p i has a gap coefficient. Decided entry by entry, not
       * by a norm: at a Young's modulus of 1e-200 the squares of a row's
       * entries underflow, and a slip row would be taken for a force row.
       */
      bool
      is_gap_row(const unsigned int i) const
      {
        for (unsigned int k = 0; k < dim; ++k)
          if (gap[i][k] != 0)
            return true;
        return false;
      }
    };

    /**
     * The rows of a pair in @p state with @p strength (doc/theory.md):
     * - stick: g = 0;
     * - slip: g_n = 0, and the tangential force at the Mohr-Coulomb limit
     *   along the slip direction (in 3D linearised about the previous
     *   iterate, turning towards the slip, PairState);
     * - open: f = 0;
     * - at the tension cut-off: f_n = sigma_t A instead of g_n = 0.
     * @p self_flexibility is the pair's own block of C (local frame); a
     * direction whose self-flexibility is at most @p held_flexibility is held
     * by Dirichlet conditions on both sides: f = 0 there (its force goes
     * into the supports, one of the equivalent solutions); a slipping pair
     * in 3D with a held tangent slips along the other one, at the limit
     * with d = +-1 as in 2D.
     */
    template <int dim>
    PairRows<dim>
    pair_rows(const PairState<dim> &state,
              const PairStrength   &strength,
              const Tensor<2, dim> &self_flexibility,
              const double          held_flexibility);

    /**
     * A pair's forces under its rows without gap coefficients ("force
     * rows", which fix combinations of the pair's own forces: open pairs,
     * held directions, the tension cut-off, the Mohr-Coulomb limit of a slip
     * pair): f = particular + N y for any y, with N (the first n_free columns
     * of @p basis) orthonormal and orthogonal to the force rows, and
     * particular the least-norm force that satisfies them. The pair's
     * remaining rows (row indices @p kept_rows, as many as N has columns)
     * then decide y: DenseMixedSolver's condensed system.
     */
    template <int dim>
    struct CondensedPair
    {
      unsigned int                  n_free = 0;
      std::array<unsigned int, dim> kept_rows{};
      Tensor<1, dim>                particular;
      /** Column t (t < n_free) of N is basis[.][t]. */
      Tensor<2, dim> basis;
    };

    /**
     * The force rows of @p rows eliminated (Gram-Schmidt on them, then the
     * unit vectors of the pair's frame that are farthest from their span
     * complete the orthonormal basis). The force rows of pair_rows() are
     * independent.
     */
    template <int dim>
    CondensedPair<dim>
    condense_force_rows(const PairRows<dim> &rows);

    /**
     * The augmentation r of z = f_t + r g_t (3D slip rows): the reciprocal
     * of the pair's mean tangential self-flexibility, so that r g_t is a
     * force of the size of f_t; 0 if the pair is held tangentially.
     */
    template <int dim>
    double
    tangential_stiffness(const Tensor<2, dim> &self_flexibility);
  } // namespace contact
} // namespace fdem
