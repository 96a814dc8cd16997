// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/elastic_block.h>
#include <fdem/contact/interface_pairs.h>
#include <fdem/geometry/mesh_description.h>
#include <fdem/parameters/model_parameters.h>

#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace fdem
{
  /**
   * Checks of a model's layout, made before any solve (doc/layout_checks.md):
   * mistakes in how the blocks touch and which of their contacts are
   * declared, which the mixed method would otherwise turn into a wrong
   * safety factor or a misleading "no static equilibrium". A certain
   * mistake throws (ExcMessage, one sentence naming the blocks or the
   * interface and where); a judgement is returned as a warning.
   */
  namespace checks
  {
    using namespace dealii;

    /**
     * Checks of the mesh alone, before it is split into blocks:
     * - faces shared by cells of two blocks (coincident vertices, merged
     *   within a tolerance of the mesh size) must belong to a face group
     *   listed in @p interface_names (contact) or in @p boundary_names (an
     *   open crack, e.g. a tension crack with water); otherwise throws,
     *   naming the two blocks, a point of the shared faces and their
     *   length (2D) or area (3D).
     * Points where three or more blocks meet need nothing here: their node
     * pairs are made once, by pair_triple_points_once().
     * Returns the warnings (none today: every finding here is an error).
     */
    template <int dim>
    std::vector<std::string>
    check_mesh_layout(const geometry::MeshDescription<dim> &mesh,
                      const std::vector<std::string>       &interface_names,
                      const std::vector<std::string>       &boundary_names);

    /**
     * Where the node pairs of the interfaces close a loop (at a point where
     * three or more blocks meet: the node of block A paired with B's, B's
     * with C's and C's with A's), the relative displacements around the loop
     * add up to zero whatever the forces, so a set of forces around the loop
     * does no work and the mixed system is singular. This removes the pair
     * that closes each loop, taking the interfaces in their listed order:
     * the point is then paired in the interfaces listed first (as a node on
     * two interfaces between the same two blocks is, Model::build_interfaces).
     * Returns one line per removed pair, for the log.
     */
    template <int dim>
    std::vector<std::string>
    pair_triple_points_once(
      std::vector<contact::Interface<dim>>                          &interfaces,
      const std::vector<std::unique_ptr<blocks::ElasticBlock<dim>>> &blocks);

    /**
     * Checks of the interfaces once their node pairs are made:
     * - an interface needs pairs enough to carry a moment: 2 in 2D, 3 not on
     *   one line in 3D; otherwise throws;
     * - its pairs must cover at least half of the shorter of its two sides
     *   (the face group's faces on each block): otherwise the sides touch
     *   only in places (e.g. at their end points) and the pairs do not stand
     *   for the contact that was meant: throws with the measures; between
     *   half and 90 % a warning;
     * - a block with free rigid modes whose interfaces are all frictionless
     *   must be able to balance its load omega^T F with normal forces alone
     *   (compressive ones, or of either sign where a tensile strength is
     *   given), its neighbours held fixed; otherwise throws.
     * @p blocks must have their load vectors assembled (for omega^T F).
     * Returns the warnings.
     */
    template <int dim>
    std::vector<std::string>
    check_interfaces(
      const geometry::MeshDescription<dim>                          &mesh,
      const std::vector<std::unique_ptr<blocks::ElasticBlock<dim>>> &blocks,
      const std::vector<contact::Interface<dim>>                    &interfaces,
      const std::map<std::string, parameters::InterfaceParameters> &parameters);

    /** Appends @p found to @p warnings and prints each as "warning: ..." on @p
     * log. */
    void
    report(const std::vector<std::string> &found,
           std::vector<std::string>       &warnings,
           std::ostream                   &log);

    /** Prints each line of @p lines on @p log (what pair_triple_points_once()
     * did). */
    void
    report(const std::vector<std::string> &lines, std::ostream &log);

    namespace internal
    {
      /** A point as "(x, y)" or "(x, y, z)", six digits: how the checks'
       * messages name a place. */
      template <int dim>
      std::string
      point_text(const Point<dim> &x);

      /**
       * The parts of check_interfaces() that need only the pairs and the
       * blocks (source/checks/support_checks.cc): the minimum number of
       * pairs and the support of blocks held by frictionless interfaces.
       */
      template <int dim>
      std::vector<std::string>
      check_support(
        const std::vector<std::unique_ptr<blocks::ElasticBlock<dim>>> &blocks,
        const std::vector<contact::Interface<dim>> &interfaces,
        const std::map<std::string, parameters::InterfaceParameters>
          &parameters);
    } // namespace internal
  }   // namespace checks
} // namespace fdem
