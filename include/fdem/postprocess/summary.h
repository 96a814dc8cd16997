// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/analysis_results.h>
#include <fdem/model.h>
#include <fdem/postprocess/interface_output.h>

#include <nlohmann/json.hpp>

#include <vector>

namespace fdem
{
  namespace postprocess
  {
    /**
     * The schema of summary.json (README, "What a run writes") for the
     * model's current contact state: case, blocks with their support
     * reactions @p reactions, interfaces from @p results, the Hertz
     * reference @p hertz if any, what the analyses found (@p analyses_results:
     * the safety factor with its steps and certificate, the FE-stress
     * factor, limit equilibrium), the last contact solve, and "status". The
     * run adds its timings and peak memory.
     */
    template <int dim>
    nlohmann::json
    make_summary(const Model<dim>                &model,
                 const analyses::AnalysisResults &analyses_results,
                 const std::vector<std::vector<PairResult<dim>>> &results,
                 const nlohmann::json                            &hertz,
                 const std::vector<double>                       &reactions);
  } // namespace postprocess
} // namespace fdem
