// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/safety_factor/safety_factor.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace fdem
{
  namespace safety_factor
  {
    template <int dim>
    ReducedStrengthSolution
    resisting_and_sliding_forces(const contact::MixedSystem<dim> &         system,
                                 const contact::ContactOutcome<dim> &      outcome,
                                 const std::vector<contact::PairStrength> &reduced_strengths,
                                 const std::vector<bool> &                 on_sliding_surface)
    {
      ReducedStrengthSolution s;
      s.converged            = outcome.converged();
      s.result               = contact::result_description(outcome.result);
      s.n_contact_iterations = outcome.iterations.size();
      double                  sum_f_t = 0;
      dealii::Tensor<1, dim> sum_tangential;
      for (unsigned int p = 0; p < on_sliding_surface.size(); ++p)
        {
          if (!on_sliding_surface[p])
            continue;
          const contact::PairStatus status = outcome.states[p].status;
          s.n_stick += status == contact::PairStatus::stick;
          s.n_slip += status == contact::PairStatus::slip;
          s.n_open += status == contact::PairStatus::open;
          if (!s.converged || status == contact::PairStatus::open)
            continue;
          sum_f_t += outcome.solution.forces[dim * p + 1];
          for (unsigned int i = 1; i < dim; ++i)
            sum_tangential += outcome.solution.forces[dim * p + i] * system.pair(p).frame[i];
          s.resisting_force += reduced_strengths[p].shear_capacity(outcome.solution.forces[dim * p]);
        }
      s.sliding_force = dim == 2 ? std::abs(sum_f_t) : sum_tangential.norm();
      return s;
    }

    namespace
    {
      /**
       * The next K after a solved step at K with K* = K + h. Near the limit
       * h(K) = K* - K can fall off faster than linearly (a wedge whose pairs
       * all slip: h ~ (K_limit - K)^1.75 measured), and plain substitution
       * K <- K* then creeps (design/formulation.md 6.5). A secant step on h
       * through the previous solved step extrapolates to h = 0; it is taken
       * only when h has decreased as K rose, and never beyond a K already
       * known to fail (bisect instead).
       */
      double
      next_factor(const double K, const double h, const double previous_K,
                  const double previous_h, const double K_low, const double K_high)
      {
        double next = K + h; // eq. (12): K* itself
        if (previous_K < K && previous_h > h && h > 0)
          next = std::max(next, K + h * (K - previous_K) / (previous_h - h));
        return next < K_high ? next : 0.5 * (K_low + K_high);
      }
    } // namespace

    Result
    iterate(const std::function<ReducedStrengthSolution(double K)> &solve,
            const parameters::SafetyFactorParameters &              parameters,
            std::ostream &                                          log)
    {
      Result       result;
      const double tolerance = parameters.tolerance;
      double       K         = parameters.initial_factor;
      const double nan       = std::numeric_limits<double>::quiet_NaN();
      double       previous_K = nan, previous_h = nan, previous_step = nan;
      double &     K_low = result.bracket_low, &K_high = result.bracket_high;
      result.reason = "iteration limit reached";
      for (unsigned int i = 0; i < parameters.max_iterations; ++i)
        {
          Step step{K, K, solve(K)}; // eqs. (10)-(11)
          const ReducedStrengthSolution &s      = step.solution;
          double                         K_star = 0;
          if (s.converged && s.sliding_force > 0)
            {
              K_star      = K * s.resisting_force / s.sliding_force; // eq. (12)
              K_low       = std::isnan(K_low) ? K : std::max(K_low, K);
              step.K_next = next_factor(K, K_star - K, previous_K, previous_h, K_low, K_high);
            }
          else if (!s.converged)
            {
              K_high      = std::min(K_high, K);
              step.K_next = std::isnan(K_low) ? 0.5 * K : 0.5 * (K_low + K_high);
            }
          result.steps.push_back(step);
          log << "  safety factor step " << std::setw(2) << result.steps.size()
              << ": K = " << std::setprecision(9) << K;
          if (s.converged && s.sliding_force > 0)
            log << ", F_R = " << s.resisting_force << ", F_tau = " << s.sliding_force
                << ", K* = " << K_star << std::endl;
          else
            log << ": no static solution (" << s.result << ")" << std::endl;

          if (s.converged && !(s.sliding_force > 0))
            {
              result.reason = "no sliding force on the sliding surface";
              break;
            }
          // Eq. (13): K* reproduces K (two successive K* agree), and the
          // distance left to the fixed point is as small. Where the steps
          // shrink geometrically by rho, that distance is the step over
          // (1 - rho), not the step.
          double distance_left = std::abs(step.K_next - K);
          if (s.converged && previous_step > 0)
            distance_left /= 1 - std::min(distance_left / previous_step, 0.99);
          if (s.converged && std::abs(K_star - K) <= tolerance * K_star &&
              distance_left <= tolerance * K_star)
            {
              result.converged     = true;
              result.safety_factor = K_star;
              result.reason        = "two successive K* agree";
              break;
            }
          // K* (nearly) independent of K: a planar surface, where F_R and
          // F_tau are linear in the reduced strengths. With K* = m K + q
          // through the last two solved steps, the fixed point lies
          // |m| |K* - K| / (1 - |m|) from K*, so K* is the answer when that
          // is within the tolerance, without solving at it: the limit of a
          // planar surface has no static solution (a singular system, Sec.
          // 6.4). It must not lie beyond a K whose solve failed. (Where K*
          // still climbs with K, |m| is not small and this does not stop.)
          const double slope =
            (K_star - (previous_K + previous_h)) / (K - previous_K);
          if (s.converged && std::abs(slope) < 1 &&
              std::abs(slope) * std::abs(K_star - K) <=
                (1 - std::abs(slope)) * tolerance * K_star &&
              !(K_high < K_star * (1 - tolerance)))
            {
              result.converged     = true;
              result.safety_factor = K_star;
              result.reason        = "two successive K* agree";
              break;
            }
          if (s.converged)
            {
              previous_K    = K;
              previous_h    = K_star - K;
              previous_step = std::abs(step.K_next - K);
            }
          else
            previous_step = nan;
          if (!std::isnan(K_low) && K_high - K_low <= tolerance * K_low)
            {
              // The largest K with a static solution, to the tolerance.
              result.converged     = true;
              result.safety_factor = K_low;
              result.reason        = "bracket narrower than the tolerance";
              break;
            }
          if (std::isnan(K_low) && step.K_next < parameters.minimum_factor)
            {
              result.reason = "no static solution for any K down to Safety factor/Minimum factor";
              break;
            }
          K = step.K_next;
        }
      return result;
    }

    template ReducedStrengthSolution
    resisting_and_sliding_forces(const contact::MixedSystem<2> &,
                                 const contact::ContactOutcome<2> &,
                                 const std::vector<contact::PairStrength> &,
                                 const std::vector<bool> &);
    template ReducedStrengthSolution
    resisting_and_sliding_forces(const contact::MixedSystem<3> &,
                                 const contact::ContactOutcome<3> &,
                                 const std::vector<contact::PairStrength> &,
                                 const std::vector<bool> &);
  } // namespace safety_factor
} // namespace fdem
