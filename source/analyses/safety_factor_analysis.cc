// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/fe_stress_factor.h>
#include <fdem/analyses/safety_factor_analysis.h>
#include <fdem/postprocess/run_log.h>

#include <deal.II/base/timer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace fdem
{
  namespace analyses
  {
    template <int dim>
    SafetyFactorAnalysis<dim>::SafetyFactorAnalysis(
      Model<dim>                                  &model,
      std::function<void(double K, double K_star)> on_solved_step)
      : model(model)
      , on_solved_step(std::move(on_solved_step))
      , on_sliding_surface(model.pairs_on_sliding_surface())
    {
      AssertThrow(
        std::find(on_sliding_surface.begin(), on_sliding_surface.end(), true) !=
          on_sliding_surface.end(),
        ExcMessage("Interfaces: no interface is a sliding surface; set "
                   "'Sliding surface = true' on one, or Safety factor/"
                   "Compute = false."));
    }

    template <int dim>
    ReducedStrengthSolution
    SafetyFactorAnalysis<dim>::solve(const double K)
    {
      std::ostringstream what;
      what << "safety factor step: K = " << std::setprecision(8) << K;
      model.progress(what.str());
      const std::vector<contact::PairStrength> strengths =
        model.pair_strengths(K); // eq. (10)
      const auto start = model.warm_start();
      model.solve_contact(strengths, K);
      ReducedStrengthSolution solution;
      {
        TimerOutput::Scope scope(model.phase_timer(), "safety factor");
        solution = resisting_and_sliding_forces(model.get_mixed_system(),
                                                model.get_contact_outcome(),
                                                strengths,
                                                on_sliding_surface); // eq. (11)
      }
      if (solution.all_slipping && !solution.degenerate &&
          solution.has_factor())
        {
          TimerOutput::Scope scope(model.phase_timer(), "contact");
          solution.K_star_slope   = K_star_slope(K, solution);
          solution.n_slope_solves = 2;
        }
      if (solution.has_factor())
        {
          model.log << "  F_R = " << std::setprecision(9)
                    << solution.resisting_force
                    << ", F_tau = " << solution.sliding_force;
          if (!std::isnan(solution.K_star_slope))
            model.log << ", dK*/dK = " << std::setprecision(12)
                      << solution.K_star_slope;
          model.log << std::endl;
        }
      if (solution.converged && on_solved_step)
        on_solved_step(K,
                       solution.has_factor() ?
                         K * solution.resisting_force /
                           solution.sliding_force : // eq. (12)
                         std::numeric_limits<double>::quiet_NaN());
      // The statuses are path dependent: started from a state with every
      // pair slipping, the solve at a lower K tends to find every pair
      // slipping again, below a K where a state with a sticking pair is
      // static. So the next solve starts where this one did.
      if (solution.degenerate)
        model.set_warm_start(start);
      return solution;
    }

    template <int dim>
    double
    SafetyFactorAnalysis<dim>::K_star_slope(const double                   K,
                                            const ReducedStrengthSolution &at_K)
    {
      // Near a fold h = K* - K = rho^2 (L - K)^2 with rho of order one
      // (1.6 on the rock wedge): dK, a hundredth of sqrt(h), is about a
      // sixtieth of the distance to the limit there, where the central
      // difference's error (dK / (L - K))^2 is far below what a step
      // needs, and h is still many times the solves' round-off.
      const double h  = K * at_K.resisting_force / at_K.sliding_force - K;
      const double dK = std::max(1e-2 * std::sqrt(std::max(h, 0.0)), 1e-9 * K);
      const contact::ContactOutcome<dim> &solved = model.get_contact_outcome();
      std::array<double, 2>               K_star{};
      for (unsigned int side = 0; side < 2 && !std::isnan(K_star[0]); ++side)
        {
          const double K_side = side == 0 ? K - dK : K + dK;
          model.apply_strength_dependent_loads(K_side);
          const std::vector<contact::PairStrength> strengths =
            model.pair_strengths(K_side);
          contact::ContactOutcome<dim> moved;
          moved.states   = solved.states;
          moved.solution = model.solve_with_states(solved.states, strengths);
          moved.result   = moved.solution.solved ?
                             contact::ContactResult::converged :
                             contact::ContactResult::numerical_breakdown;
          const ReducedStrengthSolution s = resisting_and_sliding_forces(
            model.get_mixed_system(), moved, strengths, on_sliding_surface);
          K_star[side] = s.has_factor() ?
                           K_side * s.resisting_force / s.sliding_force :
                           std::numeric_limits<double>::quiet_NaN();
        }
      model.apply_strength_dependent_loads(K);
      return (K_star[1] - K_star[0]) / (2 * dK); // NaN if either has none
    }

    template <int dim>
    double
    SafetyFactorAnalysis<dim>::estimate()
    {
      // One more solve on the same factorisations; the model's contact
      // state (the warm start) does not change.
      latest_fe_stress         = fe_stress_factor(model);
      const FeStressFactor &fe = *latest_fe_stress;
      model.log << "  the first K failed: next K the FE-stress factor ";
      if (fe.computed)
        model.log << std::setprecision(8) << fe.factor
                  << " (every pair stuck), if it is below the first"
                  << std::endl;
      else
        model.log << "(not computed: " << fe.not_computed << "): half the first"
                  << std::endl;
      return fe.computed ? fe.factor : std::numeric_limits<double>::quiet_NaN();
    }

    template <int dim>
    Result
    SafetyFactorAnalysis<dim>::run()
    {
      model.brief << "Safety factor iteration (eqs. 10-13):" << std::endl;
      Result result = iterate([this](const double K) { return solve(K); },
                              model.get_parameters().safety_factor,
                              model.brief,
                              [this]() { return estimate(); });
      fe_stress     = std::move(latest_fe_stress);
      model.restore_last_static_state();
      model.log << "Safety factor: ";
      if (result.converged)
        model.log << std::setprecision(8) << result.safety_factor << " ("
                  << result.reason
                  << "; certified: " << kind_name(result.certificate.kind)
                  << ", " << result.certificate.reason << ")" << std::endl;
      else
        model.log << "not certified (" << result.certificate.reason << ")"
                  << std::endl;
      if (result.certificate.conservative)
        {
          std::ostringstream warning;
          const Certificate &c = result.certificate;
          warning
            << "the limit lies between the last static state, K = "
            << std::setprecision(9) << c.K << " (its K* = " << c.K_star
            << "), and a limit state at K = " << c.K_failed << " (" << c.failure
            << ")"
            << ", further apart than the tolerance: equilibrium is lost before K reaches "
               "K* (e.g. a plane lifting off) or solves between failed numerically; K is "
               "the conservative value";
          model.warn(
            postprocess::warning_text("conservative-bound", warning.str()));
        }
      result.stiffness                  = stiffness_sensitivity(result);
      const StiffnessSensitivity &check = result.stiffness;
      if (check.computed &&
          !(check.relative_change <=
            model.get_parameters().safety_factor.stiffness_check_warning))
        {
          std::ostringstream warning;
          if (std::isinf(check.relative_change))
            warning << "K could not be certified";
          else
            warning << "K changes by " << std::setprecision(3)
                    << 100 * check.relative_change << " %";
          warning
            << " with the moving blocks " << check.factor
            << " times stiffer or softer (K = " << std::setprecision(8)
            << check.K_stiffer << ", " << check.K_softer
            << "): K depends on the blocks' stiffness; the sliding surface may not be a "
               "mechanism for rigid blocks (one block on a kinked surface: divide the "
               "sliding mass into blocks at the kinks), and K then measures their elasticity";
          model.warn(
            postprocess::warning_text("stiffness-dependent", warning.str()));
        }
      return result;
    }

    template <int dim>
    StiffnessSensitivity
    SafetyFactorAnalysis<dim>::stiffness_sensitivity(const Result &base)
    {
      const auto          &parameters = model.get_parameters().safety_factor;
      StiffnessSensitivity check;
      check.factor = parameters.stiffness_check_factor;
      if (!parameters.stiffness_check)
        check.not_computed = "Safety factor/Stiffness check = false";
      else if (!base.converged)
        check.not_computed = "no certified safety factor to compare with";
      else if (!model.get_mixed_system().can_scale_moving_compliance())
        check.not_computed =
          "the iterative mixed system does not keep the moving blocks' part of C";
      if (!check.not_computed.empty())
        return check;

      // Each iteration starts where the first did, not from its K: off a
      // mechanism the fixed point is not unique (every K at which all pairs
      // can slip has K* = K), and only the same path compares alike.
      Timer timer; // its share of the run: summary.json
      const contact::ContactOutcome<dim> state = model.get_contact_outcome();
      const double                       K     = model.get_strength_reduction();
      const auto                         step_files =
        std::move(on_solved_step); // no VTU of these steps
      check.computed        = true;
      check.relative_change = 0;
      for (const bool stiffer : {true, false})
        {
          const double scale = stiffer ? 1 / check.factor : check.factor;
          model.log << "Stiffness check: the moving blocks " << check.factor
                    << " times " << (stiffer ? "stiffer" : "softer")
                    << std::endl;
          model.set_moving_compliance_scale(scale);
          model.forget_warm_start();
          const Result r = iterate([this](const double K) { return solve(K); },
                                   parameters,
                                   model.log,
                                   [this]() { return estimate(); });
          (stiffer ? check.K_stiffer : check.K_softer) = r.safety_factor;
          model.brief << "Stiffness check, moving blocks " << check.factor
                      << " times " << (stiffer ? "stiffer: " : "softer:  ");
          if (r.converged)
            model.brief << "K = " << std::setprecision(8) << r.safety_factor
                        << std::endl;
          else
            model.brief << "no certified K (" << r.certificate.reason << ")"
                        << std::endl;
          check.relative_change =
            r.converged ?
              std::max(check.relative_change,
                       std::abs(r.safety_factor - base.safety_factor) /
                         base.safety_factor) :
              std::numeric_limits<double>::infinity();
        }
      model.set_moving_compliance_scale(1);
      model.set_contact_state(state, K);
      on_solved_step     = step_files;
      check.wall_seconds = timer.wall_time();
      model.log << "Stiffness check: K = " << std::setprecision(8)
                << check.K_stiffer << " stiffer, " << check.K_softer
                << " softer; relative change " << std::setprecision(3)
                << check.relative_change << std::endl;
      return check;
    }

    template class SafetyFactorAnalysis<2>;
    template class SafetyFactorAnalysis<3>;
  } // namespace analyses
} // namespace fdem
