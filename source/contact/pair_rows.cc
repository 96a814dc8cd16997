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

      // A slipping pair in 3D with a tangent held (on the rollers of a
      // side, where both blocks are held across it) cannot slip along it:
      // its force there goes into the supports (f = 0) and the slip lies
      // along the other tangent, whose limit row follows 2D's below, with d
      // the sign of the slip along it. The linearised rows would instead tie
      // the held direction's force to its gap, which is zero identically:
      // with alpha = 1 the row turning the force vanishes with the held
      // direction's column of C, the system has a zero row and a zero
      // column per such pair, and it was a numerical breakdown on the
      // cylinder meshed with tetrahedra (doc/theory.md, "3D").
      const bool slip_along_held = dim == 3 &&
                                   state.status == PairStatus::slip &&
                                   (held(1) || held(dim - 1));
      if (dim == 3 && state.status == PairStatus::slip && !slip_along_held)
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
        if (state.status == PairStatus::slip && !(slip_along_held && held(i)))
          {
            // f_t = d (c A - mu f_n): the force at the Mohr-Coulomb limit
            // along the slip direction d (in 3D along the free tangent of a
            // pair with the other held, d = +-1 by the sign of the slip).
            const double d   = slip_along_held ?
                                 (state.slip_direction[i - 1] < 0 ? -1.0 : 1.0) :
                                 state.slip_direction[i - 1];
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

    template <int dim>
    CondensedPair<dim>
    condense_force_rows(const PairRows<dim> &rows)
    {
      CondensedPair<dim>              condensed;
      std::array<Tensor<1, dim>, dim> q; // orthonormal, spanning the rows
      unsigned int                    n_q    = 0;
      unsigned int                    n_kept = 0;
      // Twice orthogonalised against q (classical Gram-Schmidt twice keeps
      // the basis orthonormal to round-off).
      const auto orthogonalised = [&](Tensor<1, dim> a) {
        for (unsigned int pass = 0; pass < 2; ++pass)
          for (unsigned int j = 0; j < n_q; ++j)
            a -= (a * q[j]) * q[j];
        return a;
      };
      for (unsigned int i = 0; i < dim; ++i)
        {
          if (rows.is_gap_row(i))
            {
              condensed.kept_rows[n_kept++] = i;
              continue;
            }
          // a . f = v: the particular force moves along the new direction
          // only, so that the earlier force rows (spanned by the earlier q,
          // orthogonal to it) stay satisfied.
          const Tensor<1, dim> a      = rows.force[i];
          const Tensor<1, dim> normal = orthogonalised(a);
          const double         length = normal.norm();
          Assert(length > 1e-8 * a.norm(),
                 ExcMessage("A pair's force rows are not independent."));
          q[n_q] = normal / length;
          condensed.particular +=
            (rows.value[i] - a * condensed.particular) / length * q[n_q];
          ++n_q;
        }
      // Complete the basis by the unit vectors farthest from its span.
      condensed.n_free = dim - n_q;
      for (unsigned int t = 0; t < condensed.n_free; ++t)
        {
          Tensor<1, dim> best;
          for (unsigned int k = 0; k < dim; ++k)
            {
              Tensor<1, dim> e;
              e[k]                   = 1;
              const Tensor<1, dim> r = orthogonalised(e);
              if (r.norm_square() > best.norm_square())
                best = r;
            }
          q[n_q] = best / best.norm();
          for (unsigned int k = 0; k < dim; ++k)
            condensed.basis[k][t] = q[n_q][k];
          ++n_q;
        }
      Assert(n_kept == condensed.n_free, ExcInternalError());
      return condensed;
    }

    template CondensedPair<2>
    condense_force_rows(const PairRows<2> &);
    template CondensedPair<3>
    condense_force_rows(const PairRows<3> &);
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
