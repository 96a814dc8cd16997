// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/elastic_block.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace fdem
{
  namespace contact
  {
    using namespace dealii;

    /**
     * A node pair of an interface (doc/theory.md): node a on
     * block I, node b on block J. Its local frame has the unit normal n,
     * pointing from J into I, as row 0 and the tangents as the other rows,
     * so that local = frame * global. Contact forces f are the forces that
     * block I exerts on block J; f_n > 0 is tension.
     */
    template <int dim>
    struct NodePair
    {
      Point<dim>                               position_I, position_J;
      std::array<types::global_dof_index, dim> dofs_I, dofs_J;
      /** Rows: n, then the tangent(s). In 2D t is n turned +90 degrees. */
      Tensor<2, dim> frame;
      /** Tributary area A_k = int phi_k dGamma on side J (length in 2D). */
      double area = 0;
      /** Initial normal gap delta_0 = (x_a - x_b) . n >= 0. */
      double initial_gap = 0;
    };

    /** An interface between block I and block J with its node pairs. */
    template <int dim>
    struct Interface
    {
      std::string                name;
      types::boundary_id         face_group = 0;
      unsigned int               block_I = 0, block_J = 0;
      std::vector<NodePair<dim>> pairs;
      /** Interface nodes left without a partner on each side. */
      unsigned int n_unpaired_I = 0, n_unpaired_J = 0;
      /** Nodes also on an interface listed before, and paired there. */
      unsigned int n_shared_nodes = 0;

      /**
       * A node of this interface paired in an interface listed before (the
       * line of intersection of a wedge): that pair carries the node's
       * contact, and this interface's cohesion and tensile strength over
       * the node's tributary area here, so that the strength of each
       * interface is that of its whole area.
       */
      struct SharedNode
      {
        unsigned int interface = 0, pair = 0;
        double       area = 0;
      };
      std::vector<SharedNode> shared_nodes;
    };

    /**
     * Pairs the nodes of face group @p face_group on @p block_I with those on
     * @p block_J: coincident nodes, or, within @p search_distance, the node
     * of J found along J's normal. Normals and areas are the consistent
     * nodal ones of side J (doc/theory.md), except that a pair takes
     * @p surface_normal at its node, when given (the exact normal of a
     * generator's surface, MeshDescription::surface_normals), as its frame's
     * normal.
     */
    template <int dim>
    Interface<dim>
    make_interface(const std::string               &name,
                   const types::boundary_id         face_group,
                   const unsigned int               index_I,
                   const blocks::ElasticBlock<dim> &block_I,
                   const unsigned int               index_J,
                   const blocks::ElasticBlock<dim> &block_J,
                   const double                     search_distance,
                   const std::function<Tensor<1, dim>(const Point<dim> &)>
                     &surface_normal = {});

    /**
     * Removes from the last of @p interfaces the pairs of the same two nodes
     * as a pair of an earlier interface between the same blocks (a node on
     * two interfaces, e.g. the line of intersection of a wedge): two pairs
     * of the same nodes would constrain one relative displacement twice.
     * The node stays in the earlier interface; the last one records it in
     * shared_nodes with its area, so that its strength is added there.
     */
    template <int dim>
    void
    remove_pairs_of_earlier_interfaces(std::vector<Interface<dim>> &interfaces);
  } // namespace contact
} // namespace fdem
