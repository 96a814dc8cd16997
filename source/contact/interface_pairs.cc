// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/contact/interface_pairs.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/symmetric_tensor.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace fdem
{
  namespace contact
  {
    namespace
    {
      /** "(x y)" with 6 digits, for messages. */
      template <int dim>
      std::string
      position_text(const Point<dim> &p)
      {
        std::ostringstream out;
        out << std::setprecision(6) << "(" << p << ")";
        return out.str();
      }

      /** Local frame with rows n, t (2D) or n, t1, t2 (3D). */
      template <int dim>
      Tensor<2, dim>
      local_frame(const Tensor<1, dim> &n)
      {
        Tensor<2, dim> frame;
        frame[0] = n;
        if constexpr (dim == 2)
          {
            frame[1][0] = -n[1];
            frame[1][1] = n[0];
          }
        else
          {
            // t1 lies in the plane of n and the axis least aligned with it.
            unsigned int axis = 0;
            for (unsigned int d = 1; d < 3; ++d)
              if (std::abs(n[d]) < std::abs(n[axis]))
                axis = d;
            Tensor<1, 3> e;
            e[axis]         = 1;
            Tensor<1, 3> t1 = e - (e * n) * n;
            t1 /= t1.norm();
            frame[1] = t1;
            frame[2] = cross_product_3d(n, t1);
          }
        return frame;
      }

      /**
       * The direction along which the Dirichlet conditions of both blocks
       * hold the relative displacement of a pair's nodes, or zero if there
       * is none or more than one: the direction normal to every
       * displacement that the nodes' constraints leave free (rollers with
       * the same normal on both sides, where a sliding surface meets a
       * side of the model). A component tied to dofs of other nodes (a
       * plate) counts as free.
       */
      template <int dim>
      Tensor<1, dim>
      held_direction(const blocks::ElasticBlock<dim>  &block_I,
                     const blocks::InterfaceNode<dim> &a,
                     const blocks::ElasticBlock<dim>  &block_J,
                     const blocks::InterfaceNode<dim> &b)
      {
        SymmetricTensor<2, dim> free; // sum of v v^T over free directions
        for (const auto &[block, node] :
             {std::make_pair(&block_I, &a), std::make_pair(&block_J, &b)})
          {
            const AffineConstraints<double> &c = block->dirichlet_constraints;
            for (unsigned int k = 0; k < dim; ++k)
              {
                Tensor<1, dim> v;
                v[k]                = 1;
                bool off_node_entry = false;
                if (c.is_constrained(node->dofs[k]))
                  {
                    for (const auto &entry :
                         *c.get_constraint_entries(node->dofs[k]))
                      off_node_entry |=
                        std::find(node->dofs.begin(),
                                  node->dofs.end(),
                                  entry.first) == node->dofs.end();
                    if (!off_node_entry)
                      continue; // follows the node's free components
                  }
                else
                  // The components that follow this one move with it.
                  for (unsigned int j = 0; j < dim; ++j)
                    if (j != k && c.is_constrained(node->dofs[j]))
                      for (const auto &entry :
                           *c.get_constraint_entries(node->dofs[j]))
                        if (entry.first == node->dofs[k])
                          v[j] += entry.second;
                free += symmetrize(outer_product(v, v));
              }
          }
        const auto   eigen   = eigenvectors(free); // descending eigenvalues
        const double largest = eigen[0].first;
        if (largest <= 0 || eigen[dim - 1].first > 1e-12 * largest ||
            (dim > 1 && eigen[dim - 2].first <= 1e-12 * largest))
          return Tensor<1, dim>();
        return eigen[dim - 1].second;
      }

      /**
       * The normal of a pair at @p position: the surface's exact normal
       * where the mesh's generator knows it, in the sense of the facets'
       * mean normal @p facets_normal; else that. The facets' normal stays
       * where the exact one is more than 60 degrees from it (not a point of
       * that surface).
       */
      template <int dim>
      Tensor<1, dim>
      pair_normal(
        const Tensor<1, dim>                                    &facets_normal,
        const Point<dim>                                        &position,
        const std::function<Tensor<1, dim>(const Point<dim> &)> &surface_normal)
      {
        if (!surface_normal)
          return facets_normal;
        Tensor<1, dim> exact  = surface_normal(position);
        const double   length = exact.norm();
        if (!(length > 0) || !std::isfinite(length))
          return facets_normal;
        exact /= (exact * facets_normal < 0 ? -length : length);
        return exact * facets_normal > 0.5 ? exact : facets_normal;
      }

      /** Typical node spacing around a node of tributary area @p area. */
      template <int dim>
      double
      node_spacing(const double area)
      {
        return dim == 2 ? area : std::sqrt(area);
      }
    } // namespace

    template <int dim>
    Interface<dim>
    make_interface(
      const std::string                                       &name,
      const types::boundary_id                                 face_group,
      const unsigned int                                       index_I,
      const blocks::ElasticBlock<dim>                         &block_I,
      const unsigned int                                       index_J,
      const blocks::ElasticBlock<dim>                         &block_J,
      const double                                             search_distance,
      const std::function<Tensor<1, dim>(const Point<dim> &)> &surface_normal)
    {
      Interface<dim> interface;
      interface.name       = name;
      interface.face_group = face_group;
      interface.block_I    = index_I;
      interface.block_J    = index_J;

      const auto nodes_I = block_I.interface_nodes(face_group);
      const auto nodes_J = block_J.interface_nodes(face_group);
      // Nodes of zero weight (the vertices of the quadratic triangles of
      // P2 tetrahedra) get no pair: a uniform traction puts no consistent
      // force on them, and as pairs with forces near zero their statuses
      // chattered (the wedge's status iteration did not converge,
      // doc/theory.md). Contact is held at the other nodes.
      std::vector<bool> used_J(nodes_J.size(), false);
      for (unsigned int j = 0; j < nodes_J.size(); ++j)
        used_J[j] = (nodes_J[j].area == 0);
      for (const auto &a : nodes_I)
        {
          if (a.area == 0)
            continue;
          // The partner: the node of J along J's normal with the smallest
          // gap, within the search distance. Matching tolerances scale with
          // the local node spacing.
          int    best     = -1;
          double best_gap = 0;
          for (unsigned int j = 0; j < nodes_J.size(); ++j)
            {
              if (used_J[j])
                continue;
              const auto          &b   = nodes_J[j];
              const Tensor<1, dim> n   = b.area_normal / b.area_normal.norm();
              const Tensor<1, dim> d   = a.position - b.position;
              const double         gap = d * n;
              const double         tolerance = 1e-6 * node_spacing<dim>(b.area);
              if ((d - gap * n).norm() > tolerance || gap < -tolerance ||
                  gap > search_distance + tolerance)
                continue;
              if (best < 0 || gap < best_gap)
                {
                  best     = j;
                  best_gap = gap;
                }
            }
          if (best < 0)
            {
              ++interface.n_unpaired_I;
              continue;
            }
          used_J[best]  = true;
          const auto &b = nodes_J[best];
          // The faces around a node that turn back on each other (a surface
          // folding, or a sliver cell between two nearly coincident lines)
          // leave it without a normal: its frame, and every force of the
          // mixed system, would be NaN.
          AssertThrow(std::isfinite(b.area_normal.norm()) &&
                        b.area_normal.norm() > 1e-3 * b.area,
                      ExcMessage(
                        "Interfaces/" + name + ": at " +
                        position_text(b.position) + " the faces of block '" +
                        block_J.name +
                        "' around a node turn back on each other, so "
                        "the surface has no normal there: it folds, or "
                        "the mesh has a sliver cell between nearly "
                        "coincident lines; move the surface or change "
                        "the mesh size."));
          NodePair<dim> pair;
          pair.position_I = a.position;
          pair.position_J = b.position;
          pair.dofs_I     = a.dofs;
          pair.dofs_J     = b.dofs;
          pair.frame      = local_frame<dim>(pair_normal<dim>(
            b.area_normal / b.area_normal.norm(), b.position, surface_normal));
          if constexpr (dim == 3)
            {
              // A direction held by rollers on both sides must be an axis
              // of the frame, where pair_rows() frees its force; the mean
              // normal of an unstructured mesh's facets is not normal to
              // the roller there, and C_pp would be singular
              // (doc/theory.md, "The 3D slope"). The normal is turned into
              // the roller's plane, or onto its normal.
              const Tensor<1, dim> m = held_direction(block_I, a, block_J, b);
              bool                 an_axis = m.norm() == 0;
              for (unsigned int i = 0; i < dim; ++i)
                an_axis |= std::abs(std::abs(pair.frame[i] * m) - 1) <= 1e-12;
              if (!an_axis)
                {
                  const Tensor<1, dim> n     = pair.frame[0];
                  const double         along = n * m;
                  if (std::abs(along) > std::sqrt(0.5))
                    pair.frame = local_frame<dim>(along > 0 ? m : -m);
                  else
                    {
                      Tensor<1, dim> turned = n - along * m;
                      turned /= turned.norm();
                      pair.frame[0] = turned;
                      pair.frame[1] = m;
                      pair.frame[2] = cross_product_3d(turned, m);
                    }
                }
            }
          pair.area        = b.area;
          pair.initial_gap = std::max(0.0, best_gap);
          interface.pairs.push_back(pair);
        }
      for (unsigned int j = 0; j < nodes_J.size(); ++j)
        interface.n_unpaired_J += (used_J[j] || nodes_J[j].area == 0) ? 0 : 1;

      AssertThrow(!interface.pairs.empty(),
                  ExcMessage("Interfaces/" + name +
                             ": no node pairs found between blocks '" +
                             block_I.name + "' and '" + block_J.name +
                             "'; the sides must have coincident nodes, or "
                             "nodes facing each other within 'Search "
                             "distance'."));
      return interface;
    }

    template <int dim>
    void
    remove_pairs_of_earlier_interfaces(std::vector<Interface<dim>> &interfaces)
    {
      Interface<dim> &last          = interfaces.back();
      const auto      paired_before = [&](const NodePair<dim> &pair) {
        for (unsigned int i = 0; i + 1 < interfaces.size(); ++i)
          for (unsigned int k = 0; k < interfaces[i].pairs.size(); ++k)
            {
              const auto &other = interfaces[i].pairs[k];
              if (interfaces[i].block_I == last.block_I &&
                  interfaces[i].block_J == last.block_J &&
                  other.dofs_I == pair.dofs_I && other.dofs_J == pair.dofs_J)
                {
                  last.shared_nodes.push_back({i, k, pair.area});
                  return true;
                }
            }
        return false;
      };
      last.pairs.erase(std::remove_if(last.pairs.begin(),
                                      last.pairs.end(),
                                      paired_before),
                       last.pairs.end());
      last.n_shared_nodes = last.shared_nodes.size();
    }

    template void
    remove_pairs_of_earlier_interfaces(std::vector<Interface<2>> &);
    template void
    remove_pairs_of_earlier_interfaces(std::vector<Interface<3>> &);
    template Interface<2>
    make_interface(const std::string &,
                   const types::boundary_id,
                   const unsigned int,
                   const blocks::ElasticBlock<2> &,
                   const unsigned int,
                   const blocks::ElasticBlock<2> &,
                   const double,
                   const std::function<Tensor<1, 2>(const Point<2> &)> &);
    template Interface<3>
    make_interface(const std::string &,
                   const types::boundary_id,
                   const unsigned int,
                   const blocks::ElasticBlock<3> &,
                   const unsigned int,
                   const blocks::ElasticBlock<3> &,
                   const double,
                   const std::function<Tensor<1, 3>(const Point<3> &)> &);
  } // namespace contact
} // namespace fdem
