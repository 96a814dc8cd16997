// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The two ways main() runs a case: validate it (up to its node pairs, with
// the layout checks) or run it into its results folder.
#include <fdem/analyses/anchors.h>
#include <fdem/analyses/newmark.h>
#include <fdem/analyses/probabilistic.h>
#include <fdem/analyses/surface_search.h>
#include <fdem/geometry/mesh_estimate.h>
#include <fdem/postprocess/report.h>
#include <fdem/postprocess/result_block.h>
#include <fdem/postprocess/results_folder.h>
#include <fdem/run/case_run.h>

#include <deal.II/base/mpi.h>

#include <filesystem>

namespace fdem
{
  namespace
  {
    /**
     * The work estimates that need the parameters alone, made before
     * anything is meshed or written: the search's grid, and the memory of
     * the samples (their time is estimated from K at the means,
     * probabilistic_safety_factor()).
     */
    void
    check_work_estimates(const parameters::Parameters &parameters)
    {
      const double limit  = geometry::memory_limit_MiB(parameters.geometry);
      const double budget = parameters.geometry.time_budget;
      if (parameters.surface_search.enabled)
        parameters::check_work_estimate(analyses::search_work_estimate(
                                          parameters.surface_search),
                                        limit,
                                        budget);
      if (parameters.probabilistic.compute)
        parameters::check_work_estimate(
          analyses::sample_work_estimate(parameters.probabilistic, 0, 0),
          limit,
          budget);
      const auto &yield = parameters.yield_acceleration;
      if (yield.compute && !yield.acceleration_record.empty())
        parameters::check_work_estimate(analyses::record_work_estimate(
                                          yield.acceleration_record),
                                        limit,
                                        budget);
    }
  } // namespace

  std::vector<std::string>
  validate_case(const std::string &prm_file, std::ostream &log)
  {
    const parameters::Parameters parameters =
      parameters::read_parameters(prm_file);
    postprocess::check_results_target(parameters.output_directory(), prm_file);
    check_work_estimates(parameters);
    // The files the analyses read after the model: the record.
    const auto &yield = parameters.yield_acceleration;
    if (!yield.acceleration_record.empty())
      analyses::read_acceleration_record(yield.acceleration_record,
                                         yield.acceleration_unit);
    if (parameters.dimension == 2)
      {
        Model<2> model(parameters, log);
        model.validate();
        analyses::locate_anchors(model);
        return model.get_warnings();
      }
    Model<3> model(parameters, log);
    model.validate();
    analyses::locate_anchors(model);
    return model.get_warnings();
  }

  nlohmann::json
  run_case(const std::string &prm_file, postprocess::RunLog &log)
  {
    return run_case(prm_file, log, true);
  }

  nlohmann::json
  run_case(const std::string   &prm_file,
           postprocess::RunLog &log,
           const bool           make_report)
  {
    std::string            expanded;
    parameters::Parameters parameters =
      parameters::read_parameters(prm_file, &expanded);
    if (!make_report)
      parameters.output.report = false;
    check_work_estimates(parameters);
    // The run writes into a partial folder that becomes the results folder
    // only when the run ends (postprocess/results_folder.h).
    postprocess::ResultsFolder folder(parameters.output_directory(),
                                      prm_file,
                                      Utilities::MPI::this_mpi_process(
                                        MPI_COMM_WORLD) == 0);
    const std::string          results = parameters.output_directory();
    parameters.output.directory        = folder.staging();
    // The file stays open across commit(): the rename moves it with the
    // folder, and the result block still reaches it.
    const std::string log_file = "log.txt";
    log.open_file(folder.staging() + "/" + log_file);
    log.brief() << "Case: " << prm_file << " (" << parameters.case_name << ", "
                << parameters.dimension << "D)" << std::endl;
    nlohmann::json summary;
    // The surface search replaces the circle of Geometry/Slope by the
    // critical one, on which the run below computes K as usual.
    analyses::SurfaceSearchResult search;
    if (parameters.surface_search.enabled)
      search =
        analyses::search_critical_surface(parameters,
                                          folder.staging() + "/search-scratch",
                                          log.brief());
    if (parameters.dimension == 2)
      {
        CaseRun<2> case_run(parameters, expanded, log.detail(), &log.brief());
        case_run.run();
        summary = case_run.summary();
        if (search.performed &&
            Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          analyses::write_surface_search(search, folder.staging(), summary);
      }
    else
      {
        CaseRun<3> case_run(parameters, expanded, log.detail(), &log.brief());
        case_run.run();
        summary = case_run.summary();
      }
    // The report reads the finished files and goes into the folder before
    // it is committed (a folder with a report is whole).
    if (parameters.output.report &&
        Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 &&
        summary.contains("status"))
      {
        postprocess::make_report(folder.staging(), summary, log.detail());
        if (!summary["report"]["made"].get<bool>())
          log.brief() << "warning: "
                      << summary["warnings"].back().get<std::string>()
                      << std::endl;
      }
    // The result block goes into log.txt before the swap, and the log is
    // checked, so that a committed folder has its whole log.
    std::string folder_name = results;
    while (folder_name.size() > 1 && folder_name.back() == '/')
      folder_name.pop_back();
    for (const std::string &line :
         postprocess::result_block(summary, folder_name, log_file))
      log.brief() << line << std::endl;
    log.check_file();
    folder.commit();
    return summary;
  }
} // namespace fdem
