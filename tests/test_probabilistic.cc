// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The random numbers and statistics of the probabilistic analysis
// (analyses/probabilistic_sampling.h) against exact or published values.
#include <fdem/analyses/probabilistic.h>
#include <fdem/analyses/probabilistic_sampling.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace fdem::analyses;
using namespace fdem::analyses::probability;

TEST(Probabilistic, InverseNormalCdf)
{
  // Quantiles to 16 digits (Abramowitz & Stegun 26.2, and Wichura 1988's
  // own test values): AS241 is accurate to about 1e-16 relative.
  EXPECT_EQ(inverse_normal_cdf(0.5), 0.0);
  EXPECT_NEAR(inverse_normal_cdf(0.975), 1.959963984540054, 1e-15);
  EXPECT_NEAR(inverse_normal_cdf(0.025), -1.959963984540054, 1e-15);
  EXPECT_NEAR(inverse_normal_cdf(0.8413447460685429), 1.0, 1e-14);
  EXPECT_NEAR(inverse_normal_cdf(1e-10), -6.361340902404056, 1e-13);
  // Round trip through Phi (erfc) over the three regions of AS241. Above
  // z = 0, p = Phi(z) is stored to 1.1e-16 absolute near 1, which moves
  // its quantile by up to 1.1e-16 / phi(z) (6e-9 at z = 6, measured 9e-9
  // at one rounding of 1 - p): the bound allows four such roundings.
  for (const double z : {-8.0, -5.5, -3.0, -1.2, -0.3, 0.1, 0.9, 2.5, 6.0})
    {
      const double density  = std::exp(-z * z / 2) / std::sqrt(2 * M_PI);
      const double rounding = z > 0 ? 4 * 1.1e-16 / density : 0.0;
      EXPECT_NEAR(inverse_normal_cdf(normal_cdf(z)),
                  z,
                  std::max(1e-12 * std::max(1.0, std::abs(z)), rounding))
        << z;
    }
}

TEST(Probabilistic, UniformOpen)
{
  EXPECT_GT(uniform_open(0), 0.0);
  EXPECT_LT(uniform_open(~std::uint64_t(0)), 1.0);
  EXPECT_EQ(uniform_open(std::uint64_t(1) << 63),
            0.5 + 0.5 / 4503599627370496.0);
}

TEST(Probabilistic, Marginals)
{
  // Lognormal: median exp(mu) with mu = ln(m / sqrt(1 + V^2)).
  Marginal lognormal{Distribution::lognormal, 3, 0.9};
  EXPECT_NEAR(lognormal.from_standard_normal(0),
              3 / std::sqrt(1 + 0.09),
              1e-14);
  // Uniform on [2, 5]: the median at 3.5, sd 3 / sqrt(12).
  Marginal uniform{Distribution::uniform, 3.5, 0, 2, 5};
  EXPECT_NEAR(uniform.from_standard_normal(0), 3.5, 1e-15);
  EXPECT_NEAR(uniform.distribution_std_dev(), 3 / std::sqrt(12.0), 1e-15);
  // Truncated at the mean: the half-normal, mean m + s sqrt(2/pi), sd
  // s sqrt(1 - 2/pi); every value above the bound.
  Marginal half{Distribution::truncated_normal, 1, 2, 1};
  EXPECT_NEAR(half.distribution_mean(), 1 + 2 * std::sqrt(2 / M_PI), 1e-14);
  EXPECT_NEAR(half.distribution_std_dev(), 2 * std::sqrt(1 - 2 / M_PI), 1e-14);
  for (const double z : {-9.0, -1.0, 0.0, 3.0})
    EXPECT_GE(half.from_standard_normal(z), 1.0);
}

TEST(Probabilistic, CholeskyAndCorrelation)
{
  const std::vector<double> R = {1, 0.5, 0.2, 0.5, 1, -0.3, 0.2, -0.3, 1};
  const std::vector<double> L = cholesky(R, 3);
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      {
        double sum = 0;
        for (unsigned int k = 0; k < 3; ++k)
          sum += L[i * 3 + k] * L[j * 3 + k];
        EXPECT_NEAR(sum, R[i * 3 + j], 1e-15);
      }
  // 0.9, 0.9 and -0.9 contradict each other: not positive definite.
  EXPECT_THROW(cholesky({1, 0.9, 0.9, 0.9, 1, -0.9, 0.9, -0.9, 1}, 3),
               std::exception);
  // The sample correlation of 20000 Monte Carlo pairs: within 4 standard
  // errors, (1 - rho^2) / sqrt(n) = 0.0053 for rho = 0.5.
  const unsigned int        n   = 20000;
  const std::vector<double> z   = standard_normal_samples(n, 3, false, 5, L);
  double                    s01 = 0, s00 = 0, s11 = 0;
  for (unsigned int s = 0; s < n; ++s)
    {
      s01 += z[3 * s] * z[3 * s + 1];
      s00 += z[3 * s] * z[3 * s];
      s11 += z[3 * s + 1] * z[3 * s + 1];
    }
  EXPECT_NEAR(s01 / std::sqrt(s00 * s11), 0.5, 4 * 0.75 / std::sqrt(double(n)));
}

TEST(Probabilistic, LatinHypercubeStrata)
{
  // Each variable: one point in each of the n strata of probability.
  const unsigned int        n = 257;
  const std::vector<double> z =
    standard_normal_samples(n, 2, true, 9, {1, 0, 0, 1});
  for (unsigned int v = 0; v < 2; ++v)
    {
      std::set<unsigned int> strata;
      for (unsigned int s = 0; s < n; ++s)
        strata.insert(static_cast<unsigned int>(normal_cdf(z[2 * s + v]) * n));
      EXPECT_EQ(strata.size(), n);
    }
  // The same seed, the same numbers bit for bit; another seed, others.
  EXPECT_EQ(z, standard_normal_samples(n, 2, true, 9, {1, 0, 0, 1}));
  EXPECT_NE(z, standard_normal_samples(n, 2, true, 10, {1, 0, 0, 1}));
}

TEST(Probabilistic, WilsonInterval)
{
  // Wilson (1927); Newcombe (1998), Table I: 81 of 263 -> [0.2553, 0.3662]
  // at 95 %; 0 of 10 -> [0, 0.2775].
  const Interval a = wilson_interval(81, 263);
  EXPECT_NEAR(a.lower, 0.2553, 5e-5);
  EXPECT_NEAR(a.upper, 0.3662, 5e-5);
  const Interval b = wilson_interval(0, 10);
  EXPECT_EQ(b.lower, 0.0);
  EXPECT_NEAR(b.upper, 0.2775, 5e-5);
}

TEST(Probabilistic, Statistics)
{
  // Four certified K, one sample without equilibrium (a failure), one
  // nonphysical (left out).
  const std::vector<double>       K      = {0.9, 1.1, 1.3, 1.5, NAN, NAN};
  const std::vector<SampleStatus> status = {SampleStatus::certified,
                                            SampleStatus::certified,
                                            SampleStatus::certified,
                                            SampleStatus::certified,
                                            SampleStatus::no_equilibrium,
                                            SampleStatus::nonphysical};
  const std::vector<double>       x      = {1, 2, 3, 4, 5, 6};
  const auto                      s = sample_statistics(K, status, x, 1, 0, 2);
  EXPECT_EQ(s["n_evaluated"], 5);
  EXPECT_EQ(s["n_failures"], 2);
  EXPECT_DOUBLE_EQ(s["P_failure"].get<double>(), 0.4);
  EXPECT_NEAR(s["K_mean"].get<double>(), 1.2, 1e-15);
  EXPECT_NEAR(s["K_std"].get<double>(), std::sqrt(0.2 / 3), 1e-15);
  // Fragility: x = 1, 2 (one failure of two), x = 3, 4, 5 (one of three).
  EXPECT_DOUBLE_EQ(s["fragility"]["bins"][0]["P_failure"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(s["fragility"]["bins"][1]["P_failure"].get<double>(),
                   1.0 / 3);
}
