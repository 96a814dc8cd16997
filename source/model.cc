// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/blocks/block_materials.h>
#include <fdem/blocks/surface_loads.h>
#include <fdem/checks/layout_checks.h>
#include <fdem/geometry/make_mesh.h>
#include <fdem/geometry/mesh_estimate.h>
#include <fdem/linear_algebra/blas_threads.h>
#include <fdem/model.h>
#include <fdem/postprocess/output_files.h>
#include <fdem/postprocess/run_cost.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <numeric>
#include <sstream>

namespace fdem
{
  template <int dim>
  Model<dim>::Model(const parameters::Parameters &parameters,
                    std::ostream                 &log,
                    std::ostream                 *brief)
    : log(log)
    , brief(brief != nullptr ? *brief : log)
    , parameters(parameters)
    , is_writer(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    , timer(log, TimerOutput::never, TimerOutput::wall_times)
  {}

  template <int dim>
  void
  Model<dim>::progress(const std::string &what) const
  {
    log << postprocess::progress_stamp(run_timer.wall_time()) << what
        << std::endl;
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
                           std::to_string(dim - 1) + ") in " + mesh.source +
                           "."));
    return it - mesh.face_group_names.begin();
  }

  template <int dim>
  void
  Model<dim>::make_geometry()
  {
    TimerOutput::Scope scope(timer, "geometry");
    // Every rank makes the same mesh; rank 0 writes it.
    const std::string msh = is_writer && !validating ?
                              parameters.output_directory() + "/mesh.msh" :
                              "";
    mesh                  = geometry::make_mesh<dim>(parameters.geometry,
                                    msh,
                                    parameters.fe_degree,
                                    parameters.material_names,
                                    parameters.solver.mixed_system == "dense");

    // Every block of the mesh needs a material, and every name a block.
    for (const std::string &name : mesh.block_names)
      AssertThrow(parameters.materials.count(name) == 1,
                  ExcMessage("Blocks/Names: the block '" + name + "' of " +
                             mesh.source +
                             " has no material; list it and give it a "
                             "subsection with its Young's modulus."));
    for (const std::string &name : parameters.block_names)
      AssertThrow(
        std::count(mesh.block_names.begin(), mesh.block_names.end(), name) == 1,
        ExcMessage("Blocks/Names: '" + name + "' is not a block " +
                   "(physical group of dimension " + std::to_string(dim) +
                   ") in " + mesh.source + "."));
    blocks::check_materials(mesh, parameters);
    blocks::check_interface_water(mesh, parameters);
    for (const std::string &name : parameters.boundary_names)
      face_group(name, "Boundaries/Names");
    for (const std::string &name : parameters.interface_names)
      face_group(name, "Interfaces/Names");
    brief << "Geometry: " << mesh.source << ", " << mesh.cells.size()
          << " cells, " << mesh.block_names.size() << " blocks" << std::endl;
    checks::report(checks::check_mesh_layout(mesh,
                                             parameters.interface_names,
                                             parameters.boundary_names),
                   warnings,
                   log);
  }

  template <int dim>
  void
  Model<dim>::setup_blocks()
  {
    TimerOutput::Scope scope(timer, "setup");
    // Parsing has checked this for a .prm file; a program may have built
    // its parameters itself.
    parameters.check_piezometric_pressures();
    std::map<types::boundary_id, parameters::BoundaryParameters> conditions;
    for (const std::string &name : parameters.boundary_names)
      conditions[face_group(name, "Boundaries/Names")] =
        parameters.boundaries.at(name);
    std::vector<types::boundary_id> interface_ids;
    for (const std::string &name : parameters.interface_names)
      interface_ids.push_back(face_group(name, "Interfaces/Names"));

    // Surface loads: boundary pressures and tractions, and the pore pressure
    // of each interface, which pushes on both sides' faces.
    std::map<types::boundary_id, std::shared_ptr<const Function<dim>>>
      pressures, tractions;
    for (const std::string &name : parameters.boundary_names)
      {
        const auto &boundary = parameters.boundaries.at(name);
        const auto  id       = face_group(name, "Boundaries/Names");
        if (boundary.pressure != "0")
          pressures[id] =
            blocks::make_pressure_function<dim>(boundary.pressure,
                                                parameters.water,
                                                parameters.geometry);
        if (boundary.traction != "0")
          tractions[id] =
            blocks::make_traction_function<dim>(boundary.traction);
      }
    for (const auto &[name, surface_point] : mesh.standing_water)
      {
        const auto id = face_group(name, mesh.source);
        AssertThrow(pressures.count(id) == 0,
                    ExcMessage(
                      "Boundaries/" + name + "/Pressure: " + mesh.source +
                      " already fills '" + name +
                      "' with water (Tension crack water "
                      "depth); give the water in one of the two places."));
        pressures[id] = blocks::make_standing_water_pressure<dim>(
          surface_point, parameters.loads.gravity_direction, parameters.water);
      }
    for (const std::string &name : parameters.interface_names)
      if (parameters.interfaces.at(name).pore_pressure != "0")
        pressures[face_group(name, "Interfaces/Names")] =
          blocks::make_pressure_function<dim>(
            parameters.interfaces.at(name).pore_pressure,
            parameters.water,
            parameters.geometry);
    // A pressure that is not a number somewhere on its faces would spread
    // NaN through the solution: check it at every vertex of its faces.
    for (const auto &[id, pressure] : pressures)
      for (const auto &face : mesh.faces)
        if (face.boundary_id == id)
          for (const unsigned int v : face.vertices)
            {
              const double       value = pressure->value(mesh.vertices[v]);
              const std::string &name  = mesh.face_group_names[id];
              const bool         is_interface =
                std::count(parameters.interface_names.begin(),
                           parameters.interface_names.end(),
                           name);
              std::ostringstream point;
              point << mesh.vertices[v];
              AssertThrow(std::isfinite(value),
                          ExcMessage(
                            (is_interface ?
                               "Interfaces/" + name + "/Pore pressure" :
                               "Boundaries/" + name + "/Pressure") +
                            ": not a number at (" + point.str() + ")."));
            }
    // The same for a traction, at every vertex of its faces.
    for (const auto &[id, traction] : tractions)
      for (const auto &face : mesh.faces)
        if (face.boundary_id == id)
          for (const unsigned int v : face.vertices)
            {
              Vector<double> value(dim);
              traction->vector_value(mesh.vertices[v], value);
              std::ostringstream point;
              point << mesh.vertices[v];
              for (unsigned int d = 0; d < dim; ++d)
                AssertThrow(std::isfinite(value[d]),
                            ExcMessage("Boundaries/" +
                                       mesh.face_group_names[id] +
                                       "/Traction: not a finite number at (" +
                                       point.str() + ")."));
            }

    blocks.clear();
    for (unsigned int b = 0; b < mesh.block_names.size(); ++b)
      {
        const std::string &name = mesh.block_names[b];
        blocks.push_back(std::make_unique<blocks::ElasticBlock<dim>>(
          name,
          mesh,
          std::vector<unsigned int>{b},
          blocks::block_materials(mesh, parameters, b),
          parameters.fe_degree));
        if (parameters.has_water_table())
          blocks.back()->water_table =
            std::make_shared<blocks::PiezometricPressure<dim>>(
              parameters.water, parameters.geometry);
        blocks.back()->setup_constraints(conditions, interface_ids);
        blocks.back()->set_surface_loads(pressures, tractions);
        blocks.back()->find_free_rigid_modes();
        log << "  block '" << name
            << "': " << blocks.back()->dof_handler.n_dofs() << " dofs, "
            << blocks.back()->n_free_rigid_modes() << " free rigid modes"
            << std::endl;
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
          using parameters::DirectSolverType;
          block->factorize(iterative && parameters.solver.direct_solver ==
                                          DirectSolverType::mumps_schur ?
                             DirectSolverType::mumps :
                             parameters.solver.direct_solver,
                           parameters.solver.block_low_rank_tolerance,
                           geometry::memory_limit_MiB(parameters.geometry));
        }
        const std::string statistics = block->factorization_statistics();
        if (!statistics.empty())
          log << "  block '" << block->name << "': " << statistics << std::endl;
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
    soil_strengths.clear();
    for (const std::string &name : parameters.interface_names)
      {
        const types::boundary_id  group = face_group(name, "Interfaces/Names");
        std::vector<unsigned int> sides;
        for (unsigned int b = 0; b < blocks.size(); ++b)
          for (const auto &face :
               blocks[b]->triangulation.active_face_iterators())
            if (face->at_boundary() && face->boundary_id() == group)
              {
                sides.push_back(b);
                break;
              }
        AssertThrow(sides.size() == 2,
                    ExcMessage("Interfaces/" + name +
                               ": the face group lies on " +
                               std::to_string(sides.size()) +
                               " blocks; an interface separates exactly two."));
        // Block I is the one that moves: the one with more free rigid modes.
        if (blocks[sides[1]]->n_free_rigid_modes() >
            blocks[sides[0]]->n_free_rigid_modes())
          std::swap(sides[0], sides[1]);
        interfaces.push_back(contact::make_interface(
          name,
          group,
          sides[0],
          *blocks[sides[0]],
          sides[1],
          *blocks[sides[1]],
          parameters.interfaces.at(name).search_distance,
          mesh.surface_normals.count(name) ? mesh.surface_normals.at(name) :
                                             nullptr));
        soil_strengths.push_back(
          parameters.interfaces.at(name).strength_from_material ?
            blocks::soil_strength_at_nodes(*blocks[sides[0]],
                                           group,
                                           mesh,
                                           name,
                                           blocks::weak_layers<dim>(
                                             parameters)) :
            std::map<types::global_dof_index, blocks::SoilStrength>());
        // A node on two interfaces (the line of intersection of a wedge) is
        // paired once, in the interface listed first.
        contact::remove_pairs_of_earlier_interfaces(interfaces);
        const auto &pairs = interfaces.back().pairs;
        AssertThrow(!pairs.empty(),
                    ExcMessage("Interfaces/" + name +
                               ": all its node pairs belong to "
                               "interfaces listed before it."));
        log << "  interface '" << name
            << "': " << interfaces.back().pairs.size()
            << " node pairs between '" << blocks[sides[0]]->name << "' and '"
            << blocks[sides[1]]->name << "'" << std::endl;
      }
    for (unsigned int b = 0; b < blocks.size(); ++b)
      if (blocks[b]->n_free_rigid_modes() > 0)
        AssertThrow(std::any_of(interfaces.begin(),
                                interfaces.end(),
                                [b](const auto &i) {
                                  return i.block_I == b || i.block_J == b;
                                }),
                    ExcMessage("Block '" + blocks[b]->name +
                               "' is not held: its constraints leave rigid "
                               "motions free and no interface touches it."));
    checks::report(checks::pair_triple_points_once(interfaces, blocks), log);
    checks::report(
      checks::check_interfaces(mesh, blocks, interfaces, parameters.interfaces),
      warnings,
      log);
    types::global_dof_index n_dofs = 0;
    for (const auto &block : blocks)
      n_dofs += block->dof_handler.n_dofs();
    brief << "Model: " << blocks.size()
          << (blocks.size() == 1 ? " block, " : " blocks, ") << n_dofs
          << " dofs; " << interfaces.size()
          << (interfaces.size() == 1 ? " interface, " : " interfaces, ")
          << n_pairs() << " node pairs" << std::endl;
    const unsigned int n_threads = linear_algebra::n_blas_threads();
    log << "Dense linear algebra (the mixed system's LU, MUMPS's fronts): ";
    if (n_threads > 0)
      log << n_threads << (n_threads == 1 ? " BLAS thread" : " BLAS threads");
    else
      log << "a BLAS that does not say how many threads it uses";
    log << " per rank" << std::endl;
  }

  template <int dim>
  std::size_t
  Model<dim>::n_pairs() const
  {
    std::size_t n = 0;
    for (const auto &interface : interfaces)
      n += interface.pairs.size();
    return n;
  }

  template <int dim>
  void
  Model<dim>::set_bar_links(std::vector<contact::BarLink<dim>> links,
                            std::vector<contact::PairStrength> capacities,
                            const bool                         reduced_by_K)
  {
    Assert(!mixed_system, ExcMessage("Bars come before the mixed system."));
    AssertDimension(links.size(), capacities.size());
    bar_links              = std::move(links);
    bar_capacities         = std::move(capacities);
    bar_capacities_reduced = reduced_by_K;
  }

  template <int dim>
  void
  Model<dim>::compute_flexibility()
  {
    TimerOutput::Scope scope(timer, "flexibility");
    AssertThrow(bar_links.empty() ||
                  parameters.solver.mixed_system != "iterative",
                ExcMessage("Reinforcement: passive bars need Solver/Mixed "
                           "system = dense; the iterative solver does not "
                           "take their rows yet."));
    contact::KrylovControl krylov;
    krylov.tolerance = parameters.solver.gmres_tolerance;
    // The Dirichlet preconditioner factorises each block once more, on one
    // rank (DirichletPreconditioner): with more MPI ranks the pairs' one.
    krylov.preconditioner =
      parameters.solver.mixed_preconditioner == "Dirichlet" &&
          Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1 ?
        contact::KrylovPreconditioner::dirichlet :
        contact::KrylovPreconditioner::pairs;
    krylov.direct_solver    = parameters.solver.direct_solver;
    krylov.memory_limit_MiB = geometry::memory_limit_MiB(parameters.geometry);
    mixed_system            = std::make_unique<contact::MixedSystem<dim>>(
      blocks,
      external_displacements,
      interfaces,
      parameters.solver.mixed_system == "iterative" ?
                   contact::MixedSystemSolver::iterative :
                   contact::MixedSystemSolver::dense,
      parameters.safety_factor.compute &&
        parameters.safety_factor.stiffness_check,
      bar_links,
      krylov);
  }

  template <int dim>
  blocks::SoilStrength
  Model<dim>::soil_strength(const unsigned int            i,
                            const contact::NodePair<dim> &pair) const
  {
    const parameters::InterfaceParameters &p =
      parameters.interfaces.at(interfaces[i].name);
    if (!p.strength_from_material)
      return blocks::SoilStrength{p.cohesion,
                                  std::tan(p.friction_angle * numbers::PI /
                                           180)};
    auto it = soil_strengths[i].find(pair.dofs_I[0]);
    if (it ==
        soil_strengths[i].end()) // an earlier interface's pair, I and J swapped
      it = soil_strengths[i].find(pair.dofs_J[0]);
    AssertThrow(it != soil_strengths[i].end(), ExcInternalError());
    return it->second;
  }

  template <int dim>
  std::vector<contact::PairStrength>
  Model<dim>::pair_strengths(const double K) const
  {
    return pair_strengths(K,
                          [this](const unsigned int            i,
                                 const contact::NodePair<dim> &pair) {
                            return soil_strength(i, pair);
                          });
  }

  template <int dim>
  std::vector<contact::PairStrength>
  Model<dim>::pair_strengths(
    const double K,
    const std::function<blocks::SoilStrength(unsigned int,
                                             const contact::NodePair<dim> &)>
      &soil) const
  {
    std::vector<contact::PairStrength> strengths;
    for (unsigned int i = 0; i < interfaces.size(); ++i)
      {
        const parameters::InterfaceParameters &p =
          parameters.interfaces.at(interfaces[i].name);
        for (const auto &pair : interfaces[i].pairs)
          {
            contact::PairStrength strength;
            const double          reduction = p.reduced_by_K ? K : 1.0;
            if (!p.frictionless)
              {
                const blocks::SoilStrength s = soil(i, pair);
                strength.friction_coefficient =
                  s.friction_coefficient / reduction;
                strength.cohesion_force = s.cohesion * pair.area / reduction;
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
    for (unsigned int i = 0; i < interfaces.size(); ++i)
      {
        const parameters::InterfaceParameters &p =
          parameters.interfaces.at(interfaces[i].name);
        for (const auto &shared : interfaces[i].shared_nodes)
          {
            contact::PairStrength &strength =
              strengths[first_pair[shared.interface] + shared.pair];
            if (!p.frictionless)
              strength.cohesion_force +=
                soil(i, interfaces[shared.interface].pairs[shared.pair])
                  .cohesion *
                shared.area / (p.reduced_by_K ? K : 1.0);
            strength.tensile_force += p.tensile_strength * shared.area;
          }
      }
    for (contact::PairStrength bar : bar_capacities)
      {
        if (bar_capacities_reduced)
          {
            bar.bar_axial_capacity /= K;
            bar.bar_shear_capacity /= K;
          }
        strengths.push_back(bar);
      }
    return strengths;
  }

  template <int dim>
  void
  Model<dim>::solve_contact(const double strength_reduction_factor)
  {
    solve_contact(pair_strengths(strength_reduction_factor),
                  strength_reduction_factor);
  }

  template <int dim>
  void
  Model<dim>::solve_contact(const std::vector<contact::PairStrength> &strengths,
                            const double strength_reduction_factor)
  {
    apply_strength_dependent_loads(strength_reduction_factor);
    TimerOutput::Scope scope(timer, "contact");
    // Warm start from the last states with a static solution (Sec. 6).
    auto states = last_converged.states.size() == mixed_system->n_pairs() ?
                    last_converged.states :
                    contact::initial_states(*mixed_system, strengths);
    contact::StatusIterationControl control;
    control.max_iterations = parameters.contact.max_status_iterations;
    control.runaway_factor = parameters.contact.runaway_factor;
    log << "  contact problem:" << std::endl;
    const linear_algebra::ReusableLU &dense = mixed_system->dense_solver();
    const unsigned int factorized_before    = dense.n_factorizations,
                       reused_before        = dense.n_reused_solves;
    const unsigned long gmres_before        = mixed_system->n_krylov_iterations;
    contact_outcome                         = contact::solve_contact_problem(
      *mixed_system, strengths, states, control, log);
    strength_reduction = strength_reduction_factor;
    if (contact_outcome.converged())
      {
        last_converged   = contact_outcome;
        last_converged_K = strength_reduction_factor;
      }
    log << "  contact problem "
        << contact::result_description(contact_outcome.result) << " after "
        << contact_outcome.iterations.size() << " solves";
    if (contact_outcome.n_cycles_broken > 0)
      log << " (" << contact_outcome.n_cycles_broken
          << " status cycles broken)";
    if (mixed_system->solver() == contact::MixedSystemSolver::iterative)
      log << "; " << mixed_system->n_krylov_iterations - gmres_before
          << " GMRES iterations" << std::endl;
    else
      log << "; " << dense.n_factorizations - factorized_before
          << " LU factorisations, " << dense.n_reused_solves - reused_before
          << " solves reusing them" << std::endl;
    // The system is equilibrated before the estimate, so a small value means
    // the answer itself is uncertain, not that the units are awkward.
    const double condition =
      contact_outcome.iterations.empty() ?
        1.0 :
        contact_outcome.iterations.back().reciprocal_condition;
    if (contact_outcome.converged() && condition < 1e-10)
      {
        const int          lost = int(std::round(-std::log10(condition)));
        std::ostringstream note;
        note
          << "the mixed system at K = " << std::setprecision(8)
          << strength_reduction_factor
          << " is ill-conditioned (reciprocal condition "
          << std::setprecision(3) << condition << "): about " << lost
          << " of the 16 significant digits of the contact forces may be lost.";
        conditioning_notes.push_back(
          postprocess::note_text("ill-conditioned", note.str()));
        max_digits_lost = std::max(max_digits_lost, lost);
        log << "  note: " << conditioning_notes.back() << std::endl;
      }
  }

  template <int dim>
  std::vector<bool>
  Model<dim>::pairs_on_sliding_surface() const
  {
    std::vector<bool> on_surface;
    for (const auto &interface : interfaces)
      on_surface.insert(
        on_surface.end(),
        interface.pairs.size(),
        parameters.interfaces.at(interface.name).sliding_surface);
    return on_surface;
  }

  template <int dim>
  void
  Model<dim>::set_contact_state(const contact::ContactOutcome<dim> &outcome,
                                const double                        K)
  {
    contact_outcome    = outcome;
    strength_reduction = K;
    apply_strength_dependent_loads(K);
    if (outcome.converged())
      {
        last_converged   = outcome;
        last_converged_K = K;
      }
  }

  template <int dim>
  void
  Model<dim>::warn(const std::string &warning)
  {
    warnings.push_back(warning);
    log << "warning: " << warning
        << std::endl; // the result block lists them again
  }

  template <int dim>
  void
  Model<dim>::restore_last_static_state()
  {
    if (last_converged.states.size() == mixed_system->n_pairs())
      {
        contact_outcome    = last_converged;
        strength_reduction = last_converged_K;
        apply_strength_dependent_loads(last_converged_K);
      }
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

  template class Model<2>;
  template class Model<3>;
} // namespace fdem
