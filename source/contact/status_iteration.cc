// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/contact/bar_link.h>
#include <fdem/contact/status_iteration.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <string>

namespace fdem
{
  namespace contact
  {
    std::string
    result_description(const ContactResult result)
    {
      switch (result)
        {
          case ContactResult::converged:
            return "converged";
          case ContactResult::singular:
            return "no rigid-mode equilibrium under the current statuses (a mechanism): "
                   "no static equilibrium";
          case ContactResult::runaway:
            return "runaway solution (the rigid motion grows without bound, a mechanism): "
                   "no static equilibrium";
          case ContactResult::numerical_breakdown:
            return "numerical breakdown: the mixed system could not be solved to accuracy "
                   "although the rigid modes can be held (not a mechanism)";
          default:
            return "status iteration limit reached";
        }
    }

    namespace
    {
      /**
       * Magnitude of the tangential part of a local vector, without
       * squares, which underflow or overflow at the extremes of the Young's
       * modulus (a slip of 1e-170 m or a force of 1e170 N).
       */
      template <int dim>
      double
      tangential_norm(const Vector<double> &v, const unsigned int p)
      {
        if (dim == 2)
          return std::abs(v[dim * p + 1]);
        return std::hypot(v[dim * p + 1], v[dim * p + dim - 1]);
      }

      /** Unit tangential direction of a local vector (+1 in 2D if zero). */
      template <int dim>
      std::array<double, dim - 1>
      tangential_direction(const Vector<double> &v, const unsigned int p)
      {
        std::array<double, dim - 1> d{};
        const double                norm = tangential_norm<dim>(v, p);
        if (norm == 0)
          {
            d[0] = 1;
            return d;
          }
        for (unsigned int i = 1; i < dim; ++i)
          d[i - 1] = v[dim * p + i] / norm;
        return d;
      }

      /**
       * Whether a pair's state differs from the previous one: its status, or
       * in 3D its slip direction by more than a round-off angle.
       */
      template <int dim>
      bool
      changed(const PairState<dim> &next, const PairState<dim> &previous)
      {
        if (next.status != previous.status ||
            next.at_cutoff != previous.at_cutoff ||
            next.yield_sign != previous.yield_sign)
          return true;
        if (next.status != PairStatus::slip)
          return false;
        double distance = 0;
        for (unsigned int i = 0; i < dim - 1; ++i)
          distance +=
            std::pow(next.slip_direction[i] - previous.slip_direction[i], 2);
        return std::sqrt(distance) > 1e-10;
      }

      /**
       * Statuses alike: in 2D also the slip direction (+1 or -1); in 3D,
       * where slip directions vary continuously, status and cut-off only.
       */
      template <int dim>
      bool
      same_statuses(const std::vector<PairState<dim>> &a,
                    const std::vector<PairState<dim>> &b)
      {
        for (unsigned int p = 0; p < a.size(); ++p)
          if (a[p].status != b[p].status || a[p].at_cutoff != b[p].at_cutoff ||
              a[p].yield_sign != b[p].yield_sign ||
              (dim == 2 && a[p].slip_direction != b[p].slip_direction))
            return false;
        return true;
      }

      /**
       * The start of a cycle that @p next closes: the first earlier set of
       * statuses equal to next's with a different set somewhere after it.
       * (In 3D statuses stay alike for several iterations while the slip
       * directions converge: that is no cycle.)
       */
      template <int dim>
      typename std::vector<std::vector<PairState<dim>>>::const_iterator
      find_cycle(const std::vector<std::vector<PairState<dim>>> &history,
                 const std::vector<PairState<dim>>              &next)
      {
        bool differs_after = false;
        for (auto h = history.end(); h != history.begin();)
          {
            --h;
            if (!same_statuses(*h, next))
              differs_after = true;
            else if (differs_after)
              {
                // Rewind to the first of a run of alike sets.
                while (h != history.begin() && same_statuses(*(h - 1), next))
                  --h;
                return h;
              }
          }
        return history.end();
      }

      /** The tangential part of a local vector. */
      template <int dim>
      std::array<double, dim - 1>
      tangential_part(const Vector<double> &v, const unsigned int p)
      {
        std::array<double, dim - 1> t;
        for (unsigned int i = 1; i < dim; ++i)
          t[i - 1] = v[dim * p + i];
        return t;
      }

      /**
       * The angle (degrees) from the unit tangential direction @p d to the
       * tangential vector @p v: in 2D 0 or 180, in 3D from the sine and
       * cosine (acos would floor at 1e-6 degrees in round-off).
       */
      template <int dim>
      double
      tangential_angle(const std::array<double, dim - 1> &d,
                       const std::array<double, dim - 1> &v)
      {
        const double cosine =
          d[0] * v[0] + (dim == 3 ? d[dim - 2] * v[dim - 2] : 0.0);
        const double sine =
          dim == 3 ? d[0] * v[dim - 2] - d[dim - 2] * v[0] : 0.0;
        return std::atan2(std::abs(sine), cosine) * 180 / numbers::PI;
      }
    } // namespace

    template <int dim>
    std::vector<PairState<dim>>
    initial_states(const MixedSystem<dim>          &system,
                   const std::vector<PairStrength> &strengths)
    {
      std::vector<PairState<dim>> states(system.n_pairs());
      for (unsigned int p = 0; p < states.size(); ++p)
        {
          states[p].slip_direction[0] = 1;
          if (system.is_bar(p))
            continue; // elastic
          if (system.pair(p).initial_gap > 0)
            states[p].status = PairStatus::open;
          else if (strengths[p].shear_capacity(0) <= 0 &&
                   strengths[p].friction_coefficient == 0)
            states[p].status = PairStatus::slip; // frictionless
        }
      return states;
    }

    template <int dim>
    StatusIteration<dim>::StatusIteration(
      MixedSystem<dim>                &system,
      const std::vector<PairStrength> &strengths,
      const StatusIterationControl    &control,
      std::ostream                    &log)
      : system(system)
      , strengths(strengths)
      , control(control)
      , log(log)
      , n_pairs(system.n_pairs())
      // Scales for the checks: forces by the largest pair force, gaps by
      // the elastic relative displacements; where those are zero, by the
      // model's characteristic force and displacement (SystemScales). All
      // tolerances are fractions of them, dimensionless.
      , gap_scale(system.external_gap.linfty_norm() > 0 ?
                    system.external_gap.linfty_norm() :
                    system.scales.displacement)
      , frozen(n_pairs)
      , tried_closed(n_pairs, false)
    {}

    template <int dim>
    ContactOutcome<dim>
    StatusIteration<dim>::run(std::vector<PairState<dim>> states)
    {
      ContactOutcome<dim> outcome;
      const auto          end = [&](const ContactResult    result,
                           const ContactSolution &solution,
                           StatusIterationRecord *record) {
        outcome.result = result;
        if (record != nullptr)
          outcome.iterations.push_back(*record);
        outcome.states   = states;
        outcome.solution = solution;
        return outcome;
      };
      frozen.assign(n_pairs, Freeze());
      tried_closed.assign(n_pairs, false);
      history.clear();
      for (unsigned int iteration = 0;; ++iteration)
        {
          history.push_back(states);
          ContactSolution       solution = system.solve(states, strengths);
          StatusIterationRecord record;
          record.reciprocal_condition = solution.reciprocal_condition;
          record.factorized           = solution.factorized;
          if (!solution.solved)
            {
              const bool mechanism =
                solution.failure == SolveFailure::mechanism;
              if (mechanism && close_all_open_pairs(states))
                continue;
              log_failure(solution);
              return end(mechanism ? ContactResult::singular :
                                     ContactResult::numerical_breakdown,
                         solution,
                         &record);
            }

          const double elastic_scale =
            std::max(gap_scale, solution.elastic_displacements.linfty_norm());
          if (runs_away(solution, elastic_scale))
            return end(ContactResult::runaway, solution, &record);

          const double largest_force = solution.forces.linfty_norm();
          const double force_scale =
            largest_force > 0 ? largest_force : system.scales.force;
          const Tolerances            tolerances{1e-10 * force_scale,
                                      1e-10 * elastic_scale};
          std::vector<PairState<dim>> next =
            update_statuses(states, solution, tolerances);

          count_changes(states, next, record);
          outcome.iterations.push_back(record);
          log_iteration(iteration, record, solution);

          if (record.n_changes == 0)
            {
              outcome.max_slip_angle =
                max_slip_angle(states, solution, tolerances.gap);
              return end(ContactResult::converged, solution, nullptr);
            }
          if (iteration + 1 >= control.max_iterations)
            return end(ContactResult::iteration_limit, solution, nullptr);

          if (break_cycle(next, solution.forces))
            ++outcome.n_cycles_broken;
          states = next;
        }
    }

    template <int dim>
    bool
    StatusIteration<dim>::close_all_open_pairs(
      std::vector<PairState<dim>> &states)
    {
      // (With some pairs closed a singular system is a free mechanism, such
      // as a rotation about one touching pair: closing every gap there would
      // force contacts the block never reaches.)
      const bool all_open =
        std::all_of(states.begin(),
                    states.end(),
                    [](const PairState<dim> &state) {
                      return state.status == PairStatus::open;
                    });
      if (!all_open)
        return false;
      unsigned int n_closed = 0;
      for (unsigned int p = 0; p < n_pairs; ++p)
        if (states[p].status == PairStatus::open && !tried_closed[p])
          {
            states[p].status = PairStatus::stick;
            tried_closed[p]  = true;
            ++n_closed;
          }
      if (n_closed == 0)
        return false;
      log << "    no rigid-mode equilibrium with every pair open: " << n_closed
          << " of them closed to hold the blocks" << std::endl;
      history.clear();
      return true;
    }

    template <int dim>
    void
    StatusIteration<dim>::log_failure(const ContactSolution &solution) const
    {
      const RigidModeTest &test = solution.rigid_modes;
      if (solution.failure == SolveFailure::mechanism)
        {
          log << "    no rigid-mode equilibrium: singular-value ratio of the "
                 "equilibrium matrix "
              << test.equilibrium_ratio << ", of the kinematic matrix "
              << test.kinematic_ratio;
          if (test.equilibrium_ratio <= system.rigid_mode_tolerance)
            log << ", unbalanced load " << test.unbalanced_load;
          log << std::endl;
        }
      else
        log
          << "    numerical breakdown: the rigid modes can be held (singular-value "
             "ratios "
          << test.equilibrium_ratio << ", " << test.kinematic_ratio
          << ") but the system was not solved to accuracy (reciprocal condition "
          << solution.reciprocal_condition << ")" << std::endl;
    }

    template <int dim>
    bool
    StatusIteration<dim>::runs_away(const ContactSolution &solution,
                                    const double           elastic_scale) const
    {
      // Rigid relative motion far beyond the elastic scale.
      Vector<double> rigid(solution.forces.size());
      if (!system.rigid_coupling.empty()) // every block held: no motion
        system.rigid_coupling.vmult(rigid, solution.rigid_motions);
      const bool finite =
        std::all_of(solution.forces.begin(),
                    solution.forces.end(),
                    [](const double f) { return std::isfinite(f); });
      return !finite ||
             rigid.linfty_norm() > control.runaway_factor * elastic_scale;
    }

    template <int dim>
    void
    StatusIteration<dim>::turn_slip_direction(
      PairState<dim>        &state,
      const unsigned int     p,
      const ContactSolution &solution) const
    {
      // 3D: the slip direction follows z = f_t + r g_t (the Newton step of
      // the Alart-Curnier projection, see PairState). At the fixed point z,
      // f_t and g_t are parallel.
      const Vector<double> &f = solution.forces;
      const Vector<double> &g = solution.relative_displacements;
      const double          r = system.tangential_stiffness(p);
      double                z[dim - 1];
      for (unsigned int i = 1; i < dim; ++i)
        z[i - 1] = f[dim * p + i] + r * g[dim * p + i];
      // hypot: the squares of z overflow from forces of about 1e154 N.
      const double norm =
        dim == 2 ? std::abs(z[0]) : std::hypot(z[0], z[dim - 2]);
      // Beyond the apex of the Mohr-Coulomb cone (tension above c A / mu,
      // allowed by a larger tensile strength) the capacity is negative and
      // the force points against d: z says nothing about the slip there,
      // and turning d by it flips d back and forth.
      const double capacity = strengths[p].shear_capacity(f[dim * p]);
      if (capacity <= 0)
        state.direction_weight = 0; // no tie between e . g_t and e . f_t
      if (norm == 0 || capacity <= 0)
        return;
      for (unsigned int i = 0; i < dim - 1; ++i)
        state.slip_direction[i] = z[i] / norm;
      state.direction_weight = std::min(capacity / norm, 1.0);
    }

    template <int dim>
    std::vector<PairState<dim>>
    StatusIteration<dim>::update_statuses(
      const std::vector<PairState<dim>> &states,
      const ContactSolution             &solution,
      const Tolerances                  &tolerances) const
    {
      const Vector<double>       &f    = solution.forces;
      const Vector<double>       &g    = solution.relative_displacements;
      std::vector<PairState<dim>> next = states;
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          PairState<dim>     &state    = next[p];
          const PairStrength &strength = strengths[p];
          if (system.is_bar(p))
            {
              Tensor<1, dim> f_p, g_p;
              for (unsigned int i = 0; i < dim; ++i)
                {
                  f_p[i] = f[dim * p + i];
                  g_p[i] = g[dim * p + i];
                }
              state = next_bar_state(states[p],
                                     strength,
                                     system.bar(p),
                                     f_p,
                                     g_p,
                                     tolerances.force,
                                     frozen[p].slipping);
              continue;
            }
          const double f_n = f[dim * p];
          const double g_n = g[dim * p];
          switch (state.status)
            {
              case PairStatus::stick:
              case PairStatus::slip:
                if (!state.at_cutoff &&
                    f_n > strength.tensile_force + tolerances.force)
                  {
                    state.status = PairStatus::open;
                    break;
                  }
                if (state.status == PairStatus::stick)
                  {
                    if (tangential_norm<dim>(f, p) >
                        strength.shear_capacity(f_n) + tolerances.force)
                      {
                        state.status         = PairStatus::slip;
                        state.slip_direction = tangential_direction<dim>(f, p);
                        // alpha = s/|z| with z = f_t (no slip yet); 0 where
                        // |f_t| is 0 (a capacity at or below zero).
                        const double norm = tangential_norm<dim>(f, p);
                        state.direction_weight =
                          norm > 0 ?
                            std::max(strength.shear_capacity(f_n), 0.0) / norm :
                            0.0;
                      }
                  }
                else
                  {
                    double along = 0;
                    for (unsigned int i = 1; i < dim; ++i)
                      along += state.slip_direction[i - 1] * g[dim * p + i];
                    const bool has_strength =
                      strength.friction_coefficient > 0 ||
                      strength.cohesion_force > 0;
                    // Slip against the force: the pair sticks. (A
                    // frictionless pair has no force to slip against.)
                    if (!frozen[p].slipping && along < -tolerances.gap &&
                        has_strength)
                      state.status = PairStatus::stick;
                    else if (dim == 3)
                      turn_slip_direction(state, p, solution);
                  }
                break;
              case PairStatus::open:
                if (g_n < -tolerances.gap)
                  {
                    // Closing: a pair that slid while open closes slipping
                    // along its slide (Sec. 6.1), not stuck at its start.
                    const bool frictionless =
                      strength.friction_coefficient == 0 &&
                      strength.cohesion_force == 0;
                    if (frictionless ||
                        tangential_norm<dim>(g, p) > tolerances.gap)
                      {
                        state.status         = PairStatus::slip;
                        state.slip_direction = tangential_direction<dim>(g, p);
                        state.direction_weight = 0;
                      }
                    else
                      state.status = PairStatus::stick;
                  }
                break;
            }
        }
      return next;
    }

    template <int dim>
    void
    StatusIteration<dim>::count_changes(
      const std::vector<PairState<dim>> &states,
      const std::vector<PairState<dim>> &next,
      StatusIterationRecord             &record) const
    {
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          record.n_changes += changed(next[p], states[p]) ? 1 : 0;
          if (dim == 3 && next[p].status == PairStatus::slip &&
              states[p].status == PairStatus::slip)
            record.max_turn =
              std::max(record.max_turn,
                       tangential_angle<dim>(next[p].slip_direction,
                                             states[p].slip_direction));
          record.n_stick += next[p].status == PairStatus::stick;
          record.n_slip += next[p].status == PairStatus::slip;
          record.n_open += next[p].status == PairStatus::open;
          record.n_at_cutoff += next[p].at_cutoff;
        }
    }

    template <int dim>
    void
    StatusIteration<dim>::log_iteration(const unsigned int           iteration,
                                        const StatusIterationRecord &record,
                                        const ContactSolution &solution) const
    {
      log << "    contact iteration " << std::setw(3) << iteration + 1 << ": "
          << record.n_stick << " stick, " << record.n_slip << " slip, "
          << record.n_open << " open";
      if (record.n_at_cutoff > 0)
        log << " (" << record.n_at_cutoff << " at the tension cut-off)";
      log << ", " << record.n_changes << " changed";
      if (dim == 3)
        log << ", slip directions turned up to " << std::setprecision(3)
            << record.max_turn << " deg" << std::setprecision(6);
      log << "; " << system.describe_solve(solution) << std::endl;
    }

    template <int dim>
    double
    StatusIteration<dim>::max_slip_angle(
      const std::vector<PairState<dim>> &states,
      const ContactSolution             &solution,
      const double                       gap_tolerance) const
    {
      // How far a slipping pair's force is from its slip direction (0 in
      // 2D; in 3D the direction is the trial force's).
      const Vector<double> &g     = solution.relative_displacements;
      double                angle = 0;
      for (unsigned int p = 0; p < n_pairs; ++p)
        if (states[p].status == PairStatus::slip && !system.is_bar(p) &&
            tangential_norm<dim>(g, p) > gap_tolerance)
          angle = std::max(angle,
                           tangential_angle<dim>(states[p].slip_direction,
                                                 tangential_part<dim>(g, p)));
      return angle;
    }

    template <int dim>
    bool
    StatusIteration<dim>::break_cycle(std::vector<PairState<dim>> &next,
                                      const Vector<double>        &forces)
    {
      // A state seen before closes a cycle: break it (Sec. 6.2, 6.3).
      const auto seen = find_cycle(history, next);
      if (seen == history.end())
        return false;
      unsigned int n_frozen = 0;
      for (unsigned int p = 0; p < n_pairs; ++p)
        {
          bool was_open = false, was_closed = false, was_stick = false,
               was_slip = false;
          for (auto h = seen; h != history.end(); ++h)
            {
              const PairStatus s = (*h)[p].status;
              was_open |= s == PairStatus::open;
              was_closed |= s != PairStatus::open;
              was_stick |= s == PairStatus::stick;
              was_slip |= s == PairStatus::slip;
            }
          if (system.is_bar(p))
            {
              // A bar's component that went elastic and yielded within the
              // cycle stays yielded, at the sign of its force now.
              bool held = false;
              for (unsigned int i = 0; i < dim; ++i)
                {
                  bool was_elastic = false, was_yielded = false;
                  for (auto h = seen; h != history.end(); ++h)
                    {
                      was_elastic |= (*h)[p].yield_sign[i] == 0;
                      was_yielded |= (*h)[p].yield_sign[i] != 0;
                    }
                  if (was_elastic && was_yielded && !frozen[p].slipping)
                    {
                      next[p].yield_sign[i] = forces[dim * p + i] > 0 ? 1 : -1;
                      next[p].status        = PairStatus::slip;
                      held                  = true;
                    }
                }
              if (held)
                {
                  frozen[p].slipping = true;
                  ++n_frozen;
                }
              continue;
            }
          if (was_open && was_closed && !frozen[p].at_cutoff)
            {
              frozen[p].at_cutoff = true;
              next[p].at_cutoff   = true;
              if (next[p].status == PairStatus::open)
                next[p].status = PairStatus::stick;
              ++n_frozen;
            }
          else if (was_stick && was_slip && !frozen[p].slipping)
            {
              frozen[p].slipping     = true;
              next[p].status         = PairStatus::slip;
              next[p].slip_direction = tangential_direction<dim>(forces, p);
              ++n_frozen;
            }
        }
      log << "    status cycle of length " << history.end() - seen
          << " broken: " << n_frozen << " pairs held" << std::endl;
      // Cycles are looked for from here on: the held pairs changed the
      // problem.
      history.clear();
      return true;
    }

    template <int dim>
    ContactOutcome<dim>
    solve_contact_problem(MixedSystem<dim>                &system,
                          const std::vector<PairStrength> &strengths,
                          std::vector<PairState<dim>>      states,
                          const StatusIterationControl    &control,
                          std::ostream                    &log)
    {
      return StatusIteration<dim>(system, strengths, control, log)
        .run(std::move(states));
    }

    template std::vector<PairState<2>>
    initial_states(const MixedSystem<2> &, const std::vector<PairStrength> &);
    template std::vector<PairState<3>>
    initial_states(const MixedSystem<3> &, const std::vector<PairStrength> &);
    template class StatusIteration<2>;
    template class StatusIteration<3>;
    template ContactOutcome<2>
    solve_contact_problem(MixedSystem<2> &,
                          const std::vector<PairStrength> &,
                          std::vector<PairState<2>>,
                          const StatusIterationControl &,
                          std::ostream &);
    template ContactOutcome<3>
    solve_contact_problem(MixedSystem<3> &,
                          const std::vector<PairStrength> &,
                          std::vector<PairState<3>>,
                          const StatusIterationControl &,
                          std::ostream &);
  } // namespace contact
} // namespace fdem
