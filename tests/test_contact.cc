// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The contact module with statuses (doc/theory.md): Hertz
// contact against the exact solution, the block on an inclined plane above
// and below its limit, and the ends of the status iteration.
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace fdem;

namespace
{
  /** The block on the inclined plane with strength c, phi. */
  parameters::Parameters
  inclined_block(const double cohesion, const double friction_angle)
  {
    auto parameters = test_support::case_parameters("inclined_block.prm");
    parameters.interfaces.at("sliding surface").cohesion       = cohesion;
    parameters.interfaces.at("sliding surface").friction_angle = friction_angle;
    return parameters;
  }
} // namespace

TEST(Hertz, BetterThanThePaperAndWithinTheConvergedAccuracy)
{
  std::ostringstream log;
  CaseRun<2>         model(test_support::case_parameters("hertz.prm"), "", log);
  model.run();
  ASSERT_EQ(model.summary()["status"], "completed");
  const auto  &hertz = model.summary()["hertz"];
  const double a = hertz["contact_half_width"], q = hertz["max_pressure"];
  // The paper's data (Liu et al. 2012, example 4.A): theory a = 6.808 mm,
  // q_max = 1870.277 N/mm^2; the paper got a = 6.63, q_max = 1881.25.
  EXPECT_NEAR(hertz["contact_half_width_exact"].get<double>(), 6.808, 0.0005);
  EXPECT_NEAR(hertz["max_pressure_exact"].get<double>(), 1870.277, 0.05);
  EXPECT_LT(std::abs(a - 6.808), std::abs(6.63 - 6.808));
  EXPECT_LT(std::abs(q - 1870.277), std::abs(1881.25 - 1870.277));
  // The convergence study (doc/hertz_convergence.md) measures -0.087 % and
  // +0.020 % on this mesh and smaller errors on finer ones: these bounds
  // leave room for round-off, not for a regression.
  EXPECT_LT(std::abs(hertz["contact_half_width_error"].get<double>()), 2e-3);
  EXPECT_LT(std::abs(hertz["max_pressure_error"].get<double>()), 5e-4);
  // The whole pressure profile follows q_max sqrt(1 - (x/a)^2). A nodal
  // pressure f/A carries a lumping error of order h^2 q'', and q'' grows like
  // (1 - x^2/a^2)^(-3/2) towards the edge: measured on this mesh, below
  // 0.08 % of q_max inside 0.75 a and 0.27 % inside 0.95 a. Bounds: 0.15 %
  // and 0.5 %.
  const auto  &interface = model.model().get_interfaces()[0];
  const double a_exact   = hertz["contact_half_width_exact"];
  const double q_exact   = hertz["max_pressure_exact"];
  unsigned int n_checked = 0;
  for (unsigned int k = 0; k < interface.pairs.size(); ++k)
    {
      const double x = interface.pairs[k].position_J[0];
      if (x > 0.95 * a_exact)
        continue;
      const double f_n =
        model.model().get_contact_outcome().solution.forces[2 * k];
      const double q_k = -f_n / interface.pairs[k].area;
      EXPECT_NEAR(q_k,
                  q_exact * std::sqrt(1 - std::pow(x / a_exact, 2)),
                  (x < 0.75 * a_exact ? 1.5e-3 : 5e-3) * q_exact)
        << "at x = " << x;
      ++n_checked;
    }
  EXPECT_GT(n_checked, 40u);
}

TEST(InclinedBlock, ContactForcesBalanceTheWeightExactly)
{
  std::ostringstream log;
  const auto model = test_support::solved_model<2>(inclined_block(10, 35), log);
  ASSERT_TRUE(model->get_contact_outcome().converged());
  const auto          &interface = model->get_interfaces()[0];
  dealii::Tensor<1, 2> total;
  for (unsigned int k = 0; k < interface.pairs.size(); ++k)
    {
      dealii::Tensor<1, 2> local;
      for (unsigned int d = 0; d < 2; ++d)
        local[d] = model->get_contact_outcome().solution.forces[2 * k + d];
      total += transpose(interface.pairs[k].frame) * local;
    }
  // The block (10 m x 5 m, 25 kN/m^3) rests on the plane only: what it
  // exerts on the foundation is its weight, 1250 kN/m straight down.
  const double weight = 25.0 * 10 * 5;
  EXPECT_NEAR(total[0], 0.0, 1e-10 * weight);
  EXPECT_NEAR(total[1], -weight, 1e-10 * weight);
}

TEST(InclinedBlock, BelowTheLimitThereIsNoEquilibrium)
{
  // Plane at 30 degrees, phi = 20 degrees: the limit cohesion is
  // (W sin 30 - W cos 30 tan 20) / L = 23.1 kPa (formulation Sec. 5).
  for (const double cohesion : {0.0, 20.0})
    {
      std::ostringstream log;
      const auto         model =
        test_support::solved_model<2>(inclined_block(cohesion, 20), log);
      EXPECT_FALSE(model->get_contact_outcome().converged())
        << "c = " << cohesion;
      EXPECT_TRUE(model->get_contact_outcome().result ==
                    contact::ContactResult::singular ||
                  model->get_contact_outcome().result ==
                    contact::ContactResult::runaway)
        << contact::result_description(model->get_contact_outcome().result);
      // A mechanism, not a numerical breakdown (doc/theory.md).
      EXPECT_TRUE(model->get_contact_outcome().is_mechanism());
    }
  std::ostringstream log;
  const auto model = test_support::solved_model<2>(inclined_block(30, 20), log);
  EXPECT_TRUE(model->get_contact_outcome().converged())
    << contact::result_description(model->get_contact_outcome().result);
}

TEST(StatusIteration, StopsAtTheIterationLimit)
{
  auto parameters = test_support::case_parameters("hertz.prm");
  parameters.contact.max_status_iterations = 2;
  std::ostringstream log;
  const auto         model = test_support::solved_model<2>(parameters, log);
  EXPECT_EQ(model->get_contact_outcome().result,
            contact::ContactResult::iteration_limit);
  EXPECT_EQ(model->get_contact_outcome().iterations.size(), 2u);
  EXPECT_FALSE(model->get_contact_outcome().is_mechanism());
}

TEST(CattaneoMindlin, StickZoneAndTangentialTractions)
{
  // Cattaneo-Mindlin (Johnson 1985, Sec. 7.1): stick for |x| < c =
  // a sqrt(1 - Q/(mu P)); q_t = mu q_max (sqrt(1 - x^2/a^2) -
  // (c/a) sqrt(1 - x^2/c^2)) in the stick zone, mu q in the slip zones.
  for (const double ratio : {0.5, 0.8})
    {
      auto parameters = test_support::case_parameters("cattaneo_mindlin.prm");
      const double P = 2000, mu = 0.3, Q = ratio * mu * P, r = 1000;
      parameters.boundaries.at("load").traction =
        std::to_string(Q / (2 * r)) + "; 0";
      std::ostringstream log;
      const auto         model = test_support::solved_model<2>(parameters, log);
      ASSERT_TRUE(model->get_contact_outcome().converged());

      const double E_star = 1e5 / (2 * (1 - 0.3 * 0.3));
      const double a = std::sqrt(4 * P * r / (dealii::numbers::PI * E_star));
      const double q_max           = 2 * P / (dealii::numbers::PI * a);
      const double c               = a * std::sqrt(1 - ratio);
      const auto  &pairs           = model->get_interfaces()[0].pairs;
      const double spacing         = 15.0 / 60;
      double       outermost_stick = 0, innermost_slip = a, worst = 0;
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          const double x      = pairs[k].position_J[0];
          const auto   status = model->get_contact_outcome().states[k].status;
          if (status == contact::PairStatus::stick)
            outermost_stick = std::max(outermost_stick, std::abs(x));
          if (status == contact::PairStatus::slip)
            innermost_slip = std::min(innermost_slip, std::abs(x));
          if (std::abs(x) < 0.9 * a)
            {
              const double q_t =
                std::abs(
                  model->get_contact_outcome().solution.forces[2 * k + 1]) /
                pairs[k].area;
              const double exact =
                mu * q_max * std::sqrt(1 - x * x / (a * a)) -
                (std::abs(x) < c ?
                   mu * q_max * c / a * std::sqrt(1 - x * x / (c * c)) :
                   0);
              worst = std::max(worst, std::abs(q_t - exact) / (mu * q_max));
            }
        }
      // The stick-slip boundary lies between two pairs: the last stick pair
      // and the first slip pair bracket c, each within one pair spacing.
      EXPECT_LE(outermost_stick, c) << "Q/(mu P) = " << ratio;
      EXPECT_GT(outermost_stick, c - spacing) << "Q/(mu P) = " << ratio;
      EXPECT_GE(innermost_slip, c) << "Q/(mu P) = " << ratio;
      EXPECT_LT(innermost_slip, c + spacing) << "Q/(mu P) = " << ratio;
      // Tangential tractions: the theory drops terms of order (a/r)/mu =
      // 2.3 %; measured 5.1 % (Q/(mu P) = 0.5). Bound: 8 % of mu q_max.
      EXPECT_LT(worst, 0.08) << "Q/(mu P) = " << ratio;
    }
}

TEST(CondensedPair, ForceRowsEliminatedExactly)
{
  // condense_force_rows(): f = particular + N y satisfies the pair's force
  // rows for every y, N is orthonormal and orthogonal to them, and as many
  // rows are kept as N has columns. Each 3D state of pair_rows(): stick (no
  // force row), slip with a turning weight (one: the limit along d), slip
  // with weight 0 (two), slip at the cut-off (two), open (three).
  // Round-off of a few operations on numbers of a few units: 1e-14 for the
  // unit basis, 1e-13 for the rows (values up to 3.5).
  contact::PairStrength strength;
  strength.friction_coefficient = 0.7;
  strength.cohesion_force       = 3.5;
  strength.tensile_force        = 1.25;
  dealii::Tensor<2, 3> self_flexibility;
  for (unsigned int i = 0; i < 3; ++i)
    self_flexibility[i][i] = 2.0 + i;
  std::vector<std::pair<contact::PairState<3>, unsigned int>> cases;
  contact::PairState<3>                                       state;
  cases.emplace_back(state, 3u);
  state.status           = contact::PairStatus::slip;
  state.slip_direction   = {{0.6, -0.8}};
  state.direction_weight = 0.4;
  cases.emplace_back(state, 2u);
  state.direction_weight = 0;
  cases.emplace_back(state, 1u);
  state.direction_weight = 0.4;
  state.at_cutoff        = true;
  cases.emplace_back(state, 1u);
  state.status = contact::PairStatus::open;
  cases.emplace_back(state, 0u);
  for (const auto &[pair_state, n_free] : cases)
    {
      const contact::PairRows<3> rows =
        contact::pair_rows(pair_state, strength, self_flexibility, 0.0);
      const contact::CondensedPair<3> condensed =
        contact::condense_force_rows(rows);
      ASSERT_EQ(condensed.n_free, n_free);
      for (unsigned int t = 0; t < n_free; ++t)
        for (unsigned int s = 0; s < n_free; ++s)
          {
            double product = 0;
            for (unsigned int k = 0; k < 3; ++k)
              product += condensed.basis[k][t] * condensed.basis[k][s];
            EXPECT_NEAR(product, t == s ? 1.0 : 0.0, 1e-14);
          }
      std::vector<bool> kept(3, false);
      for (unsigned int m = 0; m < n_free; ++m)
        {
          kept[condensed.kept_rows[m]] = true;
          EXPECT_GT(rows.gap[condensed.kept_rows[m]].norm(), 0);
        }
      for (unsigned int i = 0; i < 3; ++i)
        if (!kept[i])
          {
            // f = particular + sum_t y_t N_t with y = (1, -2): the row holds.
            dealii::Tensor<1, 3> f = condensed.particular;
            for (unsigned int t = 0; t < n_free; ++t)
              for (unsigned int k = 0; k < 3; ++k)
                f[k] += (t == 0 ? 1.0 : -2.0) * condensed.basis[k][t];
            EXPECT_NEAR(rows.force[i] * f, rows.value[i], 1e-13);
          }
    }
}

TEST(PairRows, SlipAlongAHeldTangent)
{
  // A 3D pair on the rollers of a side has a tangent held on both sides
  // (zero self-flexibility): its force there is zero and it slips along the
  // other tangent, at the limit by the sign of d. The linearised rows gave
  // the turning row (1 - alpha) e . f_t - alpha r e . g_t = 0 instead: with
  // alpha = 1 and d along the free tangent (measured on the cylinder on
  // tetrahedra: d = (5.7e-13, 1)) a row on the held gap alone, zero in the
  // mixed system. Every state below must have independent force rows and
  // no gap row on a held direction.
  contact::PairStrength strength;
  strength.friction_coefficient = 0.3;
  strength.cohesion_force       = 2.5;
  contact::PairState<3> state;
  state.status           = contact::PairStatus::slip;
  state.direction_weight = 1;
  for (const unsigned int held : {1u, 2u})
    for (const double sign : {1.0, -1.0})
      {
        const unsigned int   free = 3 - held;
        dealii::Tensor<2, 3> self_flexibility;
        self_flexibility[0][0]         = 2;
        self_flexibility[free][free]   = 3;
        state.slip_direction[free - 1] = sign;
        state.slip_direction[held - 1] = 5.7e-13;
        const contact::PairRows<3> rows =
          contact::pair_rows(state, strength, self_flexibility, 1e-12);
        EXPECT_EQ(rows.gap[0][0], 1); // g_n = 0
        EXPECT_EQ(rows.gap[held].norm(), 0);
        EXPECT_EQ(rows.gap[free].norm(), 0);
        // f_held = 0.
        dealii::Tensor<1, 3> unit;
        unit[held] = 1;
        EXPECT_EQ(rows.force[held], unit);
        EXPECT_EQ(rows.value[held], 0);
        // f_free = d (c A - mu f_n), d = +-1.
        dealii::Tensor<1, 3> limit;
        limit[free] = 1;
        limit[0]    = sign * strength.friction_coefficient;
        EXPECT_EQ(rows.force[free], limit);
        EXPECT_EQ(rows.value[free], sign * strength.cohesion_force);
        EXPECT_EQ(contact::condense_force_rows(rows).n_free, 1u);
      }
  // Both tangents held: no tangential force, as a sticking pair there.
  dealii::Tensor<2, 3> self_flexibility;
  self_flexibility[0][0] = 2;
  const contact::PairRows<3> rows =
    contact::pair_rows(state, strength, self_flexibility, 1e-12);
  for (unsigned int i = 1; i < 3; ++i)
    {
      dealii::Tensor<1, 3> unit;
      unit[i] = 1;
      EXPECT_EQ(rows.force[i], unit);
      EXPECT_EQ(rows.gap[i].norm(), 0);
      EXPECT_EQ(rows.value[i], 0);
    }
}
