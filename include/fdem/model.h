// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/block_materials.h>
#include <fdem/blocks/elastic_block.h>
#include <fdem/contact/interface_pairs.h>
#include <fdem/contact/mixed_system.h>
#include <fdem/contact/status_iteration.h>
#include <fdem/geometry/mesh_description.h>
#include <fdem/parameters/parameters.h>
#include <fdem/postprocess/interface_output.h>
#include <fdem/postprocess/output_files.h>
#include <fdem/postprocess/run_log.h>
#include <fdem/postprocess/vtu_writer.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fdem
{
  using namespace dealii;

  /**
   * A slope model of the mixed FEM-DEM method (Liu et al. 2012): elastic
   * blocks meshed with finite elements, joined by interfaces of node pairs,
   * and the mixed system of eq. (9) on their factorisations. The model only:
   * the analyses (analyses/) solve its contact problem for the strengths,
   * loads and water they choose and read its state through the get_*()
   * functions; CaseRun runs them in the paper's order and writes the
   * results. The steps below are public so that a caller (and a test) can
   * take the model through them one by one.
   */
  template <int dim>
  class Model
  {
  public:
    /**
     * @p log takes the run's full log (contact iterations, solver notes,
     * time stamps), @p brief the lines of the default screen (the model,
     * the safety-factor steps); without @p brief they go to @p log too
     * (postprocess::RunLog sends each where it belongs).
     */
    Model(const parameters::Parameters &parameters,
          std::ostream                 &log,
          std::ostream                 *brief = nullptr);

    /**
     * The checks of --validate: the mesh, the blocks (with their loads,
     * not factorised) and the node pairs, with the layout checks of
     * doc/layout_checks.md; writes nothing.
     */
    void
    validate();

    /** Mesh from Gmsh (a file or a generator): blocks, face groups. */
    void
    make_geometry();
    /** One elastic block per mesh block: dofs, constraints, free rigid modes.
     */
    void
    setup_blocks();
    /** K and F of each block, K factorised once; u_bar = K^{-1} F. */
    void
    assemble_and_factorize();
    /** Node pairs of every interface, with frames, areas and gaps. */
    void
    build_interfaces();
    /**
     * The links of the passive reinforcement bars (analyses/bars.h), after
     * build_interfaces() and before compute_flexibility(), which makes them
     * pairs of the mixed system: @p links, their capacities at full
     * strength @p capacities (PairStrength's bar capacities), and whether
     * K divides those (@p reduced_by_K).
     */
    void
    set_bar_links(std::vector<contact::BarLink<dim>> links,
                  std::vector<contact::PairStrength> capacities,
                  const bool                         reduced_by_K);

    /** The passive bars' links (set_bar_links()). */
    const std::vector<contact::BarLink<dim>> &
    get_bar_links() const
    {
      return bar_links;
    }

    /** C = C_I + C_J, g_bar, W and omega^T F (eqs. 4-8), computed once. */
    void
    compute_flexibility();
    /**
     * Solves eq. (9) with the contact conditions of Table 1 (the status
     * iteration) for the pair forces and rigid motions, with the interfaces'
     * strengths reduced by @p strength_reduction (the safety factor's K).
     */
    void
    solve_contact(const double strength_reduction = 1.0);

    /** The same with the pair strengths @p strengths of K = @p
     * strength_reduction given. */
    void
    solve_contact(const std::vector<contact::PairStrength> &strengths,
                  const double                              strength_reduction);

    /**
     * @name Load cases (doc/theory.md, "Load cases")
     *
     * The assembled load (gravity, surface loads, pore pressures: the
     * "base") and further load cases, each solved once on the blocks'
     * factorisations after compute_flexibility(). The load of the model is
     * base_factor times the base plus a coefficient times each case;
     * set_load_combination() changes it without a solve, a factorisation
     * or a new C (MixedSystem::set_load_coefficients()), and the blocks'
     * load vectors follow (for the recovery and the output). Gravity, the
     * seismic coefficients and a factor on the unit weight are
     * combinations of the body-force cases (body_force_cases()).
     */
    ///@{
    /**
     * Adds the load case of nodal forces @p loads (one vector per block):
     * one solve per block on its factorisation; returns its index.
     */
    unsigned int
    add_load_case(const std::vector<Vector<double>> &loads);

    /**
     * The dim load cases of the blocks' weight per unit coefficient in each
     * coordinate direction (ElasticBlock::unit_body_force_loads()): with
     * @p saturated the saturated weight below the water table (as gravity
     * has it), without it the unit weight everywhere. Made on the first
     * call, then the same indices.
     */
    std::vector<unsigned int>
    body_force_cases(const bool saturated);

    /**
     * Sets the model's load: @p base_factor times the assembled load plus
     * @p coefficients[k] times case k (missing ones zero). (1, {}) is the
     * assembled load bit for bit. E.g. a factor lambda on the unit weight:
     * base 1 and (lambda - 1) g_d on body_force_cases(true)[d]; a seismic
     * coefficient kh in the horizontal direction h: kh h_d on
     * body_force_cases(false)[d].
     */
    void
    set_load_combination(const double               base_factor,
                         const std::vector<double> &coefficients);

    /**
     * Replaces load case @p index in the mixed system by @p parts
     * (contact::MixedSystem::load_case()): a load that changes from one
     * solve to the next (a probabilistic sample's water) without a new
     * case. The contact problem sees it; the blocks' load vectors keep the
     * case as it was added, so set its coefficient back to zero before a
     * recovery or output.
     */
    void
    replace_load_case(const unsigned int                                  index,
                      const typename contact::MixedSystem<dim>::LoadCase &parts)
    {
      mixed_system->replace_load_case(index, parts);
    }

    /**
     * The assembled load of block @p b minus its current load (zero
     * without a load combination): what the assembled cells' residual
     * (ElasticBlock::nodal_residual()) must be corrected by.
     */
    Vector<double>
    load_change(const unsigned int b) const;

    /**
     * Loads that depend on K (the anchors' shear reduced by K,
     * analyses/anchors.h): @p loads is called with K before each contact
     * solve of solve_contact() and when a state solved at K becomes the
     * model's (set_contact_state(), restore_last_static_state()), to set
     * the load combination of that K.
     */
    void
    set_strength_dependent_loads(std::function<void(double K)> loads)
    {
      strength_dependent_loads = std::move(loads);
    }

    /**
     * Sets the loads of @p K (set_strength_dependent_loads(); nothing
     * without them): for an analysis that solves with
     * solve_contact_from().
     */
    void
    apply_strength_dependent_loads(const double K)
    {
      if (strength_dependent_loads)
        strength_dependent_loads(K);
    }
    ///@}

    /**
     * Pair strengths of all interfaces; on the sliding surfaces c and
     * tan(phi) are divided by @p K (eq. 10). The passive bars' links
     * follow, with their capacities (divided by K if the bars' are).
     */
    std::vector<contact::PairStrength>
    pair_strengths(const double K) const;

    /**
     * The same with the soil strength (c, tan(phi)) of interface i at a
     * node pair given by @p soil(i, pair) instead of the model's
     * (soil_strength()): a sample of a probabilistic analysis.
     */
    std::vector<contact::PairStrength>
    pair_strengths(
      const double K,
      const std::function<blocks::SoilStrength(unsigned int,
                                               const contact::NodePair<dim> &)>
        &soil) const;

    /**
     * c and tan(phi) of interface @p i at @p pair (of i, or of an earlier
     * interface sharing the node): the interface's own, or its materials'
     * at the node (soil_strengths).
     */
    blocks::SoilStrength
    soil_strength(const unsigned int            i,
                  const contact::NodePair<dim> &pair) const;

    /**
     * Solves eq. (9) for @p strengths from the statuses @p states with
     * @p control (contact::solve_contact_problem()), its log to @p out,
     * without changing the model's contact state or warm start: for an
     * analysis that keeps its own states (a probabilistic sample).
     */
    contact::ContactOutcome<dim>
    solve_contact_from(const std::vector<contact::PairStrength>   &strengths,
                       const std::vector<contact::PairState<dim>> &states,
                       const contact::StatusIterationControl      &control,
                       std::ostream                               &out)
    {
      return contact::solve_contact_problem(
        *mixed_system, strengths, states, control, out);
    }

    /**
     * One solve of eq. (9) with the pairs' @p states held (no status
     * iteration) and the strengths @p strengths, without changing the
     * model's contact state or warm start: the linearised response of a
     * converged state to a change of the strengths (the slope of K* at a
     * fold, SafetyFactorAnalysis).
     */
    contact::ContactSolution
    solve_with_states(const std::vector<contact::PairState<dim>> &states,
                      const std::vector<contact::PairStrength>   &strengths)
    {
      return mixed_system->solve(states, strengths);
    }

    /**
     * Solves eq. (9) with every pair stuck at the model's load (the elastic
     * state of the FE-stress factor), without changing the contact state.
     */
    contact::ContactSolution
    solve_all_stick()
    {
      return mixed_system->solve_all_stick();
    }

    /**
     * The next contact solve factorises the mixed system afresh, so that its
     * result does not depend on the solves before it (the factors are
     * reused between solves with the same rows).
     */
    void
    forget_mixed_factorization()
    {
      mixed_system->forget_factorization();
    }

    /**
     * Whether the dense mixed solver may solve a system condensed
     * (contact::DenseMixedSolver; true by default). False: always the
     * whole system, for comparisons.
     */
    void
    set_condensed_solves(const bool condense)
    {
      mixed_system->condensed_solves = condense;
    }

    /** Per pair of all interfaces: on a sliding surface? */
    std::vector<bool>
    pairs_on_sliding_surface() const;

    /**
     * Back to the last contact state with a static solution (after an
     * analysis whose last solve failed), if there is one.
     */
    void
    restore_last_static_state();

    /** The states the next contact solve starts from (the last static ones),
     * and their K. */
    std::pair<contact::ContactOutcome<dim>, double>
    warm_start() const
    {
      return {last_converged, last_converged_K};
    }

    /** The next contact solve starts from @p start (a warm_start() kept
     * before). */
    void
    set_warm_start(const std::pair<contact::ContactOutcome<dim>, double> &start)
    {
      last_converged   = start.first;
      last_converged_K = start.second;
    }

    /** The next contact solve starts from the initial states, not the last
     * static ones. */
    void
    forget_warm_start()
    {
      last_converged = contact::ContactOutcome<dim>();
    }

    /**
     * Scales the compliance of the moving blocks in C by @p scale, without
     * a new C or factorisation (the stiffness check of the safety factor);
     * 1 restores the model.
     */
    void
    set_moving_compliance_scale(const double scale)
    {
      mixed_system->set_moving_compliance_scale(scale);
    }

    /** Sets the contact state to @p outcome, solved at K = @p K. */
    void
    set_contact_state(const contact::ContactOutcome<dim> &outcome,
                      const double                        K);

    /**
     * A judgement on the model or its results that is not an error: printed
     * now, and listed in summary.json's "warnings".
     */
    void
    warn(const std::string &warning);

    /**
     * @name The model's state, read only
     *
     * What the analyses and the output read; only the model's steps and
     * set_contact_state() change it.
     */
    ///@{
    const parameters::Parameters &
    get_parameters() const
    {
      return parameters;
    }
    const geometry::MeshDescription<dim> &
    get_mesh() const
    {
      return mesh;
    }
    const std::vector<std::unique_ptr<blocks::ElasticBlock<dim>>> &
    get_blocks() const
    {
      return blocks;
    }
    const std::vector<contact::Interface<dim>> &
    get_interfaces() const
    {
      return interfaces;
    }
    /** The number of node pairs of all interfaces (after build_interfaces()).
     */
    std::size_t
    n_pairs() const;

    /** Whether compute_flexibility() has made the mixed system. */
    bool
    has_mixed_system() const
    {
      return mixed_system != nullptr;
    }
    /** The mixed system of eq. (9), after compute_flexibility(). */
    const contact::MixedSystem<dim> &
    get_mixed_system() const
    {
      Assert(mixed_system != nullptr,
             ExcMessage("compute_flexibility() has not been called."));
      return *mixed_system;
    }
    /** The last contact solution (of get_strength_reduction()'s strengths). */
    const contact::ContactOutcome<dim> &
    get_contact_outcome() const
    {
      return contact_outcome;
    }
    /** K of get_contact_outcome()'s strengths (1: full strength). */
    double
    get_strength_reduction() const
    {
      return strength_reduction;
    }
    /** Block displacements of the last recover_block_displacements(). */
    const std::vector<Vector<double>> &
    get_displacements() const
    {
      return displacements;
    }
    /**
     * The warnings of the run so far: of the layout checks
     * (doc/layout_checks.md) and of the analyses, for summary.json.
     */
    const std::vector<std::string> &
    get_warnings() const
    {
      return warnings;
    }
    /**
     * Conditioning notes of the contact solves (postprocess::note_text(),
     * id "ill-conditioned"): for the log file and summary.json, and for the
     * screen only where postprocess::conditioning_changes_answer() says so.
     */
    const std::vector<std::string> &
    get_conditioning_notes() const
    {
      return conditioning_notes;
    }
    /** The most significant digits of the contact forces a note said may be
     * lost. */
    int
    get_max_digits_lost() const
    {
      return max_digits_lost;
    }
    ///@}

    /** Block displacements u = K^{-1}(F + contact forces) + omega gamma. */
    void
    recover_block_displacements();

    /** Block displacements of the contact solution @p solution (see
     * recover_block_displacements()). */
    std::vector<Vector<double>>
    block_displacements(const contact::ContactSolution &solution) const;

    /** Results per interface for the current contact state. */
    std::vector<std::vector<postprocess::PairResult<dim>>>
    interface_results() const;

    /**
     * Block and interface VTU files of the current state, described by
     * @p state, listed in @p entries with K as their time; with the
     * mechanism displacement of each block if @p mechanism is given. Only
     * rank 0 writes; not collective.
     */
    void
    write_vtu(const std::string                  &suffix,
              const postprocess::OutputState     &state,
              std::vector<postprocess::PvdEntry> &entries,
              const std::vector<Vector<double>>  *mechanism = nullptr) const;

    /** The largest reaction at each block's minimal support: zero at
     * equilibrium. */
    std::vector<double>
    support_reactions() const;

    /** The run's full log (the log file; the screen with --verbose); only rank
     * 0's reaches it. */
    std::ostream &log;
    /** The lines of the default screen (and the log file). */
    std::ostream &brief;

    /** A progress line: elapsed time, peak memory and @p what. */
    void
    progress(const std::string &what) const;

    /** The wall-time sections of the run's phases. */
    TimerOutput &
    phase_timer()
    {
      return timer;
    }

    /** Wall time since the model was made (s): the "total" of the timings. */
    double
    wall_time() const
    {
      return run_timer.wall_time();
    }

    /**
     * Whether this process writes the output files: rank 0 of
     * MPI_COMM_WORLD. The other ranks compute the same results and write
     * nothing.
     */
    bool
    writes_files() const
    {
      return is_writer;
    }

  private:
    const parameters::Parameters                            parameters;
    geometry::MeshDescription<dim>                          mesh;
    std::vector<std::unique_ptr<blocks::ElasticBlock<dim>>> blocks;
    std::vector<contact::Interface<dim>>                    interfaces;
    /**
     * Per interface with Strength = material: the soil strength at each
     * node of its side I, by the node's x dof (empty for the others).
     */
    std::vector<std::map<types::global_dof_index, blocks::SoilStrength>>
      soil_strengths;
    /** The passive bars' links, their capacities at full strength, and
     * whether K divides them (set_bar_links()). */
    std::vector<contact::BarLink<dim>> bar_links;
    std::vector<contact::PairStrength> bar_capacities;
    bool                               bar_capacities_reduced = false;
    /** The loads that depend on K (set_strength_dependent_loads()). */
    std::function<void(double K)>              strength_dependent_loads;
    std::vector<Vector<double>>                external_displacements;
    std::unique_ptr<contact::MixedSystem<dim>> mixed_system;
    contact::ContactOutcome<dim>               contact_outcome;
    double                                     strength_reduction = 1;
    std::vector<Vector<double>>                displacements;
    std::vector<std::string>                   warnings;
    std::vector<std::string>                   conditioning_notes;
    int                                        max_digits_lost = 0;

    /** Set by validate(): make_geometry() writes no mesh.msh. */
    bool validating = false;
    /** The last contact solution that converged, and its K. */
    contact::ContactOutcome<dim> last_converged;
    double                       last_converged_K = 1;
    /** The assembled load vectors and displacements of the blocks (the base of
     * the load cases). */
    std::vector<Vector<double>> base_load_vectors, base_external_displacements;
    /** Per load case, per block: its nodal forces and displacements. */
    std::vector<std::vector<Vector<double>>> case_loads, case_displacements;
    /** Indices of the body-force cases: [0] without, [1] with the saturated
     * weight. */
    std::vector<unsigned int> body_force_case_indices[2];

    /** See writes_files(). */
    const bool is_writer;
    /**
     * Wall time of the phases of a run, one section each and none nested so
     * that they add up: summary.json's "timings" and the table at the end.
     */
    TimerOutput timer;
    /** Wall time since the model was made: the "total" of the timings. */
    Timer run_timer;

    /** Index of the face group called @p name, or throws naming @p what. */
    types::boundary_id
    face_group(const std::string &name, const std::string &what) const;
  };
} // namespace fdem
