// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/elastic_block.h>
#include <fdem/contact/bar_link.h>
#include <fdem/contact/contact_law.h>
#include <fdem/contact/interface_pairs.h>
#include <fdem/contact/pair_rows.h>
#include <fdem/contact/scaling.h>
#include <fdem/linear_algebra/reusable_lu.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace fdem
{
  namespace contact
  {
    using namespace dealii;

    /** Why a solve of the mixed system has no solution. */
    enum class SolveFailure
    {
      /** It has one. */
      none,
      /**
       * The free rigid modes cannot be held under the pairs' states
       * (RigidModeTest): the system is singular for a mechanical reason,
       * in any units.
       */
      mechanism,
      /**
       * The rigid modes can be held, but the system could not be solved to
       * accuracy (a fresh factorisation and iterative refinement did not
       * reach the backward error, a pivot vanished, or GMRES did not
       * converge): a numerical breakdown, not a statement about mechanics.
       */
      numerical
    };

    /** A solution of the mixed system: pair forces and rigid motions. */
    struct ContactSolution
    {
      /** Pair forces in the local frames, dim per pair (f_n first). */
      Vector<double> forces;
      /** Rigid unknowns gamma of the free modes of all blocks. */
      Vector<double> rigid_motions;
      /** Relative displacements g = g_bar - C f + W gamma, local, dim per pair.
       */
      Vector<double> relative_displacements;
      /** The elastic part C f of the relative displacements. */
      Vector<double> elastic_displacements;
      /**
       * Estimate of the reciprocal condition number of the dimensionless
       * system (SystemScales, then equilibrated). Information only: it
       * decides nothing below machine precision (doc/theory.md).
       */
      double reciprocal_condition = 1;
      /** False if the system has no solution: see failure. */
      bool solved = true;
      /** Why not, if not solved. */
      SolveFailure failure = SolveFailure::none;
      /** The rigid-mode test of the pairs' states in this solve. */
      RigidModeTest rigid_modes;
      /** True if the system was LU-factorised for this solve (not reused). */
      bool factorized = true;
      /** Rows that differ from the last factorised system. */
      unsigned int n_changed_rows = 0;
      /** Why the system was factorised, if it was (ReusableLU::Result). */
      const char *why_factorized = "";
      /** How the factors were reused, if they were. */
      const char *reuse_method = "";
      /**
       * Unknowns of the condensed system if the dense solver solved one
       * (DenseMixedSolver), 0 if it solved the whole system.
       */
      unsigned int n_condensed_unknowns = 0;
      /** Iterative solver: GMRES iterations of this solve (0 for the dense
       * one). */
      unsigned int n_krylov_iterations = 0;
    };

    /** How the mixed system is solved: subsection "Contact" of the parameters.
     */
    enum class MixedSystemSolver
    {
      /**
       * C formed as a dense matrix (dim per pair squared) and the system
       * LU-factorised, the factors reused while few rows change.
       */
      dense,
      /**
       * C never formed: applied as C f = T^T (K_I^{-1} + K_J^{-1}) T f through
       * the blocks' factorisations inside GMRES, preconditioned by the same
       * system with C replaced by its pairs' own blocks (solved exactly,
       * rigid unknowns included). Memory and work per iteration grow as the
       * FE model, not as pairs squared.
       */
      iterative
    };

    /**
     * The preconditioner of the iterative solver ("Solver/Mixed
     * preconditioner"), doc/theory.md.
     */
    enum class KrylovPreconditioner
    {
      /**
       * The same system with C replaced by its pairs' own blocks of P C P,
       * solved exactly, and a coarse correction on groups of neighbouring
       * pairs.
       */
      pairs,
      /**
       * FETI's Dirichlet preconditioner: C^{-1} approximated by the blocks'
       * Schur complements on their interface dofs, sum_b D_b B_b S_b B_b^T
       * D_b (DirichletPreconditioner), fitted to the pairs' rows and the
       * rigid unknowns.
       */
      dirichlet
    };

    /** Controls of the iterative solver. */
    struct KrylovControl
    {
      /** Relative reduction of the preconditioned residual (forces). */
      double tolerance = 1e-12;
      /** Largest number of GMRES iterations per solve. */
      unsigned int max_iterations = 2000;
      /** The preconditioner; read when the system is constructed. */
      KrylovPreconditioner preconditioner = KrylovPreconditioner::pairs;
      /**
       * KrylovPreconditioner::dirichlet: the back-end that factorises each
       * block's stiffness with its interface dofs fixed (MUMPS_Schur stands
       * for MUMPS: no Schur complement is kept).
       */
      parameters::DirectSolverType direct_solver =
        parameters::DirectSolverType::mumps;
      /** That back-end's memory limit (MiB; 0: none), as the blocks'. */
      double memory_limit_MiB = 0;
    };

    template <int dim>
    class DenseMixedSolver;
    template <int dim>
    class IterativeMixedSolver;

    /**
     * The mixed system of the paper's eq. (9) in the form of
     * doc/theory.md:
     *
     *   [  C  -W ] [ f     ]   [  g_bar       ]
     *   [ -W^T 0 ] [ gamma ] = [ -omega^T F   ]
     *
     * C = T^T (C_I + C_J) T is the interface flexibility in the pairs' local
     * frames (eq. 6), g_bar the relative displacement under the external
     * loads alone plus the initial gaps, W the relative motion of the pairs
     * under the free rigid modes, and omega^T F the external load on those
     * modes (eqs. 7-8). All of it is computed once: the FE part is linear.
     * The rows of each pair then follow its status (pair_rows()); solve()
     * hands them to one of two solvers over the same rows: DenseMixedSolver
     * (C formed, LU) or IterativeMixedSolver (C through the blocks, GMRES).
     */
    template <int dim>
    class MixedSystem
    {
    public:
      /**
       * Computes C, g_bar, W and omega^T F from the factorised blocks, their
       * displacements under the external loads @p external_displacements,
       * and the interfaces. The links of passive reinforcement bars @p bars
       * follow the pairs of the interfaces as pairs of their own (index
       * n_contact_pairs() + k for bar k), with the rows of their force law
       * (bar_rows()) instead of the contact law.
       */
      MixedSystem(
        const std::vector<std::unique_ptr<blocks::ElasticBlock<dim>>> &blocks,
        const std::vector<Vector<double>> &external_displacements,
        const std::vector<Interface<dim>> &interfaces,
        const MixedSystemSolver            solver = MixedSystemSolver::dense,
        const bool                         keep_moving_part = false,
        const std::vector<BarLink<dim>>   &bars             = {},
        const KrylovControl               &krylov           = KrylovControl());

      /** The solvers keep a reference to the system: it stays where it is. */
      MixedSystem(const MixedSystem &) = delete;
      MixedSystem &
      operator=(const MixedSystem &) = delete;

      ~MixedSystem();

      /**
       * Scales the compliance of the moving blocks (those with free rigid
       * modes) by @p scale, relative to the assembled one: C and g_bar are
       * linear in each block's compliance (eqs. 4-6), so C = C_fixed + s
       * C_moving and g_bar likewise, without a new factorisation; W and
       * omega^T F do not change. Needs the dense solver and the moving part
       * kept at construction.
       */
      void
      set_moving_compliance_scale(const double scale);

      /**
       * Load cases (doc/theory.md, "Load cases"): another external load on
       * the blocks, given by its nodal forces @p loads and the displacements
       * @p displacements = K^{-1} loads of each block (solved on the blocks'
       * factorisations by the caller). Its part of g_bar (and of the moving
       * blocks' part) and of omega^T F is computed once here; the system's
       * load stays the assembled one until set_load_coefficients(). Returns
       * the index of the case.
       */
      unsigned int
      add_load_case(const std::vector<Vector<double>> &displacements,
                    const std::vector<Vector<double>> &loads);

      /** A load case's parts: its g_bar, its moving blocks' part, its omega^T
       * F. */
      struct LoadCase
      {
        Vector<double> gap, moving_gap, rigid_loads;
      };

      /**
       * The parts of the load @p loads with displacements @p displacements,
       * as add_load_case() computes them, without adding a case.
       */
      LoadCase
      load_case(const std::vector<Vector<double>> &displacements,
                const std::vector<Vector<double>> &loads) const;

      /**
       * Replaces load case @p index by @p parts (load_case()) and
       * recombines the current load: a load that changes from one solve to
       * the next without the number of cases growing (the water of a
       * probabilistic sample).
       */
      void
      replace_load_case(const unsigned int index, const LoadCase &parts);

      /** Number of load cases added. */
      unsigned int
      n_load_cases() const
      {
        return case_gaps.size();
      }

      /**
       * Sets the external load to @p base_factor times the assembled load
       * plus @p coefficients[k] times load case k (missing coefficients are
       * zero): g_bar and omega^T F are linear in the load, so they follow
       * from the parts computed once, without a solve, a new factorisation
       * or a new C. The initial gaps are not a load and are not scaled. The
       * scales of the dimensionless system stay those of the assembled load
       * (a reference force; any fixed one keeps the decisions scale-free),
       * so the LU factors of the mixed system stay valid. With @p
       * base_factor 1 and no coefficient the system is the assembled one
       * bit for bit.
       */
      void
      set_load_coefficients(const double               base_factor,
                            const std::vector<double> &coefficients);

      /** The factor on the assembled load of the current combination
       * (set_load_coefficients()). */
      double
      get_base_load_factor() const
      {
        return base_load_factor;
      }

      /** The coefficients of the load cases of the current combination
       * (set_load_coefficients()). */
      const std::vector<double> &
      get_load_coefficients() const
      {
        return load_coefficients;
      }

      /**
       * The next dense solve factorises afresh instead of updating the last
       * factors (a no-op for the iterative solver): the solves that follow
       * then do not depend on what was solved before, as the samples of a
       * probabilistic analysis must not, whichever rank solves them.
       */
      void
      forget_factorization();

      /** Whether set_moving_compliance_scale() can be used. */
      bool
      can_scale_moving_compliance() const
      {
        return moving_external_gap.size() > 0;
      }

      /**
       * Solves the system with the rows of every pair set by its state
       * (doc/theory.md): stick g = 0; slip g_n = 0 and the
       * tangential force at the Mohr-Coulomb limit along the slip direction;
       * open f = 0; at the tension cut-off f_n = sigma_t A instead of g_n = 0.
       * Whether the free modes can be held is tested first (RigidModeTest);
       * then the solver solves, keeping what saves work in the next solve
       * (the dense solver's factors, the iterative solver's last solution).
       */
      ContactSolution
      solve(const std::vector<PairState<dim>> &states,
            const std::vector<PairStrength>   &strengths);

      /** Solves with every pair in stick. */
      ContactSolution
      solve_all_stick();

      /** How @p solution was solved, for the log (the solver's words). */
      std::string
      describe_solve(const ContactSolution &solution) const;

      /**
       * Nodal forces on block @p b: its external loads plus the contact
       * forces of @p solution (I receives -f, J receives f).
       */
      Vector<double>
      block_nodal_forces(const unsigned int     b,
                         const ContactSolution &solution) const;

      /** Pair @p p of all interfaces, in order. */
      const NodePair<dim> &
      pair(const unsigned int p) const
      {
        return *pairs[p];
      }

      /**
       * The augmentation r of pair @p p in z = f_t + r g_t (3D slip rows):
       * the reciprocal of its mean tangential self-flexibility, so that r g_t
       * is a force of the size of f_t; 0 if the pair is held tangentially.
       */
      double
      tangential_stiffness(const unsigned int p) const
      {
        return contact::tangential_stiffness(self_flexibility[p]);
      }

      /**
       * C times each of @p sources through the block factorisations: the
       * load of the pair forces on each block, one blocked solve, its
       * displacements at the pairs. Counted in n_flexibility_products.
       */
      std::vector<Vector<double>>
      flexibility_products(const std::vector<Vector<double>> &sources);

      /**
       * The solution from x = [f; gamma] and the elastic relative
       * displacements @p elastic = C f that the solver computed: g = g_bar -
       * C f + W gamma.
       */
      ContactSolution
      solution_from(const Vector<double> &x, Vector<double> elastic) const;

      /** Zero forces and motions, marked as not solved for @p failure. */
      ContactSolution
      unsolved(const SolveFailure failure) const;

      /** The solver of the system. */
      MixedSystemSolver
      solver() const
      {
        return solver_type;
      }

      /** Controls of the iterative solver. */
      KrylovControl krylov_control;

      /**
       * The characteristic force, flexibility, displacement and rigid-mode
       * scales of this model: every decision on the system is taken on
       * quantities divided by them (doc/theory.md, "Scale-free decisions").
       */
      SystemScales scales;

      /**
       * A rank of the dimensionless rigid-mode matrices (RigidModeTest) is
       * deficient where their smallest singular value is below this
       * fraction of the largest.
       */
      double rigid_mode_tolerance = 1e-10;

      /**
       * Whether the dense solver may eliminate the pairs' force rows when
       * many 3D slip rows change (DenseMixedSolver); false: it always solves
       * the whole system.
       */
      bool condensed_solves = true;

      /** Products C f computed so far (the iterative solver's block solves). */
      unsigned long n_flexibility_products = 0;
      /** GMRES iterations so far. */
      unsigned long n_krylov_iterations = 0;

      /**
       * The dense solver's LU: its counts of factorisations and reused
       * solves (an unused one, with zero counts, for the iterative solver).
       */
      const linear_algebra::ReusableLU &
      dense_solver() const;

      /** The iterative solver (its preconditioner's parts); the system must use
       * it. */
      const IterativeMixedSolver<dim> &
      iterative_solver() const;

      /** The mean of the diagonal of C: the scale of the rigid unknowns in
       * GMRES. */
      double
      mean_self_flexibility() const
      {
        return mean_flexibility;
      }

      /** Number of pairs over all interfaces, the bars' links included. */
      unsigned int
      n_pairs() const
      {
        return pairs.size();
      }

      /** Number of pairs of the interfaces: the bars' links follow them. */
      unsigned int
      n_contact_pairs() const
      {
        return pairs.size() - bar_links.size();
      }

      /** Whether pair @p p is a bar's link. */
      bool
      is_bar(const unsigned int p) const
      {
        return p >= n_contact_pairs();
      }

      /** The link of pair @p p, a bar's (is_bar()). */
      const BarLink<dim> &
      bar(const unsigned int p) const
      {
        Assert(is_bar(p), ExcInternalError());
        return bar_links[p - n_contact_pairs()];
      }

      /**
       * The pairs that touch one block, the sign of the load they put on it
       * (I receives -f, J receives +f), and their dofs on it, dim per pair.
       */
      struct BlockTouch
      {
        unsigned int                         block = 0;
        std::vector<unsigned int>            pairs;
        std::vector<double>                  signs;
        std::vector<types::global_dof_index> dofs;
      };

      /** Every block that a pair touches, with those pairs. */
      const std::vector<BlockTouch> &
      block_touches() const
      {
        return touches;
      }

      /** Block @p b of the model. */
      const blocks::ElasticBlock<dim> &
      block(const unsigned int b) const
      {
        return *blocks[b];
      }

      /** Number of rigid unknowns (free modes over all blocks). */
      unsigned int
      n_rigid_unknowns() const
      {
        return rigid_loads.size();
      }

      /** First rigid unknown of block b. */
      std::vector<unsigned int> first_rigid_unknown;

      /**
       * Interface flexibility C (eq. 6), local frames, dim per pair. Empty
       * for the iterative solver, which never forms it.
       */
      FullMatrix<double> flexibility;
      /** The pairs' own dim x dim blocks of C (both solvers). */
      std::vector<Tensor<2, dim>> self_flexibility;
      /** Relative displacement under the external loads, plus gaps. */
      Vector<double> external_gap;
      /** d g / d gamma: relative motion of the pairs under each free mode. */
      FullMatrix<double> rigid_coupling;
      /** omega^T F per rigid unknown (eqs. 7-8). */
      Vector<double> rigid_loads;

    private:
      const std::vector<std::unique_ptr<blocks::ElasticBlock<dim>>> &blocks;
      const MixedSystemSolver solver_type;
      /** The bars' links (their pairs follow the interfaces' pairs). */
      const std::vector<BarLink<dim>> bar_links;
      /** All pairs of all interfaces, in order, then the bars' links, with
       * their blocks. */
      std::vector<const NodePair<dim> *> pairs;
      std::vector<unsigned int>          pair_block_I, pair_block_J;

      /** Every block that a pair touches. */
      std::vector<BlockTouch> touches;
      /** A direction with at most this self-flexibility is held (pair_rows()).
       */
      double held_flexibility = 0;
      /** The mean of the diagonal of C: the scale of the rigid unknowns in
       * GMRES. */
      double mean_flexibility = 1;
      /** The moving blocks' parts of C and g_bar
       * (set_moving_compliance_scale()). */
      FullMatrix<double> moving_flexibility;
      Vector<double>     moving_external_gap;
      /** The current scale of the moving blocks' compliance. */
      double moving_compliance_scale = 1;

      /** g_bar and omega^T F of the assembled load (at the current compliance
       * scale). */
      Vector<double> base_external_gap, base_rigid_loads;
      /** The initial gaps in g_bar (not a load: never scaled). */
      Vector<double> initial_gaps;
      /** Per load case: its g_bar, its moving blocks' part, its omega^T F. */
      std::vector<Vector<double>> case_gaps, case_moving_gaps, case_rigid_loads;
      /** The current load combination (set_load_coefficients()). */
      double              base_load_factor = 1;
      std::vector<double> load_coefficients;
      /** The force scale of the assembled load (set_diagonal_scales()), once
       * computed. */
      double base_force_scale = -1;

      /** external_gap and rigid_loads of the current combination and compliance
       * scale. */
      void
      combine_loads();

      /**
       * self_flexibility, held_flexibility, mean_flexibility and the scales
       * of the dimensionless system, from C, g_bar and W.
       */
      void
      set_diagonal_scales();

      /** Throws one line if C or g_bar holds a value beyond a double. */
      void
      check_within_range() const;

      /** The solver: one of the two. */
      std::unique_ptr<DenseMixedSolver<dim>>     dense;
      std::unique_ptr<IterativeMixedSolver<dim>> iterative;
    };
  } // namespace contact
} // namespace fdem
