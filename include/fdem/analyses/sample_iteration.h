// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/safety_factor_iteration.h>

#include <functional>
#include <ostream>
#include <vector>

namespace fdem
{
  namespace analyses
  {
    /** K of one probabilistic sample and how it was reached. */
    struct SampleIteration
    {
      /** The certified iteration (or the reference one's, if it fell back). */
      Result result;
      /** The K the first iteration started at. */
      double start = 0;
      /**
       * The iteration from the predicted start was not certified and the
       * reference iteration (from Safety factor/Initial factor) was run.
       */
      bool fell_back = false;
      /** Steps of the iteration from the prediction when it fell back. */
      unsigned int n_discarded_steps = 0;
    };

    /**
     * The predicted start of a sample's iteration: the first-order
     * prediction K_means + sum_v g_v (x_v - m_v) from the gradient g of
     * FOSM, lowered by @p margin (relative) so that the first solve is
     * below the sample's limit, and rounded down to 2^-12 relative so that
     * round-off in K_means or g does not move it. A function of the sample
     * @p x alone (the means, K_means and g are computed once, before the
     * samples). NaN where the prediction is not finite or not positive.
     */
    double
    predicted_start(const double               K_means,
                    const std::vector<double> &gradient,
                    const std::vector<double> &means,
                    const std::vector<double> &x,
                    const double               margin);

    /**
     * K of one sample: iterate() started at @p start (instead of Safety
     * factor/Initial factor). Its answer is taken only if certified, with
     * the certificate of iterate() unchanged. Otherwise @p reset() restores
     * the sample's starting state (contact states, factorisation) and the
     * reference iteration, from Safety factor/Initial factor, decides: its
     * result is then the one the sample had before the prediction existed,
     * bit for bit. A @p start that is NaN runs the reference iteration only.
     */
    SampleIteration
    iterate_from(const std::function<ReducedStrengthSolution(double K)> &solve,
                 const std::function<void()>                            &reset,
                 const parameters::SafetyFactorParameters &parameters,
                 const double                              start,
                 std::ostream                             &log);
  } // namespace analyses
} // namespace fdem
