// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <array>
#include <string>

namespace fdem
{
  namespace contact
  {
    /** Contact status of a node pair (the paper's Table 1). */
    enum class PairStatus
    {
      stick,
      slip,
      open
    };

    /** "stick", "slip" or "open". */
    std::string
    status_name(const PairStatus status);

    /**
     * Strength of one node pair (Mohr-Coulomb with cohesion and a tension
     * cut-off, the paper's Table 1), as forces: the admissible set is
     * |f_t| <= cohesion_force - friction_coefficient * f_n and
     * f_n <= tensile_force (f_n > 0 is tension).
     */
    struct PairStrength
    {
      /** mu = tan(phi). */
      double friction_coefficient = 0;
      /** c A (force). */
      double cohesion_force = 0;
      /** sigma_t A (force, >= 0). */
      double tensile_force = 0;
      /**
       * A reinforcement bar's link (contact/bar_link.h) only: the axial
       * force N_y and the shear force V_y at which the bar yields, as the
       * current K reduces them (forces, per unit width in 2D). Contact
       * pairs leave them 0.
       */
      double bar_axial_capacity = 0, bar_shear_capacity = 0;

      /** Shear capacity c A - mu f_n at the normal force @p f_n. */
      double
      shear_capacity(const double normal_force) const
      {
        return cohesion_force - friction_coefficient * normal_force;
      }
    };

    /**
     * The state of a pair in the status iteration: its status, the
     * direction in which it slips (a unit vector in the tangent plane; +1 or
     * -1 in 2D), and whether it is held at the tension cut-off (the corner of
     * the admissible set, doc/theory.md): a closed
     * pair whose normal force is fixed at sigma_t A while its tangential
     * status still applies.
     *
     * In 3D the slip direction is itself an unknown: the tangential force
     * must lie along the slip. A slipping pair's rows are the Newton
     * linearisation of f_t = s z/|z|, z = f_t + r g_t (Alart-Curnier), about
     * the previous iterate; @p direction_weight is alpha = s/|z| there. With
     * alpha = 0 the direction is held fixed (the first slipping iterate).
     */
    template <int dim>
    struct PairState
    {
      PairStatus                  status = PairStatus::stick;
      std::array<double, dim - 1> slip_direction{};
      bool                        at_cutoff        = false;
      double                      direction_weight = 0;
      /**
       * A reinforcement bar's link only (contact/bar_link.h): per component
       * of its frame (axial first), 0 while elastic, +1 or -1 when yielded
       * at plus or minus its capacity. Its status is then stick while every
       * component is elastic and slip once one has yielded.
       */
      std::array<int, dim> yield_sign{};
    };
  } // namespace contact
} // namespace fdem
