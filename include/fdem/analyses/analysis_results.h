// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/fe_stress_factor.h>
#include <fdem/analyses/limit_equilibrium_model.h>
#include <fdem/analyses/safety_factor_iteration.h>
#include <fdem/analyses/seismic_results.h>

#include <nlohmann/json.hpp>

namespace fdem
{
  namespace analyses
  {
    /**
     * What the analyses of one run found on one Model: the results view
     * that the output (summary.json, the result block, the report) and the
     * tests read. The model holds the model's state (blocks, interfaces,
     * contact solution); each analysis fills its part here.
     */
    struct AnalysisResults
    {
      /** Whether the safety factor of eqs. (10)-(13) was computed. */
      bool has_safety_factor = false;
      /** The safety factor with its steps and certificate
       * (SafetyFactorAnalysis). */
      Result safety_factor;
      /** The FE-stress factor of the sliding surface (computed with the safety
       * factor). */
      FeStressFactor fe_stress;
      /** Limit equilibrium on the same sliding surface (slope generator only).
       */
      LimitEquilibriumResults limit_equilibrium;
      /** The seismic load, the yield acceleration and the Newmark displacement.
       */
      SeismicResults seismic;
      /** summary.json's "probabilistic" (analyses/probabilistic.h), if
       * computed. */
      nlohmann::json probabilistic;
    };
  } // namespace analyses
} // namespace fdem
