// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Robustness (numerical stability): the planar block under conditions
// where contact solvers break. Wherever the planar oracle applies, it must
// hold; elsewhere the run must end in a converged K, a bracket or a clear
// failure, and never a NaN or a K reported as converged when the contact
// problem failed.
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace fdem;
using dealii::numbers::PI;

namespace
{
  struct Variant
  {
    std::string  name;
    double       stiffness_ratio  = 1; // E_block / E_foundation
    double       poissons_ratio   = 0.25;
    double       friction_angle   = 35;
    double       cohesion         = 10;
    double       tensile_strength = 1e3;
    double       length_scale     = 1; // 1000: the model in mm
    unsigned int n_along          = 10;
    unsigned int n_across         = 5;
  };

  /** Runs the variant; checks the outcome is well-formed; returns the summary.
   */
  nlohmann::json
  run_variant(const Variant &v, double *exact)
  {
    auto p             = test_support::case_parameters("inclined_block.prm");
    p.output.write_vtu = false;
    auto &g            = p.geometry.inclined_block;
    g.n_elements_along_length                   = v.n_along;
    g.n_elements_across_height                  = v.n_across;
    p.materials.at("block").youngs_modulus      = 1e5 * v.stiffness_ratio;
    p.materials.at("foundation").youngs_modulus = 1e5;
    for (auto &[name, m] : p.materials)
      m.poissons_ratio = v.poissons_ratio;
    auto &i            = p.interfaces.at("sliding surface");
    i.friction_angle   = v.friction_angle;
    i.cohesion         = v.cohesion;
    i.tensile_strength = v.tensile_strength;
    // Exact planar K (formulation Sec. 5), in the model's own units.
    const double theta = g.inclination * PI / 180;
    const double W     = 25.0 * g.block_length * g.block_height;
    *exact             = (v.cohesion * g.block_length +
              W * std::cos(theta) * std::tan(v.friction_angle * PI / 180)) /
             (W * std::sin(theta));
    // Units: lengths times s, forces kept: stresses / s^2, weights / s^3.
    const double s          = v.length_scale;
    p.geometry.scale_factor = s;
    for (auto &[name, m] : p.materials)
      {
        m.youngs_modulus /= s * s;
        m.unit_weight /= s * s * s;
      }
    i.cohesion /= s * s;
    i.tensile_strength /= s * s;

    std::ostringstream log;
    CaseRun<2>         model(p, "", log);
    model.run();
    const nlohmann::json &summary = model.summary();
    // Never a NaN where a number is reported.
    if (summary["safety_factor"].is_number())
      {
        EXPECT_TRUE(std::isfinite(summary["safety_factor"].get<double>()))
          << v.name;
      }
    // A converged K always comes from a contact problem that converged.
    if (summary["converged"].get<bool>())
      {
        bool any_static = false;
        for (const auto &step : summary["iterations"])
          any_static |= step["contact_result"] == "converged";
        EXPECT_TRUE(any_static) << v.name;
      }
    return summary;
  }
} // namespace

TEST(Robustness, PlanarOracleAcrossConditions)
{
  std::vector<Variant> variants;
  for (const double ratio : {1e-4, 1e-2, 1.0, 1e2, 1e4})
    variants.push_back({"stiffness ratio " + std::to_string(ratio), ratio});
  for (const double nu : {0.0, 0.3, 0.45, 0.49})
    {
      Variant v;
      v.name           = "nu " + std::to_string(nu);
      v.poissons_ratio = nu;
      variants.push_back(v);
    }
  for (const double phi : {5.0, 20.0, 45.0, 60.0})
    {
      Variant v;
      v.name           = "phi " + std::to_string(phi);
      v.friction_angle = phi;
      variants.push_back(v);
    }
  for (const double c : {0.0, 1.0, 100.0, 1e4})
    {
      Variant v;
      v.name     = "c " + std::to_string(c);
      v.cohesion = c;
      variants.push_back(v);
    }
  {
    Variant v;
    v.name         = "model in mm";
    v.length_scale = 1000;
    variants.push_back(v);
  }
  {
    Variant v;
    v.name     = "coarse mesh";
    v.n_along  = 2;
    v.n_across = 1;
    variants.push_back(v);
  }
  {
    Variant v;
    v.name     = "fine mesh";
    v.n_along  = 60;
    v.n_across = 30;
    variants.push_back(v);
  }
  for (const Variant &v : variants)
    {
      double     exact   = 0;
      const auto summary = run_variant(v, &exact);
      ASSERT_TRUE(summary["converged"].get<bool>())
        << v.name << ": " << summary["safety_factor_reason"];
      // The planar oracle holds wherever no pair opens (tensile strength on).
      EXPECT_NEAR(summary["safety_factor"].get<double>(), exact, 1e-8 * exact)
        << v.name;
    }
}

TEST(Robustness, JustBelowAndJustAboveTheLimit)
{
  // Strength set so that K = 1 lies within 1e-3 of the limit, on both sides:
  // with the initial K at 1 the first solve is just below or just above.
  for (const double offset : {-1e-3, 1e-3})
    {
      Variant v;
      v.friction_angle = 0;
      v.name           = "offset " + std::to_string(offset);
      // K = c L / (W sin 30) = 1 + offset.
      v.cohesion         = (1 + offset) * 25.0 * 10 * 5 * 0.5 / 10;
      double     exact   = 0;
      const auto summary = run_variant(v, &exact);
      ASSERT_TRUE(summary["converged"].get<bool>()) << v.name;
      EXPECT_NEAR(summary["safety_factor"].get<double>(), exact, 1e-8 * exact)
        << v.name;
    }
}

TEST(Robustness, FrictionlessPlaneHasNoEquilibrium)
{
  // phi = 0 and c = 0 on a plane: no K holds the block.
  Variant v;
  v.name             = "frictionless";
  v.friction_angle   = 0;
  v.cohesion         = 0;
  double     exact   = 0;
  const auto summary = run_variant(v, &exact);
  EXPECT_FALSE(summary["converged"].get<bool>());
  EXPECT_NE(summary["status"], "completed");
}

namespace
{
  /** The inclined block without tensile strength: its heel pair may open. */
  parameters::Parameters
  heel_case(const unsigned int n_along,
            const double       cohesion,
            const double       friction_angle,
            const double       inclination)
  {
    auto  p = test_support::case_parameters("inclined_block.prm");
    auto &g = p.geometry.inclined_block;
    g.n_elements_along_length  = n_along;
    g.n_elements_across_height = n_along / 2;
    g.inclination              = inclination;
    auto &i                    = p.interfaces.at("sliding surface");
    i.cohesion                 = cohesion;
    i.friction_angle           = friction_angle;
    i.tensile_strength         = 0;
    return p;
  }

  /**
   * The exact K for the final contact set: an open pair carries nothing and
   * loses its cohesion; a pair held at the tension cut-off keeps it
   * (doc/theory.md); equilibrium fixes sum f_n and sum f_t.
   */
  double
  planar_factor_without_open(const Model<2> &model)
  {
    const auto  &p     = model.get_parameters();
    const auto  &g     = p.geometry.inclined_block;
    const auto  &i     = p.interfaces.at("sliding surface");
    const double theta = g.inclination * PI / 180;
    const double W =
      p.materials.at("block").unit_weight * g.block_length * g.block_height;
    double closed = 0;
    for (unsigned int k = 0; k < model.get_interfaces()[0].pairs.size(); ++k)
      if (model.get_contact_outcome().states[k].status !=
          contact::PairStatus::open)
        closed += model.get_interfaces()[0].pairs[k].area;
    return (i.cohesion * closed +
            W * std::cos(theta) * std::tan(i.friction_angle * PI / 180)) /
           (W * std::sin(theta));
  }
} // namespace

TEST(Robustness, StatusCycleIsDetectedAndBroken)
{
  // The block of prm/inclined_block.prm with c = 5 kPa and no tensile
  // strength. At K = 1 its heel opens, and K* = (c (L - A_heel) + W cos 30
  // tan 35) / (W sin 30) with A_heel = 0.5. Warm-started from there, the
  // solve at that K* cycles: the heel closes (penetration) and opens again
  // (tension). The cycle must be found and broken (the heel held at the
  // tension cut-off, f_n = sigma_t A = 0, shear strength kept) and the
  // solve converge.
  std::ostringstream log;
  const auto         p     = heel_case(10, 5, 35, 30);
  auto               model = std::make_unique<Model<2>>(p, log);
  model->make_geometry();
  model->setup_blocks();
  model->assemble_and_factorize();
  model->build_interfaces();
  model->compute_flexibility();
  model->solve_contact(1.0);
  ASSERT_TRUE(model->get_contact_outcome().converged()) << log.str();
  const double W = 25.0 * 10 * 5, theta = PI / 6;
  const double K_1 =
    (5 * (10 - 0.5) + W * std::cos(theta) * std::tan(35 * PI / 180)) /
    (W * std::sin(theta));
  EXPECT_NEAR(planar_factor_without_open(*model), K_1, 1e-12 * K_1);
  model->solve_contact(K_1);
  const auto &outcome = model->get_contact_outcome();
  ASSERT_TRUE(outcome.converged()) << log.str();
  EXPECT_GT(outcome.n_cycles_broken, 0u) << log.str();
  unsigned int n_at_cutoff = 0;
  for (unsigned int k = 0; k < outcome.states.size(); ++k)
    if (outcome.states[k].at_cutoff)
      {
        ++n_at_cutoff;
        // f_n = sigma_t A = 0 exactly: the pair's row says so.
        EXPECT_NEAR(outcome.solution.forces[2 * k], 0.0, 1e-12 * W);
      }
  EXPECT_EQ(n_at_cutoff, 1u);
}

TEST(Robustness, SafetyFactorThroughStatusCyclesIsExact)
{
  // Cases (found by a sweep over c, phi, the inclination and the mesh of
  // the block without tensile strength) whose safety-factor iteration meets
  // status cycles. Each must end with the exact K of its final contact set
  // (to round-off, 1e-8), never a K from a contact problem that failed.
  struct Case
  {
    unsigned int n_along;
    double       cohesion, friction_angle, inclination;
  };
  for (const Case &c : {Case{10, 5, 35, 30},
                        Case{20, 5, 20, 30},
                        Case{20, 20, 20, 40},
                        Case{10, 20, 45, 40}})
    {
      const std::string name = std::to_string(c.n_along) + " elements, c " +
                               std::to_string(c.cohesion) + ", phi " +
                               std::to_string(c.friction_angle) + ", theta " +
                               std::to_string(c.inclination);
      std::ostringstream log;
      CaseRun<2>         model(
        heel_case(c.n_along, c.cohesion, c.friction_angle, c.inclination),
        "",
        log);
      model.run();
      EXPECT_NE(log.str().find("status cycle"), std::string::npos) << name;
      ASSERT_EQ(model.summary()["status"], "completed") << name << "\n"
                                                        << log.str();
      ASSERT_TRUE(model.model().get_contact_outcome().converged()) << name;
      const double exact = planar_factor_without_open(model.model());
      EXPECT_NEAR(model.summary()["safety_factor"].get<double>(),
                  exact,
                  1e-8 * exact)
        << name;
    }
}
