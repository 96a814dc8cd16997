// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Heavy robustness variants (ctest label "heavy", left out of the default run:
// `ctest -L heavy` or `bash bootstrap.sh heavy`): the planar oracle on fine
// 2D meshes and on 3D blocks across stiffness contrast and Poisson's ratio.
// Each checks K against the exact planar value
//   K = (c A + W cos(theta) tan(phi)) / (W sin(theta)),
// to round-off (1e-8 relative): equilibrium fixes sum f_n and sum f_t, so no
// discretisation error enters while no pair opens (doc/theory.md
//; a tensile strength keeps the heel closed).
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

using namespace fdem;
using dealii::numbers::PI;

namespace
{
  /** The summary of a run; a converged K comes only from a converged contact
   * problem. */
  template <int dim>
  nlohmann::json
  run(const parameters::Parameters &p)
  {
    std::ostringstream log;
    CaseRun<dim>       model(p, "", log);
    model.run();
    if (model.summary()["converged"].template get<bool>())
      {
        EXPECT_TRUE(model.model().get_contact_outcome().converged());
      }
    return model.summary();
  }
} // namespace

TEST(RobustnessHeavy, PlanarOracleOnFineMeshes2D)
{
  struct Variant
  {
    unsigned int degree, n_along, n_across;
    double       stiffness_ratio; // E_block / E_foundation
  };
  for (const Variant &v : {Variant{1, 120, 60, 0.1},
                           Variant{2, 60, 30, 0.1},
                           Variant{2, 40, 20, 1e-4},
                           Variant{2, 40, 20, 1e4}})
    {
      auto p      = test_support::case_parameters("inclined_block.prm");
      p.fe_degree = v.degree;
      auto &g     = p.geometry.inclined_block;
      g.n_elements_along_length  = v.n_along;
      g.n_elements_across_height = v.n_across;
      p.materials.at("block").youngs_modulus =
        v.stiffness_ratio * p.materials.at("foundation").youngs_modulus;
      auto &i            = p.interfaces.at("sliding surface");
      i.tensile_strength = 1e3;
      const double theta = g.inclination * PI / 180;
      const double W =
        p.materials.at("block").unit_weight * g.block_length * g.block_height;
      const double exact =
        (i.cohesion * g.block_length +
         W * std::cos(theta) * std::tan(i.friction_angle * PI / 180)) /
        (W * std::sin(theta));
      const auto        summary = run<2>(p);
      const std::string name    = "Q" + std::to_string(v.degree) + " " +
                               std::to_string(v.n_along) + "x" +
                               std::to_string(v.n_across) + " ratio " +
                               std::to_string(v.stiffness_ratio);
      ASSERT_EQ(summary["status"], "completed")
        << name << ": " << summary["safety_factor_reason"];
      EXPECT_NEAR(summary["safety_factor"].get<double>(), exact, 1e-8 * exact)
        << name;
    }
}

TEST(RobustnessHeavy, PlanarOracleOnThreeDBlocks)
{
  // The built-in 3D block on a plane dipping 30 degrees towards 120: a
  // 10 x 6 x 5 block, phi = 30, c = 15 kPa, A = 60.
  struct Variant
  {
    double       stiffness_ratio, poissons_ratio;
    unsigned int n_along, n_width, n_height;
  };
  for (const Variant &v : {Variant{1e-2, 0.25, 10, 6, 5},
                           Variant{1e2, 0.25, 10, 6, 5},
                           Variant{0.1, 0.45, 10, 6, 5},
                           Variant{0.1, 0.25, 20, 12, 10}})
    {
      const std::string name =
        "ratio " + std::to_string(v.stiffness_ratio) + ", nu " +
        std::to_string(v.poissons_ratio) + ", " + std::to_string(v.n_along) +
        "x" + std::to_string(v.n_width) + "x" + std::to_string(v.n_height);
      const std::filesystem::path directory =
        test_support::test_directory("heavy-3d");
      const std::string prm = (directory / "block_on_plane.prm").string();
      std::ofstream(prm)
        << "set Dimension = 3\n"
        << "subsection Geometry\n  set Source = block on plane\n"
        << "  subsection Block on plane\n"
        << "    set Dip = 30\n    set Dip direction = 120\n"
        << "    set Elements along length = " << v.n_along << "\n"
        << "    set Elements along width = " << v.n_width << "\n"
        << "    set Elements across height = " << v.n_height << "\n"
        << "  end\nend\n"
        << "subsection Blocks\n  set Names = block, foundation\n"
        << "  subsection block\n    set Young's modulus = "
        << 1e6 * v.stiffness_ratio
        << "\n    set Poisson's ratio = " << v.poissons_ratio
        << "\n    set Unit weight = 25\n  end\n"
        << "  subsection foundation\n    set Young's modulus = 1e6"
        << "\n    set Poisson's ratio = " << v.poissons_ratio
        << "\n    set Unit weight = 25\n  end\nend\n"
        << "subsection Boundaries\n  set Names = foundation base\n"
        << "  subsection foundation base\n    set Constraint = fixed\n  end\nend\n"
        << "subsection Interfaces\n  set Names = sliding surface\n"
        << "  subsection sliding surface\n    set Friction angle = 30\n"
        << "    set Cohesion = 15\n    set Tensile strength = 1e3\n  end\nend\n"
        << "subsection Output\n  set Directory = "
        << (directory / "output").string()
        << "\n  set Write VTU = false\nend\n";
      const auto   p = parameters::read_parameters(prm);
      const double W = 25.0 * 10 * 6 * 5, dip = PI / 6;
      const double exact =
        (15 * 60 + W * std::cos(dip) * std::tan(PI / 6)) / (W * std::sin(dip));
      const auto summary = run<3>(p);
      ASSERT_EQ(summary["status"], "completed")
        << name << ": " << summary["safety_factor_reason"];
      EXPECT_NEAR(summary["safety_factor"].get<double>(), exact, 1e-8 * exact)
        << name;
    }
}
