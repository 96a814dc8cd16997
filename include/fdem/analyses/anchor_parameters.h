// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <vector>

namespace fdem
{
  namespace analyses
  {
    /**
     * Active anchors across the sliding surface: subsection "Reinforcement"
     * (analyses/anchors.h, doc/theory.md "Anchors"). Anchor k is the
     * prestress force forces[k] pulling its head (on the sliding mass)
     * towards its bond point (in the stable ground), and the bond point
     * towards the head.
     */
    struct AnchorParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /** Reads the subsection; throws naming the entry at the first error. */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /** Number of anchors. */
      unsigned int
      n_anchors() const
      {
        return forces.size();
      }

      /** Each anchor's head and bond point, 2 or 3 coordinates as given (before
       * the Geometry transformation). */
      std::vector<std::vector<double>> heads, bond_points;
      /** Prestress forces: per unit width in 2D, a force in 3D (> 0). */
      std::vector<double> forces;
      /**
       * Whether the anchors' shear component along the sliding surface is a
       * resistance divided by K like c and tan(phi) (Duncan & Wright's
       * method B, Slide's "passive"), or every anchor force an unreduced
       * load (method A, "active").
       */
      bool reduced_by_K = false;

      /** Number of passive bars. */
      unsigned int
      n_bars() const
      {
        return bar_tensile_capacities.size();
      }
      /**
       * Passive bars, nails and piles (doc/theory.md, "Passive bars"): each
       * bar's head (on the sliding mass) and end (in the stable ground), 2 or
       * 3 coordinates as given.
       */
      std::vector<std::vector<double>> bar_heads, bar_ends;
      /** The bar's tensile (and compressive) strength as a force (> 0). */
      std::vector<double> bar_tensile_capacities;
      /** The pull-out resistance per unit length of bar (>= 0; 0: none). */
      std::vector<double> bar_pullout_resistances;
      /** The axial stiffness across the surface, force per length (> 0). */
      std::vector<double> bar_axial_stiffnesses;
      /** The shear capacity and stiffness of a pile (0: a bar or nail). */
      std::vector<double> bar_shear_capacities, bar_shear_stiffnesses;
      /** Whether K divides the bars' capacities like c and tan(phi). */
      bool bar_capacity_reduced_by_K = false;
    };
  } // namespace analyses
} // namespace fdem
