// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// A probabilistic sample's iteration from its predicted start
// (analyses/sample_iteration.h): taken only if certified, else the
// reference iteration decides, bit for bit as without the prediction.
#include "synthetic_step.h"

#include <fdem/analyses/sample_iteration.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

using namespace fdem;
using namespace fdem::analyses;

namespace
{
  /**
   * A solve with K* = K_limit below K_limit (a planar limit), a mechanism
   * from K_limit up; every solve fails numerically while
   * @p poisoned (a start that leads nowhere), until reset.
   */
  struct SyntheticSample
  {
    double              K_limit  = 1.5;
    bool                poisoned = false;
    std::vector<double> solved_at;
    ReducedStrengthSolution
    operator()(const double K)
    {
      solved_at.push_back(K);
      // Poisoned: no K below the limit, a numerical failure everywhere.
      return test_support::synthetic_step(K,
                                          K_limit,
                                          poisoned ? 0. : K_limit,
                                          poisoned);
    }
  };
} // namespace

TEST(SampleIteration, PredictedStartIsTakenWhenCertified)
{
  parameters::SafetyFactorParameters control;
  std::ostringstream                 log;
  SyntheticSample                    reference_sample, sample;
  const Result reference = iterate(std::ref(reference_sample), control, log);
  ASSERT_TRUE(reference.converged) << log.str();
  bool       reset_called = false;
  const auto fast         = iterate_from(
    std::ref(sample), [&]() { reset_called = true; }, control, 1.47, log);
  ASSERT_TRUE(fast.result.converged) << log.str();
  EXPECT_FALSE(fast.fell_back);
  EXPECT_FALSE(reset_called);
  EXPECT_EQ(sample.solved_at.front(), 1.47);
  // Both certified: within the tolerance of each other.
  EXPECT_LE(std::abs(fast.result.safety_factor - reference.safety_factor),
            2 * control.tolerance * reference.safety_factor);
  EXPECT_LE(fast.result.steps.size(), reference.steps.size());
}

TEST(SampleIteration, UncertifiedStartFallsBackToTheReference)
{
  // From the predicted start every solve fails numerically (no
  // certificate); reset() restores the sample's state and the reference
  // iteration, from Initial factor, gives exactly its own answer.
  parameters::SafetyFactorParameters control;
  std::ostringstream                 log;
  SyntheticSample                    reference_sample, sample;
  const Result reference = iterate(std::ref(reference_sample), control, log);
  ASSERT_TRUE(reference.converged);
  sample.poisoned       = true;
  unsigned int n_resets = 0;
  const auto   fallback = iterate_from(
    std::ref(sample),
    [&]() {
      ++n_resets;
      sample.poisoned = false;
      sample.solved_at.clear();
    },
    control,
    1.47,
    log);
  EXPECT_TRUE(fallback.fell_back);
  EXPECT_EQ(n_resets, 1u);
  EXPECT_GT(fallback.n_discarded_steps, 0u);
  ASSERT_TRUE(fallback.result.converged) << log.str();
  EXPECT_EQ(fallback.result.safety_factor, reference.safety_factor);
  EXPECT_EQ(fallback.result.steps.size(), reference.steps.size());
  ASSERT_FALSE(sample.solved_at.empty());
  EXPECT_EQ(sample.solved_at.front(), control.initial_factor);
  EXPECT_EQ(sample.solved_at, reference_sample.solved_at);
  EXPECT_NE(log.str().find("reference iteration"), std::string::npos);

  // No prediction (NaN): the reference iteration only.
  SyntheticSample plain;
  const auto      none = iterate_from(
    std::ref(plain),
    []() { FAIL() << "no reset without a prediction"; },
    control,
    std::numeric_limits<double>::quiet_NaN(),
    log);
  EXPECT_FALSE(none.fell_back);
  EXPECT_EQ(none.result.safety_factor, reference.safety_factor);
}

TEST(SampleIteration, PredictedStart)
{
  // K_means + g . (x - m), lowered by the margin, rounded down to 12 bits:
  // 1.3 + 0.1 * 1 - 2 * 0.05 = 1.3, times 0.98 = 1.274, and 1.274 rounded
  // down to a multiple of 2^-12 (K in [1, 2): mantissa steps of 2^-12).
  const std::vector<double> g{0.1, 2}, m{3, 0.35}, x{4, 0.3};
  const double              start = predicted_start(1.3, g, m, x, 0.02);
  EXPECT_EQ(start, std::floor(1.274 * 4096) / 4096);
  EXPECT_LE(start, 1.274);
  EXPECT_GT(start, 1.274 - 1.0 / 4096);
  // Round-off in K_means or g does not reach the start.
  EXPECT_EQ(predicted_start(1.3 * (1 + 4e-16), g, m, x, 0.02), start);
  EXPECT_EQ(predicted_start(1.3, {0.1 * (1 - 4e-16), 2}, m, x, 0.02), start);
  // No positive prediction: NaN, the reference start.
  EXPECT_TRUE(std::isnan(predicted_start(1.3, g, m, {-20, 0.3}, 0.02)));
  EXPECT_TRUE(std::isnan(predicted_start(1.3, {0.1}, m, x, 0.02)));
}
