// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Load cases (doc/theory.md, "Load cases"): the assembled load plus unit
// body-force cases solved once, combined without a new factorisation.
#include "test_helpers.h"

#include <fdem/analyses/safety_factor_analysis.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace fdem;

namespace
{
  constexpr double PI = numbers::PI;

  double
  relative_difference(const Vector<double> &a, const Vector<double> &b)
  {
    Vector<double> d = a;
    d -= b;
    return d.linfty_norm() / std::max(b.linfty_norm(), 1e-300);
  }
} // namespace

TEST(LoadCases, DefaultCombinationIsTheAssembledLoadBitForBit)
{
  // Adding cases and setting (1, {}) or (1, {0, 0}) must leave g_bar and
  // omega^T F exactly as assembled: the verified results cannot move.
  std::ostringstream log;
  auto               model = test_support::factorised_model<2>(
    test_support::case_parameters("inclined_block.prm"), log);
  const Vector<double> gap   = model->get_mixed_system().external_gap;
  const Vector<double> rigid = model->get_mixed_system().rigid_loads;
  const auto           cases = model->body_force_cases(false);
  ASSERT_EQ(cases.size(), 2u);
  model->set_load_combination(1, {0, 0});
  for (unsigned int i = 0; i < gap.size(); ++i)
    ASSERT_EQ(model->get_mixed_system().external_gap[i], gap[i]);
  for (unsigned int i = 0; i < rigid.size(); ++i)
    ASSERT_EQ(model->get_mixed_system().rigid_loads[i], rigid[i]);
}

TEST(LoadCases, GravityIsTheCombinationOfTheBodyForceCases)
{
  // The assembled load of a model without surface loads is its gravity:
  // 0 x base + g_d x case d must give the same g_bar, omega^T F and block
  // loads, to round-off (the same quadrature, summed in another order).
  for (const char *name : {"inclined_block.prm", "paper_slope.prm"})
    {
      std::ostringstream log;
      auto               model =
        test_support::factorised_model<2>(test_support::case_parameters(name),
                                          log);
      const auto          gap   = model->get_mixed_system().external_gap;
      const auto          rigid = model->get_mixed_system().rigid_loads;
      const auto          load  = model->get_blocks()[0]->load_vector;
      const auto          cases = model->body_force_cases(true);
      std::vector<double> c(2);
      for (unsigned int d = 0; d < 2; ++d)
        c[cases[d]] = model->get_parameters().loads.gravity_direction[d];
      model->set_load_combination(0, c);
      EXPECT_LT(relative_difference(model->get_mixed_system().external_gap,
                                    gap),
                1e-12)
        << name;
      EXPECT_LT(relative_difference(model->get_mixed_system().rigid_loads,
                                    rigid),
                1e-12)
        << name;
      EXPECT_LT(relative_difference(model->get_blocks()[0]->load_vector, load),
                1e-12)
        << name;
    }
}

TEST(LoadCases, UnitWeightFactorOnTheInclinedBlock)
{
  // A factor lambda on the unit weight: K = (c L + lambda W cos(theta)
  // tan(phi)) / (lambda W sin(theta)) (the planar limit of
  // doc/theory.md with the weight lambda W), to round-off:
  // 1e-10. A tensile strength keeps the heel closed (as in
  // PlanarSlidingSurface.ExactForAnyMeshAndMaterial).
  auto parameters = test_support::case_parameters("inclined_block.prm");
  parameters.interfaces.at("sliding surface").tensile_strength = 1e3;
  std::ostringstream log;
  auto               model = test_support::factorised_model<2>(parameters, log);
  const auto         cases = model->body_force_cases(true);
  const auto        &geometry = parameters.geometry.inclined_block;
  const double theta = geometry.inclination * PI / 180, phi = 35 * PI / 180,
               c = 10;
  const double W = 25 * geometry.block_length * geometry.block_height;
  for (const double lambda : {1.0, 0.5, 2.0})
    {
      std::vector<double> coefficients(2);
      for (unsigned int d = 0; d < 2; ++d)
        coefficients[cases[d]] =
          (lambda - 1) * parameters.loads.gravity_direction[d];
      model->set_load_combination(1, coefficients);
      model->forget_warm_start();
      const analyses::Result result =
        analyses::SafetyFactorAnalysis<2>(*model).run();
      ASSERT_TRUE(result.converged) << result.reason;
      const double exact = (c * geometry.block_length +
                            lambda * W * std::cos(theta) * std::tan(phi)) /
                           (lambda * W * std::sin(theta));
      EXPECT_NEAR(result.safety_factor, exact, 1e-10 * exact)
        << "lambda " << lambda;
    }
}
