// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/contact/contact_law.h>
#include <fdem/contact/mixed_system.h>
#include <fdem/contact/status_iteration.h>
#include <fdem/parameters/model_parameters.h>

#include <functional>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace fdem
{
  /**
   * Analyses on top of one factorised Model: each solves the contact problem
   * of the model for its own strengths and loads, and reuses the model's
   * factorisations. The safety factor of eqs. (10)-(13) is the first.
   */
  namespace analyses
  {
    /** What the iteration needs from one contact solve at reduced strength. */
    struct ReducedStrengthSolution
    {
      bool converged = false;
      /**
       * For a solve without a static solution: whether the failure is a
       * mechanism (the blocks move without bound under the reduced
       * strengths), as opposed to a numerical breakdown.
       */
      bool mechanism = false;
      /** The contact solver's result, in words. */
      std::string  result;
      unsigned int n_contact_iterations = 0;
      /** F_R: shearing resistance of the sliding surface (eq. 11). */
      double resisting_force = 0;
      /** F_tau: sliding force along the sliding direction (eq. 11). */
      double       sliding_force = 0;
      unsigned int n_stick = 0, n_slip = 0, n_open = 0;
      /**
       * Every pair in contact on the sliding surface slips, and their shear
       * forces add up (F_tau = F_R to round-off): eq. (12) then gives K* = K
       * at any K where this state is static, so the step says nothing about
       * the distance to the limit. Such a state bounds the safety factor
       * from above in the iteration; it never certifies it (doc/theory.md,
       * "Degenerate states").
       */
      bool degenerate = false;
      /**
       * Every pair in contact on the sliding surface slips and no passive
       * bar is elastic (degenerate or not). In 3D such states lead up to the
       * limit with K* - K falling off as (K_limit - K)^2: the shears turn
       * towards one direction (doc/theory.md, "The safety-factor
       * iteration").
       */
      bool all_slipping = false;
      /**
       * The slope d(K*)/dK at this K along the solved state (its statuses and
       * slip directions held, the mixed system being the status iteration's
       * linearisation there): computed for all-slipping steps that are not
       * degenerate (a fold), NaN otherwise. The iteration takes Newton
       * steps on sqrt(K* - K) with it (doc/theory.md, "The fold's slope").
       */
      double K_star_slope = std::numeric_limits<double>::quiet_NaN();
      /** Solves of the mixed system for K_star_slope (2, or 0). */
      unsigned int n_slope_solves = 0;

      /** Solved, with a sliding force: K* is defined. */
      bool
      has_factor() const
      {
        return converged && sliding_force > 0;
      }
    };

    /** One step of the iteration: the K solved for, its K*, the K it leads to.
     */
    struct Step
    {
      double K = 0, K_star = 0, K_next = 0;
      /**
       * Solved steps: the distance still to the fixed point, estimated from
       * the step to K_next and the ratio of the last two steps (absolute).
       */
      double distance_left = std::numeric_limits<double>::quiet_NaN();
      ReducedStrengthSolution solution;
    };

    /**
     * Why a reported safety factor can be trusted: what the run computed
     * shows it. A fixed point: a solved state at K whose K* agrees with K to
     * the tolerance, with the estimated distance still to the fixed point
     * as small. A bracket: a solved K_lo whose K* agrees with K_lo to the
     * tolerance, and a K_hi within the tolerance above it whose solve failed
     * as a mechanism (not a numerical breakdown); conservatively, K* may
     * exceed K_lo by up to Safety factor/Bracket agreement, and K_lo, the
     * smaller, is the answer.
     */
    struct Certificate
    {
      enum class Kind
      {
        none,
        fixed_point,
        bracket
      };
      Kind kind = Kind::none;
      /** Whether the numbers below show the safety factor. */
      bool holds = false;
      /**
       * A bracket that holds only conservatively: K* at K_lo exceeds K_lo
       * by more than the tolerance (at most by Bracket agreement), the
       * equilibrium being lost before eq. (12) reaches its limit.
       */
      bool conservative = false;
      /** The solved state it rests on: its K and K*. */
      double K      = std::numeric_limits<double>::quiet_NaN();
      double K_star = std::numeric_limits<double>::quiet_NaN();
      /** |K* - K| / K. */
      double relative_difference = std::numeric_limits<double>::quiet_NaN();
      /** Fixed point: the estimated distance still to go, relative to K. */
      double relative_distance_left = std::numeric_limits<double>::quiet_NaN();
      /** Bracket: the failed K above and how its solve ended. */
      double      K_failed = std::numeric_limits<double>::quiet_NaN();
      std::string failure;
      double      tolerance = 0;
      /** One line: what held, or what disagreed. */
      std::string reason;
    };

    /**
     * K recomputed with the moving blocks (those with free rigid modes)
     * stiffer and softer by a factor (contact solves only): a sliding
     * surface that is a mechanism for rigid blocks gives nearly the same K;
     * one that is not (a kinked surface under one block) gives a K that
     * measures the blocks' elasticity.
     */
    struct StiffnessSensitivity
    {
      bool computed = false;
      /** Why it was not computed, if it was not. */
      std::string not_computed;
      double      factor    = 0;
      double      K_stiffer = std::numeric_limits<double>::quiet_NaN();
      double      K_softer  = std::numeric_limits<double>::quiet_NaN();
      /** max |K_s - K| / K over both; infinite if either is not certified. */
      double relative_change = std::numeric_limits<double>::quiet_NaN();
      /** Wall time of the check (seconds). */
      double wall_seconds = 0;
    };

    /** The safety factor, or the bracket that holds it, and why. */
    struct Result
    {
      bool converged = false;
      /** The safety factor K (NaN if none was found). */
      double safety_factor = std::numeric_limits<double>::quiet_NaN();
      /** Largest K with a static solution and smallest K without (NaN, inf if
       * unknown). */
      double bracket_low  = std::numeric_limits<double>::quiet_NaN();
      double bracket_high = std::numeric_limits<double>::infinity();
      /** The stop test that fired, or why the iteration ended. */
      std::string reason;
      /** Every solve failed, each as a mechanism: no static equilibrium. */
      bool                 no_equilibrium = false;
      Certificate          certificate;
      StiffnessSensitivity stiffness;
      std::vector<Step>    steps;
    };

    /**
     * Eq. (11) over the pairs of the sliding surface. F_R is the sum over
     * the pairs in contact of their shear strength c'A - tan(phi') f_n at
     * the reduced strength (for a compressed pair tan(phi') |f_n| + c'A, as
     * in the paper; open pairs carry none). F_tau is the sliding force: in
     * 2D |sum f_t|, the tangential forces summed along the surface's tangent
     * as in the paper; in 3D, where a pair's tangents have no common
     * direction, each pair's shear along the sliding direction on its
     * tangent plane (the shear resultant projected on it), summed: the 2D
     * sum in plane strain, the resultant's magnitude where every shear is
     * along it (a plane, a wedge at its limit).
     */
    template <int dim>
    ReducedStrengthSolution
    resisting_and_sliding_forces(
      const contact::MixedSystem<dim>          &system,
      const contact::ContactOutcome<dim>       &outcome,
      const std::vector<contact::PairStrength> &reduced_strengths,
      const std::vector<bool>                  &on_sliding_surface);

    /**
     * The paper's iteration, eqs. (10)-(13), with safeguards (doc/theory.md,
     * "The safety factor"): solve at K (@p solve reduces c and tan(phi) by
     * K and returns F_R and F_tau), K* = K F_R / F_tau, repeat from K*; stop
     * when K* reproduces K to the tolerance. A K with no static solution is
     * never a result: the iteration halves K until a solve succeeds when none
     * has yet, else bisects between the largest K that solved and the
     * smallest that did not. The answer is then certified (certify()); a
     * result is converged only if its certificate holds.
     *
     * @p estimate, if given, is called once if the first K fails before any
     * has solved: an estimate of K (the FE-stress factor) to try next instead
     * of half the first K, if it lies below that K and above Safety
     * factor/Minimum factor.
     */
    Result
    iterate(const std::function<ReducedStrengthSolution(double K)> &solve,
            const parameters::SafetyFactorParameters               &parameters,
            std::ostream                                           &log,
            const std::function<double()> &estimate = {});

    /**
     * The certificate of the iteration's answer, from its steps alone: which
     * of the two kinds of Certificate holds, with its numbers, or the one
     * line that says what disagreed.
     */
    Certificate
    certify(const Result &result,
            const double  tolerance,
            const double  bracket_agreement = 0);

    /** "fixed point", "bracket" or "none". */
    std::string
    kind_name(const Certificate::Kind kind);
  } // namespace analyses
} // namespace fdem
