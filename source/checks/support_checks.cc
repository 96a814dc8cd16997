// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/checks/layout_checks.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

namespace fdem
{
  namespace checks
  {
    namespace
    {
      /**
       * Non-negative least squares, min |A x - b| over x >= 0 (Lawson and
       * Hanson's active set method), for the few rows of a block's free
       * rigid modes and the many columns of its pairs. Returns |A x - b|.
       * Columns that depend on those already in the passive set are not
       * taken in (they add nothing to the cone), so the small normal
       * equations stay regular.
       */
      double
      nnls_residual(const std::vector<Vector<double>> &columns,
                    const Vector<double>              &b)
      {
        const unsigned int  n = columns.size();
        std::vector<double> x(n, 0.0);
        std::vector<bool>   passive(n, false), excluded(n, false);
        Vector<double>      residual(b);
        const double        tolerance   = 1e-12 * std::max(b.l2_norm(), 1e-300);
        const auto          passive_set = [&]() {
          std::vector<unsigned int> set;
          for (unsigned int j = 0; j < n; ++j)
            if (passive[j])
              set.push_back(j);
          return set;
        };
        // The least-squares solution on the passive columns (normal equations).
        const auto least_squares = [&](const std::vector<unsigned int> &set) {
          FullMatrix<double> normal(set.size(), set.size());
          Vector<double>     rhs(set.size());
          for (unsigned int i = 0; i < set.size(); ++i)
            {
              rhs[i] = columns[set[i]] * b;
              for (unsigned int j = 0; j < set.size(); ++j)
                normal(i, j) = columns[set[i]] * columns[set[j]];
            }
          normal.gauss_jordan();
          Vector<double> z(set.size());
          normal.vmult(z, rhs);
          return z;
        };
        for (unsigned int outer = 0; outer < 3 * n + 10; ++outer)
          {
            // The column most downhill, among those independent of the passive
            // set.
            int    best   = -1;
            double best_w = tolerance;
            for (unsigned int j = 0; j < n; ++j)
              if (!passive[j] && !excluded[j] && columns[j] * residual > best_w)
                {
                  best   = j;
                  best_w = columns[j] * residual;
                }
            if (best < 0)
              break;
            {
              // Independence: what is left of the column after projecting it
              // onto the passive columns' span.
              std::vector<unsigned int> set = passive_set();
              Vector<double>            left(columns[best]);
              if (!set.empty())
                {
                  FullMatrix<double> normal(set.size(), set.size());
                  Vector<double>     rhs(set.size()), z(set.size());
                  for (unsigned int i = 0; i < set.size(); ++i)
                    {
                      rhs[i] = columns[set[i]] * columns[best];
                      for (unsigned int j = 0; j < set.size(); ++j)
                        normal(i, j) = columns[set[i]] * columns[set[j]];
                    }
                  normal.gauss_jordan();
                  normal.vmult(z, rhs);
                  for (unsigned int i = 0; i < set.size(); ++i)
                    left.add(-z[i], columns[set[i]]);
                }
              if (left.l2_norm() < 1e-10 * columns[best].l2_norm())
                {
                  excluded[best] = true;
                  continue;
                }
            }
            passive[best] = true;
            for (unsigned int inner = 0; inner < n + 10; ++inner)
              {
                const std::vector<unsigned int> set = passive_set();
                const Vector<double>            z   = least_squares(set);
                if (std::all_of(z.begin(), z.end(), [](const double v) {
                      return v > 0;
                    }))
                  {
                    for (unsigned int i = 0; i < set.size(); ++i)
                      x[set[i]] = z[i];
                    break;
                  }
                // Step towards z as far as x stays non-negative.
                double alpha = 1;
                for (unsigned int i = 0; i < set.size(); ++i)
                  if (z[i] <= 0)
                    alpha = std::min(alpha, x[set[i]] / (x[set[i]] - z[i]));
                for (unsigned int i = 0; i < set.size(); ++i)
                  {
                    x[set[i]] += alpha * (z[i] - x[set[i]]);
                    if (x[set[i]] <= 1e-14 * std::abs(z[i]) + 1e-300)
                      {
                        x[set[i]]       = 0;
                        passive[set[i]] = false;
                      }
                  }
                // Columns that left the passive set may be taken again.
                std::fill(excluded.begin(), excluded.end(), false);
              }
            residual = b;
            for (unsigned int j = 0; j < n; ++j)
              if (x[j] != 0)
                residual.add(-x[j], columns[j]);
          }
        return residual.l2_norm();
      }
    } // namespace

    template <int dim>
    std::vector<std::string>
    pair_triple_points_once(
      std::vector<contact::Interface<dim>>                          &interfaces,
      const std::vector<std::unique_ptr<blocks::ElasticBlock<dim>>> &blocks)
    {
      // Union-find over the paired nodes (block, first dof): a pair whose two
      // nodes are already joined through earlier pairs closes a loop.
      std::map<std::pair<unsigned int, types::global_dof_index>, unsigned int>
                                node_index;
      std::vector<unsigned int> parent;
      const auto                node = [&](const unsigned int            block,
                            const types::global_dof_index dof) {
        const auto [it, inserted] =
          node_index.emplace(std::make_pair(block, dof), parent.size());
        if (inserted)
          parent.push_back(parent.size());
        return it->second;
      };
      const auto root = [&](unsigned int i) {
        while (parent[i] != i)
          i = parent[i] = parent[parent[i]];
        return i;
      };
      std::vector<std::string>               removed;
      std::vector<std::vector<unsigned int>> new_index(interfaces.size());
      for (unsigned int i = 0; i < interfaces.size(); ++i)
        {
          auto                               &interface = interfaces[i];
          std::vector<contact::NodePair<dim>> kept;
          for (const auto &pair : interface.pairs)
            {
              const unsigned int a =
                root(node(interface.block_I, pair.dofs_I[0]));
              const unsigned int b =
                root(node(interface.block_J, pair.dofs_J[0]));
              if (a == b)
                {
                  new_index[i].push_back(numbers::invalid_unsigned_int);
                  removed.push_back(
                    "  interface '" + interface.name + "': the pair at " +
                    internal::point_text(pair.position_J) + " between '" +
                    blocks[interface.block_I]->name + "' and '" +
                    blocks[interface.block_J]->name +
                    "' is left out: its nodes are joined through pairs "
                    "of interfaces listed before it (blocks meet there)");
                  continue;
                }
              parent[a] = b;
              new_index[i].push_back(kept.size());
              kept.push_back(pair);
            }
          interface.pairs = kept;
          AssertThrow(!interface.pairs.empty(),
                      ExcMessage(
                        "Interfaces/" + interface.name +
                        ": all its node pairs are joined through interfaces "
                        "listed before it."));
          // Nodes paired in an earlier interface point at that interface's
          // pairs.
          std::vector<typename contact::Interface<dim>::SharedNode> shared;
          for (auto node : interface.shared_nodes)
            if (new_index[node.interface][node.pair] !=
                numbers::invalid_unsigned_int)
              {
                node.pair = new_index[node.interface][node.pair];
                shared.push_back(node);
              }
          interface.shared_nodes   = shared;
          interface.n_shared_nodes = shared.size();
        }
      return removed;
    }

    namespace internal
    {
      template <int dim>
      std::vector<std::string>
      check_support(
        const std::vector<std::unique_ptr<blocks::ElasticBlock<dim>>> &blocks,
        const std::vector<contact::Interface<dim>> &interfaces,
        const std::map<std::string, parameters::InterfaceParameters>
          &parameters)
      {
        // Enough pairs to carry a moment: two places in 2D, three not on a
        // line in 3D (nodes paired in an earlier interface count here).
        for (const auto &interface : interfaces)
          {
            std::vector<Point<dim>> places;
            for (const auto &pair : interface.pairs)
              places.push_back(pair.position_J);
            for (const auto &shared : interface.shared_nodes)
              places.push_back(
                interfaces[shared.interface].pairs[shared.pair].position_J);
            double size = 0;
            for (const auto &x : places)
              size = std::max(size, x.distance(places[0]));
            unsigned int n_independent = places.empty() ? 0 : 1;
            if (size > 0)
              {
                n_independent = 2;
                if constexpr (dim == 3)
                  {
                    // The farthest from places[0], then the farthest from that
                    // line.
                    const Point<3> far =
                      *std::max_element(places.begin(),
                                        places.end(),
                                        [&](const auto &a, const auto &b) {
                                          return a.distance(places[0]) <
                                                 b.distance(places[0]);
                                        });
                    const Tensor<1, 3> axis =
                      (far - places[0]) / far.distance(places[0]);
                    double off = 0;
                    for (const auto &x : places)
                      off =
                        std::max(off,
                                 cross_product_3d(x - places[0], axis).norm());
                    if (off > 1e-6 * size)
                      n_independent = 3;
                  }
              }
            AssertThrow(
              n_independent >= dim,
              ExcMessage(
                "Interfaces/" + interface.name + ": its node pairs (" +
                std::to_string(places.size()) +
                ") cannot carry a moment; an interface needs at least " +
                (dim == 2 ? "2 pairs" : "3 pairs not on one line") +
                ": check that its sides meet over more than a point, "
                "or refine the mesh along it."));
          }

        // A free block held only by frictionless interfaces: its load on the
        // free modes, omega^T F, must lie in the cone of what the pairs' normal
        // forces can do on those modes (with the neighbours held fixed, which
        // only helps). Compression pushes block I along n and block J against
        // it.
        for (unsigned int b = 0; b < blocks.size(); ++b)
          {
            const auto        &block = *blocks[b];
            const unsigned int m     = block.n_free_rigid_modes();
            if (m == 0)
              continue;
            std::vector<Vector<double>> columns;
            std::string                 names;
            bool                        frictionless = true, touched = false;
            for (const auto &interface : interfaces)
              {
                if (interface.block_I != b && interface.block_J != b)
                  continue;
                touched       = true;
                const auto &p = parameters.at(interface.name);
                frictionless  = frictionless && p.frictionless;
                names += (names.empty() ? "'" : ", '") + interface.name + "'";
                for (const auto &pair : interface.pairs)
                  {
                    const bool     on_I = interface.block_I == b;
                    Vector<double> column(m);
                    for (unsigned int k = 0; k < m; ++k)
                      column[k] =
                        (on_I ? 1 : -1) *
                        (block.free_mode_displacement(k,
                                                      on_I ? pair.position_I :
                                                             pair.position_J) *
                         pair.frame[0]);
                    if (column.l2_norm() == 0)
                      continue;
                    column /= column.l2_norm();
                    columns.push_back(column);
                    if (p.tensile_strength > 0)
                      {
                        column *= -1;
                        columns.push_back(column);
                      }
                  }
              }
            if (!touched || !frictionless)
              continue;
            Vector<double> load(m);
            for (unsigned int k = 0; k < m; ++k)
              load[k] = -block.free_mode_load(k);
            if (load.l2_norm() == 0)
              continue;
            const double left = nnls_residual(columns, load) / load.l2_norm();
            std::ostringstream share;
            share.precision(3);
            share << 100 * left;
            AssertThrow(
              left < 1e-6,
              ExcMessage(
                "Block '" + block.name +
                "' is held only by frictionless interfaces (" + names +
                ") whose normal forces cannot balance its load (" +
                share.str() +
                " % of the load on its free rigid motions is left over "
                "even with its neighbours fixed): give an interface "
                "friction, or a boundary condition that holds it."));
          }
        return {};
      }

      template std::vector<std::string>
      check_support(
        const std::vector<std::unique_ptr<blocks::ElasticBlock<2>>> &,
        const std::vector<contact::Interface<2>> &,
        const std::map<std::string, parameters::InterfaceParameters> &);
      template std::vector<std::string>
      check_support(
        const std::vector<std::unique_ptr<blocks::ElasticBlock<3>>> &,
        const std::vector<contact::Interface<3>> &,
        const std::map<std::string, parameters::InterfaceParameters> &);
    } // namespace internal

    template std::vector<std::string>
    pair_triple_points_once(
      std::vector<contact::Interface<2>> &,
      const std::vector<std::unique_ptr<blocks::ElasticBlock<2>>> &);
    template std::vector<std::string>
    pair_triple_points_once(
      std::vector<contact::Interface<3>> &,
      const std::vector<std::unique_ptr<blocks::ElasticBlock<3>>> &);
  } // namespace checks
} // namespace fdem
