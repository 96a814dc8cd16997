// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/sample_iteration.h>

#include <cmath>
#include <limits>

namespace fdem
{
  namespace analyses
  {
    double
    predicted_start(const double               K_means,
                    const std::vector<double> &gradient,
                    const std::vector<double> &means,
                    const std::vector<double> &x,
                    const double               margin)
    {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      if (gradient.size() != means.size() || x.size() != means.size())
        return nan;
      double K = K_means;
      for (unsigned int v = 0; v < means.size(); ++v)
        K += gradient[v] * (x[v] - means[v]);
      K *= 1 - margin;
      if (!std::isfinite(K) || !(K > 0))
        return nan;
      // Down to 12 significant bits: K_means and g carry the model's
      // round-off, which must not reach the start.
      int          exponent = 0;
      const double mantissa = std::frexp(K, &exponent);
      return std::ldexp(std::floor(std::ldexp(mantissa, 12)), exponent - 12);
    }

    SampleIteration
    iterate_from(const std::function<ReducedStrengthSolution(double K)> &solve,
                 const std::function<void()>                            &reset,
                 const parameters::SafetyFactorParameters &parameters,
                 const double                              start,
                 std::ostream                             &log)
    {
      SampleIteration sample;
      sample.start = parameters.initial_factor;
      if (std::isfinite(start) && start > 0)
        {
          parameters::SafetyFactorParameters from_start = parameters;
          from_start.initial_factor                     = start;
          sample.start                                  = start;
          sample.result = iterate(solve, from_start, log);
          if (sample.result.converged)
            return sample;
          sample.fell_back         = true;
          sample.n_discarded_steps = sample.result.steps.size();
          log << "  not certified from the predicted start K = " << start
              << " (" << sample.result.certificate.reason
              << "): the reference iteration from Initial factor decides"
              << std::endl;
          reset();
        }
      sample.result = iterate(solve, parameters, log);
      return sample;
    }
  } // namespace analyses
} // namespace fdem
