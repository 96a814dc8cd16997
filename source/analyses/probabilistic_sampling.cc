// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/probabilistic_sampling.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>

namespace fdem
{
  namespace analyses
  {
    namespace probability
    {
      using namespace dealii;

      namespace
      {
        /** sum_k c[k] x^k by Horner's rule. */
        double
        horner(const std::array<double, 8> &c, const double x)
        {
          double sum = c[7];
          for (int k = 6; k >= 0; --k)
            sum = sum * x + c[k];
          return sum;
        }

        // Wichura (1988), Algorithm AS241, PPND16: ascending powers.
        constexpr std::array<double, 8> a = {{3.3871328727963666080e0,
                                              1.3314166789178437745e+2,
                                              1.9715909503065514427e+3,
                                              1.3731693765509461125e+4,
                                              4.5921953931549871457e+4,
                                              6.7265770927008700853e+4,
                                              3.3430575583588128105e+4,
                                              2.5090809287301226727e+3}};
        constexpr std::array<double, 8> b = {{1.0,
                                              4.2313330701600911252e+1,
                                              6.8718700749205790830e+2,
                                              5.3941960214247511077e+3,
                                              2.1213794301586595867e+4,
                                              3.9307895800092710610e+4,
                                              2.8729085735721942674e+4,
                                              5.2264952788528545610e+3}};
        constexpr std::array<double, 8> c = {{1.42343711074968357734e0,
                                              4.63033784615654529590e0,
                                              5.76949722146069140550e0,
                                              3.64784832476320460504e0,
                                              1.27045825245236838258e0,
                                              2.41780725177450611770e-1,
                                              2.27238449892691845833e-2,
                                              7.74545014278341407640e-4}};
        constexpr std::array<double, 8> d = {{1.0,
                                              2.05319162663775882187e0,
                                              1.67638483018380384940e0,
                                              6.89767334985100004550e-1,
                                              1.48103976427480074590e-1,
                                              1.51986665636164571966e-2,
                                              5.47593808499534494600e-4,
                                              1.05075007164441684324e-9}};
        constexpr std::array<double, 8> e = {{6.65790464350110377720e0,
                                              5.46378491116411436990e0,
                                              1.78482653991729133580e0,
                                              2.96560571828504891230e-1,
                                              2.65321895265761230930e-2,
                                              1.24266094738807843860e-3,
                                              2.71155556874348757815e-5,
                                              2.01033439929228813265e-7}};
        constexpr std::array<double, 8> f = {{1.0,
                                              5.99832206555887937690e-1,
                                              1.36929880922735805310e-1,
                                              1.48753612908506148525e-2,
                                              7.86869131145613259100e-4,
                                              1.84631831751005468180e-5,
                                              1.42151175831644588870e-7,
                                              2.04426310338993978564e-15}};

        /** Lognormal: the mean and standard deviation of log x. */
        std::pair<double, double>
        log_moments(const double mean, const double std_dev)
        {
          const double s2 = std::log1p((std_dev / mean) * (std_dev / mean));
          return {std::log(mean) - 0.5 * s2, std::sqrt(s2)};
        }

        /** The standard normal density. */
        double
        normal_pdf(const double z)
        {
          return std::exp(-0.5 * z * z) / std::sqrt(2 * M_PI);
        }
      } // namespace

      std::string
      distribution_name(const Distribution distribution)
      {
        switch (distribution)
          {
            case Distribution::normal:
              return "normal";
            case Distribution::lognormal:
              return "lognormal";
            case Distribution::uniform:
              return "uniform";
            case Distribution::truncated_normal:
              return "truncated normal";
          }
        return "";
      }

      double
      normal_cdf(const double z)
      {
        return 0.5 * std::erfc(-z / std::sqrt(2.0));
      }

      double
      inverse_normal_cdf(const double p)
      {
        Assert(p > 0 && p < 1,
               ExcMessage("the probability must lie in (0, 1)"));
        const double q = p - 0.5;
        if (std::abs(q) <= 0.425)
          {
            const double r = 0.180625 - q * q;
            return q * horner(a, r) / horner(b, r);
          }
        double       r = std::sqrt(-std::log(q < 0 ? p : 1 - p));
        const double z = r <= 5 ? horner(c, r - 1.6) / horner(d, r - 1.6) :
                                  horner(e, r - 5) / horner(f, r - 5);
        return q < 0 ? -z : z;
      }

      double
      uniform_open(const std::uint64_t word)
      {
        // The 52 high bits and a half: never 0, never 1. (With 53 bits the
        // largest value, 1 - 2^-54, rounds to 1.0, whose normal is
        // infinite.)
        return (double(word >> 12) + 0.5) * (1.0 / 4503599627370496.0);
      }

      double
      Marginal::from_standard_normal(const double z) const
      {
        switch (distribution)
          {
            case Distribution::normal:
              return mean + std_dev * z;
            case Distribution::lognormal:
              {
                const auto [mu, sigma] = log_moments(mean, std_dev);
                return std::exp(mu + sigma * z);
              }
            case Distribution::uniform:
              return lower + (upper - lower) * normal_cdf(z);
            case Distribution::truncated_normal:
              {
                const double p_low  = normal_cdf((lower - mean) / std_dev);
                const double p_high = normal_cdf((upper - mean) / std_dev);
                const double p =
                  std::clamp(p_low + (p_high - p_low) * normal_cdf(z),
                             std::nextafter(0.0, 1.0),
                             std::nextafter(1.0, 0.0));
                return std::clamp(mean + std_dev * inverse_normal_cdf(p),
                                  lower,
                                  upper);
              }
          }
        return 0;
      }

      double
      Marginal::distribution_mean() const
      {
        if (distribution == Distribution::uniform)
          return 0.5 * (lower + upper);
        if (distribution != Distribution::truncated_normal)
          return mean;
        const double alpha = (lower - mean) / std_dev,
                     beta  = (upper - mean) / std_dev;
        const double Z     = normal_cdf(beta) - normal_cdf(alpha);
        return mean + std_dev * (normal_pdf(alpha) - normal_pdf(beta)) / Z;
      }

      double
      Marginal::distribution_std_dev() const
      {
        if (distribution == Distribution::uniform)
          return (upper - lower) / std::sqrt(12.0);
        if (distribution != Distribution::truncated_normal)
          return std_dev;
        const double alpha = (lower - mean) / std_dev,
                     beta  = (upper - mean) / std_dev;
        const double Z     = normal_cdf(beta) - normal_cdf(alpha);
        // alpha phi(alpha) vanishes at an infinite bound.
        const double a_phi =
          std::isfinite(alpha) ? alpha * normal_pdf(alpha) : 0;
        const double b_phi = std::isfinite(beta) ? beta * normal_pdf(beta) : 0;
        const double shift = (normal_pdf(alpha) - normal_pdf(beta)) / Z;
        return std_dev * std::sqrt(1 + (a_phi - b_phi) / Z - shift * shift);
      }

      std::vector<double>
      cholesky(const std::vector<double> &R, const unsigned int n)
      {
        std::vector<double> L(n * n, 0.0);
        for (unsigned int j = 0; j < n; ++j)
          {
            double diagonal = R[j * n + j];
            for (unsigned int k = 0; k < j; ++k)
              diagonal -= L[j * n + k] * L[j * n + k];
            // A pivot this small relative to 1 (the diagonal of R) leaves a
            // variable that is a combination of the others: no density.
            AssertThrow(
              diagonal > 1e-12,
              ExcMessage(
                "Probabilistic/Correlations: the correlation matrix is not "
                "positive definite (Cholesky fails at variable " +
                std::to_string(j + 1) +
                "); the correlations given contradict each other."));
            L[j * n + j] = std::sqrt(diagonal);
            for (unsigned int i = j + 1; i < n; ++i)
              {
                double sum = R[i * n + j];
                for (unsigned int k = 0; k < j; ++k)
                  sum -= L[i * n + k] * L[j * n + k];
                L[i * n + j] = sum / L[j * n + j];
              }
          }
        return L;
      }

      std::vector<double>
      standard_normal_samples(const unsigned int         n_samples,
                              const unsigned int         n_variables,
                              const bool                 latin_hypercube,
                              const std::uint64_t        seed,
                              const std::vector<double> &L)
      {
        std::mt19937_64     generator(seed);
        std::vector<double> u(std::size_t(n_samples) * n_variables);
        if (latin_hypercube)
          {
            // Per variable: a random order of the strata (Fisher-Yates with
            // our own index draw: std::shuffle's use of the generator is the
            // library's choice), then a uniform point in each stratum.
            std::vector<unsigned int> order(n_samples);
            for (unsigned int v = 0; v < n_variables; ++v)
              {
                std::iota(order.begin(), order.end(), 0u);
                for (unsigned int i = n_samples; i > 1; --i)
                  {
                    // The modulo's bias, i / 2^64, is far below anything
                    // sampled.
                    const auto j = static_cast<unsigned int>(generator() % i);
                    std::swap(order[i - 1], order[j]);
                  }
                for (unsigned int s = 0; s < n_samples; ++s)
                  u[std::size_t(s) * n_variables + v] =
                    (order[s] + uniform_open(generator())) / n_samples;
              }
          }
        else
          for (double &value : u)
            value = uniform_open(generator());

        std::vector<double> z(u.size()), independent(n_variables);
        for (unsigned int s = 0; s < n_samples; ++s)
          {
            for (unsigned int v = 0; v < n_variables; ++v)
              independent[v] = inverse_normal_cdf(std::clamp(
                u[std::size_t(s) * n_variables + v], 0x1p-60, 1 - 0x1p-53));
            for (unsigned int i = 0; i < n_variables; ++i)
              {
                double sum = 0;
                for (unsigned int k = 0; k <= i; ++k)
                  sum += L[i * n_variables + k] * independent[k];
                z[std::size_t(s) * n_variables + i] = sum;
              }
          }
        return z;
      }

      Interval
      wilson_interval(const unsigned long k,
                      const unsigned long n,
                      const double        z)
      {
        if (n == 0)
          return {0, 1};
        const double p = double(k) / n, z2 = z * z;
        const double centre = (p + z2 / (2 * n)) / (1 + z2 / n);
        const double half =
          z / (1 + z2 / n) * std::sqrt(p * (1 - p) / n + z2 / (4.0 * n * n));
        return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
      }
    } // namespace probability
  }   // namespace analyses
} // namespace fdem
