// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/model.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace fdem
{
  namespace analyses
  {
    /**
     * One passive bar, nail or pile of Reinforcement (doc/theory.md,
     * "Passive bars"), placed in the model: a straight bar from its head
     * (in a block that can move) to its end (in another block), crossing a
     * sliding surface, where it becomes a link of the mixed system
     * (contact::BarLink) between the two nodes of the nearest node pair.
     */
    template <int dim>
    struct Bar
    {
      /** Head, end, and where the bar leaves the head's block (after the
       * Geometry transformation). */
      Point<dim> head, end, crossing;
      /** Unit vector from the head to the end. */
      Tensor<1, dim> direction;
      /** Unit normal of the sliding surface at the crossing, out of the
       * head's block. */
      Tensor<1, dim> normal;
      unsigned int   head_block = 0, end_block = 0;
      /** The sliding-surface interface the bar crosses. */
      std::string interface;
      /** The steel's capacity, and the pull-out resistance of the bar's
       * length in the sliding mass and in the stable ground (forces; 0
       * where the bond does not limit it). */
      double tensile_capacity = 0, pullout_in_mass = 0, pullout_in_ground = 0;
      /** N_y: the least of those; V_y: the shear capacity (piles). */
      double axial_capacity = 0, shear_capacity = 0;
      /** The bar's pair in the mixed system. */
      unsigned int pair = 0;
    };

    /**
     * Places the passive bars of Reinforcement in the model (after
     * build_interfaces(), before compute_flexibility()) and gives the model
     * their links (Model::set_bar_links()); prints one line per bar. Throws
     * one line naming the bar at the first that is not on a sliding mass,
     * does not end in another block, or does not cross a sliding surface.
     * Returns the bars placed (none without bars).
     */
    template <int dim>
    std::vector<Bar<dim>>
    place_bars(Model<dim> &model);

    /**
     * Writes bars.csv into the results folder (rank 0) and returns the
     * bars' list for summary.json's "reinforcement" in the model's current
     * state (its K): per bar its axial force N (tension positive), shear
     * force, status (elastic or yielded) and capacities.
     */
    template <int dim>
    nlohmann::json
    bars_output(const Model<dim> &model, const std::vector<Bar<dim>> &bars);
  } // namespace analyses
} // namespace fdem
