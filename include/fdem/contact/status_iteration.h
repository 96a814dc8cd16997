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
      /** A fixed point: every pair's state is consistent with its forces and
         gaps. */
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
      unsigned int n_changes            = 0;
      double       reciprocal_condition = 1;
      /** False if the solve reused the LU factors of an earlier system. */
      bool factorized = true;
      /** 3D: the largest turn of a slip direction in this iteration (degrees).
       */
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
      /** Cycles of statuses met and broken (doc/theory.md). */
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
        return result == ContactResult::singular ||
               result == ContactResult::runaway;
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

    /** The states every solve starts from without a better guess: gapped pairs
     * open, the rest stick (frictionless ones slip). */
    template <int dim>
    std::vector<PairState<dim>>
    initial_states(const MixedSystem<dim>          &system,
                   const std::vector<PairStrength> &strengths);

    /**
     * The status iteration that solves the contact problem (eq. 9 with the
     * conditions of Table 1): solve the mixed system with the current
     * states, check every pair, update, repeat until nothing changes. run()
     * starts from given states (warm start) and goes through its phases in
     * each iteration:
     * - solve (MixedSystem::solve); if it fails, close_all_open_pairs() when
     *   every pair is open and nothing holds the blocks, or end;
     * - runs_away(): the runaway test (doc/theory.md);
     * - update_statuses(), by the rules (doc/theory.md):
     *   - stick: tension beyond sigma_t A opens the pair; a tangential force
     *     beyond c A - mu f_n makes it slip along that force (in 3D it keeps
     *     that direction while it slips);
     *   - slip: tension beyond sigma_t A opens it; slip against the force
     *     (d . g_t < 0) returns it to stick;
     *   - open: penetration (g_n < 0) closes it, to slip along its relative
     *     tangential displacement (it has slid while open), or to stick if
     *     it has not;
     * - count_changes() and log them; converged when nothing changed;
     * - break_cycle(): a status set seen before is a cycle: pairs that go
     *   open and closed within it are held at the tension cut-off (touching,
     *   f_n = sigma_t A, shear strength kept), and pairs that go stick and
     *   slip are left to slip; both for the rest of this solve.
     */
    template <int dim>
    class StatusIteration
    {
    public:
      /** The iteration for @p system with the pairs' @p strengths; it logs on
       * @p log. */
      StatusIteration(MixedSystem<dim>                &system,
                      const std::vector<PairStrength> &strengths,
                      const StatusIterationControl    &control,
                      std::ostream                    &log);

      /** Iterates from @p states to a fixed point, or to why there is none. */
      ContactOutcome<dim>
      run(std::vector<PairState<dim>> states);

    private:
      /** How a pair is held to break a cycle (both may apply). */
      struct Freeze
      {
        bool at_cutoff = false, slipping = false;
      };

      /** Tolerances of the status tests in one iteration (fractions of its
       * scales). */
      struct Tolerances
      {
        double force = 0, gap = 0;
      };

      /**
       * With every pair open nothing holds a free block, e.g. one that
       * starts above its gapped support: closes them all (the gaps close
       * under the load) and lets tension reopen them, once per pair. False
       * if not every pair is open or none is left to close.
       */
      bool
      close_all_open_pairs(std::vector<PairState<dim>> &states);

      /** Logs why a solve failed: a mechanism or a numerical breakdown. */
      void
      log_failure(const ContactSolution &solution) const;

      /** Rigid relative motion beyond the runaway factor times @p
       * elastic_scale, or forces not finite. */
      bool
      runs_away(const ContactSolution &solution,
                const double           elastic_scale) const;

      /** The states that the solution asks for, by the rules above. */
      std::vector<PairState<dim>>
      update_statuses(const std::vector<PairState<dim>> &states,
                      const ContactSolution             &solution,
                      const Tolerances                  &tolerances) const;

      /** 3D: turns the slip direction of pair @p p towards z = f_t + r g_t. */
      void
      turn_slip_direction(PairState<dim>        &state,
                          const unsigned int     p,
                          const ContactSolution &solution) const;

      /** The counts of @p next and how it differs from @p states into @p
       * record. */
      void
      count_changes(const std::vector<PairState<dim>> &states,
                    const std::vector<PairState<dim>> &next,
                    StatusIterationRecord             &record) const;

      /** One line on the log for iteration @p iteration. */
      void
      log_iteration(const unsigned int           iteration,
                    const StatusIterationRecord &record,
                    const ContactSolution       &solution) const;

      /**
       * Largest angle between a slipping pair's slip direction and its
       * relative tangential displacement, over the pairs that moved.
       */
      double
      max_slip_angle(const std::vector<PairState<dim>> &states,
                     const ContactSolution             &solution,
                     const double                       gap_tolerance) const;

      /**
       * If @p next closes a cycle of the statuses since the last break,
       * holds the pairs that change within it (@p forces gives the slip
       * direction of those left to slip) and clears the history. True if
       * it broke one.
       */
      bool
      break_cycle(std::vector<PairState<dim>> &next,
                  const Vector<double>        &forces);

      MixedSystem<dim>                &system;
      const std::vector<PairStrength> &strengths;
      const StatusIterationControl     control;
      std::ostream                    &log;
      const unsigned int               n_pairs;
      /**
       * The scale of the gaps in the status tests: the elastic relative
       * displacements, or where those are zero the model's characteristic
       * displacement (SystemScales).
       */
      const double                             gap_scale;
      std::vector<Freeze>                      frozen;
      std::vector<bool>                        tried_closed;
      std::vector<std::vector<PairState<dim>>> history;
    };

    /** StatusIteration(system, strengths, control, log).run(states). */
    template <int dim>
    ContactOutcome<dim>
    solve_contact_problem(MixedSystem<dim>                &system,
                          const std::vector<PairStrength> &strengths,
                          std::vector<PairState<dim>>      states,
                          const StatusIterationControl    &control,
                          std::ostream                    &log);
  } // namespace contact
} // namespace fdem
