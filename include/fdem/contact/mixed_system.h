// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/elastic_block.h>
#include <fdem/contact/contact_law.h>
#include <fdem/contact/interface_pairs.h>
#include <fdem/contact/pair_rows.h>
#include <fdem/contact/reusable_lu.h>
#include <fdem/contact/scaling.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
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
      /** Relative displacements g = g_bar - C f + W gamma, local, dim per pair. */
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
      /** Iterative solver: GMRES iterations of this solve (0 for the dense one). */
      unsigned int n_krylov_iterations = 0;
    };

    /** How the mixed system is solved: subsection "Contact" of the parameters. */
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

    /** Controls of the iterative solver. */
    struct KrylovControl
    {
      /** Relative reduction of the preconditioned residual (forces). */
      double tolerance = 1e-12;
      /** Largest number of GMRES iterations per solve. */
      unsigned int max_iterations = 2000;
    };

    /**
     * The mixed system of the paper's eq. (9) in the form of
     * design/formulation.md Sec. 2-3:
     *
     *   [  C  -W ] [ f     ]   [  g_bar       ]
     *   [ -W^T 0 ] [ gamma ] = [ -omega^T F   ]
     *
     * C = T^T (C_I + C_J) T is the interface flexibility in the pairs' local
     * frames (eq. 6), g_bar the relative displacement under the external
     * loads alone plus the initial gaps, W the relative motion of the pairs
     * under the free rigid modes, and omega^T F the external load on those
     * modes (eqs. 7-8). All of it is computed once: the FE part is linear.
     * The rows of each pair then follow its status.
     */
    template <int dim>
    class MixedSystem
    {
    public:
      /**
       * Computes C, g_bar, W and omega^T F from the factorised blocks, their
       * displacements under the external loads @p external_displacements,
       * and the interfaces.
       */
      MixedSystem(
        const std::vector<std::unique_ptr<blocks::ElasticBlock<dim>>> &blocks,
        const std::vector<Vector<double>> &external_displacements,
        const std::vector<Interface<dim>> &interfaces,
        const MixedSystemSolver            solver = MixedSystemSolver::dense,
        const bool                         keep_moving_part = false);

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

      /** Whether set_moving_compliance_scale() can be used. */
      bool
      can_scale_moving_compliance() const
      {
        return moving_external_gap.size() > 0;
      }

      /**
       * Solves the system with the rows of every pair set by its state
       * (design/formulation.md Sec. 3): stick g = 0; slip g_n = 0 and the
       * tangential force at the Mohr-Coulomb limit along the slip direction;
       * open f = 0; at the tension cut-off f_n = sigma_t A instead of g_n = 0.
       */
      ContactSolution
      solve(const std::vector<PairState<dim>> &states,
            const std::vector<PairStrength> &  strengths) const;

      /** Solves with every pair in stick. */
      ContactSolution
      solve_all_stick() const;

      /**
       * Nodal forces on block @p b: its external loads plus the contact
       * forces of @p solution (I receives -f, J receives f).
       */
      Vector<double>
      block_nodal_forces(const unsigned int b, const ContactSolution &solution) const;

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
       * dst = C src, with the dense C or, for the iterative solver, through
       * one solve of each block that a pair touches.
       */
      void
      vmult_flexibility(Vector<double> &dst, const Vector<double> &src) const;

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

      /** Products C f computed so far (the iterative solver's block solves). */
      mutable unsigned long n_flexibility_products = 0;
      /** GMRES iterations so far. */
      mutable unsigned long n_krylov_iterations = 0;

      /** The dense solver: its counts of factorisations and reused solves. */
      const ReusableLU &
      dense_solver() const
      {
        return lu;
      }

      /** When the dense solver factorises afresh (tests compare with reuse = false). */
      ReusableLU::Control &
      dense_solver_control()
      {
        return lu.control;
      }

      /** Number of pairs over all interfaces. */
      unsigned int
      n_pairs() const
      {
        return pairs.size();
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
      /**
       * The pairs' blocks of P C P, P the orthogonal projector onto the
       * forces that the free modes do not feel (ker W^T): the pairs' own
       * flexibility without the part that the minimal supports of free
       * blocks add to every entry of C, a rigid motion that the rigid
       * unknowns take up. The iterative solver's preconditioner uses them
       * (empty for the dense solver).
       */
      std::vector<Tensor<2, dim>> projected_self_flexibility;
      /** Relative displacement under the external loads, plus gaps. */
      Vector<double> external_gap;
      /** d g / d gamma: relative motion of the pairs under each free mode. */
      FullMatrix<double> rigid_coupling;
      /** omega^T F per rigid unknown (eqs. 7-8). */
      Vector<double> rigid_loads;

    private:
      const std::vector<std::unique_ptr<blocks::ElasticBlock<dim>>> &blocks;
      const MixedSystemSolver                                         solver_type;
      /** All pairs of all interfaces, in order, with their blocks. */
      std::vector<const NodePair<dim> *> pairs;
      std::vector<unsigned int>          pair_block_I, pair_block_J;

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
      /** Every block that a pair touches. */
      std::vector<BlockTouch> touches;
      /** A direction with at most this self-flexibility is held (pair_rows()). */
      double held_flexibility = 0;
      /** The mean of the diagonal of C: the scale of the rigid unknowns in GMRES. */
      double mean_flexibility = 1;
      /** The moving blocks' parts of C and g_bar (set_moving_compliance_scale()). */
      FullMatrix<double> moving_flexibility;
      Vector<double>     moving_external_gap;
      /** The current scale of the moving blocks' compliance. */
      double moving_compliance_scale = 1;

      /**
       * self_flexibility, held_flexibility, mean_flexibility and the scales
       * of the dimensionless system, from C, g_bar and W.
       */
      void
      set_diagonal_scales();

      /** The iterative solver's last solution: the start of the next solve. */
      mutable Vector<double> last_iterate;

      /** C times each of @p sources, through the block factorisations. */
      std::vector<Vector<double>>
      flexibility_products(const std::vector<Vector<double>> &sources) const;

      /**
       * W (W^T W)^{-1} (n_forces x n_rigid): z - B W^T z is the part of z in
       * ker W^T (empty without free modes).
       */
      FullMatrix<double> projector_coefficients;

      /**
       * The iterative solver's coarse space: the pairs in groups of
       * neighbours, Z with one column per group and local direction (1 on
       * the group's pairs in that direction, projected onto ker W^T), and
       * C Z.
       */
      std::vector<unsigned int> pair_group;
      unsigned int              n_groups = 0;
      FullMatrix<double>        coarse_basis, coarse_flexibility;

      /** Groups the pairs and computes Z and C Z. */
      void
      setup_coarse_space();

      /**
       * Computes projected_self_flexibility and the coarse space (the
       * iterative solver).
       */
      void
      setup_preconditioner();

      /** The system with the rows @p rows by the dense LU. */
      ContactSolution
      solve_dense(const std::vector<PairRows<dim>> &rows) const;

      /** The system with the rows @p rows by GMRES (the iterative solver). */
      ContactSolution
      solve_iterative(const std::vector<PairRows<dim>> &rows) const;

      /** g, C f and the unknowns into @p solution from x = [f; gamma]. */
      void
      finish_solution(const Vector<double> &x, ContactSolution &solution) const;

      /** Zero forces and motions into @p solution, marked as not solved. */
      void
      unsolved(ContactSolution &solution) const;
      /**
       * The factors of the last factorised system, reused while few rows
       * change between solves. Mutable: solve() leaves the system as it is,
       * the factors only save work (one solve at a time, no threads).
       */
      mutable ReusableLU lu;
    };
  } // namespace contact
} // namespace fdem
