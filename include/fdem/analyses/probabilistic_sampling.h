// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace fdem
{
  namespace analyses
  {
    /**
     * Random numbers and statistics of the probabilistic analysis, written
     * out in full so that a seed gives the same numbers bit for bit with any
     * standard library: the uniform numbers come from std::mt19937_64 (its
     * sequence is fixed by the C++ standard), the normal ones from them by
     * an inverse normal CDF in plain arithmetic (Wichura's AS241), not from
     * std::normal_distribution (whose algorithm each library chooses).
     */
    namespace probability
    {
      /** Distributions of a random variable. */
      enum class Distribution
      {
        normal,
        lognormal,
        uniform,
        truncated_normal
      };

      /** "normal", "lognormal", "uniform" or "truncated normal". */
      std::string
      distribution_name(const Distribution distribution);

      /**
       * A distribution by its parameters: normal and lognormal by their
       * mean and standard deviation; uniform on [lower, upper]; truncated
       * normal by the mean and standard deviation of the normal it is cut
       * from, and its bounds (either may be infinite).
       */
      struct Marginal
      {
        Distribution distribution = Distribution::normal;
        double       mean         = 0;
        double       std_dev      = 0;
        double       lower        = -std::numeric_limits<double>::infinity();
        double       upper        = std::numeric_limits<double>::infinity();

        /** The value whose standard-normal image is @p z (x = F^{-1}(Phi(z))).
         */
        double
        from_standard_normal(const double z) const;

        /** The distribution's own mean and standard deviation. */
        double
        distribution_mean() const;
        double
        distribution_std_dev() const;
      };

      /** The standard normal CDF Phi. */
      double
      normal_cdf(const double z);

      /**
       * The inverse of Phi for 0 < @p p < 1: Wichura's algorithm AS241
       * (PPND16, Applied Statistics 37, 1988), relative error about 1e-16.
       */
      double
      inverse_normal_cdf(const double p);

      /** A uniform number in (0, 1) from 53 bits of one draw of a 64-bit
       * generator word. */
      double
      uniform_open(const std::uint64_t word);

      /**
       * The lower-triangular L with L L^T = @p R (n x n, row-major), or
       * throws naming the first variable (1-based) at which R is not
       * positive definite.
       */
      std::vector<double>
      cholesky(const std::vector<double> &R, const unsigned int n);

      /**
       * @p n_samples points of @p n_variables correlated standard normals,
       * row-major (sample by sample): z = L u with u independent standard
       * normals, drawn by Monte Carlo or Latin hypercube (each variable's
       * n_samples strata of probability, one point in each, in a random
       * order), from one generator seeded with @p seed. Sample i is the
       * same whoever computes it.
       */
      std::vector<double>
      standard_normal_samples(const unsigned int         n_samples,
                              const unsigned int         n_variables,
                              const bool                 latin_hypercube,
                              const std::uint64_t        seed,
                              const std::vector<double> &L);

      /** A binomial proportion's confidence interval (Wilson score). */
      struct Interval
      {
        double lower = 0, upper = 1;
      };

      /**
       * The Wilson score interval of @p k successes in @p n trials at the
       * two-sided normal quantile @p z (1.96: 95 %).
       */
      Interval
      wilson_interval(const unsigned long k,
                      const unsigned long n,
                      const double        z = 1.959963984540054);
    } // namespace probability
  }   // namespace analyses
} // namespace fdem
