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
  namespace safety_factor
  {
    /** What the iteration needs from one contact solve at reduced strength. */
    struct ReducedStrengthSolution
    {
      bool         converged = false;
      /** The contact solver's result, in words. */
      std::string  result;
      unsigned int n_contact_iterations = 0;
      /** F_R: shearing resistance of the sliding surface (eq. 11). */
      double resisting_force = 0;
      /** F_tau: sliding force along the sliding direction (eq. 11). */
      double sliding_force = 0;
      unsigned int n_stick = 0, n_slip = 0, n_open = 0;
    };

    /** One step of the iteration: the K solved for and the K it leads to. */
    struct Step
    {
      double                  K = 0, K_next = 0;
      ReducedStrengthSolution solution;
    };

    /** The safety factor, or the bracket that holds it, and why. */
    struct Result
    {
      bool converged = false;
      /** The safety factor K (NaN if none was found). */
      double safety_factor = std::numeric_limits<double>::quiet_NaN();
      /** Largest K with a static solution and smallest K without (NaN, inf if unknown). */
      double bracket_low  = std::numeric_limits<double>::quiet_NaN();
      double bracket_high = std::numeric_limits<double>::infinity();
      std::string       reason;
      std::vector<Step> steps;
    };

    /**
     * Eq. (11) over the pairs of the sliding surface. F_R is the sum over
     * the pairs in contact of their shear strength c'A - tan(phi') f_n at
     * the reduced strength (for a compressed pair tan(phi') |f_n| + c'A, as
     * in the paper; open pairs carry none). F_tau is the sliding force: in
     * 2D |sum f_t|, the tangential forces summed along the surface's tangent
     * as in the paper; in 3D, where a pair's tangents have no common
     * direction, the magnitude of the sum of the pairs' tangential force
     * vectors, i.e. the shear resultant along the direction in which it
     * drives the sliding mass (on a wedge at its limit: the line of
     * intersection).
     */
    template <int dim>
    ReducedStrengthSolution
    resisting_and_sliding_forces(const contact::MixedSystem<dim> &         system,
                                 const contact::ContactOutcome<dim> &      outcome,
                                 const std::vector<contact::PairStrength> &reduced_strengths,
                                 const std::vector<bool> &                 on_sliding_surface);

    /**
     * The paper's iteration, eqs. (10)-(13), with safeguards
     * (design/formulation.md Sec. 4, 6): solve at K (@p solve reduces c and
     * tan(phi) by K and returns F_R and F_tau), K* = K F_R / F_tau, repeat
     * from K*; stop when two successive K* agree to the tolerance. A K with
     * no static solution (singular, runaway or unconverged contact) is never
     * a result: the iteration steps back, halving K until a solve succeeds
     * when none has yet, else bisecting between the largest K that solved
     * and the smallest that did not; a K* beyond a failed K is bisected too.
     * When that bracket is narrower than the tolerance, its lower end is
     * the safety factor: the largest K with a static solution.
     */
    Result
    iterate(const std::function<ReducedStrengthSolution(double K)> &solve,
            const parameters::SafetyFactorParameters &              parameters,
            std::ostream &                                          log);
  } // namespace safety_factor
} // namespace fdem
