// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/anchor_results.h>
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
     * One active anchor of Reinforcement (doc/theory.md, "Anchors"), placed
     * in the model: a prestress force T pulling its head (in a block that can
     * move) towards its bond point (in another block), and the bond point
     * back, across a sliding surface.
     */
    template <int dim>
    struct Anchor
    {
      /** Head, bond point and where the anchor leaves the head's block (after
       * the Geometry transformation). */
      Point<dim> head, bond, crossing;
      /** Unit vector from the head to the bond point: the force on the head is
       * T direction. */
      Tensor<1, dim> direction;
      /** Unit normal of the sliding surface at the crossing, out of the head's
       * block. */
      Tensor<1, dim> normal;
      /** T. */
      double force = 0;
      /** T direction . normal (> 0: presses the head's block onto the surface).
       */
      double normal_force = 0;
      /** |T direction - normal_force normal|: the part along the surface. */
      double       shear_force = 0;
      unsigned int head_block = 0, bond_block = 0;
      /** The sliding-surface interface the anchor crosses. */
      std::string interface;
    };

    /**
     * The anchors of Reinforcement placed in the model (after
     * build_interfaces()): each head and bond point found in a cell, the
     * head in a block that can move and the bond point in another, and the
     * point where the straight anchor leaves the head's block on a sliding
     * surface, with that surface's normal there (of its nearest node pair).
     * Throws one line naming the anchor at the first that is not so.
     */
    template <int dim>
    std::vector<Anchor<dim>>
    locate_anchors(const Model<dim> &model);

    /**
     * Adds the anchors' loads to the model (after compute_flexibility()),
     * as two load cases on the blocks' factorisations (no new
     * factorisation): the normal and the shear components of all anchors,
     * each a pair of opposite point forces at head and bond point shared by
     * the cell's vertices through the shape functions. Sets the model's
     * strength-dependent loads (Model::set_strength_dependent_loads():
     * coefficient 1 on the normal case, 1 or 1/K on the shear case) and
     * prints one line per anchor. Returns the anchors placed (none without
     * Reinforcement).
     */
    template <int dim>
    std::vector<Anchor<dim>>
    add_anchor_loads(Model<dim> &model);

    /**
     * Writes anchors.csv into the results folder (rank 0) and returns
     * summary.json's "reinforcement" for the model's current state (its K).
     */
    template <int dim>
    nlohmann::json
    reinforcement_output(const Model<dim>               &model,
                         const std::vector<Anchor<dim>> &anchors);
  } // namespace analyses
} // namespace fdem
