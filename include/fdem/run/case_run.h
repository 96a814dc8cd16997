// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/analysis_results.h>
#include <fdem/analyses/anchors.h>
#include <fdem/analyses/bars.h>
#include <fdem/model.h>
#include <fdem/postprocess/run_log.h>

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace fdem
{
  /**
   * One run of a case: the Model, the analyses on it in the paper's order
   * (run()), and what the run writes into its results folder (VTU/PVD,
   * the interface CSV, summary.json).
   */
  template <int dim>
  class CaseRun
  {
  public:
    /**
     * @p expanded_parameters is the .prm file with its includes expanded
     * (written as parameters.prm); @p log and @p brief as for Model.
     */
    CaseRun(const parameters::Parameters &parameters,
            const std::string            &expanded_parameters,
            std::ostream                 &log,
            std::ostream                 *brief = nullptr);

    /** Everything, as the paper does it, then the output files. */
    void
    run();

    /** The model (its state after run()). */
    const Model<dim> &
    model() const
    {
      return the_model;
    }

    /** What the analyses found. */
    const analyses::AnalysisResults &
    results() const
    {
      return analysis_results;
    }

    /** summary.json's content (every rank has it). */
    const nlohmann::json &
    summary() const
    {
      return summary_json;
    }

  private:
    /** VTU/PVD, interface CSV and summary.json of the model's current state. */
    void
    output_results();

    /** The VTU files of a safety-factor step with a static solution
     * (Output/Write steps). */
    void
    write_step(const double K, const double K_star);

    Model<dim>                the_model;
    analyses::AnalysisResults analysis_results;
    nlohmann::json            summary_json;
    const std::string         expanded_parameters;
    /** VTU/PVD files of the steps of the safety-factor iteration. */
    std::vector<postprocess::PvdEntry> step_files;
    /** The anchors of Reinforcement placed in the model. */
    std::vector<analyses::Anchor<dim>> anchors;
    /** The passive bars of Reinforcement placed in the model. */
    std::vector<analyses::Bar<dim>> bars;
  };

  /**
   * Reads the .prm file and runs the case in its dimension; returns the
   * summary. Its "status" is "completed", or says why the contact problem
   * has no solution. The full log goes to log.txt in the results folder
   * as well as to @p log's screen; the run ends with the result block
   * (postprocess::result_block()).
   */
  nlohmann::json
  run_case(const std::string &prm_file, postprocess::RunLog &log);

  /**
   * The same with Output/Report switched off whatever the .prm file says
   * (the command line's --no-report) when @p make_report is false.
   */
  nlohmann::json
  run_case(const std::string   &prm_file,
           postprocess::RunLog &log,
           bool                 make_report);

  /**
   * Reads the .prm file and makes the model up to its node pairs, with the
   * layout checks (Model::validate()); throws at the first error, returns
   * the warnings.
   */
  std::vector<std::string>
  validate_case(const std::string &prm_file, std::ostream &log);
} // namespace fdem
