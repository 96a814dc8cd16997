// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// 3D: the same code on hexahedral blocks with six rigid modes and two
// tangential directions.
#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace fdem;
using dealii::numbers::PI;

namespace
{
  /**
   * tests/data/block_on_plane_3d.geo: a 10 x 6 x 5 block on a slab; gravity
   * tilted by the dip towards the dip direction makes the horizontal
   * contact an inclined plane whose dip direction is off the axes.
   */
  parameters::Parameters
  block_on_plane(const double dip, const double dip_direction, const double phi,
                 const double cohesion)
  {
    parameters::Parameters p;
    p.dimension                = 3;
    p.case_name                = "block_on_plane_3d";
    p.geometry.source          = parameters::GeometryParameters::Source::mesh_file;
    p.geometry.mesh_file       = std::string(FDEM_SOURCE_DIR) + "/tests/data/block_on_plane_3d.geo";
    p.geometry.translation     = {0, 0, 0};
    const double d = dip * PI / 180, a = dip_direction * PI / 180;
    // Gravity in the frame of the slab: the slab's plane dips by d towards a.
    p.loads.gravity_direction = {std::sin(d) * std::sin(a), std::sin(d) * std::cos(a), -std::cos(d)};
    p.block_names             = {"block", "foundation"};
    p.materials["block"].youngs_modulus      = 1e5;
    p.materials["block"].unit_weight         = 25;
    p.materials["foundation"].youngs_modulus = 1e6;
    p.materials["foundation"].unit_weight    = 25;
    p.boundary_names                          = {"foundation base"};
    p.boundaries["foundation base"].constraint = parameters::Constraint::fixed;
    p.interface_names                          = {"sliding surface"};
    auto &interface                            = p.interfaces["sliding surface"];
    interface.friction_angle                   = phi;
    interface.cohesion                         = cohesion;
    interface.tensile_strength                 = 1e3;
    p.output.directory = (std::filesystem::temp_directory_path() / "fdem-test-3d").string();
    p.output.write_vtu = false;
    std::filesystem::create_directories(p.output.directory);
    return p;
  }
} // namespace

TEST(ThreeD, FreeBlockHasSixRigidModes)
{
  std::ostringstream log;
  Model<3>           model(block_on_plane(30, 120, 35, 0), "", log);
  model.make_geometry();
  model.setup_blocks();
  EXPECT_EQ(model.blocks[0]->n_free_rigid_modes(), 6u);
  EXPECT_EQ(model.blocks[1]->n_free_rigid_modes(), 0u);
}

TEST(ThreeD, BlockOnPlaneMatchesThePlanarFormula)
{
  // K = (c L B + W cos(dip) tan(phi)) / (W sin(dip)), W = 25 * 10*6*5.
  for (const auto &[phi, cohesion] : {std::pair{35.0, 0.0}, std::pair{25.0, 15.0}})
    {
      std::ostringstream log;
      Model<3>           model(block_on_plane(30, 120, phi, cohesion), "", log);
      model.run();
      ASSERT_EQ(model.summary["status"], "completed") << model.summary["safety_factor_reason"];
      const double W     = 25.0 * 10 * 6 * 5, dip = PI / 6;
      const double exact = (cohesion * 60 + W * std::cos(dip) * std::tan(phi * PI / 180)) /
                           (W * std::sin(dip));
      // Sums of normal and tangential forces are fixed by equilibrium:
      // round-off only.
      EXPECT_NEAR(model.summary["safety_factor"].get<double>(), exact, 1e-8 * exact)
        << "phi = " << phi << ", c = " << cohesion;
    }
}
