// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The iterative solver of the mixed system (Solver/Mixed system = iterative:
// C applied through the block factorisations inside GMRES) against the dense
// one, which forms C and LU-factorises: the same states, forces and safety
// factors, on 2D and 3D cases with free blocks, slip, opening and cohesion;
// the exact planar limits; and the pieces it is built from (the pairs' own
// blocks of C from MUMPS's entries of K^{-1}, their projection).
#include "test_helpers.h"

#include <fdem/contact/iterative_mixed_solver.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

using namespace fdem;
using dealii::numbers::PI;

namespace
{
  parameters::Parameters
  with_solver(parameters::Parameters parameters,
              const std::string     &mixed_system)
  {
    parameters.solver.mixed_system = mixed_system;
    parameters.output.directory =
      test_support::test_directory(parameters.case_name + "-" + mixed_system);
    return parameters;
  }

  /** Largest difference of two vectors over the largest entry of the first. */
  double
  relative_difference(const dealii::Vector<double> &a,
                      const dealii::Vector<double> &b)
  {
    dealii::Vector<double> difference = a;
    difference -= b;
    return difference.linfty_norm() / std::max(a.linfty_norm(), 1e-300);
  }

  /**
   * Runs prm/@p name with both solvers: the same safety factor, and at full
   * strength the same statuses and forces. The iterative solves stop at
   * 1e-12 of the preconditioned right-hand side; with the preconditioned
   * condition numbers met here (up to a few hundred) that leaves the forces
   * right to about 1e-9 of the largest, hence 1e-8. K follows from the
   * forces (F_R / F_tau) along the same path of statuses: 1e-9 relative.
   * (The forces are compared at full strength, not at the converged K:
   * near the limit they change fast with K, and the two K differ by their
   * own round-off.)
   */
  template <int dim>
  void
  check_same_as_dense(const std::string &name)
  {
    const parameters::Parameters base = test_support::case_parameters(name);
    if (base.safety_factor.compute)
      {
        std::ostringstream dense_log, iterative_log;
        CaseRun<dim>       dense(with_solver(base, "dense"), "", dense_log);
        CaseRun<dim>       iterative(with_solver(base, "iterative"),
                               "",
                               iterative_log);
        dense.run();
        iterative.run();
        ASSERT_EQ(dense.summary()["status"], "completed");
        ASSERT_EQ(iterative.summary()["status"], "completed")
          << iterative_log.str();
        EXPECT_GT(iterative.summary()["contact"]["n_gmres_iterations"]
                    .template get<unsigned long>(),
                  0u);
        EXPECT_EQ(iterative.summary()["contact"]["n_factorizations"]
                    .template get<unsigned int>(),
                  0u);
        const double K_dense =
          dense.summary()["safety_factor"].template get<double>();
        const double K_iterative =
          iterative.summary()["safety_factor"].template get<double>();
        EXPECT_NEAR(K_iterative, K_dense, 1e-9 * K_dense) << name;
      }

    std::ostringstream log;
    const auto         dense =
      test_support::solved_model<dim>(with_solver(base, "dense"), log);
    const auto iterative =
      test_support::solved_model<dim>(with_solver(base, "iterative"), log);
    ASSERT_TRUE(dense->get_contact_outcome().converged());
    ASSERT_TRUE(iterative->get_contact_outcome().converged());
    EXPECT_TRUE(iterative->get_mixed_system().flexibility.empty())
      << "C must not be formed";
    const auto &states_dense     = dense->get_contact_outcome().states;
    const auto &states_iterative = iterative->get_contact_outcome().states;
    ASSERT_EQ(states_dense.size(), states_iterative.size());
    unsigned int n_different = 0;
    for (unsigned int p = 0; p < states_dense.size(); ++p)
      n_different += states_dense[p].status != states_iterative[p].status;
    EXPECT_EQ(n_different, 0u) << name;
    EXPECT_LT(
      relative_difference(dense->get_contact_outcome().solution.forces,
                          iterative->get_contact_outcome().solution.forces),
      1e-8)
      << name;
  }
} // namespace

TEST(IterativeMixedSystem, PaperSlopeAsDense)
{
  check_same_as_dense<2>("paper_slope.prm");
}

TEST(IterativeMixedSystem, PriestPlaneFailureAsDense)
{
  // Tension crack, water and a free block on two planes.
  check_same_as_dense<2>("priest_plane_failure.prm");
}

TEST(IterativeMixedSystem, HertzAsDense)
{
  // Two blocks with supports, contact only: pairs open and close.
  check_same_as_dense<2>("hertz.prm");
}

TEST(IterativeMixedSystem, CattaneoMindlinAsDense)
{
  // Partial slip: stick centre, slipping annulus.
  check_same_as_dense<2>("cattaneo_mindlin.prm");
}

TEST(IterativeMixedSystem, HertzSphereAsDense)
{
  check_same_as_dense<3>("hertz_sphere.prm");
}

TEST(IterativeMixedSystem, BlockOnPlaneThreeDExactLimit)
{
  // prm/block_on_plane_3d.prm: every pair slips at the limit, whose K is
  // (c A + W cos 30 tan 30) / (W sin 30) = 1.24; the slip directions turn
  // in 3D (the slip rows are nonsymmetric).
  check_same_as_dense<3>("block_on_plane_3d.prm");
  std::ostringstream log;
  CaseRun<3>         model(with_solver(test_support::case_parameters(
                                 "block_on_plane_3d.prm"),
                               "iterative"),
                   "",
                   log);
  model.run();
  const double W = 25.0 * 10 * 6 * 5, dip = PI / 6;
  const double exact =
    (15.0 * 60 + W * std::cos(dip) * std::tan(PI / 6)) / (W * std::sin(dip));
  EXPECT_NEAR(model.summary()["safety_factor"].get<double>(),
              exact,
              1e-8 * exact);
}

TEST(IterativeMixedSystem, InclinedBlockExactLimitForAnyStrength)
{
  // The planar oracle (doc/theory.md) with and without
  // cohesion; a tensile strength keeps the heel closed (with c = 0 an open
  // pair costs nothing), as in PlanarSlidingSurface.*. Round-off: 1e-8.
  for (const auto &[c, phi, tension] :
       std::vector<std::tuple<double, double, double>>{{0, 35, 0},
                                                       {20, 30, 1e3},
                                                       {50, 10, 1e3}})
    {
      parameters::Parameters parameters =
        with_solver(test_support::case_parameters("inclined_block.prm"),
                    "iterative");
      auto &interface            = parameters.interfaces.at("sliding surface");
      interface.cohesion         = c;
      interface.friction_angle   = phi;
      interface.tensile_strength = tension;
      const auto  &geometry      = parameters.geometry.inclined_block;
      const double theta         = geometry.inclination * PI / 180;
      const double W = parameters.materials.at("block").unit_weight *
                       geometry.block_length * geometry.block_height;
      const double exact = (c * geometry.block_length +
                            W * std::cos(theta) * std::tan(phi * PI / 180)) /
                           (W * std::sin(theta));
      std::ostringstream log;
      CaseRun<2>         model(parameters, "", log);
      model.run();
      ASSERT_EQ(model.summary()["status"], "completed") << log.str();
      EXPECT_NEAR(model.summary()["safety_factor"].get<double>(),
                  exact,
                  1e-8 * exact)
        << "c = " << c << ", phi = " << phi;
    }
}

TEST(IterativeMixedSystem, PairBlocksFromEntriesOfTheInverseAndTheirProjection)
{
  // The pairs' own blocks of C that the iterative solver asks MUMPS for
  // (selected entries of K^{-1}) are those of the dense C; and its projected
  // blocks are those of P C P, P = I - W (W^T W)^{-1} W^T, formed densely.
  std::ostringstream           log;
  const parameters::Parameters base =
    test_support::case_parameters("block_on_plane_3d.prm");
  const auto dense =
    test_support::solved_model<3>(with_solver(base, "dense"), log);
  const auto iterative =
    test_support::solved_model<3>(with_solver(base, "iterative"), log);
  const auto                       &system = iterative->get_mixed_system();
  const dealii::FullMatrix<double> &C = dense->get_mixed_system().flexibility;
  const dealii::FullMatrix<double> &W =
    dense->get_mixed_system().rigid_coupling;
  ASSERT_EQ(W.n(), 6u);

  dealii::FullMatrix<double> WtW(6, 6), P(C.m(), C.m()), PCP(C.m(), C.m()),
    CP(C.m(), C.m());
  W.Tmmult(WtW, W);
  dealii::FullMatrix<double> WtW_inverse(6, 6), B(C.m(), 6);
  WtW_inverse.invert(WtW);
  W.mmult(B, WtW_inverse);
  B.mTmult(P, W);
  P *= -1;
  for (unsigned int i = 0; i < C.m(); ++i)
    P(i, i) += 1;
  C.mmult(CP, P);
  P.mmult(PCP, CP);

  double max_C = 0, error_C = 0, max_PCP = 0, error_PCP = 0;
  for (unsigned int p = 0; p < system.n_pairs(); ++p)
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        {
          const unsigned int a = 3 * p + i, b = 3 * p + j;
          max_C   = std::max(max_C, std::abs(C(a, b)));
          max_PCP = std::max(max_PCP, std::abs(PCP(a, b)));
          error_C =
            std::max(error_C,
                     std::abs(system.self_flexibility[p][i][j] - C(a, b)));
          error_PCP = std::max(error_PCP,
                               std::abs(system.iterative_solver()
                                          .projected_self_flexibility[p][i][j] -
                                        PCP(a, b)));
        }
  // Two computations of the same numbers from one factorisation: round-off.
  EXPECT_LT(error_C, 1e-10 * max_C);
  EXPECT_LT(error_PCP, 1e-10 * max_PCP);
  // The projection removes most of the diagonal on this free block (the
  // reason for it): the check above would pass trivially otherwise.
  EXPECT_LT(max_PCP, 0.5 * max_C);
}

TEST(IterativeMixedSystem, NoEquilibriumIsFoundToo)
{
  // A block on a plane steeper than its friction angle, without cohesion:
  // no static equilibrium at full strength, as the dense solver finds.
  parameters::Parameters parameters =
    test_support::case_parameters("inclined_block.prm");
  auto &interface          = parameters.interfaces.at("sliding surface");
  interface.cohesion       = 0;
  interface.friction_angle = 10;
  parameters.safety_factor.compute = false;
  for (const std::string solver : {"dense", "iterative"})
    {
      std::ostringstream log;
      CaseRun<2>         model(with_solver(parameters, solver), "", log);
      model.run();
      EXPECT_FALSE(model.model().get_contact_outcome().converged()) << solver;
      EXPECT_NE(model.summary()["status"], "completed") << solver;
    }
}
