// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/safety_factor_iteration.h>

#include <algorithm>
#include <array>
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
       * The solved steps that inform the next K: the last three that had a
       * factor and were not degenerate, the latest first (nullptr where
       * there are fewer).
       */
      using History = std::array<const Step *, 3>;

      /** Where K* - K reaches zero by fold_limit(), and where to aim. */
      struct Fold
      {
        /** The extrapolated limit (NaN if the steps are not of the kind). */
        double limit = nan;
        /** A K below it that a step can aim at without overshooting. */
        double aim = nan;
        /**
         * Three steps, and the limit agrees with the secant on sqrt(h)
         * through the latest two to 3 tolerances: the parabola's error is
         * then far below the tolerance (its error is of the cube of the
         * distances, the secant's of their square), and the iteration can
         * go for the end of the solves below it (next_factor()).
         */
        bool known = false;
        /** Extrapolated with the steps' slopes of K* (fold_by_slope()). */
        bool by_slope = false;
        /** An estimate of the limit's error (fold_by_slope(); else 0). */
        double error = 0;
      };

      /** q = h/(-h') of a fold step with a slope (fold_by_slope()), else
       * NaN. */
      double
      q_of(const Step *step)
      {
        if (step == nullptr || !std::isfinite(step->solution.K_star_slope))
          return nan;
        const double h     = step->K_star - step->K;
        const double slope = step->solution.K_star_slope - 1; // h'(K)
        return step->solution.all_slipping && h > 0 && slope < 0 &&
                   slope >= -0.5 ?
                 h / -slope :
                 nan;
      }

      /**
       * L of fold_by_slope() at @p step after @p previous (or nullptr); NaN
       * if @p step is no fold step with a slope. @p two_slopes: whether
       * both had one.
       */
      double
      limit_by_slope(const Step *step,
                     const Step *previous,
                     bool       &two_slopes,
                     bool       &fitted_to_h)
      {
        const double q = q_of(step);
        two_slopes     = false;
        fitted_to_h    = false;
        if (std::isnan(q))
          return nan;
        const bool   earlier    = previous != nullptr && previous->K < step->K;
        const double previous_q = earlier ? q_of(previous) : nan;
        two_slopes              = !std::isnan(previous_q);
        double p                = 2;
        if (two_slopes && previous_q > q)
          p = (step->K - previous->K) / (previous_q - q);
        else if (!two_slopes && earlier &&
                 previous->K_star - previous->K > step->K_star - step->K)
          {
            fitted_to_h = true;
            // h_1/h_0 = (1 + (K_0 - K_1)/(p q))^p: its left side rises
            // with p, towards exp((K_0 - K_1)/q).
            const double ratio = std::log((previous->K_star - previous->K) /
                                          (step->K_star - step->K));
            const double dK    = step->K - previous->K;
            const auto   f     = [&](const double p) {
              return p * std::log1p(dK / (p * q)) - ratio;
            };
            double lo = 1, hi = 2;
            if (f(lo) >= 0)
              hi = lo;
            else if (f(hi) <= 0)
              lo = hi;
            for (unsigned int i = 0; i < 60 && hi - lo > 1e-6; ++i)
              (f(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
            p = 0.5 * (lo + hi);
          }
        return step->K + std::clamp(p, 1.0, 2.0) * q;
      }

      /**
       * The fold from the steps' slopes of K* (K_star_slope), with the
       * model h = K* - K = c (L - K)^p: at a step, L - K = p q with
       * q = h/(-h'). Its exponent p is 2 near a fold (every pair slipping in
       * 3D, fold_limit()) but can be far less further away (measured 2.04
       * on prm/rock_wedge.prm 4.4 % below its limit, 1.1 on prm/slope_3d.prm
       * 4 % below), so it is taken from the steps (limit_by_slope()), kept
       * between 1 and 2:
       * - two fold steps with slopes: p = (K_0 - K_1)/(q_1 - q_0), exact for
       *   the model;
       * - one, after a solved step with a larger h: the p for which the
       *   model through this step's h and h' has that step's h too;
       * - one alone: p = 2 (Newton's step on sqrt(h)).
       * The aim: 95 % of the way to that L, 90 % where p came from the
       * earlier step's h (its L lay 8.5 % of the distance beyond the limit
       * on the slope).
       *
       * The limit is known from Newton's roots on sqrt(h) (p = 2, the
       * fold's own exponent), which on the wedge lie 1 to 4 % of the
       * distance off the limit from 4.4 % to 0.3 % below it, their error
       * then falling as the distance to a power between 1.5 and 2: the
       * error of this step's root is estimated as the previous root's (the
       * two roots' difference, this one being far closer) times the ratio
       * of the two steps' distances to their roots to the power 1.5. Within
       * 2 @p tolerance (relative) the limit is known to be this root:
       * next_factor() then aims below it by the error as well, and the
       * distance still to go counts it. A step whose slope of h is not
       * between -1/2 and 0 is no fold step (the test of fold_limit() on
       * two steps without slopes): no fold.
       */
      Fold
      fold_by_slope(const History &history, const double tolerance)
      {
        const Step  *step       = history[0];
        bool         two_slopes = false, fitted_to_h = false;
        const double limit =
          limit_by_slope(step, history[1], two_slopes, fitted_to_h);
        if (std::isnan(limit))
          return {};
        Fold fold{limit,
                  step->K + (fitted_to_h ? 0.9 : 0.95) * (limit - step->K),
                  false,
                  true,
                  0};
        if (two_slopes)
          {
            // Known by Newton's roots on sqrt(h) (p = 2, the fold's own
            // exponent): this step's and the previous one's.
            const Step  *previous      = history[1];
            const double root          = step->K + 2 * q_of(step);
            const double previous_root = previous->K + 2 * q_of(previous);
            const double error =
              std::abs(root - previous_root) *
              std::pow((root - step->K) / (previous_root - previous->K), 1.5);
            if (error <= 2 * tolerance * step->K)
              fold = {root, root, true, true, error};
          }
        return fold;
      }

      /**
       * L of h = c (L - K)^p through three points (K_i, h_i), K rising, h
       * falling: the root of ln((L-K_0)/(L-K_1)) / ln((L-K_1)/(L-K_2)) =
       * ln(h_0/h_1) / ln(h_1/h_2) above K_2 (points latest last), by
       * bisection; NaN where there is none (h falling off exponentially).
       */
      double
      power_law_limit(const std::array<double, 3> &K,
                      const std::array<double, 3> &h)
      {
        const double r = std::log(h[0] / h[1]) / std::log(h[1] / h[2]);
        const auto   f = [&](const double L) {
          return std::log((L - K[0]) / (L - K[1])) /
                   std::log((L - K[1]) / (L - K[2])) -
                 r;
        };
        double lo = K[2], hi = K[2] + (K[2] - K[0]);
        for (unsigned int i = 0; i < 40 && !(f(hi) > 0); ++i)
          hi = K[2] + 2 * (hi - K[2]);
        if (!(f(hi) > 0))
          return nan;
        for (unsigned int i = 0; i < 100 && hi - lo > 1e-15 * hi; ++i)
          {
            const double mid       = 0.5 * (lo + hi);
            (f(mid) > 0 ? hi : lo) = mid;
          }
        return hi;
      }

      /**
       * Where K* - K reaches zero, extrapolated from the steps of @p history
       * if each had every pair slipping, at rising K with falling K* - K and
       * rising K*.
       * Such states lead up to the limit of a 3D sliding mass: as K nears
       * it, the slip directions turn towards one, and K* - K, which measures
       * how far the shears cancel, falls off as the square of the distance:
       * h = a (L - K)^2 (1 + b (L - K)) (measured on prm/rock_wedge.prm: the
       * local exponent goes 1.72, 1.88, 1.95, 1.99 from 5e-3 to 1e-4 below
       * L). A secant on h then only halves the distance per step.
       *
       * The limit: sqrt(h) is nearly linear in K, and a parabola through
       * three (K, sqrt(h)) (Muller's method) extrapolates to L with an error
       * of the cube of the distances (1.3e-5 from 1e-3 below L, 5e-8 from
       * 1.4e-4); with two steps, the secant on sqrt(h). Further away the
       * exponent is below 2 and both overshoot (by 0.8 % from 1.6e-2 below
       * L). The aim: the lowest of that, the power law c (L - K)^p through
       * the three (which undershoots there by 1 to 8 % of the distance) and
       * K plus a quarter of the three steps' span; with two steps, the
       * secant on h. The limit is known (Fold::known) once the secant on
       * sqrt(h) through the latest two agrees with the parabola to 3
       * @p tolerance (relative): on the wedge from 2e-5 below L, where the
       * parabola is 2e-8 from it.
       */
      Fold
      fold_limit(const History &history, const double tolerance)
      {
        if (history[0] != nullptr &&
            std::isfinite(history[0]->solution.K_star_slope))
          return fold_by_slope(history, tolerance);
        std::array<double, 3> K{}, h{};
        unsigned int          n = 0;
        for (; n < 3 && history[n] != nullptr; ++n)
          {
            const Step &step = *history[n];
            K[n]             = step.K;
            h[n]             = step.K_star - step.K;
            // h falling at most half as fast as K rises (K* climbing with
            // K): a planar limit, where K* is independent of K, falls as
            // fast and is no fold.
            if (!step.solution.all_slipping || !(h[n] > 0) ||
                (n > 0 && !(K[n] < K[n - 1] && h[n] > h[n - 1] &&
                            h[n] - h[n - 1] <= 0.5 * (K[n - 1] - K[n]))))
              break;
          }
        if (n < 2)
          return {};
        // Newton's form through (K_0, g_0), (K_1, g_1) [, (K_2, g_2)] with
        // g = sqrt(h), in t = K - K_0: g = g_0 + beta t + d2 t^2.
        const std::array<double, 3> g = {
          {std::sqrt(h[0]), std::sqrt(h[1]), std::sqrt(h[2])}};
        const double d1 = (g[0] - g[1]) / (K[0] - K[1]);
        const double d2 =
          n < 3 ? 0.0 : (d1 - (g[1] - g[2]) / (K[1] - K[2])) / (K[0] - K[2]);
        const double beta  = d1 + d2 * (K[0] - K[1]);
        const double disc  = beta * beta - 4 * d2 * g[0];
        const double t_two = -g[0] / d1;
        if (n < 3 || disc < 0)
          return {K[0] + t_two,
                  K[0] + h[0] * ((K[0] - K[1]) / (h[1] - h[0])),
                  false};
        // The smaller positive root, in the form without cancellation.
        const double limit = K[0] + 2 * g[0] / (-beta + std::sqrt(disc));
        const double power =
          power_law_limit({{K[2], K[1], K[0]}}, {{h[2], h[1], h[0]}});
        // Not further than a quarter of the three steps' span: from afar
        // neither model is known to hold.
        // The secant on sqrt(h) through the latest two: where it agrees with
        // the parabola to a few tolerances, the parabola is far closer.
        const bool known =
          std::abs(limit - (K[0] + t_two)) <= 3 * tolerance * K[0];
        return {limit,
                std::min({limit, power, K[0] + 0.25 * (K[0] - K[2])}),
                known};
      }

      /**
       * The next K after a solved step at K with K* = K + h. Near the limit
       * h(K) = K* - K can fall off faster than linearly, and plain
       * substitution K <- K* then creeps. A secant step on h through the
       * previous solved step extrapolates to h = 0; it is taken only when h
       * has decreased as K rose, and never beyond a K already known to fail
       * (bisect instead). Where every pair slips, fold_limit() extrapolates
       * further and better.
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
                  const Fold  &fold,
                  const double K_low,
                  const double K_high,
                  const double tolerance)
      {
        const double K = step.K, h = step.K_star - step.K;
        double       next = step.K_star; // eq. (12): K* itself
        if (previous != nullptr)
          {
            const double previous_h = previous->K_star - previous->K;
            // The secant's step as h times a ratio: h (K - K_prev) itself
            // overflows where K is large (1e198 with a cohesion of 1e200).
            if (previous->K < K && previous_h > h && h > 0)
              next =
                std::max(next, K + h * ((K - previous->K) / (previous_h - h)));
          }
        if (fold.aim > next)
          next = fold.aim;
        // The fold known to far below the tolerance: the solves end just
        // below it (on the wedge 1.2e-6 to 1.4e-6 below, relative), so go
        // for that end: 1.5 tolerances below the limit, and from a static
        // solve there just under a tolerance above it, so that a failure
        // closes the bracket and a static solve leaves K within the
        // tolerance of the limit (a fixed point).
        if (fold.known)
          {
            double target = fold.limit * (1 - 1.5 * tolerance) - fold.error;
            if (target < K * (1 + 0.5 * tolerance))
              target = K * (1 + 0.95 * tolerance);
            if (target >= K_high)
              target =
                K_high - std::min(0.5 * tolerance * K, 0.5 * (K_high - K));
            return target;
          }
        // A fold beyond a K that failed: the solves end before K* - K
        // reaches zero (on the wedge 1.3e-6 below it, where the slip
        // directions are nearly parallel). The limit is then that end; try
        // just below the failure, by an eighth of the bracket, so that a
        // static solve there closes it.
        if (fold.limit >= K_high)
          return K_high - std::max(0.5 * tolerance * K, (K_high - K) / 8);
        // A fold within a few tolerances: the solves may end before it (the
        // wedge: 1.3e-6 below), so probe a tolerance above K. A failure there
        // closes the bracket; a static solve moves K_low up as far.
        if (fold.limit - K <= 8 * tolerance * K &&
            next - K > 0.9 * tolerance * K)
          return std::min(K + 0.9 * tolerance * K, 0.5 * (K + K_high));
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
      advance(Step              &step,
              const History     &solved,
              const unsigned int failures_in_row,
              const double       previous_step,
              const double       tolerance,
              double            &K_low,
              double            &K_high)
      {
        const ReducedStrengthSolution &s        = step.solution;
        const double                   K        = step.K;
        const Step                    *previous = solved[0];
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
            K_low = std::isnan(K_low) ? K : std::max(K_low, K);
            const Fold fold =
              fold_limit({{&step, solved[0], solved[1]}}, tolerance);
            step.K_next =
              next_factor(step, previous, fold, K_low, K_high, tolerance);
            step.distance_left = distance_left(step, previous_step);
            // The fixed point is where the fold lies, wherever the step goes;
            // once it is known, the step (a probe) says nothing more.
            if (fold.known)
              step.distance_left = std::abs(fold.limit - K) + fold.error;
            else if (fold.limit > K)
              step.distance_left = std::max(step.distance_left, fold.limit - K);
          }
        else if (!s.converged)
          {
            K_high = std::min(K_high, K);
            // Right after a solved step that aimed at a fold, the failure is
            // most likely the end of the solves just below it: try just below
            // the failure first (as next_factor()); bisect after two failures.
            const Fold last = fold_limit(solved, tolerance);
            const bool fold = failures_in_row == 0 && !std::isnan(K_low) &&
                              !std::isnan(last.limit) && !last.by_slope;
            // Below a known fold, the failure is the end of the solves (the
            // next_factor() above aimed 1.5 tolerances below the limit): go
            // half a tolerance lower, so that a static solve closes the
            // bracket; after four such failures, bisect.
            const bool known =
              !std::isnan(K_low) && last.known && failures_in_row < 4;
            step.K_next =
              std::isnan(K_low) ? 0.5 * K :
              known             ? std::max(0.5 * (K_low + K_high),
                               K_high * (1 - 0.5 * tolerance)) :
              fold              ? std::max(0.5 * (K_low + K_high),
                              K_high - std::max(0.5 * tolerance * K_low,
                                                (K_high - K_low) / 8)) :
                                  0.5 * (K_low + K_high);
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
       * Whether to solve again at the failure K_high from the static state
       * @p step solved after it: where that state has strength to spare
       * beyond K_high by eq. (12) (K* above K_high by more than Bracket
       * agreement, so a bracket closing there could certify nothing), the
       * failure may belong to the state it started from rather than to K.
       * Each solve starts from the last static state: on a sphere in
       * undrained soil with a 10 times softer mass, a solve at K = 1.017281
       * from a state with 12 pairs open ran away, the closed states solved
       * below it afterwards had K* 1.1 % above K, and the same K solved
       * again from one of them was static (the iteration then closed at
       * K* = K). Once per failure K, and at most max_retries times in a
       * run, so that a model whose failures are real (a free crack: K*
       * far above every K) pays a few solves, not one per bisection.
       */
      bool
      retry_failure(const Step                               &step,
                    const double                              K_high,
                    const double                              K_retried,
                    const unsigned int                        n_retries,
                    const parameters::SafetyFactorParameters &parameters)
      {
        constexpr unsigned int max_retries = 2;
        return step.solution.has_factor() && !step.solution.degenerate &&
               std::isfinite(K_high) && K_high != K_retried &&
               n_retries < max_retries &&
               step.K_star > K_high * (1 + parameters.bracket_agreement);
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
            std::ostream                                           &log,
            const std::function<double()>                          &estimate)
    {
      Result       result;
      const double tolerance = parameters.tolerance;
      double      &K_low = result.bracket_low, &K_high = result.bracket_high;
      double       K = parameters.initial_factor, previous_step = nan;
      History      solved{}; // the last solved steps, latest first
      const Step *&previous        = solved[0];
      unsigned int failures_in_row = 0;
      double       K_retried       = nan; // a failure solved again
      unsigned int n_retries       = 0;
      result.reason                = "iteration limit reached";
      result.steps.reserve(parameters.max_iterations); // keeps `solved` valid
      for (unsigned int i = 0; i < parameters.max_iterations; ++i)
        {
          Step step{K, nan, nan, nan, solve(K)}; // eqs. (10)-(11)
          const ReducedStrengthSolution &s = step.solution;
          if (s.has_factor())
            step.K_star = K * s.resisting_force / s.sliding_force; // eq. (12)
          advance(step,
                  solved,
                  failures_in_row,
                  previous_step,
                  tolerance,
                  K_low,
                  K_high);
          // The first K failed: the estimate (the FE-stress factor) is
          // likelier close to the limit than half of K (on the rock wedge 4 %
          // below it, where halving went to 0.5 and took two more steps).
          if (i == 0 && !s.converged && estimate)
            {
              const double K_estimate = estimate();
              if (K_estimate >= parameters.minimum_factor && K_estimate < K)
                step.K_next = K_estimate;
            }
          failures_in_row = s.converged ? 0 : failures_in_row + 1;
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
          if (retry_failure(step, K_high, K_retried, n_retries, parameters))
            {
              log << "  K* = " << std::setprecision(8) << step.K_star
                  << " lies beyond the failure at K = " << K_high
                  << ": solving there again from this static state"
                  << std::endl;
              K_retried = K_high;
              ++n_retries;
              result.steps.back().K_next = K_high;
              K_high = std::numeric_limits<double>::infinity();
            }
          else if (!std::isnan(K_low) && K_high - K_low <= tolerance * K_low)
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
              solved        = {{&result.steps.back(), solved[0], solved[1]}};
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
