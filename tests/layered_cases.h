// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The layered slope (prm/layered_slope.prm) and the test plane through its
// layers, shared by the tests of layers (test_layers.cc) and of perched
// water (test_perched_water.cc).
#pragma once

#include "test_helpers.h"

#include <fdem/analyses/limit_equilibrium_model.h>
#include <fdem/blocks/elastic_block.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <vector>

namespace fdem::test_support::layered_cases
{
  using dealii::Point;

  /** y of the polyline @p line at @p x (x inside its range). */
  inline double
  elevation(const std::vector<Point<2>> &line, const double x)
  {
    for (unsigned int i = 1; i < line.size(); ++i)
      if (x <= line[i][0])
        {
          const double t = (x - line[i - 1][0]) / (line[i][0] - line[i - 1][0]);
          return (1 - t) * line[i - 1][1] + t * line[i][1];
        }
    return line.back()[1];
  }

  inline parameters::Parameters
  layered(const double mesh_size)
  {
    auto p = test_support::case_parameters("layered_slope.prm");
    p.geometry.slope.mesh_size      = mesh_size;
    p.safety_factor.tolerance       = 1e-11;
    p.safety_factor.stiffness_check = false;
    // Without water in the surface every pair slips at the limit, where K
    // is a function of the pair strengths alone; with it a pair near the
    // toe stays stuck, and K then also depends on the path of the status
    // iteration, which the order of the pairs (one interface or two) may
    // change (the weights still see the water table).
    p.interfaces.at("sliding surface").pore_pressure = "0";
    return p;
  }

  /** The model run through its safety factor. */
  inline std::unique_ptr<CaseRun<2>>
  run(const parameters::Parameters &p)
  {
    std::ostringstream log;
    auto               model = std::make_unique<CaseRun<2>>(p, "", log);
    model->run();
    EXPECT_TRUE(model->results().safety_factor.converged) << log.str();
    return model;
  }

  /** The weight of @p block: minus the y components of its load vector. */
  inline double
  weight_of(const blocks::ElasticBlock<2> &block)
  {
    double W = 0;
    // The y components: dofs come in component order at each support point.
    std::vector<bool> is_y(block.dof_handler.n_dofs(), false);
    std::vector<dealii::types::global_dof_index> dofs(
      block.fe.n_dofs_per_cell());
    for (const auto &cell : block.dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          is_y[dofs[i]] = block.fe.system_to_component_index(i).first == 1;
      }
    for (unsigned int i = 0; i < block.load_vector.size(); ++i)
      if (is_y[i])
        W -= block.load_vector[i];
    return W;
  }

  /** The test planes' line y = 25 + (x - 10) 10/36, from (10, 25). */
  inline const double plane_slope = 10.0 / 36;

  /** Where the test plane crosses the segment @p a - @p b. */
  inline Point<2>
  plane_crossing(const Point<2> &a, const Point<2> &b)
  {
    const double m = (b[1] - a[1]) / (b[0] - a[0]);
    const double x =
      (a[1] - m * a[0] - 25 + 10 * plane_slope) / (plane_slope - m);
    return Point<2>(x, 25 + (x - 10) * plane_slope);
  }

  /** The layered slope cut by the test plane (10,25) -> (46,35) through
   * fill, clay and fill again, with the friction angle @p phi everywhere
   * and no water. */
  inline parameters::Parameters
  layered_plane(const double phi)
  {
    auto  p                        = layered(2.0);
    auto &slope                    = p.geometry.slope;
    slope.sliding_surface          = geometry::Slope::SlidingSurface::polyline;
    slope.sliding_surface_polyline = {Point<2>(10, 25), Point<2>(46, 35)};
    slope.layer_boundaries[0]      = {Point<2>(0, 23),
                                      Point<2>(10, 24),
                                      Point<2>(30, 31),
                                      Point<2>(50, 33)};
    p.water.piezometric_line.clear();
    for (auto &[name, material] : p.materials)
      material.friction_angle = phi;
    return p;
  }

  /** The full-strength cohesive force of the pairs open at the end. */
  inline double
  open_cohesion(const Model<2> &model)
  {
    const auto strengths = model.pair_strengths(1.0);
    double     open      = 0;
    for (unsigned int k = 0; k < strengths.size(); ++k)
      if (model.get_contact_outcome().states[k].status ==
          contact::PairStatus::open)
        open += strengths[k].cohesion_force;
    return open;
  }
  /**
   * Every limit-equilibrium method of the model @p p that applies (all but
   * Bishop's on a polyline; at least four) gives @p K to @p tolerance
   * relative.
   */
  inline void
  expect_every_method_gives(const parameters::Parameters &p,
                            const double                  K,
                            const double                  tolerance)
  {
    const auto le = analyses::model_limit_equilibrium(p);
    ASSERT_TRUE(le.computed) << le.not_computed;
    unsigned int n_methods = 0;
    for (const auto &entry : le.methods)
      if (entry.not_computed.empty()) // Bishop's is for circles only
        {
          ++n_methods;
          const std::string name =
            analyses::limit_equilibrium::method_key(entry.method);
          std::cout << "  " << name << " K " << entry.result.K << std::endl;
          EXPECT_NEAR(entry.result.K, K, tolerance * K) << name;
        }
    EXPECT_GE(n_methods, 4u);
  }
} // namespace fdem::test_support::layered_cases
