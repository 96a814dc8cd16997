// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// One run of a case: the model's steps and the analyses on it in the
// paper's order, then what the run writes (postprocess/ holds the formats;
// this file only drives them).
#include <fdem/analyses/fe_stress_factor.h>
#include <fdem/analyses/limit_equilibrium_model.h>
#include <fdem/analyses/probabilistic.h>
#include <fdem/analyses/safety_factor_analysis.h>
#include <fdem/analyses/seismic.h>
#include <fdem/postprocess/hertz_reference.h>
#include <fdem/postprocess/interface_csv.h>
#include <fdem/postprocess/output_file.h>
#include <fdem/postprocess/run_cost.h>
#include <fdem/postprocess/summary.h>
#include <fdem/run/case_run.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace fdem
{
  template <int dim>
  CaseRun<dim>::CaseRun(const parameters::Parameters &parameters,
                        const std::string            &expanded_parameters,
                        std::ostream                 &log,
                        std::ostream                 *brief)
    : the_model(parameters, log, brief)
    , expanded_parameters(expanded_parameters)
  {}

  template <int dim>
  void
  CaseRun<dim>::run()
  {
    Model<dim>                   &model      = the_model;
    const parameters::Parameters &parameters = model.get_parameters();
    const std::string             directory  = parameters.output_directory();
    if (model.writes_files())
      {
        std::filesystem::create_directories(directory);
        // A summary.json left from an earlier run must not pass for this one.
        std::filesystem::remove(directory + "/summary.json");
        postprocess::write_text_file(directory + "/parameters.prm",
                                     expanded_parameters);
      }

    // A progress line at the start of each phase: on a long run the screen
    // says what the program is doing and how long it has taken so far.
    model.progress("mesh");
    model.make_geometry();
    // Limit equilibrium on the generator's section: after the mesh, so that
    // the generator's own checks of the surface come first; it needs only
    // the parameters. Its root searches take a few tenths of a second, more
    // than the whole contact analysis of a coarse mesh: a phase of its own.
    {
      TimerOutput::Scope scope(model.phase_timer(), "limit equilibrium");
      analysis_results.limit_equilibrium =
        analyses::model_limit_equilibrium(parameters);
    }
    model.progress("blocks: dofs, constraints, free rigid modes");
    model.setup_blocks();
    model.progress("assembly and factorisation");
    model.assemble_and_factorize();
    model.progress("node pairs of the interfaces");
    model.build_interfaces();
    // Passive bars are pairs of the mixed system of their own: placed
    // before C is made.
    bars = analyses::place_bars(model);
    model.progress("flexibility C of " + std::to_string(model.n_pairs()) +
                   " node pairs");
    model.compute_flexibility();
    // The anchors' load cases, before the seismic analyses (k_y with them).
    anchors = analyses::add_anchor_loads(model);
    // The seismic load (and k_y, Newmark) before K: K is then that of the
    // seismic load; without one the load stays the assembled one.
    analysis_results.seismic = analyses::seismic_analyses(model);
    if (parameters.safety_factor.compute)
      {
        // With Output/Write steps, each step with a static solution can be
        // looked at in ParaView, K as its time.
        std::function<void(double, double)> step_output;
        if (parameters.output.write_vtu && parameters.output.write_steps)
          step_output = [this](const double K, const double K_star) {
            write_step(K, K_star);
          };
        analyses::SafetyFactorAnalysis<dim> analysis(model, step_output);
        analysis_results.safety_factor     = analysis.run();
        analysis_results.has_safety_factor = true;
        // Beside K, the factor that stress-based programs report: one more
        // solve on the same factorisations (after K, so as not to change
        // the factors the iteration starts from), unless the iteration
        // solved it already (its estimate after a failed first K).
        analysis_results.fe_stress = analysis.fe_stress_factor_computed() ?
                                       *analysis.fe_stress_factor_computed() :
                                       analyses::fe_stress_factor(model);
        if (analysis_results.fe_stress.computed)
          model.log << "FE-stress factor (every pair stuck, full strength): "
                    << std::setprecision(8) << analysis_results.fe_stress.factor
                    << std::endl;
        if (parameters.probabilistic.compute)
          analysis_results.probabilistic =
            analyses::probabilistic_safety_factor(
              model,
              analysis_results.safety_factor.safety_factor,
              analysis_results.seismic);
      }
    else
      {
        model.progress("contact problem");
        model.solve_contact();
      }
    analyses::print_limit_equilibrium(analysis_results.limit_equilibrium,
                                      model.log);
    if (model.get_contact_outcome().converged())
      model.recover_block_displacements();
    model.progress("output");
    output_results();

    model.progress("done");
    model.phase_timer().print_summary();
    std::ostringstream memory; // not to leave the log's format changed
    memory << std::fixed << std::setprecision(1)
           << postprocess::peak_memory_mib();
    model.log << "Peak memory: " << memory.str() << " MiB" << std::endl;
  }

  template <int dim>
  void
  CaseRun<dim>::write_step(const double K, const double K_star)
  {
    // The recovery is collective (the block solves): every rank comes here.
    the_model.recover_block_displacements();
    TimerOutput::Scope scope(the_model.phase_timer(), "output");
    const unsigned int step =
      step_files.size() /
      (the_model.get_blocks().size() + the_model.get_interfaces().size());
    std::ostringstream description;
    description << "safety-factor step " << step
                << " with a static solution, K = " << std::setprecision(9) << K;
    the_model.write_vtu("-step" + Utilities::int_to_string(step, 3),
                        {K, K_star, description.str()},
                        step_files);
  }

  template <int dim>
  void
  CaseRun<dim>::output_results()
  {
    const Model<dim>             &model      = the_model;
    const parameters::Parameters &parameters = model.get_parameters();
    const std::string             directory  = parameters.output_directory();
    TimerOutput::Scope            scope(the_model.phase_timer(), "output");

    auto                 results = model.interface_results();
    const nlohmann::json hertz   = postprocess::hertz_reference(model, results);

    // Without equilibrium there is no field to show: only the summary says why.
    const bool converged = model.get_contact_outcome().converged();
    if (converged && model.writes_files())
      {
        // Each interface from its upper end: against gravity.
        Tensor<1, dim> up;
        for (unsigned int d = 0; d < dim; ++d)
          up[d] = -parameters.loads.gravity_direction[d];
        postprocess::write_interface_csv(directory + "/interfaces.csv",
                                         model.get_interfaces(),
                                         results,
                                         up);
      }
    if (converged && parameters.output.write_vtu)
      {
        postprocess::OutputState state;
        state.K = model.get_strength_reduction();
        // The mechanism: from the elastic state with every pair stuck (the
        // FE-stress factor's, same loads) to this one: one more solve per
        // block (collective), where the safety factor was computed.
        std::vector<Vector<double>> mechanism;
        const auto &all_stick = analysis_results.fe_stress.all_stick;
        if (analysis_results.has_safety_factor && all_stick.solved &&
            all_stick.forces.size() == dim * model.get_mixed_system().n_pairs())
          {
            // The all-stick state was solved with the loads of K = 1 (an
            // anchor reduced by K: its full shear); its displacements need
            // the same loads, then the final state's are put back.
            the_model.apply_strength_dependent_loads(1.0);
            mechanism = model.block_displacements(all_stick);
            the_model.apply_strength_dependent_loads(
              model.get_strength_reduction());
            for (unsigned int b = 0; b < model.get_blocks().size(); ++b)
              mechanism[b].sadd(-1.0, 1.0, model.get_displacements()[b]);
          }
        if (analysis_results.has_safety_factor)
          {
            for (const auto &step : analysis_results.safety_factor.steps)
              if (step.K == state.K && step.solution.has_factor())
                state.K_star = step.K_star;
            state.description =
              "final state: the last state of the safety-factor iteration "
              "with a static solution";
          }
        else
          state.description =
            "final state: the contact problem at full strength";
        std::vector<postprocess::PvdEntry> entries;
        model.write_vtu("",
                        state,
                        entries,
                        mechanism.empty() ? nullptr : &mechanism);
        if (model.writes_files())
          postprocess::write_pvd(directory + "/solution.pvd", entries);
        // The steps' files if they were written, else the final state's.
        if (analysis_results.has_safety_factor && model.writes_files())
          postprocess::write_pvd(directory + "/safety_factor_steps.pvd",
                                 step_files.empty() ? entries : step_files);
      }
    // Reactions at the minimal support, zero at equilibrium: a pass over
    // all cells, timed as output.
    const std::vector<double> reactions =
      converged ? model.support_reactions() :
                  std::vector<double>(model.get_blocks().size(), 0.0);
    scope.stop();

    summary_json = postprocess::make_summary(
      model, analysis_results, results, hertz, reactions);
    if (analysis_results.seismic.active)
      summary_json["seismic"] = analyses::to_json(analysis_results.seismic);
    if (!anchors.empty())
      summary_json["reinforcement"] =
        analyses::reinforcement_output(model, anchors);
    if (!bars.empty())
      summary_json["reinforcement"]["passive_bars"] =
        analyses::bars_output(model, bars);
    if (!analysis_results.probabilistic.is_null())
      summary_json["probabilistic"] = analysis_results.probabilistic;
    // The only entries that differ between two runs of the same input.
    summary_json["timings"] =
      postprocess::section_wall_times(the_model.phase_timer(),
                                      model.wall_time());
    summary_json["peak_memory_MiB"] = postprocess::peak_memory_mib();
    if (model.writes_files())
      postprocess::write_json(directory + "/summary.json", summary_json);
  }

  template class CaseRun<2>;
  template class CaseRun<3>;
} // namespace fdem
