// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/blocks/surface_loads.h>
#include <fdem/checks/layout_checks.h>
#include <fdem/geometry/make_mesh.h>
#include <fdem/model.h>
#include <fdem/postprocess/block_output.h>
#include <fdem/postprocess/hertz_sphere.h>
#include <fdem/postprocess/interface_output.h>
#include <fdem/postprocess/output_files.h>
#include <fdem/postprocess/run_cost.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <iomanip>
#include <numeric>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fdem
{
  namespace
  {
    template <int dim>
    std::size_t
    n_pairs_of(const std::vector<contact::Interface<dim>> &interfaces)
    {
      std::size_t n = 0;
      for (const auto &interface : interfaces)
        n += interface.pairs.size();
      return n;
    }
  } // namespace

  template <int dim>
  Model<dim>::Model(const parameters::Parameters &parameters,
                    const std::string &           expanded_parameters,
                    std::ostream &                log)
    : parameters(parameters)
    , expanded_parameters(expanded_parameters)
    , log(log)
    , writes_files(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    , timer(log, TimerOutput::never, TimerOutput::wall_times)
  {}

  template <int dim>
  void
  Model<dim>::run()
  {
    const std::string directory = parameters.output_directory();
    if (writes_files)
      {
        std::filesystem::create_directories(directory);
        // A summary.json left from an earlier run must not pass for this one.
        std::filesystem::remove(directory + "/summary.json");
        std::ofstream out(directory + "/parameters.prm");
        out << expanded_parameters;
      }

    // A progress line at the start of each phase: on a long run the screen
    // says what the program is doing and how long it has taken so far.
    progress("mesh");
    make_geometry();
    progress("blocks: dofs, constraints, free rigid modes");
    setup_blocks();
    progress("assembly and factorisation");
    assemble_and_factorize();
    progress("node pairs of the interfaces");
    build_interfaces();
    progress("flexibility C of " + std::to_string(n_pairs_of(interfaces)) + " node pairs");
    compute_flexibility();
    if (parameters.safety_factor.compute)
      compute_safety_factor();
    else
      {
        progress("contact problem");
        solve_contact();
      }
    if (contact_outcome.converged())
      recover_block_displacements();
    progress("output");
    output_results();

    progress("done");
    timer.print_summary();
    std::ostringstream memory; // not to leave the log's format changed
    memory << std::fixed << std::setprecision(1) << postprocess::peak_memory_mib();
    log << "Peak memory: " << memory.str() << " MiB" << std::endl;
  }

  template <int dim>
  void
  Model<dim>::progress(const std::string &what) const
  {
    log << postprocess::progress_stamp(run_timer.wall_time()) << what << std::endl;
  }

  template <int dim>
  types::boundary_id
  Model<dim>::face_group(const std::string &name, const std::string &what) const
  {
    const auto it = std::find(mesh.face_group_names.begin(),
                              mesh.face_group_names.end(),
                              name);
    AssertThrow(it != mesh.face_group_names.end(),
                ExcMessage(what + ": '" + name + "' is not a face group " +
                           "(physical group of dimension " +
                           std::to_string(dim - 1) + ") in " + mesh.source + "."));
    return it - mesh.face_group_names.begin();
  }

  template <int dim>
  void
  Model<dim>::make_geometry()
  {
    TimerOutput::Scope scope(timer, "geometry");
    // Every rank makes the same mesh; rank 0 writes it.
    const std::string  msh = writes_files && !validating ? parameters.output_directory() + "/mesh.msh" : "";
    mesh = geometry::make_mesh<dim>(parameters.geometry, parameters.prm_directory, msh);

    // Every block of the mesh needs a material, and every name a block.
    for (const std::string &name : mesh.block_names)
      AssertThrow(parameters.materials.count(name) == 1,
                  ExcMessage("Blocks/Names: the block '" + name + "' of " +
                             mesh.source +
                             " has no material; list it and give it a "
                             "subsection with its Young's modulus."));
    for (const std::string &name : parameters.block_names)
      AssertThrow(std::count(mesh.block_names.begin(), mesh.block_names.end(), name) == 1,
                  ExcMessage("Blocks/Names: '" + name + "' is not a block " +
                             "(physical group of dimension " + std::to_string(dim) +
                             ") in " + mesh.source + "."));
    for (const std::string &name : parameters.boundary_names)
      face_group(name, "Boundaries/Names");
    for (const std::string &name : parameters.interface_names)
      face_group(name, "Interfaces/Names");
    log << "Geometry: " << mesh.source << ", " << mesh.cells.size() << " cells, "
        << mesh.block_names.size() << " blocks" << std::endl;
    checks::report(checks::check_mesh_layout(mesh, parameters.interface_names, parameters.boundary_names), warnings, log);
  }

  template <int dim>
  void
  Model<dim>::setup_blocks()
  {
    TimerOutput::Scope scope(timer, "setup");
    std::map<types::boundary_id, parameters::BoundaryParameters> conditions;
    for (const std::string &name : parameters.boundary_names)
      conditions[face_group(name, "Boundaries/Names")] = parameters.boundaries.at(name);
    std::vector<types::boundary_id> interface_ids;
    for (const std::string &name : parameters.interface_names)
      interface_ids.push_back(face_group(name, "Interfaces/Names"));

    // Surface loads: boundary pressures and tractions, and the pore pressure
    // of each interface, which pushes on both sides' faces.
    std::map<types::boundary_id, std::shared_ptr<const Function<dim>>> pressures, tractions;
    for (const std::string &name : parameters.boundary_names)
      {
        const auto &boundary = parameters.boundaries.at(name);
        const auto  id       = face_group(name, "Boundaries/Names");
        if (boundary.pressure != "0")
          pressures[id] = blocks::make_pressure_function<dim>(boundary.pressure, parameters.water);
        if (boundary.traction != "0")
          tractions[id] = blocks::make_traction_function<dim>(boundary.traction);
      }
    for (const std::string &name : parameters.interface_names)
      if (parameters.interfaces.at(name).pore_pressure != "0")
        pressures[face_group(name, "Interfaces/Names")] =
          blocks::make_pressure_function<dim>(parameters.interfaces.at(name).pore_pressure,
                                              parameters.water);
    // A pressure that is not a number somewhere on its faces would spread
    // NaN through the solution: check it at every vertex of its faces.
    for (const auto &[id, pressure] : pressures)
      for (const auto &face : mesh.faces)
        if (face.boundary_id == id)
          for (const unsigned int v : face.vertices)
            {
              const double value = pressure->value(mesh.vertices[v]);
              const std::string &name = mesh.face_group_names[id];
              const bool is_interface =
                std::count(parameters.interface_names.begin(), parameters.interface_names.end(), name);
              std::ostringstream point;
              point << mesh.vertices[v];
              AssertThrow(std::isfinite(value),
                          ExcMessage((is_interface ? "Interfaces/" + name + "/Pore pressure" :
                                                     "Boundaries/" + name + "/Pressure") +
                                     ": not a number at (" + point.str() + ")."));
            }

    blocks.clear();
    for (unsigned int b = 0; b < mesh.block_names.size(); ++b)
      {
        const std::string &name = mesh.block_names[b];
        blocks.push_back(std::make_unique<blocks::ElasticBlock<dim>>(
          name, mesh, std::vector<unsigned int>{b},
          std::map<unsigned int, parameters::MaterialParameters>{
            {b, parameters.materials.at(name)}},
          parameters.fe_degree));
        blocks.back()->setup_constraints(conditions, interface_ids);
        blocks.back()->set_surface_loads(pressures, tractions);
        blocks.back()->find_free_rigid_modes();
        log << "  block '" << name << "': " << blocks.back()->dof_handler.n_dofs()
            << " dofs, " << blocks.back()->n_free_rigid_modes()
            << " free rigid modes" << std::endl;
      }
  }

  template <int dim>
  void
  Model<dim>::assemble_and_factorize()
  {
    external_displacements.clear();
    for (const auto &block : blocks)
      {
        {
          TimerOutput::Scope scope(timer, "assembly");
          block->assemble(parameters.loads);
        }
        {
          TimerOutput::Scope scope(timer, "factorisation");
          // The iterative mixed system never uses the interface's Schur
          // complement: computing it would only cost time and memory.
          const bool iterative = parameters.solver.mixed_system == "iterative";
          block->factorize(iterative && parameters.solver.direct_solver == "MUMPS_Schur" ?
                             "MUMPS" :
                             parameters.solver.direct_solver);
        }
        // Timed on its own: the cost of one linear solve of the model is the
        // yardstick of the benchmarks (doc/benchmarks.md).
        TimerOutput::Scope scope(timer, "one solve");
        external_displacements.push_back(block->solve(block->load_vector));
      }
  }

  template <int dim>
  void
  Model<dim>::build_interfaces()
  {
    TimerOutput::Scope scope(timer, "interfaces");
    interfaces.clear();
    for (const std::string &name : parameters.interface_names)
      {
        const types::boundary_id group = face_group(name, "Interfaces/Names");
        std::vector<unsigned int> sides;
        for (unsigned int b = 0; b < blocks.size(); ++b)
          for (const auto &face : blocks[b]->triangulation.active_face_iterators())
            if (face->at_boundary() && face->boundary_id() == group)
              {
                sides.push_back(b);
                break;
              }
        AssertThrow(sides.size() == 2,
                    ExcMessage("Interfaces/" + name + ": the face group lies on " +
                               std::to_string(sides.size()) +
                               " blocks; an interface separates exactly two."));
        // Block I is the one that moves: the one with more free rigid modes.
        if (blocks[sides[1]]->n_free_rigid_modes() > blocks[sides[0]]->n_free_rigid_modes())
          std::swap(sides[0], sides[1]);
        interfaces.push_back(contact::make_interface(name, group,
                                                     sides[0], *blocks[sides[0]],
                                                     sides[1], *blocks[sides[1]],
                                                     parameters.interfaces.at(name).search_distance));
        // A node on two interfaces (the line of intersection of a wedge) is
        // paired once, in the interface listed first: two pairs of the same
        // two nodes would constrain one relative displacement twice.
        auto &     pairs         = interfaces.back().pairs;
        auto &     shared_nodes  = interfaces.back().shared_nodes;
        const auto paired_before = [&](const contact::NodePair<dim> &pair) {
          for (unsigned int i = 0; i + 1 < interfaces.size(); ++i)
            for (unsigned int k = 0; k < interfaces[i].pairs.size(); ++k)
              {
                const auto &other = interfaces[i].pairs[k];
                if (interfaces[i].block_I == sides[0] && interfaces[i].block_J == sides[1] &&
                    other.dofs_I == pair.dofs_I && other.dofs_J == pair.dofs_J)
                  {
                    shared_nodes.push_back({i, k, pair.area});
                    return true;
                  }
              }
          return false;
        };
        pairs.erase(std::remove_if(pairs.begin(), pairs.end(), paired_before), pairs.end());
        interfaces.back().n_shared_nodes = shared_nodes.size();
        AssertThrow(!pairs.empty(),
                    ExcMessage("Interfaces/" + name + ": all its node pairs belong to "
                               "interfaces listed before it."));
        log << "  interface '" << name << "': " << interfaces.back().pairs.size()
            << " node pairs between '" << blocks[sides[0]]->name << "' and '"
            << blocks[sides[1]]->name << "'" << std::endl;
      }
    for (unsigned int b = 0; b < blocks.size(); ++b)
      if (blocks[b]->n_free_rigid_modes() > 0)
        AssertThrow(std::any_of(interfaces.begin(), interfaces.end(),
                                [b](const auto &i) { return i.block_I == b || i.block_J == b; }),
                    ExcMessage("Block '" + blocks[b]->name +
                               "' is not held: its constraints leave rigid "
                               "motions free and no interface touches it."));
    checks::report(checks::pair_triple_points_once(interfaces, blocks), log);
    checks::report(checks::check_interfaces(mesh, blocks, interfaces, parameters.interfaces), warnings, log);
  }

  template <int dim>
  void
  Model<dim>::compute_flexibility()
  {
    TimerOutput::Scope scope(timer, "flexibility");
    mixed_system = std::make_unique<contact::MixedSystem<dim>>(
      blocks,
      external_displacements,
      interfaces,
      parameters.solver.mixed_system == "iterative" ? contact::MixedSystemSolver::iterative :
                                                      contact::MixedSystemSolver::dense);
    mixed_system->krylov_control.tolerance = parameters.solver.gmres_tolerance;
  }

  template <int dim>
  std::vector<contact::PairStrength>
  Model<dim>::pair_strengths(const double K) const
  {
    std::vector<contact::PairStrength> strengths;
    for (const auto &interface : interfaces)
      {
        const parameters::InterfaceParameters &p = parameters.interfaces.at(interface.name);
        for (const auto &pair : interface.pairs)
          {
            contact::PairStrength strength;
            const double          reduction = p.sliding_surface ? K : 1.0;
            if (!p.frictionless)
              {
                strength.friction_coefficient =
                  std::tan(p.friction_angle * numbers::PI / 180) / reduction;
                strength.cohesion_force = p.cohesion * pair.area / reduction;
              }
            strength.tensile_force = p.tensile_strength * pair.area;
            strengths.push_back(strength);
          }
      }
    // Nodes paired in an earlier interface add this interface's strength
    // over their area here to that pair.
    std::vector<unsigned int> first_pair(interfaces.size(), 0);
    for (unsigned int i = 1; i < interfaces.size(); ++i)
      first_pair[i] = first_pair[i - 1] + interfaces[i - 1].pairs.size();
    for (const auto &interface : interfaces)
      {
        const parameters::InterfaceParameters &p = parameters.interfaces.at(interface.name);
        for (const auto &shared : interface.shared_nodes)
          {
            contact::PairStrength &strength = strengths[first_pair[shared.interface] + shared.pair];
            if (!p.frictionless)
              strength.cohesion_force +=
                p.cohesion * shared.area / (p.sliding_surface ? K : 1.0);
            strength.tensile_force += p.tensile_strength * shared.area;
          }
      }
    return strengths;
  }

  template <int dim>
  void
  Model<dim>::solve_contact(const double strength_reduction_factor)
  {
    TimerOutput::Scope scope(timer, "contact");
    const auto strengths = pair_strengths(strength_reduction_factor);
    // Warm start from the last states with a static solution (Sec. 6).
    auto states = last_converged.states.size() == mixed_system->n_pairs() ?
                    last_converged.states :
                    contact::initial_states(*mixed_system, strengths);
    contact::StatusIterationControl control;
    control.max_iterations = parameters.contact.max_status_iterations;
    control.runaway_factor = parameters.contact.runaway_factor;
    log << "  contact problem:" << std::endl;
    const contact::ReusableLU &dense = mixed_system->dense_solver();
    const unsigned int factorized_before = dense.n_factorizations, reused_before = dense.n_reused_solves;
    const unsigned long gmres_before = mixed_system->n_krylov_iterations;
    contact_outcome    = contact::solve_contact_problem(*mixed_system, strengths, states, control, log);
    strength_reduction = strength_reduction_factor;
    if (contact_outcome.converged())
      {
        last_converged   = contact_outcome;
        last_converged_K = strength_reduction_factor;
      }
    log << "  contact problem " << contact::result_description(contact_outcome.result)
        << " after " << contact_outcome.iterations.size() << " solves";
    if (contact_outcome.n_cycles_broken > 0)
      log << " (" << contact_outcome.n_cycles_broken << " status cycles broken)";
    if (mixed_system->solver() == contact::MixedSystemSolver::iterative)
      log << "; " << mixed_system->n_krylov_iterations - gmres_before
          << " GMRES iterations" << std::endl;
    else
      log << "; " << dense.n_factorizations - factorized_before << " LU factorisations, "
          << dense.n_reused_solves - reused_before << " solves reusing them" << std::endl;
    // The system is equilibrated before the estimate, so a small value means
    // the answer itself is uncertain, not that the units are awkward.
    const double condition = contact_outcome.iterations.empty() ?
                               1.0 :
                               contact_outcome.iterations.back().reciprocal_condition;
    if (contact_outcome.converged() && condition < 1e-10)
      log << "  warning: the mixed system is ill-conditioned (reciprocal condition "
          << condition << "): about " << int(std::round(-std::log10(condition)))
          << " of the 16 significant digits of the contact forces may be lost." << std::endl;
  }

  template <int dim>
  std::vector<bool>
  Model<dim>::pairs_on_sliding_surface() const
  {
    std::vector<bool> on_surface;
    for (const auto &interface : interfaces)
      on_surface.insert(on_surface.end(),
                        interface.pairs.size(),
                        parameters.interfaces.at(interface.name).sliding_surface);
    return on_surface;
  }

  template <int dim>
  void
  Model<dim>::compute_safety_factor()
  {
    const std::vector<bool> on_surface = pairs_on_sliding_surface();
    AssertThrow(std::find(on_surface.begin(), on_surface.end(), true) != on_surface.end(),
                ExcMessage("Interfaces: no interface is a sliding surface; set "
                           "'Sliding surface = true' on one, or Safety factor/"
                           "Compute = false."));
    log << "Safety factor (eqs. 10-13):" << std::endl;
    unsigned int n_steps = 0;
    const auto   solve   = [&](const double K) {
      std::ostringstream what;
      what << "safety factor step " << ++n_steps << ": K = " << std::setprecision(8) << K;
      progress(what.str());
      solve_contact(K);
      safety_factor::ReducedStrengthSolution solution;
      {
        TimerOutput::Scope scope(timer, "safety factor");
        solution = safety_factor::resisting_and_sliding_forces(*mixed_system, contact_outcome,
                                                               pair_strengths(K), on_surface);
      }
      // Each step with a static solution can be looked at in ParaView.
      if (solution.converged && parameters.output.write_vtu)
        {
          // Both collective: every rank comes here, rank 0 writes.
          recover_block_displacements();
          TimerOutput::Scope scope(timer, "output");
          const unsigned int step = step_files.empty() ? 0 : step_files.back().time + 1;
          write_vtu("-step" + Utilities::int_to_string(step, 3), step, step_files);
        }
      return solution;
    };
    safety_factor_result = safety_factor::iterate(solve, parameters.safety_factor, log);
    // The model's state: the last one with a static solution.
    if (last_converged.states.size() == mixed_system->n_pairs())
      {
        contact_outcome    = last_converged;
        strength_reduction = last_converged_K;
      }
    log << "Safety factor: ";
    if (safety_factor_result.converged)
      log << std::setprecision(8) << safety_factor_result.safety_factor;
    else
      log << "not converged";
    log << " (" << safety_factor_result.reason << ")" << std::endl;
  }

  template <int dim>
  void
  Model<dim>::recover_block_displacements()
  {
    TimerOutput::Scope scope(timer, "recovery");
    displacements.clear();
    for (unsigned int b = 0; b < blocks.size(); ++b)
      {
        Vector<double> u =
          blocks[b]->solve(mixed_system->block_nodal_forces(b, contact_outcome.solution));
        Vector<double> gamma(blocks[b]->n_free_rigid_modes());
        for (unsigned int m = 0; m < gamma.size(); ++m)
          gamma[m] = contact_outcome.solution.rigid_motions[mixed_system->first_rigid_unknown[b] + m];
        blocks[b]->add_rigid_motion(gamma, u);
        displacements.push_back(u);
      }
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
        results.push_back(postprocess::pair_results(interface, first_pair,
                                                    contact_outcome.solution,
                                                    contact_outcome.states,
                                                    full_strengths));
        first_pair += interface.pairs.size();
      }
    return results;
  }

  template <int dim>
  void
  Model<dim>::write_vtu(const std::string &                 suffix,
                        const double                        time,
                        std::vector<postprocess::PvdEntry> &entries)
  {
    const std::string directory = parameters.output_directory();
    const auto        results   = interface_results();
    unsigned int      part      = 0;
    for (unsigned int b = 0; b < blocks.size(); ++b)
      entries.push_back({time, part++,
                         postprocess::write_block_vtu(*blocks[b], b, displacements[b],
                                                      directory, suffix)});
    for (unsigned int i = 0; i < interfaces.size(); ++i)
      entries.push_back({time, part++,
                         postprocess::write_interface_vtu(*blocks[interfaces[i].block_J],
                                                          interfaces[i], results[i],
                                                          directory, suffix)});
  }

  template <int dim>
  void
  Model<dim>::output_results()
  {
    const std::string directory = parameters.output_directory();
    TimerOutput::Scope scope(timer, "output");

    auto results = interface_results();
    const nlohmann::json hertz = hertz_reference(results);

    // Without equilibrium there is no field to show: only the summary says why.
    const bool converged = contact_outcome.converged();
    if (converged && writes_files)
      postprocess::write_interface_csv(directory + "/interfaces.csv", interfaces, results);
    if (converged && parameters.output.write_vtu)
      {
        std::vector<postprocess::PvdEntry> entries;
        write_vtu("", 0, entries); // collective, rank 0 writes
        if (writes_files)
          postprocess::write_pvd(directory + "/solution.pvd", entries);
        if (!step_files.empty() && writes_files)
          postprocess::write_pvd(directory + "/safety_factor_steps.pvd", step_files);
      }
    // Reactions at the minimal support, zero at equilibrium: a pass over all
    // cells, timed as output.
    std::vector<double> reactions(blocks.size(), 0.0);
    if (converged)
      for (unsigned int b = 0; b < blocks.size(); ++b)
        {
          const Vector<double> residual = blocks[b]->nodal_residual(displacements[b]);
          for (const auto dof : blocks[b]->support_dofs)
            reactions[b] = std::max(reactions[b], std::abs(residual[dof]));
        }
    scope.stop();

    summary                = nlohmann::json::object();
    summary["case"]        = parameters.case_name;
    summary["dimension"]   = dim;
    summary["fe_degree"]   = parameters.fe_degree;
    summary["n_mpi_ranks"] = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    unsigned int n_dofs    = 0;
    summary["blocks"]      = nlohmann::json::array();
    for (unsigned int b = 0; b < blocks.size(); ++b)
      {
        const auto &block = *blocks[b];
        n_dofs += block.dof_handler.n_dofs();
        double volume = 0;
        for (const auto &cell : block.triangulation.active_cell_iterators())
          volume += cell->measure();
        summary["blocks"].push_back({{"name", block.name},
                                     {"volume", volume},
                                     {"n_cells", block.triangulation.n_active_cells()},
                                     {"n_dofs", block.dof_handler.n_dofs()},
                                     {"free_rigid_modes", block.n_free_rigid_modes()},
                                     {"max_support_reaction", reactions[b]},
                                     {"max_load", block.load_vector.linfty_norm()}});
      }
    summary["n_dofs"]     = n_dofs;
    summary["interfaces"] = nlohmann::json::array();
    for (unsigned int i = 0; i < interfaces.size(); ++i)
      {
        unsigned int n_status[3] = {0, 0, 0};
        double max_pressure = 0, normal_force = 0, tangential_force = 0;
        Tensor<1, dim> tangential_resultant;
        for (unsigned int k = 0; k < results[i].size(); ++k)
          {
            const auto &r = results[i][k];
            ++n_status[static_cast<int>(r.status)];
            max_pressure = std::max(max_pressure, r.normal_pressure);
            normal_force += r.normal_force;
            tangential_force += r.tangential_force[0];
            for (unsigned int t = 0; t + 1 < dim; ++t)
              tangential_resultant += r.tangential_force[t] * interfaces[i].pairs[k].frame[t + 1];
          }
        // In 3D the pairs' tangents differ: the magnitude of the resultant.
        if (dim == 3)
          tangential_force = tangential_resultant.norm();
        const double extent = postprocess::contact_extent(results[i]);
        summary["interfaces"].push_back(
          {{"name", interfaces[i].name},
           {"block_I", blocks[interfaces[i].block_I]->name},
           {"block_J", blocks[interfaces[i].block_J]->name},
           {"n_pairs", interfaces[i].pairs.size()},
           {"area", std::accumulate(results[i].begin(), results[i].end(), 0.0,
                                    [](const double a, const auto &r) { return a + r.area; }) +
                      std::accumulate(interfaces[i].shared_nodes.begin(),
                                      interfaces[i].shared_nodes.end(), 0.0,
                                      [](const double a, const auto &n) { return a + n.area; })},
           {"n_unpaired_nodes", interfaces[i].n_unpaired_I + interfaces[i].n_unpaired_J},
           {"n_nodes_paired_in_an_earlier_interface", interfaces[i].n_shared_nodes},
           {"n_stick", n_status[0]},
           {"n_slip", n_status[1]},
           {"n_open", n_status[2]},
           {"max_normal_pressure", max_pressure},
           {"contact_extent", extent},
           {"total_normal_force", normal_force},
           {"total_tangential_force", tangential_force}});
      }
    if (!hertz.empty())
      summary["hertz"] = hertz;
    summary["strength_reduction"] = strength_reduction;
    summary["warnings"]           = warnings;
    if (parameters.safety_factor.compute)
      {
        const auto &sf = safety_factor_result;
        const auto  number_or_null = [](const double x) {
          return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
        };
        summary["safety_factor"]         = number_or_null(sf.safety_factor);
        summary["converged"]             = sf.converged;
        summary["safety_factor_reason"]  = sf.reason;
        summary["safety_factor_bracket"] = {number_or_null(sf.bracket_low),
                                            number_or_null(sf.bracket_high)};
        nlohmann::json steps = nlohmann::json::array();
        for (const auto &step : sf.steps)
          steps.push_back({{"K", step.K},
                           {"K_next", step.K_next},
                           {"F_R", step.solution.resisting_force},
                           {"F_tau", step.solution.sliding_force},
                           {"n_stick", step.solution.n_stick},
                           {"n_slip", step.solution.n_slip},
                           {"n_open", step.solution.n_open},
                           {"n_contact_iterations", step.solution.n_contact_iterations},
                           {"contact_result", step.solution.result}});
        summary["iterations"] = steps;
      }
    summary["rigid_motions"] = std::vector<double>(contact_outcome.solution.rigid_motions.begin(),
                                                   contact_outcome.solution.rigid_motions.end());
    nlohmann::json iterations = nlohmann::json::array();
    for (const auto &record : contact_outcome.iterations)
      iterations.push_back({{"n_stick", record.n_stick},
                            {"n_slip", record.n_slip},
                            {"n_open", record.n_open},
                            {"n_at_cutoff", record.n_at_cutoff},
                            {"n_changes", record.n_changes},
                            {"reciprocal_condition", record.reciprocal_condition},
                            {"factorized", record.factorized}});
    summary["contact"] = {{"result", contact::result_description(contact_outcome.result)},
                          {"converged", contact_outcome.converged()},
                          {"n_solves", contact_outcome.iterations.size()},
                          {"n_cycles_broken", contact_outcome.n_cycles_broken},
                          {"max_slip_angle_degrees", contact_outcome.max_slip_angle},
                          {"reciprocal_condition",
                           contact_outcome.iterations.empty() ?
                             1.0 :
                             contact_outcome.iterations.back().reciprocal_condition},
                          {"n_factorizations",
                           mixed_system ? mixed_system->dense_solver().n_factorizations : 0},
                          {"n_reused_solves",
                           mixed_system ? mixed_system->dense_solver().n_reused_solves : 0},
                          {"mixed_system", parameters.solver.mixed_system},
                          {"n_gmres_iterations",
                           mixed_system ? mixed_system->n_krylov_iterations : 0},
                          {"n_flexibility_products",
                           mixed_system ? mixed_system->n_flexibility_products : 0},
                          {"iterations", iterations}};
    // The only entries that differ between two runs of the same input.
    summary["timings"]         = postprocess::section_wall_times(timer, run_timer.wall_time());
    summary["peak_memory_MiB"] = postprocess::peak_memory_mib();
    if (!contact_outcome.converged())
      summary["status"] = "no static equilibrium: " +
                          (parameters.safety_factor.compute ?
                             safety_factor_result.reason :
                             contact::result_description(contact_outcome.result));
    else if (parameters.safety_factor.compute && !safety_factor_result.converged)
      summary["status"] = "safety factor not converged: " + safety_factor_result.reason;
    else
      summary["status"] = "completed";
    if (writes_files)
      postprocess::write_json(directory + "/summary.json", summary);
    log << "Results in " << directory << "/" << std::endl;
  }

  template <int dim>
  nlohmann::json
  Model<dim>::hertz_reference(
    std::vector<std::vector<postprocess::PairResult<dim>>> &results) const
  {
    // Plane-strain Hertz contact of a cylinder on a half-space (the paper's
    // example 4.A, its ref. [12]): a = sqrt(4 p r / (pi E')), q_max =
    // 2 p / (pi a), 1/E' = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, and
    // q(x) = q_max sqrt(1 - (x/a)^2). The generator's model is a half model,
    // so p is twice the normal force on its interface. In 3D, the Hertz
    // sphere generator's quarter model: see postprocess/hertz_sphere.h.
    using Source = parameters::GeometryParameters::Source;
    if (parameters.geometry.source != (dim == 2 ? Source::hertz : Source::hertz_sphere) ||
        interfaces.size() != 1 || !contact_outcome.converged())
      return {};
    const auto &cylinder   = parameters.materials.at(blocks[interfaces[0].block_I]->name);
    const auto &foundation = parameters.materials.at(blocks[interfaces[0].block_J]->name);
    const double inverse_E = (1 - std::pow(cylinder.poissons_ratio, 2)) / cylinder.youngs_modulus +
                             (1 - std::pow(foundation.poissons_ratio, 2)) / foundation.youngs_modulus;
    if constexpr (dim == 3)
      return postprocess::hertz_sphere_reference(
        results[0], inverse_E,
        parameters.geometry.hertz_sphere.radius * parameters.geometry.scale_factor);
    double half_load = 0;
    for (const auto &r : results[0])
      half_load -= r.normal_force;
    const double p = 2 * half_load, r = parameters.geometry.hertz.radius * parameters.geometry.scale_factor;
    const double a_exact = std::sqrt(4 * p * r * inverse_E / numbers::PI);
    const double q_exact = 2 * p / (numbers::PI * a_exact);
    // Distance from the symmetry axis: the pair that touches before loading.
    Point<dim> axis         = results[0][0].position;
    double     smallest_gap = results[0][0].initial_gap;
    for (const auto &pair : results[0])
      if (pair.initial_gap < smallest_gap)
        {
          smallest_gap = pair.initial_gap;
          axis         = pair.position;
        }
    for (auto &pair : results[0])
      {
        const double x         = pair.position.distance(axis) / a_exact;
        pair.reference_pressure = x < 1 ? q_exact * std::sqrt(1 - x * x) : 0.0;
      }
    double q_max = 0;
    for (const auto &pair : results[0])
      q_max = std::max(q_max, pair.normal_pressure);
    const double a = postprocess::contact_extent(results[0]);
    return {{"load_per_unit_length", p},
            {"contact_half_width_exact", a_exact},
            {"max_pressure_exact", q_exact},
            {"contact_half_width", a},
            {"max_pressure", q_max},
            {"contact_half_width_error", a / a_exact - 1},
            {"max_pressure_error", q_max / q_exact - 1}};
  }

  template <int dim>
  void
  Model<dim>::validate()
  {
    validating = true;
    make_geometry();
    setup_blocks();
    for (const auto &block : blocks)
      block->assemble(parameters.loads);
    build_interfaces();
  }

  std::vector<std::string>
  validate_case(const std::string &prm_file, std::ostream &log)
  {
    const parameters::Parameters parameters = parameters::read_parameters(prm_file);
    if (parameters.dimension == 2)
      {
        Model<2> model(parameters, "", log);
        model.validate();
        return model.warnings;
      }
    Model<3> model(parameters, "", log);
    model.validate();
    return model.warnings;
  }

  nlohmann::json
  run_case(const std::string &prm_file, std::ostream &log)
  {
    std::string                        expanded;
    const parameters::Parameters       parameters = parameters::read_parameters(prm_file, &expanded);
    if (parameters.dimension == 2)
      {
        Model<2> model(parameters, expanded, log);
        model.run();
        return model.summary;
      }
    Model<3> model(parameters, expanded, log);
    model.run();
    return model.summary;
  }

  template class Model<2>;
  template class Model<3>;
} // namespace fdem
