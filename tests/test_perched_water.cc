// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// A piezometric line per material (Materials/<name>/Piezometric line, issue
// 17): a perched water table in one layer and another in the next. Each
// cell takes its material's line for its saturated weight, and each face
// with a 'piezometric' pressure the line of its cell's material; limit
// equilibrium does the same for each slice's layers and base.
#include "layered_cases.h"
#include "test_helpers.h"

#include <fdem/analyses/limit_equilibrium_model.h>
#include <fdem/blocks/surface_loads.h>
#include <fdem/geometry/make_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>

using namespace fdem;
using dealii::Point;
using namespace fdem::test_support::layered_cases;

namespace
{
  /** The layered slope with its water, at mesh size 2 m. */
  parameters::Parameters
  layered_with_water()
  {
    auto p = test_support::case_parameters("layered_slope.prm");
    p.geometry.slope.mesh_size = 2.0;
    return p;
  }

  /** The blocks' load vectors of @p p, assembled. */
  std::vector<dealii::Vector<double>>
  load_vectors(const parameters::Parameters &p)
  {
    std::ostringstream log;
    Model<2>           model(p, log);
    model.make_geometry();
    model.setup_blocks();
    model.assemble_and_factorize();
    std::vector<dealii::Vector<double>> loads;
    for (const auto &block : model.get_blocks())
      loads.push_back(block->load_vector);
    return loads;
  }

  /** The largest difference of two sets of load vectors, relative to the
   * largest entry. */
  double
  load_difference(const std::vector<dealii::Vector<double>> &a,
                  const std::vector<dealii::Vector<double>> &b)
  {
    EXPECT_EQ(a.size(), b.size());
    double difference = 0, largest = 0;
    for (unsigned int k = 0; k < a.size(); ++k)
      {
        EXPECT_EQ(a[k].size(), b[k].size());
        largest = std::max(largest, a[k].linfty_norm());
        auto d  = a[k];
        d -= b[k];
        difference = std::max(difference, d.linfty_norm());
      }
    return difference / largest;
  }
} // namespace

// Every layer given Water/Piezometric line as its own, and the slope's line
// removed: the same water everywhere, so the same loads, the same K and the
// same limit-equilibrium factors, to round-off (the same arithmetic).
TEST(PerchedWater, EachLayerOnTheSlopesLineChangesNothing)
{
  const auto slope = layered_with_water();
  auto       own   = slope;
  for (auto &[name, material] : own.materials)
    material.piezometric_line = slope.water.piezometric_line;
  own.water.piezometric_line.clear();
  own.output.directory += "/own";
  const double K_slope = run(slope)->results().safety_factor.safety_factor;
  const double K_own   = run(own)->results().safety_factor.safety_factor;
  std::cout << "  K " << std::setprecision(15) << K_slope << " and " << K_own
            << std::endl;
  EXPECT_NEAR(K_own, K_slope, 1e-13 * K_slope);

  const auto le_slope = analyses::model_limit_equilibrium(slope);
  const auto le_own   = analyses::model_limit_equilibrium(own);
  ASSERT_TRUE(le_slope.computed) << le_slope.not_computed;
  ASSERT_EQ(le_slope.methods.size(), le_own.methods.size());
  for (unsigned int m = 0; m < le_slope.methods.size(); ++m)
    {
      if (!le_slope.methods[m].not_computed.empty())
        continue;
      EXPECT_NEAR(le_own.methods[m].result.K,
                  le_slope.methods[m].result.K,
                  1e-13 * le_slope.methods[m].result.K)
        << analyses::limit_equilibrium::method_key(le_slope.methods[m].method);
    }
}

// Each cell weighs its saturated unit weight below its own material's line:
// the clay's line above the whole model and the fill's and sand's below it
// give the loads of the same model without water in which the clay weighs
// its saturated unit weight everywhere (the same quadrature and the same
// numbers: round-off). The slope's one line, which wets part of every
// layer, gives other loads, so the comparison can fail.
TEST(PerchedWater, EachCellWeighsBelowItsMaterialsLine)
{
  auto wet_clay = layered_with_water();
  wet_clay.interfaces.at("sliding surface").pore_pressure = "0";
  auto one_line                                           = wet_clay;
  wet_clay.water.piezometric_line.clear();
  wet_clay.materials.at("clay").piezometric_line = {{{0, 40}}, {{50, 40}}};
  wet_clay.materials.at("fill").piezometric_line = {{{0, 0}}, {{50, 0}}};
  wet_clay.materials.at("sand").piezometric_line = {{{0, 0}}, {{50, 0}}};

  auto  dry                  = wet_clay;
  auto &clay                 = dry.materials.at("clay");
  clay.unit_weight           = clay.saturated_unit_weight;
  clay.saturated_unit_weight = 0;
  for (auto &[name, material] : dry.materials)
    material.piezometric_line.clear();

  const auto   loads = load_vectors(wet_clay);
  const double same  = load_difference(loads, load_vectors(dry));
  const double other = load_difference(loads, load_vectors(one_line));
  std::cout << "  relative difference to the dry model with saturated clay "
            << same << ", to the slope's one line " << other << std::endl;
  EXPECT_LT(same, 1e-14);
  EXPECT_GT(other, 1e-3);
}

// A perched water table in the fill on the test plane (10,25) -> (46,35)
// through fill, clay and fill: the fill's line runs from the toe (10,25)
// to h_in above the plane where the plane enters the clay, and from h_out
// above it where the plane leaves the clay to the crest end (46,35); the
// clay is dry (no line of its own, none for the slope). The pore pressure
// on the plane is then linear on each fill segment (its kinks are at the
// layer crossings, which are mesh nodes, so the face quadrature integrates
// it exactly) and zero in the clay:
//   U = gamma_w (L_1 h_in + L_3 h_out) / 2.
// A rigid translation is the mechanism, every pair slips at the limit, and
// statics gives
//   K = (sum_i c_i L_i - C_open + tan(phi) (W cos(a) - U)) / (W sin(a)),
// W the weight of the sliding mass (its load vector without the water; no
// saturated weights, so W is exact). Limit equilibrium slices the same
// section (slice boundaries at the line's vertices and the crossings) and
// gives it with C_open = 0. Tolerances: the iteration's 1e-11 and the root
// search's 1e-14, with margin for round-off.
TEST(PerchedWater, PerchedTableOnThePlaneGivesTheClosedForm)
{
  const double phi = 25, h_in = 1.0, h_out = 1.5;
  auto         dry = layered_plane(phi);
  for (auto &[name, material] : dry.materials)
    material.saturated_unit_weight = 0;
  dry.limit_equilibrium.n_slices = 40;
  const Point<2> start(10, 25), end(46, 35);
  const Point<2> in  = plane_crossing(Point<2>(10, 24), Point<2>(30, 31)),
                 out = plane_crossing(Point<2>(30, 31), Point<2>(50, 33));
  auto perched       = dry;
  perched.interfaces.at("sliding surface").pore_pressure = "piezometric";
  perched.materials.at("fill").piezometric_line = {{{start[0], start[1]}},
                                                   {{in[0], in[1] + h_in}},
                                                   {{out[0], out[1] + h_out}},
                                                   {{end[0], end[1]}}};
  perched.output.directory += "/perched";

  std::ostringstream log;
  Model<2>           model(dry, log);
  model.make_geometry();
  model.setup_blocks();
  model.assemble_and_factorize();
  ASSERT_EQ(model.get_blocks()[0]->name, "sliding mass");
  const double W = weight_of(*model.get_blocks()[0]);

  const double L_1 = start.distance(in), L_2 = in.distance(out),
               L_3 = out.distance(end);
  const double U   = perched.water.unit_weight * (L_1 * h_in + L_3 * h_out) / 2;
  const double cohesion = perched.materials.at("fill").cohesion * (L_1 + L_3) +
                          perched.materials.at("clay").cohesion * L_2;
  const double alpha       = std::atan(plane_slope);
  const auto   closed_form = [&](const double open) {
    return (cohesion - open +
            std::tan(phi * dealii::numbers::PI / 180) *
              (W * std::cos(alpha) - U)) /
           (W * std::sin(alpha));
  };
  const auto   result = run(perched);
  const double K      = result->results().safety_factor.safety_factor;
  const double open   = open_cohesion(result->model());
  std::cout << "  W " << W << ", U " << U << ", open pairs' cohesion " << open
            << ", K " << std::setprecision(12) << K << ", from statics "
            << closed_form(open) << std::endl;
  EXPECT_NEAR(K, closed_form(open), 1e-9 * K);
  // The water lowers K (the same run dry).
  EXPECT_LT(K, run(dry)->results().safety_factor.safety_factor);

  expect_every_method_gives(perched, closed_form(0), 1e-9);
}

// Water/Piezometric surface file (3D): the pressure below a water table
// given on a grid is gamma_w times the depth under its bilinear surface,
// clamped beyond the grid, in the input's coordinates: scaled, turned and
// moved with the mesh (Geometry transformation), a point's pressure is the
// same depth times the scale. A material's own line still wins in its
// cells.
TEST(PerchedWater, WaterSurfaceGridGivesTheDepthBelowItInAnyFrame)
{
  parameters::WaterParameters water;
  water.unit_weight           = 9.81;
  water.piezometric_surface.x = {0, 10, 30};
  water.piezometric_surface.y = {-5, 20};
  water.piezometric_surface.z = {25, 26, 30, 27, 29, 33};
  const auto surface_level    = [](double x, double y) {
    // Bilinear per cell: in x piecewise linear, in y linear (0 at y = -5,
    // 1 at y = 20), clamped beyond.
    x               = std::clamp(x, 0.0, 30.0);
    y               = std::clamp(y, -5.0, 20.0);
    const double t  = (y + 5) / 25;
    const double z0 = x <= 10 ? 25 + 0.1 * x : 26 + 0.2 * (x - 10);
    const double z1 = x <= 10 ? 27 + 0.2 * x : 29 + 0.2 * (x - 10);
    return (1 - t) * z0 + t * z1;
  };
  parameters::GeometryParameters plain;
  plain.translation = {0, 0, 0};
  parameters::GeometryParameters moved;
  moved.scale_factor   = 1000;
  moved.rotation_angle = 30;
  moved.rotation_axis  = dealii::Tensor<1, 3>({1., 2., 3.});
  moved.rotation_axis /= moved.rotation_axis.norm();
  moved.translation = {500, -200, 100};
  const blocks::PiezometricPressure<3> in_plain(water, plain),
    in_moved(water, moved), raised(water, plain, 1.5);
  parameters::MaterialParameters own_line, no_line;
  own_line.piezometric_line = {{{0, 20}}, {{30, 20}}};
  for (const Point<3> &p : {Point<3>(5, 0, 24),
                            Point<3>(20, 10, 27.5),
                            Point<3>(-4, 30, 26),
                            Point<3>(40, -9, 31),
                            Point<3>(25, 12, 40)})
    {
      const double depth = std::max(0.0, surface_level(p[0], p[1]) - p[2]);
      EXPECT_NEAR(in_plain.value(p), 9.81 * depth, 1e-12) << p;
      EXPECT_NEAR(in_plain.value(p, no_line), 9.81 * depth, 1e-12) << p;
      EXPECT_NEAR(in_plain.value(p, own_line),
                  9.81 * std::max(0.0, 20 - p[2]),
                  1e-12)
        << p;
      EXPECT_NEAR(raised.value(p),
                  9.81 * std::max(0.0, surface_level(p[0], p[1]) + 1.5 - p[2]),
                  1e-12)
        << p;
      const Point<3> image = geometry::transformed_point(moved, p);
      EXPECT_NEAR(in_moved.value(image), 1000 * 9.81 * depth, 1e-8) << p;
    }
}
