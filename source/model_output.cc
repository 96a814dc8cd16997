// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

// The Model's state as output reads it: the blocks' displacements recovered
// from the contact solution, the results per pair, the support reactions
// and the VTU files of the current state (postprocess/ holds the formats).
#include <fdem/model.h>
#include <fdem/postprocess/block_output.h>
#include <fdem/postprocess/interface_output.h>
#include <fdem/postprocess/interface_vtu.h>
#include <fdem/postprocess/output_files.h>

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
                        const std::vector<Vector<double>>  *mechanism) const
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
  std::vector<double>
  Model<dim>::support_reactions() const
  {
    std::vector<double> reactions(blocks.size(), 0.0);
    for (unsigned int b = 0; b < blocks.size(); ++b)
      {
        Vector<double> residual = blocks[b]->nodal_residual(displacements[b]);
        residual +=
          load_change(b); // the assembled cells have the assembled load
        for (const auto dof : blocks[b]->support_dofs)
          reactions[b] = std::max(reactions[b], std::abs(residual[dof]));
      }
    return reactions;
  }

  template void
  Model<2>::recover_block_displacements();
  template void
  Model<3>::recover_block_displacements();
  template std::vector<double>
  Model<2>::support_reactions() const;
  template std::vector<double>
  Model<3>::support_reactions() const;
  template std::vector<std::vector<postprocess::PairResult<2>>>
  Model<2>::interface_results() const;
  template std::vector<std::vector<postprocess::PairResult<3>>>
  Model<3>::interface_results() const;
  template void
  Model<2>::write_vtu(const std::string &,
                      const postprocess::OutputState &,
                      std::vector<postprocess::PvdEntry> &,
                      const std::vector<Vector<double>> *) const;
  template void
  Model<3>::write_vtu(const std::string &,
                      const postprocess::OutputState &,
                      std::vector<postprocess::PvdEntry> &,
                      const std::vector<Vector<double>> *) const;
  template std::vector<Vector<double>>
  Model<2>::block_displacements(const contact::ContactSolution &) const;
  template std::vector<Vector<double>>
  Model<3>::block_displacements(const contact::ContactSolution &) const;
} // namespace fdem
