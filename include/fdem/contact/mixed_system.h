// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/elastic_block.h>
#include <fdem/contact/contact_law.h>
#include <fdem/contact/interface_pairs.h>
#include <fdem/contact/reusable_lu.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace fdem
{
  namespace contact
  {
    using namespace dealii;

    /** A solution of the mixed system: pair forces and rigid motions. */
    struct ContactSolution
    {
      /** Pair forces in the local frames, dim per pair (f_n first). */
      Vector<double> forces;
      /** Rigid unknowns gamma of the free modes of all blocks. */
      Vector<double> rigid_motions;
      /** Relative displacements g = g_bar - C f + W gamma, local, dim per pair. */
      Vector<double> relative_displacements;
      /** Estimate of the reciprocal condition number of the scaled system. */
      double reciprocal_condition = 1;
      /** False if the system was singular (no static equilibrium). */
      bool solved = true;
      /** True if the system was LU-factorised for this solve (not reused). */
      bool factorized = true;
      /** Rows that differ from the last factorised system. */
      unsigned int n_changed_rows = 0;
      /** Why the system was factorised, if it was (ReusableLU::Result). */
      const char *why_factorized = "";
      /** How the factors were reused, if they were. */
      const char *reuse_method = "";
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
        const std::vector<Interface<dim>> &interfaces);

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
      tangential_stiffness(const unsigned int p) const;

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

      /** Interface flexibility C (eq. 6), local frames, dim per pair. */
      FullMatrix<double> flexibility;
      /** Relative displacement under the external loads, plus gaps. */
      Vector<double> external_gap;
      /** d g / d gamma: relative motion of the pairs under each free mode. */
      FullMatrix<double> rigid_coupling;
      /** omega^T F per rigid unknown (eqs. 7-8). */
      Vector<double> rigid_loads;

    private:
      const std::vector<std::unique_ptr<blocks::ElasticBlock<dim>>> &blocks;
      /** All pairs of all interfaces, in order, with their blocks. */
      std::vector<const NodePair<dim> *> pairs;
      std::vector<unsigned int>          pair_block_I, pair_block_J;
      /**
       * The factors of the last factorised system, reused while few rows
       * change between solves. Mutable: solve() leaves the system as it is,
       * the factors only save work (one solve at a time, no threads).
       */
      mutable ReusableLU lu;
    };
  } // namespace contact
} // namespace fdem
