// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Robustness, initial gaps (issue 7): a block whose base has a profile of
// initial normal gaps above a flat foundation, with gravity tilted by 30
// degrees so that the flat contact is an inclined plane. Gaps that close
// under gravity, gaps that stay open, a block left standing on a foot of two
// pairs, and one that tips onto a pair that was open. On a flat contact the
// safety factor is exact once the set of closed pairs is known:
//   K = (c A_closed + W cos(theta) tan(phi)) / (W sin(theta)),
// since equilibrium fixes sum f_n = -W cos(theta) and sum f_t = W sin(theta),
// and open pairs carry nothing (doc/theory.md).
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

using namespace fdem;
using dealii::numbers::PI;

namespace
{
  constexpr double block_height   = 5;
  constexpr double unit_weight    = 25;
  constexpr double inclination    = 30; // degrees, of gravity from the normal
  constexpr double friction_angle = 35;
  constexpr double cohesion       = 10;

  /**
   * Writes a Gmsh .geo file: a block over x in [0, n] whose base node at
   * x = i lies gaps[i] above the foundation's top y = 0 (straight between
   * nodes, one element per unit length, 5 across the height), on a foundation
   * [-5, n + 5] x [-5, 0]. Points of the block that touch the foundation
   * coincide with its points (Gmsh merges them).
   */
  std::string
  write_geo(const std::vector<double> &gaps, const std::string &directory)
  {
    const unsigned int n    = gaps.size() - 1;
    const std::string  file = directory + "/profile.geo";
    std::ofstream      geo(file);
    geo.precision(17);
    for (unsigned int i = 0; i <= n; ++i)
      {
        geo << "Point(" << 100 + i << ") = {" << i << ", " << gaps[i]
            << ", 0};\n";
        geo << "Point(" << 200 + i << ") = {" << i << ", " << block_height
            << ", 0};\n";
      }
    for (unsigned int k = 0; k <= n + 10; ++k)
      {
        const double x = double(k) - 5;
        geo << "Point(" << 300 + k << ") = {" << x << ", 0, 0};\n";
        geo << "Point(" << 400 + k << ") = {" << x << ", -5, 0};\n";
      }
    std::string block_cells, interface_lines, foundation_cells, base_lines;
    for (unsigned int i = 0; i <= n; ++i)
      geo << "Line(" << 1200 + i << ") = {" << 100 + i << ", " << 200 + i
          << "};\n";
    for (unsigned int i = 0; i < n; ++i)
      {
        geo << "Line(" << 1000 + i << ") = {" << 100 + i << ", " << 101 + i
            << "};\n";
        geo << "Line(" << 1100 + i << ") = {" << 200 + i << ", " << 201 + i
            << "};\n";
        geo << "Curve Loop(" << 1300 + i << ") = {" << 1000 + i << ", "
            << 1201 + i << ", -" << 1100 + i << ", -" << 1200 + i << "};\n";
        geo << "Plane Surface(" << 1300 + i << ") = {" << 1300 + i << "};\n";
        geo << "Transfinite Curve{" << 1000 + i << ", " << 1100 + i
            << "} = 2;\n";
        block_cells += (i ? ", " : "") + std::to_string(1300 + i);
        interface_lines += (i ? ", " : "") + std::to_string(1000 + i);
      }
    geo << "Transfinite Curve{1200:" << 1200 + n << "} = 6;\n";
    for (unsigned int k = 0; k <= n + 10; ++k)
      geo << "Line(" << 2200 + k << ") = {" << 400 + k << ", " << 300 + k
          << "};\n";
    for (unsigned int k = 0; k < n + 10; ++k)
      {
        geo << "Line(" << 2000 + k << ") = {" << 300 + k << ", " << 301 + k
            << "};\n";
        geo << "Line(" << 2100 + k << ") = {" << 400 + k << ", " << 401 + k
            << "};\n";
        geo << "Curve Loop(" << 2300 + k << ") = {" << 2100 + k << ", "
            << 2201 + k << ", -" << 2000 + k << ", -" << 2200 + k << "};\n";
        geo << "Plane Surface(" << 2300 + k << ") = {" << 2300 + k << "};\n";
        geo << "Transfinite Curve{" << 2000 + k << ", " << 2100 + k
            << "} = 2;\n";
        foundation_cells += (k ? ", " : "") + std::to_string(2300 + k);
        base_lines += (k ? ", " : "") + std::to_string(2100 + k);
        if (k >= 5 && k < n + 5)
          interface_lines += ", " + std::to_string(2000 + k);
      }
    geo << "Transfinite Curve{2200:" << 2200 + n + 10 << "} = 6;\n"
        << "Transfinite Surface{:};\nRecombine Surface{:};\n"
        << "Physical Surface(\"block\") = {" << block_cells << "};\n"
        << "Physical Surface(\"foundation\") = {" << foundation_cells << "};\n"
        << "Physical Curve(\"sliding surface\") = {" << interface_lines
        << "};\n"
        << "Physical Curve(\"foundation base\") = {" << base_lines << "};\n";
    return file;
  }

  /** The case of a gap profile; @p E is the block's Young's modulus, the
   * foundation's ten times it. */
  parameters::Parameters
  profile_case(const std::string         &name,
               const std::vector<double> &gaps,
               const double               E)
  {
    parameters::Parameters p;
    p.case_name          = name;
    p.output.directory   = test_support::test_directory("gaps-" + name);
    p.output.write_vtu   = false;
    p.geometry.source    = parameters::GeometryParameters::Source::mesh_file;
    p.geometry.mesh_file = write_geo(gaps, p.output.directory);
    const double theta   = inclination * PI / 180;
    p.loads.gravity_direction           = {std::sin(theta), -std::cos(theta)};
    p.block_names                       = {"block", "foundation"};
    p.materials["block"].youngs_modulus = E;
    p.materials["block"].unit_weight    = unit_weight;
    p.materials["foundation"].youngs_modulus   = 10 * E;
    p.materials["foundation"].unit_weight      = unit_weight;
    p.boundary_names                           = {"foundation base"};
    p.boundaries["foundation base"].constraint = parameters::Constraint::fixed;
    p.interface_names                          = {"sliding surface"};
    auto &interface          = p.interfaces["sliding surface"];
    interface.friction_angle = friction_angle;
    interface.cohesion       = cohesion;
    // Keeps a closed pair closed (as in the planar oracle tests): with it,
    // which pairs touch depends on the gaps alone.
    interface.tensile_strength = 1e3;
    interface.search_distance = 2 * *std::max_element(gaps.begin(), gaps.end());
    return p;
  }

  /** Weight of the block of a gap profile (trapezoidal strips). */
  double
  block_weight(const std::vector<double> &gaps)
  {
    double area = 0;
    for (unsigned int i = 0; i + 1 < gaps.size(); ++i)
      area += block_height - (gaps[i] + gaps[i + 1]) / 2;
    return unit_weight * area;
  }

  /** The planar K with cohesion on @p closed_area (formulation Sec. 5). */
  double
  planar_factor(const double weight, const double closed_area)
  {
    const double theta = inclination * PI / 180;
    return (cohesion * closed_area +
            weight * std::cos(theta) * std::tan(friction_angle * PI / 180)) /
           (weight * std::sin(theta));
  }

  /** Runs the case: the model after run(), with its log on failure. */
  std::unique_ptr<CaseRun<2>>
  run(const parameters::Parameters &p, std::ostringstream &log)
  {
    auto model = std::make_unique<CaseRun<2>>(p, "", log);
    model->run();
    // Never a NaN where a number is reported, and a converged K only from a
    // contact problem that converged.
    const auto &summary = model->summary();
    if (summary["safety_factor"].is_number())
      {
        EXPECT_TRUE(std::isfinite(summary["safety_factor"].get<double>()));
      }
    if (summary["converged"].get<bool>())
      {
        EXPECT_TRUE(model->model().get_contact_outcome().converged());
      }
    return model;
  }

  /**
   * Either the exact answer or a clear failure: no K, "converged" false, a
   * status that says there is no static equilibrium. Returns true for the
   * exact answer.
   */
  bool
  exact_or_clear_failure(const CaseRun<2>  &model,
                         const double       exact,
                         const std::string &name)
  {
    const auto &summary = model.summary();
    if (summary["status"] == "completed")
      {
        EXPECT_TRUE(summary["converged"].get<bool>()) << name;
        EXPECT_NEAR(summary["safety_factor"].get<double>(), exact, 1e-8 * exact)
          << name;
        return true;
      }
    EXPECT_FALSE(summary["converged"].get<bool>()) << name;
    EXPECT_TRUE(summary["safety_factor"].is_null()) << name;
    EXPECT_EQ(
      summary["status"].get<std::string>().rfind("no static equilibrium", 0),
      0u)
      << name << ": " << summary["status"];
    return false;
  }

  /** Tributary area of the foundation's node at x (end nodes of the interface:
   * half). */
  double
  nodal_area(const double x, const unsigned int n)
  {
    return (x == 0 || x == n) ? 0.5 : 1.0;
  }
} // namespace

namespace
{
  /** The block floating delta above the plane: every pair starts open. */
  std::unique_ptr<CaseRun<2>>
  run_uniform_gap(const double delta, std::ostringstream &log, double *exact)
  {
    const std::vector<double> gaps(11, delta);
    *exact = planar_factor(block_weight(gaps), 10);
    return run(profile_case("uniform", gaps, 1e5), log);
  }
} // namespace

// Gravity closes every gap, and the planar K with cohesion on the whole
// base (L = 10) is the answer, for gaps from far below to far above the
// elastic displacements (about 1e-3 m here). With every pair open the first
// mixed system is singular (nothing holds the free block); the status
// iteration then closes the pairs and lets tension reopen them.
TEST(RobustnessGaps, UniformGapClosesUnderGravity)
{
  for (const double delta : {1e-5, 1e-3, 0.1})
    {
      std::ostringstream log;
      double             exact = 0;
      const auto         model = run_uniform_gap(delta, log, &exact);
      ASSERT_EQ(model->summary()["status"], "completed")
        << "delta " << delta << "\n"
        << log.str();
      for (const auto &state : model->model().get_contact_outcome().states)
        EXPECT_NE(state.status, contact::PairStatus::open) << "delta " << delta;
      // Equilibrium fixes sum f_n and sum f_t: round-off only.
      EXPECT_NEAR(model->summary()["safety_factor"].get<double>(),
                  exact,
                  1e-8 * exact)
        << "delta " << delta;
    }
}

TEST(RobustnessGaps, RecessStaysOpen)
{
  // Feet on x in [0, 2] and [8, 10] touch; a 5 cm recess between them
  // (x in [3, 7], sloping to the feet) is far deeper than the block's sag
  // (stiff block, about 1e-4 m): its pairs stay open, carry exactly nothing,
  // and the cohesion acts on the feet only (A = 0.5 + 1 + 1 on each).
  const double              delta = 0.05;
  const std::vector<double> gaps  = {
     0, 0, 0, delta, delta, delta, delta, delta, 0, 0, 0};
  std::ostringstream log;
  const auto         model = run(profile_case("recess", gaps, 1e6), log);
  ASSERT_EQ(model->summary()["status"], "completed") << log.str();
  const auto &pairs = model->model().get_interfaces()[0].pairs;
  ASSERT_EQ(pairs.size(), gaps.size());
  double closed_area = 0;
  for (unsigned int k = 0; k < pairs.size(); ++k)
    {
      const double x    = pairs[k].position_J[0];
      const double gap  = gaps[std::lround(x)];
      const auto status = model->model().get_contact_outcome().states[k].status;
      EXPECT_NEAR(pairs[k].initial_gap, gap, 1e-12) << "x = " << x;
      if (gap > 0)
        {
          EXPECT_EQ(status, contact::PairStatus::open) << "x = " << x;
          EXPECT_EQ(model->model().get_contact_outcome().solution.forces[2 * k],
                    0.0)
            << "x = " << x;
          EXPECT_EQ(
            model->model().get_contact_outcome().solution.forces[2 * k + 1],
            0.0)
            << "x = " << x;
          // Still open by more than half the recess: the sag is ~1e-4 m.
          EXPECT_GT(model->model()
                      .get_contact_outcome()
                      .solution.relative_displacements[2 * k],
                    delta / 2)
            << "x = " << x;
        }
      else
        {
          EXPECT_NE(status, contact::PairStatus::open) << "x = " << x;
          closed_area += nodal_area(x, 10);
        }
    }
  EXPECT_DOUBLE_EQ(closed_area, 5.0);
  const double exact = planar_factor(block_weight(gaps), closed_area);
  EXPECT_NEAR(model->summary()["safety_factor"].get<double>(),
              exact,
              1e-8 * exact);
}

TEST(RobustnessGaps, SlidesOnAFootOfTwoPairs)
{
  // Almost no contact left: the base touches at x = 6 and 7 only, under the
  // line of action of the weight (it meets the plane at x = 5 + 2.5 tan 30 =
  // 6.44), everything else is 5 cm above the plane. At the limit the whole
  // block slides on two pairs; cohesion acts on A = 2.
  const double        delta = 0.05;
  std::vector<double> gaps(11, delta);
  gaps[6] = gaps[7] = 0;
  std::ostringstream log;
  const auto         model = run(profile_case("foot", gaps, 1e6), log);
  ASSERT_EQ(model->summary()["status"], "completed") << log.str();
  unsigned int n_closed = 0;
  for (unsigned int k = 0; k < model->model().get_interfaces()[0].pairs.size();
       ++k)
    {
      const double x =
        model->model().get_interfaces()[0].pairs[k].position_J[0];
      const bool closed =
        model->model().get_contact_outcome().states[k].status !=
        contact::PairStatus::open;
      EXPECT_EQ(closed, x == 6 || x == 7) << "x = " << x;
      n_closed += closed;
    }
  EXPECT_EQ(n_closed, 2u);
  const double exact = planar_factor(block_weight(gaps), 2);
  EXPECT_NEAR(model->summary()["safety_factor"].get<double>(),
              exact,
              1e-8 * exact);
}

namespace
{
  /** One pair touches (x = 6), every other pair is 5 cm above the plane. */
  std::unique_ptr<CaseRun<2>>
  run_tip(std::ostringstream &log, double *exact)
  {
    std::vector<double> gaps(11, 0.05);
    gaps[6] = 0;
    *exact  = planar_factor(block_weight(gaps), 2);
    return run(profile_case("tip", gaps, 1e6), log);
  }

  /** The block rests on the pairs at x = 6 and 7, and no other. */
  void
  expect_on_pairs_6_and_7(const CaseRun<2> &model)
  {
    for (unsigned int k = 0; k < model.model().get_interfaces()[0].pairs.size();
         ++k)
      {
        const double x =
          model.model().get_interfaces()[0].pairs[k].position_J[0];
        const bool closed =
          model.model().get_contact_outcome().states[k].status !=
          contact::PairStatus::open;
        EXPECT_EQ(closed, x == 6 || x == 7) << "x = " << x;
      }
  }
} // namespace

TEST(RobustnessGaps, TipsOntoAPairThatWasOpenOrFailsClearly)
{
  // One pair touches (x = 6); the weight's line of action passes 0.44 m
  // down-slope of it, so the block rotates about it onto the next pair down
  // the slope (x = 7, 5 cm gap: closed by a rotation of 0.05, before x = 8
  // which needs 0.1). The answer is the two-pair equilibrium with cohesion
  // on A = 2. A single closed pair leaves the rotation free, so the first
  // system is singular: today that ends the contact solve (the DISABLED_
  // test below), a clear failure, never a wrong K.
  std::ostringstream log;
  double             exact = 0;
  const auto         model = run_tip(log, &exact);
  if (exact_or_clear_failure(*model, exact, "tip"))
    expect_on_pairs_6_and_7(*model);
}

// Reproducer of a contact-solver limitation: with one pair closed the first
// system is singular (a free rotation about it), which solve_contact_problem()
// takes for "no static equilibrium". Run: unit_tests
// --gtest_also_run_disabled_tests --gtest_filter='RobustnessGaps.DISABLED_*'.
TEST(RobustnessGaps, DISABLED_TipsOntoAPairThatWasOpenExactly)
{
  std::ostringstream log;
  double             exact = 0;
  const auto         model = run_tip(log, &exact);
  ASSERT_EQ(model->summary()["status"], "completed") << log.str();
  expect_on_pairs_6_and_7(*model);
  EXPECT_NEAR(model->summary()["safety_factor"].get<double>(),
              exact,
              1e-8 * exact);
}
