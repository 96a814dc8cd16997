// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/block_factorization.h>
#include <fdem/contact/mixed_system.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace fdem
{
  namespace contact
  {
    /**
     * FETI's Dirichlet preconditioner of the interface flexibility C
     * (doc/theory.md, "The iterative solver"): C = sum_b B_b K_b^{-1} B_b^T,
     * B_b the relative displacement at the pairs (local frames, sign s_b) of
     * block b's nodal displacements, is a FETI operator, and
     *
     *   H = sum_b D_b B_b S_b B_b^T D_b  ~  C^{-1},
     *
     * with S_b the Schur complement of block b's stiffness on its interface
     * dofs Gamma_b (the unconstrained dofs of its pairs), applied sparsely as
     * S_b v = K_GG v - K_GR K_RR^{-1} K_RG v, and D_b the stiffness scaling
     * k_other / (k_b + k_other) per pair (k the mean diagonal of K at the
     * pair's node on each side), which makes H exact for a single pair. Its
     * condition number on C grows as (1 + log(H/h))^2 only, not with the
     * number of pairs (Farhat, Mandel & Roux 1994; Klawonn & Widlund 2001).
     *
     * K_RR is the block's stiffness K, as factorised for the solves (the
     * Dirichlet conditions and a free block's minimal support condensed),
     * with the interface dofs fixed: one more sparse factorisation per block
     * that a pair touches. With the support kept S_b is the inverse of the
     * block's flexibility on Gamma_b (what the unit test checks); it differs
     * from the floating block's Schur complement by a matrix of the rank of
     * the free modes, which the rigid unknowns of the mixed system take.
     *
     * One MPI rank only: K_RR is copied from the block's matrix on that rank.
     */
    template <int dim>
    class DirichletPreconditioner
    {
    public:
      /**
       * Factorises, for each block that a pair of @p system touches, its
       * stiffness with its interface dofs fixed, by the back-end
       * @p solver_type (MUMPS_Schur stands for MUMPS) within
       * @p memory_limit_MiB (make_block_factorization()).
       */
      DirichletPreconditioner(const MixedSystem<dim>            &system,
                              const parameters::DirectSolverType solver_type,
                              const double memory_limit_MiB = 0);

      ~DirichletPreconditioner();

      /**
       * H u for each relative displacement u of @p displacements (dim per
       * pair, local frames): pair forces. One blocked solve per block.
       */
      std::vector<Vector<double>>
      apply(const std::vector<Vector<double>> &displacements) const;

      /**
       * S_b v for block touch @p t of the system (MixedSystem::
       * block_touches()): @p values on its interface dofs (interface_dofs()),
       * the forces there, for several vectors at once.
       */
      std::vector<Vector<double>>
      schur_products(const unsigned int                 t,
                     const std::vector<Vector<double>> &values) const;

      /** The interface dofs Gamma_b of block touch @p t, in order. */
      const std::vector<types::global_dof_index> &
      interface_dofs(const unsigned int t) const
      {
        return parts[t].interface_dofs;
      }

      /** Products H u computed so far (one per vector). */
      mutable unsigned long n_applications = 0;

      /** Wall time of the factorisations (s). */
      double factorization_seconds = 0;

    private:
      const MixedSystem<dim> &system;

      /** One block that pairs touch. */
      struct BlockPart
      {
        /** Gamma_b: the unconstrained dofs of its pairs, distinct. */
        std::vector<types::global_dof_index> interface_dofs;
        /**
         * Per dof of the touch (dim per pair, MixedSystem::BlockTouch::dofs)
         * its index in interface_dofs, or -1 if the dof is constrained (a
         * fixed or roller direction: the block does not take it).
         */
        std::vector<int> interface_index;
        /** Per dof of the block, its index in interface_dofs, or -1 (an
         * interior dof): built once, used by every Schur product. */
        std::vector<int> dof_to_interface;
        /** Per pair of the touch, its weight D_b. */
        std::vector<double> weights;
        /** K with the interface dofs' rows and columns fixed, factorised. */
        TrilinosWrappers::SparseMatrix              fixed_stiffness;
        std::unique_ptr<blocks::BlockFactorization> fixed_factorization;
      };
      std::vector<BlockPart> parts;
    };
  } // namespace contact
} // namespace fdem
