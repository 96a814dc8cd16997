// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Scale-free decisions (doc/theory.md): the rigid-mode test that decides
// "no static equilibrium" on a block on a flat plane, in two sets of units;
// a model with a common Young's modulus from 1e-8 to 1e14; the dense
// solver's verdict on a nearly singular but solvable system; and what
// ContactOutcome::is_mechanism() says. The runs in other units are
// tests/invariance/*.prm (run_checks.py invariance).
#include "../test_helpers.h"

#include <fdem/contact/scaling.h>
#include <fdem/contact/status_iteration.h>
#include <fdem/linear_algebra/reusable_lu.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace fdem;
using dealii::FullMatrix;
using dealii::Tensor;
using dealii::Vector;

namespace
{
  /**
   * A 2D block on the plane y = 0 touching it at x = -1, 0, 1 (local frame
   * n = e_y, t = e_x), free in x, y and rotation, loaded by its weight
   * (1 force unit) leaning down the slope. Lengths are multiplied by
   * @p length and forces by @p force: the same model in other units.
   */
  struct FlatBlock
  {
    FullMatrix<double>    W     = FullMatrix<double>(6, 3);
    Vector<double>        loads = Vector<double>(3);
    contact::SystemScales scales;

    FlatBlock(const double length, const double force)
    {
      const double x[3] = {-length, 0, length};
      for (unsigned int p = 0; p < 3; ++p)
        {
          W(2 * p + 1, 0) = 1;    // translation along x: tangential
          W(2 * p, 1)     = 1;    // translation along y: normal
          W(2 * p, 2)     = x[p]; // rotation about the origin: normal
        }
      loads[0]            = 0.3 * force;
      loads[1]            = -1.0 * force;
      loads[2]            = 0.1 * force * length;
      scales.force        = 3 * force;
      scales.flexibility  = 1e-7 * length / force;
      scales.displacement = scales.force * scales.flexibility;
      scales.rigid        = {1, 1, length};
    }

    contact::RigidModeTest
    test(const contact::PairStatus status,
         const unsigned int        n_in_state,
         const double              force) const
    {
      std::vector<contact::PairRows<2>> rows;
      contact::PairStrength             strength;
      strength.friction_coefficient = 0.5;
      strength.cohesion_force       = 0.01 * force;
      for (unsigned int p = 0; p < 3; ++p)
        {
          contact::PairState<2> state;
          state.status = p < n_in_state ? status : contact::PairStatus::open;
          state.slip_direction[0] = 1;
          rows.push_back(contact::pair_rows(
            state,
            strength,
            Tensor<2, 2>(dealii::unit_symmetric_tensor<2>()) *
              scales.flexibility,
            0.0));
        }
      return contact::rigid_mode_test(W, loads, rows, scales, 1e-10);
    }
  };
} // namespace

TEST(ScaleFree, RigidModeTestIsAStatementAboutMechanics)
{
  for (const auto &[length, force] : std::vector<std::pair<double, double>>{
         {1, 1}, {1000, 1000}, {3.28084, 224.809}})
    {
      const FlatBlock block(length, force);
      // Three pairs stuck: held.
      const auto stick = block.test(contact::PairStatus::stick, 3, force);
      EXPECT_TRUE(stick.holds);
      // Every pair slipping on a plane: normal and tangential equilibrium
      // are one equation (sum f_t = -mu sum f_n + c A), the weight's two
      // components another two: no equilibrium, and nothing resists the
      // slide along x.
      const auto slip = block.test(contact::PairStatus::slip, 3, force);
      EXPECT_FALSE(slip.holds);
      EXPECT_LT(slip.equilibrium_ratio, 1e-14);
      EXPECT_LT(slip.kinematic_ratio, 1e-14);
      EXPECT_GT(slip.unbalanced_load, 0.1);
      // One pair stuck, two open: a free rotation about it.
      const auto one = block.test(contact::PairStatus::stick, 1, force);
      EXPECT_FALSE(one.holds);
      EXPECT_EQ(one.kinematic_ratio, 0);
      // Every pair open: nothing at all.
      EXPECT_FALSE(block.test(contact::PairStatus::open, 3, force).holds);

      // The numbers do not depend on the units.
      const FlatBlock reference(1, 1);
      const auto stick_ref = reference.test(contact::PairStatus::stick, 3, 1);
      EXPECT_NEAR(stick.equilibrium_ratio,
                  stick_ref.equilibrium_ratio,
                  1e-12 * stick_ref.equilibrium_ratio);
      EXPECT_NEAR(stick.kinematic_ratio,
                  stick_ref.kinematic_ratio,
                  1e-12 * stick_ref.kinematic_ratio);
    }
}

// The inclined block with a common Young's modulus from 1e-8 to 1e14 (kPa):
// C and g_bar scale by 1/E, the forces do not. The same statuses and the
// same contact forces to round-off; before the scale-free decisions the
// extremes were "singular system: no static equilibrium".
TEST(ScaleFree, CommonModulusChangesNothingButDisplacements)
{
  std::vector<double> reference_forces;
  std::string         reference_statuses;
  for (const double E : {1e4, 1e-8, 1e-2, 1e8, 1e14})
    {
      auto parameters = test_support::case_parameters("inclined_block.prm");
      for (auto &[name, material] : parameters.materials)
        material.youngs_modulus = E;
      std::ostringstream log;
      const auto         model = test_support::solved_model<2>(parameters, log);
      ASSERT_TRUE(model->get_contact_outcome().converged())
        << "E = " << E << ": "
        << contact::result_description(model->get_contact_outcome().result);
      std::string statuses;
      for (const auto &state : model->get_contact_outcome().states)
        statuses += contact::status_name(state.status)[1];
      const Vector<double> &f = model->get_contact_outcome().solution.forces;
      if (reference_forces.empty())
        {
          reference_forces.assign(f.begin(), f.end());
          reference_statuses = statuses;
          continue;
        }
      EXPECT_EQ(statuses, reference_statuses) << "E = " << E;
      double largest = 0;
      for (const double value : reference_forces)
        largest = std::max(largest, std::abs(value));
      for (unsigned int i = 0; i < f.size(); ++i)
        EXPECT_NEAR(f[i], reference_forces[i], 1e-9 * largest)
          << "E = " << E << ", force " << i;
    }
}

// An ill-conditioned system (reciprocal condition about 1e-15, well above
// the unit round-off) is solved and refined to its backward error, not
// declared singular as the old threshold of 1e-14 did; a system singular
// to working precision (two equal rows) is not solved.
TEST(ScaleFree, IllConditionedIsRefinedNotFailed)
{
  const unsigned int                     n = 40;
  std::mt19937                           random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  // A = Q1 diag(sigma) Q2 with sigma from 1 down to 1e-14: orthogonal Q1,
  // Q2 from Gram-Schmidt of random matrices.
  const auto orthogonal = [&]() {
    FullMatrix<double> Q(n, n);
    for (unsigned int j = 0; j < n; ++j)
      {
        Vector<double> v(n);
        for (unsigned int i = 0; i < n; ++i)
          v[i] = uniform(random);
        for (unsigned int k = 0; k < j; ++k)
          {
            double c = 0;
            for (unsigned int i = 0; i < n; ++i)
              c += Q(i, k) * v[i];
            for (unsigned int i = 0; i < n; ++i)
              v[i] -= c * Q(i, k);
          }
        const double norm = v.l2_norm();
        for (unsigned int i = 0; i < n; ++i)
          Q(i, j) = v[i] / norm;
      }
    return Q;
  };
  const FullMatrix<double> Q1 = orthogonal(), Q2 = orthogonal();
  FullMatrix<double>       A(n, n);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int k = 0; k < n; ++k)
        A(i, j) += Q1(i, k) * std::pow(10.0, -14.0 * k / (n - 1)) * Q2(j, k);
  Vector<double> x_exact(n), b(n);
  for (unsigned int i = 0; i < n; ++i)
    x_exact[i] = uniform(random);
  A.vmult(b, x_exact);

  linear_algebra::ReusableLU lu;
  Vector<double>             x      = b;
  const auto                 result = lu.solve(A, x);
  EXPECT_LT(result.reciprocal_condition, 1e-14);
  EXPECT_TRUE(result.solved) << "rcond " << result.reciprocal_condition;
  EXPECT_LE(result.backward_error, lu.control.backward_error_tolerance);

  FullMatrix<double> singular = A;
  for (unsigned int j = 0; j < n; ++j)
    singular(1, j) = singular(0, j);
  linear_algebra::ReusableLU fresh;
  Vector<double>             y = b;
  EXPECT_FALSE(fresh.solve(singular, y).solved);
}

TEST(ScaleFree, MechanismOrNumericalBreakdown)
{
  contact::ContactOutcome<2> outcome;
  for (const auto result :
       {contact::ContactResult::singular, contact::ContactResult::runaway})
    {
      outcome.result = result;
      EXPECT_TRUE(outcome.is_mechanism());
      EXPECT_NE(contact::result_description(result).find("mechanism"),
                std::string::npos);
    }
  for (const auto result : {contact::ContactResult::converged,
                            contact::ContactResult::iteration_limit,
                            contact::ContactResult::numerical_breakdown})
    {
      outcome.result = result;
      EXPECT_FALSE(outcome.is_mechanism());
    }
  const std::string breakdown =
    contact::result_description(contact::ContactResult::numerical_breakdown);
  EXPECT_EQ(breakdown.find("no static equilibrium"), std::string::npos);
  EXPECT_NE(breakdown.find("not a mechanism"), std::string::npos);
}
