// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/probabilistic_parameters.h>
#include <fdem/analyses/seismic_results.h>
#include <fdem/model.h>
#include <fdem/parameters/work_estimate.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace fdem
{
  namespace analyses
  {
    /** How a sample's safety factor ended. */
    enum class SampleStatus
    {
      /** A certified K (fixed point or bracket). */
      certified,
      /** No static solution at any K down to Safety factor/Minimum factor: a
         failure. */
      no_equilibrium,
      /** The iteration found no certified K: counted as a failure, never as a
         number. */
      not_certified,
      /** A strength outside its physical range (c < 0, phi outside [0, 90)):
         not evaluated. */
      nonphysical
    };

    /** "certified", "no equilibrium", "not certified" or "nonphysical". */
    std::string
    status_name(const SampleStatus status);

    /**
     * The statistics of the samples' K (summary.json "probabilistic"): over
     * the certified samples the mean, standard deviation, quantiles,
     * histogram and reliability indices (normal: (mean - 1)/std; lognormal:
     * ln(mean / sqrt(1 + V^2)) / sqrt(ln(1 + V^2)), V = std/mean); over the
     * evaluated samples (all but the nonphysical) P(K < 1), counting those
     * without a certified K as failures, with its 95 % Wilson score
     * interval; the fragility curve P(K < 1) against variable
     * @p fragility_variable (0-based, -1: none) in @p n_bins bins of equal
     * counts. @p values holds the samples' variables row by row.
     */
    nlohmann::json
    sample_statistics(const std::vector<double>       &K,
                      const std::vector<SampleStatus> &status,
                      const std::vector<double>       &values,
                      const unsigned int               n_variables,
                      const int                        fragility_variable,
                      const unsigned int               n_bins);

    /**
     * The probabilistic safety factor (Probabilistic subsection): after the
     * model's safety factor, K of every sample of the random variables by
     * the iteration of eqs. (10)-(13) (iterate(), with its certificate) on
     * the model's one factorisation: the blocks' stiffness, C and W do not
     * depend on c and phi, nor on the weight, kh or the water level, which
     * are right-hand sides (SampleLoads), so a sample costs its contact
     * solves (and, with a random water level, one block solve of its
     * water). Each sample starts as the deterministic K did, at Safety
     * factor/Initial factor from the initial states, with a fresh
     * factorisation of the mixed system, so its result does not depend on
     * which samples were solved before: the samples are split over the MPI
     * ranks and gathered in order, and the results are the same bit for
     * bit with any number of ranks. Also FOSM and Rosenblueth's point
     * estimates, if asked. Rank 0 writes samples.csv into the results
     * folder. Returns summary.json's "probabilistic", with
     * @p deterministic_K, the model's own K, beside the samples' statistics.
     * @p seismic is the model's seismic load (seismic_analyses()).
     */
    /**
     * The work of the samples of @p p (parameters/work_estimate.h): each
     * takes @p seconds_per_sample (0 where not yet known: the memory
     * alone), and holds its values, its results and, where the water level
     * is random, @p bytes_per_water_case for its load case.
     */
    parameters::WorkEstimate
    sample_work_estimate(const ProbabilisticParameters &p,
                         double                         seconds_per_sample,
                         double                         bytes_per_water_case);

    template <int dim>
    nlohmann::json
    probabilistic_safety_factor(Model<dim>           &model,
                                const double          deterministic_K,
                                const SeismicResults &seismic);
  } // namespace analyses
} // namespace fdem
