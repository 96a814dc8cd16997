// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/limit_equilibrium.h>
#include <fdem/analyses/safety_factor_analysis.h>
#include <fdem/analyses/safety_factor_iteration.h>
#include <fdem/analyses/yield_acceleration.h>

#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

namespace fdem
{
  namespace analyses
  {
    namespace
    {
      /** Why the search stopped without k_y: a sentence for summary.json. */
      struct SearchStopped
      {
        std::string reason;
      };

      /** The K(kh) evaluations of one direction, each computed once. */
      template <int dim>
      class KOfKh
      {
      public:
        KOfKh(Model<dim>                        &model,
              const SeismicLoad<dim>            &load,
              const YieldAccelerationParameters &parameters,
              YieldAccelerationResult           &result,
              unsigned int                      &n_evaluations)
          : model(model)
          , load(load)
          , parameters(parameters)
          , result(result)
          , n_evaluations(n_evaluations)
        {}

        /** K at @p kh; 0 where no strength holds the mass (no equilibrium at
         * any K). */
        double
        operator()(const double kh)
        {
          const auto known = values.find(kh);
          if (known != values.end())
            return known->second;
          if (n_evaluations >= parameters.max_evaluations)
            throw SearchStopped{
              "Yield acceleration/Maximum evaluations (" +
              std::to_string(parameters.max_evaluations) +
              ") reached before the root was bracketed to the tolerance"};
          ++n_evaluations;
          SeismicLoad<dim> at = load;
          at.kh               = kh;
          set_seismic_load(model, at);
          std::ostringstream quiet; // the steps go to the log, not the screen
          SafetyFactorAnalysis<dim> steps(model);
          const Result              r =
            iterate([&steps](const double K) { return steps.solve(K); },
                    model.get_parameters().safety_factor,
                    model.log);
          double K = r.safety_factor;
          if (!r.converged)
            {
              // Every solve a mechanism: no strength reduction K > 0 holds
              // it, i.e. K = 0 below 1 (e.g. the mass lifted off its base).
              if (r.no_equilibrium)
                K = 0;
              else
                throw SearchStopped{"K at kh = " + number(kh) +
                                    " is not certified (" +
                                    r.certificate.reason + ")"};
            }
          values[kh] = K;
          result.curve.push_back({load.direction_sign * kh, K, r.converged});
          model.brief << "  kh = " << std::setprecision(8)
                      << load.direction_sign * kh << ": K = " << K
                      << (r.converged ? "" : " (no static solution at any K)")
                      << std::endl;
          return K;
        }

        static std::string
        number(const double x)
        {
          std::ostringstream text;
          text << std::setprecision(8) << x;
          return text.str();
        }

        /** Whether the last K evaluated was certified (not "no static
         * solution"). */
        bool
        last_certified() const
        {
          return !result.curve.empty() && result.curve.back().certified;
        }

      private:
        Model<dim>                        &model;
        const SeismicLoad<dim>             load;
        const YieldAccelerationParameters &parameters;
        YieldAccelerationResult           &result;
        unsigned int                      &n_evaluations;
        std::map<double, double>           values;
      };

      /**
       * The root of K(kh) = 1 for kh in [0, max]: @p K_of in one direction.
       * Returns infinity if K stays above 1 up to the maximum; throws
       * SearchStopped if K < 1 at kh = 0.
       */
      template <int dim>
      double
      search(KOfKh<dim>                        &K_of,
             const YieldAccelerationParameters &parameters,
             double                            &low,
             double                            &high)
      {
        double a = 0, K_a = K_of(0.0);
        if (!(K_a >= 1))
          throw SearchStopped{
            "K = " + KOfKh<dim>::number(K_a) +
            " < 1 already without a horizontal seismic force: the slope "
            "slides under its weight; there is no yield acceleration"};
        // Bracket: secant steps towards K = 1 from the last two values,
        // at least 0.05 and at most doubling the distance from 0, so that a
        // flat or curved K(kh) is neither crawled along nor overshot far.
        double step = 0.05, b = 0, K_b = K_a;
        while (true)
          {
            b   = std::min(a + step, parameters.max_coefficient);
            K_b = K_of(b);
            if (K_b <= 1)
              break;
            if (b >= parameters.max_coefficient)
              return std::numeric_limits<double>::infinity();
            const double slope = (K_b - K_a) / (b - a);
            double       next  = slope < 0 ? (1 - K_b) / slope : 2 * step;
            next = std::clamp(1.2 * next, 0.05, std::max(b, 0.05));
            a    = b;
            K_a  = K_b;
            step = next;
          }
        if (K_b == 1)
          {
            low = high = b;
            return b;
          }
        // K = 0 at b stands for "no static solution at any K": between a
        // and b, K(kh) may jump rather than pass through 1, and a root
        // search would return the jump as k_y. k_y is reported only when
        // bracketed by two certified K.
        if (!K_of.last_certified())
          throw SearchStopped{
            "K(kh) does not pass through 1 between two certified values: "
            "K = " +
            KOfKh<dim>::number(K_a) + " at kh = " + KOfKh<dim>::number(a) +
            ", no static solution at any K at kh = " + KOfKh<dim>::number(b) +
            "; no yield acceleration is reported"};
        // Brent's method (scipy.optimize.brentq's algorithm) on K - 1, which
        // changes sign in [a, b]; K is continuous in kh (a linear load).
        const double root = limit_equilibrium::find_root(
          [&](const double kh) { return K_of(kh) - 1; },
          a,
          b,
          parameters.tolerance);
        // Brent finds a sign change, which a jump gives too: where the
        // contact problem loses its static solution at every K (K counted
        // as 0) before K reaches 1, the "root" is the jump, not k_y. K at
        // the root must be 1 to the root's accuracy (|dK/dkh| times the
        // tolerance, a few 1e-6 on the slopes tested; a jump leaves 1).
        const double K_root = K_of(root);
        if (!(std::abs(K_root - 1) <= 1e-3))
          throw SearchStopped{
            "K(kh) does not pass through 1 between kh = " +
            KOfKh<dim>::number(a) + " and " + KOfKh<dim>::number(b) +
            ": K = " + KOfKh<dim>::number(K_root) +
            " at kh = " + KOfKh<dim>::number(root) +
            " (the contact problem has no static solution at any K beyond "
            "it); no yield acceleration is reported"};
        low  = a;
        high = b;
        return root;
      }
    } // namespace

    template <int dim>
    YieldAccelerationResult
    yield_acceleration(Model<dim>                        &model,
                       const SeismicLoad<dim>            &load,
                       const YieldAccelerationParameters &parameters)
    {
      Timer                   timer;
      YieldAccelerationResult result;
      result.computed            = true;
      unsigned int n_evaluations = 0;
      model.brief
        << "Yield acceleration: K(kh) = 1 (root search on kh, safety-factor iterations):"
        << std::endl;
      for (const double sign : {1.0, -1.0})
        {
          if (sign < 0 && !parameters.two_directional)
            break;
          SeismicLoad<dim> directed = load;
          directed.direction *= sign;
          directed.direction_sign = sign;
          KOfKh<dim> K_of(model, directed, parameters, result, n_evaluations);
          double     low = std::numeric_limits<double>::quiet_NaN(), high = low;
          try
            {
              const double k_y = search(K_of, parameters, low, high);
              if (sign > 0)
                {
                  result.k_y          = k_y;
                  result.bracket_low  = low;
                  result.bracket_high = high;
                  if (std::isinf(k_y))
                    result.not_found =
                      "K > 1 up to Yield acceleration/Maximum coefficient = " +
                      KOfKh<dim>::number(parameters.max_coefficient);
                }
              else
                result.k_y_backward = k_y;
            }
          catch (const SearchStopped &stopped)
            {
              if (sign > 0)
                {
                  result.not_found = stopped.reason;
                  result.k_y       = std::numeric_limits<double>::quiet_NaN();
                  break;
                }
              result.k_y_backward = std::numeric_limits<double>::infinity();
            }
          model.forget_warm_start();
        }
      std::sort(result.curve.begin(),
                result.curve.end(),
                [](const auto &p, const auto &q) { return p.kh < q.kh; });
      result.curve.erase(std::unique(result.curve.begin(),
                                     result.curve.end(),
                                     [](const auto &p, const auto &q) {
                                       return p.kh == q.kh;
                                     }),
                         result.curve.end());
      result.wall_seconds = timer.wall_time();
      if (result.not_found.empty())
        model.brief << "Yield acceleration: k_y = " << std::setprecision(8)
                    << result.k_y << " (" << n_evaluations << " K evaluations)"
                    << std::endl;
      else
        model.brief << "Yield acceleration: none (" << result.not_found << ")"
                    << std::endl;
      return result;
    }

    template YieldAccelerationResult
    yield_acceleration(Model<2> &,
                       const SeismicLoad<2> &,
                       const YieldAccelerationParameters &);
    template YieldAccelerationResult
    yield_acceleration(Model<3> &,
                       const SeismicLoad<3> &,
                       const YieldAccelerationParameters &);
  } // namespace analyses
} // namespace fdem
