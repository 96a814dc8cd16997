// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/contact/contact_law.h>
#include <fdem/contact/mixed_system.h>

#include <ostream>
#include <string>
#include <vector>

namespace fdem
{
  namespace contact
  {
    /** How a contact solve ended. */
    enum class ContactResult
    {
      /** A fixed point: every pair's state is consistent with its forces and gaps. */
      converged,
      /**
       * The free rigid modes have no equilibrium under the current statuses
       * (RigidModeTest: the dimensionless rigid-mode system is rank
       * deficient), which makes the mixed system singular: a mechanism.
       */
      singular,
      /**
       * The solution runs away: the rigid relative motion exceeds the
       * runaway factor times the elastic relative displacements, a motion
       * that grows without bound (a mechanism).
       */
      runaway,
      /** The iteration limit was reached. */
      iteration_limit,
      /**
       * The rigid modes can be held, but a solve of the mixed system did not
       * reach its accuracy (SolveFailure::numerical): a numerical breakdown,
       * which says nothing about the mechanics.
       */
      numerical_breakdown
    };

    /** A short sentence for each result. */
    std::string
    result_description(const ContactResult result);

    /** One status iteration, as logged and reported. */
    struct StatusIterationRecord
    {
      unsigned int n_stick = 0, n_slip = 0, n_open = 0, n_at_cutoff = 0;
      unsigned int n_changes = 0;
      double       reciprocal_condition = 1;
      /** False if the solve reused the LU factors of an earlier system. */
      bool factorized = true;
      /** 3D: the largest turn of a slip direction in this iteration (degrees). */
      double max_turn = 0;
    };

    /** The outcome of solving the contact problem for given strengths. */
    template <int dim>
    struct ContactOutcome
    {
      ContactResult                      result = ContactResult::converged;
      std::vector<PairState<dim>>        states;
      ContactSolution                    solution;
      std::vector<StatusIterationRecord> iterations;
      /** Cycles of statuses met and broken (design/formulation.md Sec. 6.3). */
      unsigned int n_cycles_broken = 0;
      /**
       * Largest angle (degrees) between a slipping pair's force direction and
       * its slip at convergence: 0 in 2D; in 3D a slipping pair keeps the
       * direction of its trial force (doc/theory.md).
       */
      double max_slip_angle = 0;

      bool
      converged() const
      {
        return result == ContactResult::converged;
      }

      /**
       * True only if the failure is mechanical: no rigid-mode equilibrium
       * under the statuses reached (singular, established on the
       * dimensionless rigid-mode system, the same in any units and for any
       * common E), or a runaway. False when converged, at the iteration
       * limit, and for a numerical breakdown.
       */
      bool
      is_mechanism() const
      {
        return result == ContactResult::singular || result == ContactResult::runaway;
      }
    };

    /** Limits of the status iteration. */
    struct StatusIterationControl
    {
      unsigned int max_iterations = 100;
      /**
       * A solution whose rigid relative motion exceeds this many times the
       * elastic scale (|g_bar|, |C f|) has run away (Sec. 6.4). A ratio of
       * two displacements, both proportional to 1/E: the same in any units
       * and for any common E.
       */
      double runaway_factor = 1e6;
    };

    /** The states every solve starts from without a better guess: gapped pairs open, the rest stick (frictionless ones slip). */
    template <int dim>
    std::vector<PairState<dim>>
    initial_states(const MixedSystem<dim> &system, const std::vector<PairStrength> &strengths);

    /**
     * Solves the contact problem (eq. 9 with the conditions of Table 1) by
     * the status iteration: solve the mixed system with the current states,
     * check every pair, update, repeat until nothing changes. Starts from
     * @p states (warm start). The rules (doc/theory.md):
     * - stick: tension beyond sigma_t A opens the pair; a tangential force
     *   beyond c A - mu f_n makes it slip along that force (in 3D it keeps
     *   that direction while it slips);
     * - slip: tension beyond sigma_t A opens it; slip against the force
     *   (d . g_t < 0) returns it to stick;
     * - open: penetration (g_n < 0) closes it, to slip along its relative
     *   tangential displacement (it has slid while open), or to stick if it
     *   has not;
     * - a status set seen before is a cycle: pairs that go open and closed
     *   within it are held at the tension cut-off (touching, f_n = sigma_t A,
     *   shear strength kept), and pairs that go stick and slip are left to
     *   slip; both for the rest of this solve.
     */
    template <int dim>
    ContactOutcome<dim>
    solve_contact_problem(const MixedSystem<dim> &          system,
                          const std::vector<PairStrength> & strengths,
                          std::vector<PairState<dim>>       states,
                          const StatusIterationControl &    control,
                          std::ostream &                    log);
  } // namespace contact
} // namespace fdem
