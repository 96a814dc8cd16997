// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/safety_factor_iteration.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fdem
{
  namespace analyses
  {
    namespace
    {
      /** "K* = 41.9 at K = 0.334" with enough digits to see the difference. */
      std::string
      factors(const Step &step)
      {
        std::ostringstream text;
        text.precision(9);
        text << "K* = " << step.K_star << " at K = " << step.K;
        return text.str();
      }

      /**
       * A step that bounds the safety factor from above: a solve without a
       * static solution, or a state with every pair in contact slipping
       * (degenerate: K* = K at any K).
       */
      bool
      bounds_from_above(const Step &step)
      {
        return !step.solution.has_factor() || step.solution.degenerate;
      }

      /** A step that is a limit state: a mechanism, or every pair slipping. */
      bool
      limit_state(const Step &step)
      {
        return step.solution.mechanism || step.solution.degenerate;
      }

      /** The last step at exactly @p K that bounds from above (or not), or
       * nullptr. */
      const Step *
      step_at(const std::vector<Step> &steps,
              const double             K,
              const bool               from_above)
      {
        for (auto step = steps.rbegin(); step != steps.rend(); ++step)
          if (step->K == K && bounds_from_above(*step) == from_above)
            return &*step;
        return nullptr;
      }

      const char *why_not_closed =
        ": the iteration did not close; the model may have an undeclared contact "
        "(a face two blocks share that is no interface) or a sliding surface that "
        "is not a mechanism";
    } // namespace

    std::string
    kind_name(const Certificate::Kind kind)
    {
      switch (kind)
        {
          case Certificate::Kind::fixed_point:
            return "fixed point";
          case Certificate::Kind::bracket:
            return "bracket";
          default:
            return "none";
        }
    }

    namespace
    {
      /** The fixed-point certificate of the solved step @p solved. */
      Certificate
      fixed_point(const Step &solved, const double tolerance)
      {
        Certificate c;
        c.kind                   = Certificate::Kind::fixed_point;
        c.tolerance              = tolerance;
        c.K                      = solved.K;
        c.K_star                 = solved.K_star;
        c.relative_difference    = std::abs(c.K_star - c.K) / c.K;
        c.relative_distance_left = solved.distance_left / c.K;
        if (solved.solution.degenerate)
          {
            c.reason = factors(solved) +
                       ": every pair in contact slips, so K* = K at any K "
                       "where this state is static; it bounds K from above "
                       "and certifies nothing";
            return c;
          }
        const bool agrees = c.relative_difference <= tolerance;
        c.holds           = agrees && c.relative_distance_left <= tolerance;
        std::ostringstream numbers;
        numbers.precision(3);
        numbers << " (relative difference " << c.relative_difference
                << ", estimated distance to the fixed point "
                << c.relative_distance_left << ", tolerance " << tolerance
                << ")";
        c.reason =
          factors(solved) + (c.holds ? numbers.str() :
                             agrees  ? ": still moving" + numbers.str() :
                                       why_not_closed);
        return c;
      }

      /** The bracket certificate of a solved @p solved below a failed @p
       * failed. */
      Certificate
      bracket(const Step  &solved,
              const Step  &failed,
              const double tolerance,
              const double agreement)
      {
        Certificate c;
        c.kind                = Certificate::Kind::bracket;
        c.tolerance           = tolerance;
        c.K                   = solved.K;
        c.K_star              = solved.K_star;
        c.relative_difference = std::abs(c.K_star - c.K) / c.K;
        c.K_failed            = failed.K;
        c.failure             = failed.solution.degenerate ?
                                  "every pair in contact slips, a limit state" :
                                  failed.solution.result;
        const bool   agrees   = c.relative_difference <= tolerance;
        const double width    = (c.K_failed - c.K) / c.K;
        // K* above K_lo, by a little: the blocks have strength to spare by
        // eq. (12), yet lose equilibrium just above K_lo. Or the mechanism
        // above lies a little further than the tolerance, solves between
        // having failed numerically. K_lo, a static state, is then the
        // conservative answer.
        c.conservative = (!agrees || width > tolerance) && c.K_star >= c.K &&
                         c.relative_difference <= agreement &&
                         width <= agreement;
        c.holds = (agrees || c.conservative) && limit_state(failed);
        std::ostringstream numbers;
        numbers.precision(9);
        numbers << (failed.solution.degenerate ?
                      " and a limit state at K = " :
                      " and no static solution at K = ")
                << c.K_failed << " (" << c.failure << ")";
        if (!agrees && !c.conservative)
          c.reason = factors(solved) +
                     ", the largest K with a static solution" + why_not_closed;
        else if (!limit_state(failed))
          c.reason = "the solve at K = " + std::to_string(c.K_failed) +
                     " above " + factors(solved) + " failed numerically (" +
                     c.failure + "), not as a mechanism";
        else
          c.reason =
            factors(solved) + numbers.str() +
            (c.conservative ?
               "; K* or the mechanism above lies beyond the tolerance, "
               "within Bracket agreement: K is the conservative value" :
               "");
        return c;
      }
    } // namespace

    Certificate
    certify(const Result &result,
            const double  tolerance,
            const double  bracket_agreement)
    {
      Certificate none;
      none.tolerance = tolerance;
      none.reason    = result.reason;
      if (result.steps.empty())
        return none;
      const Step &last      = result.steps.back();
      const bool  bracketed = std::isfinite(result.bracket_high) &&
                             !std::isnan(result.bracket_low) &&
                             result.bracket_high - result.bracket_low <=
                               tolerance * result.bracket_low;
      // A solved last step first: its K* is the answer where it holds.
      if (last.solution.has_factor())
        {
          const Certificate c = fixed_point(last, tolerance);
          if (c.holds || !bracketed)
            return c;
        }
      if (bracketed)
        {
          const Step *solved = step_at(result.steps, result.bracket_low, false);
          const Step *failed = step_at(result.steps, result.bracket_high, true);
          Assert(solved != nullptr && failed != nullptr,
                 dealii::ExcInternalError());
          // A numerical failure just above K_lo bounds nothing: the smallest
          // K above it whose solve failed as a mechanism does.
          const Step *mechanism = nullptr;
          for (const Step &step : result.steps)
            if (limit_state(step) && step.K > solved->K &&
                (mechanism == nullptr || step.K < mechanism->K))
              mechanism = &step;
          if (!limit_state(*failed) && mechanism != nullptr)
            {
              const Certificate c =
                bracket(*solved, *mechanism, tolerance, bracket_agreement);
              if (c.holds)
                return c;
            }
          return bracket(*solved, *failed, tolerance, bracket_agreement);
        }
      if (!last.solution.converged && !last.solution.mechanism)
        none.reason +=
          "; the last solve failed numerically (" + last.solution.result + ")";
      return none;
    }
  } // namespace analyses
} // namespace fdem
