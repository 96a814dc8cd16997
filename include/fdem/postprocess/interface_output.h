// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/elastic_block.h>
#include <fdem/contact/interface_pairs.h>
#include <fdem/contact/mixed_system.h>

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace fdem
{
  namespace postprocess
  {
    /** What the output says about one node pair. */
    template <int dim>
    struct PairResult
    {
      dealii::Point<dim> position;
      /** f_n: force of block I on block J along n (> 0 tension). */
      double normal_force = 0;
      /** f_t (2D), f_t1 and f_t2 (3D). */
      std::array<double, dim - 1> tangential_force{};
      /** -f_n / A (> 0 in compression). */
      double normal_pressure = 0;
      /** |f_t| / A. */
      double shear_stress = 0;
      /** g_n: normal relative displacement plus initial gap (> 0 open). */
      double gap = 0;
      /** Tangential relative displacement (2D: along t; 3D: magnitude). */
      double              slip   = 0;
      contact::PairStatus status = contact::PairStatus::stick;
      double              area = 0, initial_gap = 0;
      /**
       * The pair's full-strength cohesion (its cohesive force over its area)
       * and friction angle (degrees): the interface's, or the materials'
       * with Strength = material (0 and 0 for a frictionless interface).
       */
      double cohesion = 0, friction_angle = 0;
      /**
       * Local safety factor: the pair's full shear strength c A - tan(phi)
       * f_n over its mobilised shear |f_t|; 0 for an open pair, at most 1000
       * (a pair with no shear).
       */
      double local_safety_factor = 0;
      /** Normal pressure of an exact solution here, if the case has one (else
       * NaN, not written). */
      double reference_pressure = std::numeric_limits<double>::quiet_NaN();
    };

    /** Per-pair results of @p interface, whose first pair is @p first_pair
     * overall. */
    template <int dim>
    std::vector<PairResult<dim>>
    pair_results(const contact::Interface<dim>              &interface,
                 const unsigned int                          first_pair,
                 const contact::ContactSolution             &solution,
                 const std::vector<contact::PairState<dim>> &states,
                 const std::vector<contact::PairStrength>   &full_strengths);

    /**
     * Extent of the contact zone: its length in 2D (doc/theory.md
     * asks for an estimate from the whole pressure profile, not the
     * last closed pair, which jumps by a pair spacing). Pairs are ordered
     * along the chord of the interface; each run of closed pairs counts from
     * edge to edge. An edge at the end of the interface is that end; an edge
     * next to an open pair is where the square of the pressure, fitted by a
     * quadratic over the outer half of the run, reaches zero (exact in form
     * for the elliptic Hertz profile). In 3D: the total tributary area of
     * the closed pairs.
     */
    template <int dim>
    double
    contact_extent(const std::vector<PairResult<dim>> &results);

    /**
     * The index of the pair of @p results farthest from @p x (the first of
     * equals): from pair 0, then from that one, the two ends of an
     * interface's chord.
     */
    template <int dim>
    unsigned int
    farthest_pair(const std::vector<PairResult<dim>> &results,
                  const dealii::Point<dim>           &x);

  } // namespace postprocess
} // namespace fdem
