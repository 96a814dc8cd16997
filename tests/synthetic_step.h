// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// A synthetic solve of the safety-factor iteration, for tests of the
// iteration and its certificate without a model.
#pragma once

#include <fdem/analyses/safety_factor_iteration.h>

namespace fdem::test_support
{
  /**
   * A synthetic step: K* = K F_R/F_tau given as a function of K, no static
   * solution from @p K_limit up, failing as a mechanism unless
   * @p numerical_failure.
   */
  inline analyses::ReducedStrengthSolution
  synthetic_step(const double K,
                 const double K_star,
                 const double K_limit,
                 const bool   numerical_failure = false)
  {
    analyses::ReducedStrengthSolution s;
    s.converged = K < K_limit;
    s.mechanism = !s.converged && !numerical_failure;
    s.result    = s.converged       ? "converged" :
                  numerical_failure ? "breakdown" :
                                      "singular system";
    if (s.converged)
      {
        s.sliding_force   = 1000;
        s.resisting_force = s.sliding_force * K_star / K;
      }
    return s;
  }
} // namespace fdem::test_support
