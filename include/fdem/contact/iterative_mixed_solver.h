// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/contact/mixed_system.h>
#include <fdem/contact/pair_rows.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace fdem
{
  namespace contact
  {
    template <int dim>
    class DirichletPreconditioner;

    /**
     * The iterative solver of the mixed system (MixedSystemSolver::iterative):
     * C is never formed. GMRES works on x = [f; gamma w / c_0] (the rigid
     * unknowns as forces: w_m the largest relative motion of mode m, c_0 the
     * mean self-flexibility, so that the norm it reduces weighs both alike
     * in any units), and each iteration applies C once, through one solve of
     * every block a pair touches (MixedSystem::flexibility_products()). The
     * preconditioner is the same system with C replaced by the pairs' own
     * blocks of P C P (P onto ker W^T), solved exactly, with a coarse
     * correction on groups of neighbouring pairs for the smooth force
     * patterns, which the pairs' blocks precondition worst. With
     * KrylovPreconditioner::dirichlet the pairs' solution is corrected by
     * FETI's Dirichlet preconditioner H ~ C^{-1} (DirichletPreconditioner)
     * through the pairs' rows, and the groups are not needed.
     */
    template <int dim>
    class IterativeMixedSolver
    {
    public:
      /**
       * A solver of @p system: sets up the preconditioner (the pairs' blocks
       * of P C P and the coarse space), with products C f through the
       * blocks, which @p system counts.
       */
      explicit IterativeMixedSolver(MixedSystem<dim> &system);

      ~IterativeMixedSolver();

      /**
       * The system with the rows @p rows, whose rigid modes can be held
       * (MixedSystem::solve() has tested them), from the last solution.
       */
      ContactSolution
      solve(const std::vector<PairRows<dim>> &rows);

      /** How @p solution was solved, for the log: its GMRES iterations. */
      static std::string
      describe(const ContactSolution &solution);

      /**
       * The pairs' blocks of P C P, P the orthogonal projector onto the
       * forces that the free modes do not feel (ker W^T): the pairs' own
       * flexibility without the part that the minimal supports of free
       * blocks add to every entry of C, a rigid motion that the rigid
       * unknowns take up. The preconditioner is made of them.
       */
      std::vector<Tensor<2, dim>> projected_self_flexibility;

      /**
       * The Dirichlet preconditioner, with KrylovPreconditioner::dirichlet;
       * nullptr otherwise.
       */
      const DirichletPreconditioner<dim> *
      dirichlet_preconditioner() const
      {
        return dirichlet.get();
      }

    private:
      MixedSystem<dim> &system;

      /** The last solution: the start of the next solve. */
      Vector<double> last_iterate;

      /**
       * W (W^T W)^{-1} (n_forces x n_rigid): z - B W^T z is the part of z in
       * ker W^T (empty without free modes).
       */
      FullMatrix<double> projector_coefficients;

      /**
       * The coarse space: the pairs in groups of neighbours, Z with one
       * column per group and local direction (1 on the group's pairs in that
       * direction, projected onto ker W^T), and C Z.
       */
      std::vector<unsigned int> pair_group;
      unsigned int              n_groups = 0;
      FullMatrix<double>        coarse_basis, coarse_flexibility;

      /** KrylovPreconditioner::dirichlet: H ~ C^{-1}. */
      std::unique_ptr<DirichletPreconditioner<dim>> dirichlet;

      /** Computes projected_self_flexibility and the coarse space. */
      void
      setup_preconditioner();

      /** Groups the pairs and computes Z and C Z. */
      void
      setup_coarse_space();
    };
  } // namespace contact
} // namespace fdem
