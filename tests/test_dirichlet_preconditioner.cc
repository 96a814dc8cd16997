// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// FETI's Dirichlet preconditioner of the iterative mixed system
// (contact::DirichletPreconditioner, doc/theory.md "The iterative solver"):
// the sparse Schur complement of each block on its interface dofs is the
// inverse of the block's dense flexibility there, and the GMRES iterations
// it leaves do not grow with the pairs as those of the pairs' blocks do.
#include "test_helpers.h"

#include <fdem/contact/dirichlet_preconditioner.h>
#include <fdem/contact/iterative_mixed_solver.h>

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

using namespace fdem;

namespace
{
  /** prm/block_on_plane_3d.prm with n x n elements along the plane. */
  parameters::Parameters
  block_on_plane(const unsigned int n)
  {
    parameters::Parameters parameters =
      test_support::case_parameters("block_on_plane_3d.prm");
    parameters.geometry.block_on_plane.n_elements_along_length = n;
    parameters.geometry.block_on_plane.n_elements_along_width  = n;
    parameters.solver.mixed_system                             = "iterative";
    return parameters;
  }

  /** The blocks' displacements under their external loads, K^{-1} F. */
  template <int dim>
  std::vector<dealii::Vector<double>>
  external_displacements(const Model<dim> &model)
  {
    std::vector<dealii::Vector<double>> displacements;
    for (const auto &block : model.get_blocks())
      displacements.push_back(block->solve(block->load_vector));
    return displacements;
  }

  /**
   * The mixed system of @p model's blocks and interfaces, solved by GMRES
   * with @p preconditioner.
   */
  template <int dim>
  std::unique_ptr<contact::MixedSystem<dim>>
  iterative_system(const Model<dim>                          &model,
                   const std::vector<dealii::Vector<double>> &displacements,
                   const contact::KrylovPreconditioner        preconditioner)
  {
    contact::KrylovControl krylov;
    krylov.preconditioner = preconditioner;
    return std::make_unique<contact::MixedSystem<dim>>(
      model.get_blocks(),
      displacements,
      model.get_interfaces(),
      contact::MixedSystemSolver::iterative,
      false,
      std::vector<contact::BarLink<dim>>(),
      krylov);
  }
} // namespace

TEST(DirichletPreconditioner, SchurComplementIsTheInverseOfTheFlexibility)
{
  // On each block of the block on a plane (the sliding block, free and held
  // by its minimal support, and the fixed foundation), S_b from the sparse
  // factorisation of K with the interface dofs fixed, times the dense
  // flexibility K^{-1} restricted to those dofs, is the identity.
  std::ostringstream log;
  const auto model = test_support::factorised_model<3>(block_on_plane(6), log);
  const auto system =
    iterative_system(*model,
                     external_displacements(*model),
                     contact::KrylovPreconditioner::dirichlet);
  const contact::DirichletPreconditioner<3> *dirichlet =
    system->iterative_solver().dirichlet_preconditioner();
  ASSERT_NE(dirichlet, nullptr);
  const auto &touches = system->block_touches();
  ASSERT_EQ(touches.size(), 2u);
  for (unsigned int t = 0; t < touches.size(); ++t)
    {
      const auto &dofs = dirichlet->interface_dofs(t);
      // 7 x 7 nodes, 3 dofs each: none constrained on this interface.
      ASSERT_EQ(dofs.size(), 3u * 49u);
      const dealii::FullMatrix<double> C =
        system->block(touches[t].block).flexibility(dofs);
      std::vector<dealii::Vector<double>> columns(
        dofs.size(), dealii::Vector<double>(dofs.size()));
      for (unsigned int j = 0; j < dofs.size(); ++j)
        for (unsigned int i = 0; i < dofs.size(); ++i)
          columns[j][i] = C(i, j);
      const std::vector<dealii::Vector<double>> SC =
        dirichlet->schur_products(t, columns);
      double error = 0;
      for (unsigned int j = 0; j < dofs.size(); ++j)
        for (unsigned int i = 0; i < dofs.size(); ++i)
          error = std::max(error, std::abs(SC[j][i] - (i == j ? 1.0 : 0.0)));
      // Two factorisations of K (with and without the interface fixed):
      // round-off amplified by the conditioning of K (measured 3.5e-14 on
      // the sliding block, 1.3e-15 on the foundation).
      EXPECT_LT(error, 1e-11) << "block touch " << t;
    }
}

TEST(DirichletPreconditioner, IterationsDoNotGrowWithThePairs)
{
  // An all-stick solve from zero on the block on a plane with 49 and 196
  // pairs (4 x the interface, h halved): with the Dirichlet preconditioner
  // the condition number grows as (1 + log(H/h))^2, the GMRES iterations
  // about as 1 + log(H/h), a factor (1 + ln 13) / (1 + ln 6) = 1.27 here
  // (measured 12 and 15); the pairs' preconditioner needs more than twice
  // as many on both (measured 37 and 50). The
  // forces agree with those of the pairs' preconditioner (both stop at
  // 1e-12 of their preconditioned right-hand sides: 1e-8 of the largest
  // force, as IterativeMixedSystem.* compare with the dense solver).
  std::vector<unsigned int> dirichlet_iterations, pairs_iterations;
  for (const unsigned int n : {6u, 13u})
    {
      std::ostringstream log;
      const auto         model =
        test_support::factorised_model<3>(block_on_plane(n), log);
      const auto displacements = external_displacements(*model);
      const auto dirichlet =
        iterative_system(*model,
                         displacements,
                         contact::KrylovPreconditioner::dirichlet);
      const auto pairs = iterative_system(*model,
                                          displacements,
                                          contact::KrylovPreconditioner::pairs);
      ASSERT_EQ(dirichlet->n_pairs(), (n + 1) * (n + 1));
      const contact::ContactSolution a = dirichlet->solve_all_stick();
      const contact::ContactSolution b = pairs->solve_all_stick();
      ASSERT_TRUE(a.solved);
      ASSERT_TRUE(b.solved);
      dirichlet_iterations.push_back(a.n_krylov_iterations);
      pairs_iterations.push_back(b.n_krylov_iterations);
      dealii::Vector<double> difference = a.forces;
      difference -= b.forces;
      EXPECT_LT(difference.linfty_norm(), 1e-8 * b.forces.linfty_norm())
        << n << " x " << n;
    }
  EXPECT_LE(dirichlet_iterations[1], 1.4 * dirichlet_iterations[0])
    << dirichlet_iterations[0] << ", " << dirichlet_iterations[1];
  for (unsigned int level = 0; level < 2; ++level)
    EXPECT_LT(2 * dirichlet_iterations[level], pairs_iterations[level])
      << dirichlet_iterations[level] << ", " << pairs_iterations[level];
}

TEST(DirichletPreconditioner, BothPreconditionersGiveTheDenseSafetyFactor)
{
  // The default is Dirichlet, which IterativeMixedSystem.* check against
  // the dense solver; the pairs' preconditioner stays selectable and must
  // give the same K (1e-9 relative, as there) on the block on a plane,
  // where every pair slips at the limit.
  parameters::Parameters base =
    test_support::case_parameters("block_on_plane_3d.prm");
  std::ostringstream dense_log;
  CaseRun<3>         dense(base, "", dense_log);
  dense.run();
  ASSERT_EQ(dense.summary()["status"], "completed");
  const double K_dense = dense.summary()["safety_factor"].get<double>();
  for (const std::string preconditioner : {"pairs", "Dirichlet"})
    {
      parameters::Parameters parameters      = base;
      parameters.solver.mixed_system         = "iterative";
      parameters.solver.mixed_preconditioner = preconditioner;
      parameters.output.directory =
        test_support::test_directory("block_on_plane_3d-" + preconditioner);
      std::ostringstream log;
      CaseRun<3>         run(parameters, "", log);
      run.run();
      ASSERT_EQ(run.summary()["status"], "completed") << log.str();
      EXPECT_NEAR(run.summary()["safety_factor"].get<double>(),
                  K_dense,
                  1e-9 * K_dense)
        << preconditioner;
    }
}
