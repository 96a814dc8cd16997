// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/safety_factor_iteration.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace fdem
{
  namespace analyses
  {
    namespace
    {
      const double nan = std::numeric_limits<double>::quiet_NaN();

      /**
       * The next K after a solved step at K with K* = K + h. Near the limit
       * h(K) = K* - K can fall off faster than linearly (a wedge whose pairs
       * all slip: h ~ (K_limit - K)^1.75 measured), and plain substitution
       * K <- K* then creeps. A secant step on h through the previous solved
       * step extrapolates to h = 0; it is taken only when h has decreased as
       * K rose, and never beyond a K already known to fail (bisect instead).
       *
       * Once a K has failed, the limit is known to be where the static
       * solutions end, and a step aimed at it exactly lands above it about
       * half the time (the secant's own error), which costs a failed solve
       * and a bisection each time (a yielding bar: 33 steps). There the
       * step goes 99 % of the way: the next solve is as close below the
       * limit as the secant was accurate, and each step shrinks the
       * distance a hundredfold.
       */
      double
      next_factor(const Step  &step,
                  const Step  *previous,
                  const double K_low,
                  const double K_high)
      {
        const double K = step.K, h = step.K_star - step.K;
        double       next = step.K_star; // eq. (12): K* itself
        if (previous != nullptr)
          {
            const double previous_h = previous->K_star - previous->K;
            if (previous->K < K && previous_h > h && h > 0)
              next =
                std::max(next, K + h * (K - previous->K) / (previous_h - h));
          }
        if (std::isfinite(K_high) && next > K)
          next = K + 0.99 * (next - K);
        return next < K_high ? next : 0.5 * (K_low + K_high);
      }

      /**
       * The distance still to go to the fixed point: the step to K_next, or
       * where the steps shrink geometrically by rho, that step over
       * (1 - rho).
       */
      double
      distance_left(const Step &step, const double previous_step)
      {
        const double next_step = std::abs(step.K_next - step.K);
        return previous_step > 0 ?
                 next_step / (1 - std::min(next_step / previous_step, 0.99)) :
                 next_step;
      }

      /**
       * Narrows the bracket [K_low, K_high] by the solved @p step and sets
       * its K_next (and distance_left): a step with a factor raises K_low,
       * one without a static solution or with every pair slipping lowers
       * K_high.
       */
      void
      advance(Step        &step,
              const Step  *previous,
              const double previous_step,
              double      &K_low,
              double      &K_high)
      {
        const ReducedStrengthSolution &s = step.solution;
        const double                   K = step.K;
        if (s.has_factor() && s.degenerate)
          {
            // Every pair in contact slips: K* = K whatever K is, which only
            // says that the reduced strength is used up. The limit lies at
            // or below K; go back to K* of the last informative step.
            K_high      = std::min(K_high, K);
            step.K_next = previous != nullptr && previous->K_star < K_high ?
                            previous->K_star :
                          std::isnan(K_low) ? 0.5 * K :
                                              0.5 * (K_low + K_high);
          }
        else if (s.has_factor())
          {
            K_low              = std::isnan(K_low) ? K : std::max(K_low, K);
            step.K_next        = next_factor(step, previous, K_low, K_high);
            step.distance_left = distance_left(step, previous_step);
          }
        else if (!s.converged)
          {
            K_high      = std::min(K_high, K);
            step.K_next = std::isnan(K_low) ? 0.5 * K : 0.5 * (K_low + K_high);
          }
      }

      /**
       * K* independent of K, a planar surface (F_R and F_tau linear in the
       * reduced strengths): with K* = m K + q through the last two solved
       * steps, |m| below 1 % and the fixed point |m| |K* - K| / (1 - |m|)
       * from K* within the tolerance. Its fixed point is then K* itself,
       * whose solve is singular on a planar surface (the limit is a
       * mechanism); it must not lie beyond a K that failed. (Where K* climbs
       * with K, as on a wedge with m of 0.4 to 0.6, the linear model misjudges
       * the distance: eq. (13) decides there.)
       */
      bool
      independent_of_K(const Step  &step,
                       const Step  *previous,
                       const double K_high,
                       const double tolerance)
      {
        if (previous == nullptr || previous->K == step.K)
          return false;
        const double m =
          std::abs((step.K_star - previous->K_star) / (step.K - previous->K));
        return m < 0.01 &&
               m * std::abs(step.K_star - step.K) <=
                 (1 - m) * tolerance * step.K_star &&
               !(K_high < step.K_star * (1 - tolerance));
      }

      /**
       * One line per step, for the default screen: K, K* and the pairs'
       * statuses (F_R and F_tau are in summary.json and the log file).
       */
      void
      log_step(const Step &step, const unsigned int n, std::ostream &log)
      {
        const ReducedStrengthSolution &s = step.solution;
        std::ostringstream             K;
        K << std::setprecision(8) << step.K;
        log << "  step " << std::setw(2) << n << ": K = " << std::left
            << std::setw(11) << K.str() << std::right;
        if (s.has_factor())
          log << " K* = " << std::left << std::setw(11) << std::setprecision(8)
              << step.K_star << std::right << " " << s.n_stick << " stick, "
              << s.n_slip << " slip, " << s.n_open << " open"
              << (s.degenerate ? " (all slipping: K* = K at any K, a bound)" :
                                 "")
              << std::endl;
        else
          log << " no static solution"
              << (s.mechanism ? ": a mechanism" : " (" + s.result + ")")
              << std::endl;
      }
    } // namespace

    Result
    iterate(const std::function<ReducedStrengthSolution(double K)> &solve,
            const parameters::SafetyFactorParameters               &parameters,
            std::ostream                                           &log)
    {
      Result       result;
      const double tolerance = parameters.tolerance;
      double      &K_low = result.bracket_low, &K_high = result.bracket_high;
      double       K = parameters.initial_factor, previous_step = nan;
      const Step  *previous = nullptr; // the last solved step
      result.reason         = "iteration limit reached";
      result.steps.reserve(parameters.max_iterations); // keeps `previous` valid
      for (unsigned int i = 0; i < parameters.max_iterations; ++i)
        {
          Step step{K, nan, nan, nan, solve(K)}; // eqs. (10)-(11)
          const ReducedStrengthSolution &s = step.solution;
          if (s.has_factor())
            step.K_star = K * s.resisting_force / s.sliding_force; // eq. (12)
          advance(step, previous, previous_step, K_low, K_high);
          result.steps.push_back(step);
          log_step(step, result.steps.size(), log);

          if (s.converged && !s.has_factor())
            {
              result.reason = "no sliding force on the sliding surface";
              break;
            }
          // Eq. (13): K* reproduces K, and the distance still to go is as
          // small.
          if (s.has_factor() && !s.degenerate &&
              std::abs(step.K_star - K) <= tolerance * step.K_star &&
              step.distance_left <= tolerance * step.K_star)
            {
              result.reason = "fixed point: K* reproduces K";
              break;
            }
          // A planar limit: K* is the answer, shown by one solve just below it.
          if (s.has_factor() && !s.degenerate &&
              independent_of_K(step, previous, K_high, tolerance))
            {
              result.steps.back().K_next = step.K_star * (1 - 0.25 * tolerance);
              log
                << "  K* is independent of K (a planar limit): solving just below it"
                << std::endl;
            }
          if (!std::isnan(K_low) && K_high - K_low <= tolerance * K_low)
            {
              result.reason =
                "bracket: the largest K with a static solution, to the tolerance";
              break;
            }
          if (std::isnan(K_low) && step.K_next < parameters.minimum_factor)
            {
              result.reason =
                "no static solution for any K down to Safety factor/Minimum factor";
              result.no_equilibrium =
                std::all_of(result.steps.begin(),
                            result.steps.end(),
                            [](const Step &s) { return s.solution.mechanism; });
              break;
            }
          if (s.has_factor() && !s.degenerate)
            {
              previous      = &result.steps.back();
              previous_step = std::abs(result.steps.back().K_next - K);
            }
          else
            previous_step = nan;
          K = result.steps.back().K_next;
        }
      result.certificate =
        certify(result, tolerance, parameters.bracket_agreement);
      result.converged = result.certificate.holds;
      if (result.converged)
        result.safety_factor =
          result.certificate.kind == Certificate::Kind::fixed_point ?
            result.certificate.K_star :
            result.certificate.K;
      return result;
    }
  } // namespace analyses
} // namespace fdem
