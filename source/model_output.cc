// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

// What a run of the Model writes: the blocks' displacements recovered from
// the contact solution, VTU and PVD files, the interface CSV and
// summary.json (postprocess/ holds the formats; this file only drives them).
#include <fdem/model.h>
#include <fdem/postprocess/block_output.h>
#include <fdem/postprocess/hertz_reference.h>
#include <fdem/postprocess/interface_csv.h>
#include <fdem/postprocess/interface_output.h>
#include <fdem/postprocess/interface_vtu.h>
#include <fdem/postprocess/output_files.h>
#include <fdem/postprocess/run_cost.h>
#include <fdem/postprocess/summary.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace fdem
{
  template <int dim>
  std::vector<Vector<double>>
  Model<dim>::block_displacements(
    const contact::ContactSolution &solution) const
  {
    std::vector<Vector<double>> u_all;
    for (unsigned int b = 0; b < blocks.size(); ++b)
      {
        Vector<double> u =
          blocks[b]->solve(mixed_system->block_nodal_forces(b, solution));
        Vector<double> gamma(blocks[b]->n_free_rigid_modes());
        for (unsigned int m = 0; m < gamma.size(); ++m)
          gamma[m] =
            solution.rigid_motions[mixed_system->first_rigid_unknown[b] + m];
        blocks[b]->add_rigid_motion(gamma, u);
        u_all.push_back(u);
      }
    return u_all;
  }

  template <int dim>
  void
  Model<dim>::recover_block_displacements()
  {
    TimerOutput::Scope scope(timer, "recovery");
    displacements = block_displacements(contact_outcome.solution);
  }

  template <int dim>
  std::vector<std::vector<postprocess::PairResult<dim>>>
  Model<dim>::interface_results() const
  {
    std::vector<std::vector<postprocess::PairResult<dim>>> results;
    const auto   full_strengths = pair_strengths(1.0);
    unsigned int first_pair     = 0;
    for (const auto &interface : interfaces)
      {
        results.push_back(postprocess::pair_results(interface,
                                                    first_pair,
                                                    contact_outcome.solution,
                                                    contact_outcome.states,
                                                    full_strengths));
        first_pair += interface.pairs.size();
      }
    return results;
  }

  template <int dim>
  void
  Model<dim>::write_vtu(const std::string                  &suffix,
                        const postprocess::OutputState     &state,
                        std::vector<postprocess::PvdEntry> &entries,
                        const std::vector<Vector<double>>  *mechanism)
  {
    const std::string directory = parameters.output_directory();
    const auto        results   = interface_results();
    unsigned int      part      = 0;
    // Two names may give one file name ('rock/1' and 'rock 1'): the later
    // gets its index appended, so that no file is written twice.
    std::set<std::string> stems;
    const auto            unique = [&](const std::string &kind,
                            const std::string &name,
                            const unsigned int i) {
      return stems.insert(kind + postprocess::file_stem(name)).second ?
                          suffix :
                          "-" + std::to_string(i) + suffix;
    };
    // Only rank 0 writes (every rank holds every block); not collective.
    for (unsigned int b = 0; b < blocks.size(); ++b)
      entries.push_back(
        {state.K,
         part++,
         blocks[b]->name,
         postprocess::write_block_vtu(*blocks[b],
                                      b,
                                      displacements[b],
                                      mechanism ? &(*mechanism)[b] : nullptr,
                                      state,
                                      directory,
                                      unique("block-", blocks[b]->name, b))});
    for (unsigned int i = 0; i < interfaces.size(); ++i)
      {
        // Nodes paired on an interface listed before (a wedge's line of
        // intersection): no pair of this one.
        std::vector<Point<dim>> shared;
        for (const auto &node : interfaces[i].shared_nodes)
          shared.push_back(
            interfaces[node.interface].pairs[node.pair].position_J);
        const unsigned int J = interfaces[i].block_J;
        entries.push_back({state.K,
                           part++,
                           interfaces[i].name,
                           postprocess::write_interface_vtu(
                             *blocks[J],
                             interfaces[i],
                             results[i],
                             shared,
                             displacements[J],
                             mechanism ? &(*mechanism)[J] : nullptr,
                             state,
                             directory,
                             unique("interface-", interfaces[i].name, i))});
      }
  }

  template <int dim>
  void
  Model<dim>::output_results()
  {
    const std::string  directory = parameters.output_directory();
    TimerOutput::Scope scope(timer, "output");

    auto                 results = interface_results();
    const nlohmann::json hertz   = postprocess::hertz_reference(*this, results);

    // Without equilibrium there is no field to show: only the summary says why.
    const bool converged = contact_outcome.converged();
    if (converged && writes_files)
      {
        // Each interface from its upper end: against gravity.
        Tensor<1, dim> up;
        for (unsigned int d = 0; d < dim; ++d)
          up[d] = -parameters.loads.gravity_direction[d];
        postprocess::write_interface_csv(directory + "/interfaces.csv",
                                         interfaces,
                                         results,
                                         up);
      }
    if (converged && parameters.output.write_vtu)
      {
        postprocess::OutputState state;
        state.K = strength_reduction;
        // The mechanism: from the elastic state with every pair stuck (the
        // FE-stress factor's, same loads) to this one: one more solve per
        // block (collective), where the safety factor was computed.
        std::vector<Vector<double>> mechanism;
        const auto                 &all_stick = fe_stress.all_stick;
        if (parameters.safety_factor.compute && all_stick.solved &&
            all_stick.forces.size() == dim * mixed_system->n_pairs())
          {
            mechanism = block_displacements(all_stick);
            for (unsigned int b = 0; b < blocks.size(); ++b)
              mechanism[b].sadd(-1.0, 1.0, displacements[b]);
          }
        if (parameters.safety_factor.compute)
          {
            for (const auto &step : safety_factor_result.steps)
              if (step.K == strength_reduction && step.solution.has_factor())
                state.K_star = step.K_star;
            state.description =
              "final state: the last state of the safety-factor iteration "
              "with a static solution";
          }
        else
          state.description =
            "final state: the contact problem at full strength";
        std::vector<postprocess::PvdEntry> entries;
        write_vtu("", state, entries, mechanism.empty() ? nullptr : &mechanism);
        if (writes_files)
          postprocess::write_pvd(directory + "/solution.pvd", entries);
        // The steps' files if they were written, else the final state's.
        if (parameters.safety_factor.compute && writes_files)
          postprocess::write_pvd(directory + "/safety_factor_steps.pvd",
                                 step_files.empty() ? entries : step_files);
      }
    // Reactions at the minimal support, zero at equilibrium: a pass over all
    // cells, timed as output.
    std::vector<double> reactions(blocks.size(), 0.0);
    if (converged)
      for (unsigned int b = 0; b < blocks.size(); ++b)
        {
          Vector<double> residual = blocks[b]->nodal_residual(displacements[b]);
          residual +=
            load_change(b); // the assembled cells have the assembled load
          for (const auto dof : blocks[b]->support_dofs)
            reactions[b] = std::max(reactions[b], std::abs(residual[dof]));
        }
    scope.stop();

    summary = postprocess::make_summary(*this,
                                        results,
                                        hertz,
                                        reactions,
                                        parameters.safety_factor.compute ?
                                          &safety_factor_result :
                                          nullptr);
    if (seismic.active)
      summary["seismic"] = analyses::to_json(seismic);
    if (reinforcement_output)
      summary["reinforcement"] = reinforcement_output();
    if (!probabilistic.is_null())
      summary["probabilistic"] = probabilistic;
    // The only entries that differ between two runs of the same input.
    summary["timings"] =
      postprocess::section_wall_times(timer, run_timer.wall_time());
    summary["peak_memory_MiB"] = postprocess::peak_memory_mib();
    if (writes_files)
      postprocess::write_json(directory + "/summary.json", summary);
  }

  template void
  Model<2>::recover_block_displacements();
  template void
  Model<3>::recover_block_displacements();
  template void
  Model<2>::output_results();
  template void
  Model<3>::output_results();
  template void
  Model<2>::write_vtu(const std::string &,
                      const postprocess::OutputState &,
                      std::vector<postprocess::PvdEntry> &,
                      const std::vector<Vector<double>> *);
  template void
  Model<3>::write_vtu(const std::string &,
                      const postprocess::OutputState &,
                      std::vector<postprocess::PvdEntry> &,
                      const std::vector<Vector<double>> *);
  template std::vector<Vector<double>>
  Model<2>::block_displacements(const contact::ContactSolution &) const;
  template std::vector<Vector<double>>
  Model<3>::block_displacements(const contact::ContactSolution &) const;
} // namespace fdem
