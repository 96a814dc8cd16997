// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Where a reinforcement lies in the mesh: the blocks its points are in and
// where it crosses a sliding surface (anchors and passive bars alike).
#include <fdem/analyses/reinforcement_geometry.h>
#include <fdem/geometry/make_mesh.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>

#include <iomanip>
#include <limits>
#include <sstream>

namespace fdem
{
  namespace analyses
  {
    template <int dim>
    PointLocator<dim>::PointLocator(const Model<dim> &model)
      : model(model)
    {
      for (const auto &block : model.get_blocks())
        caches.push_back(
          std::make_unique<GridTools::Cache<dim>>(block->triangulation,
                                                  block->mapping));
    }

    template <int dim>
    std::pair<typename Triangulation<dim>::active_cell_iterator, Point<dim>>
    PointLocator<dim>::find(const unsigned int b, const Point<dim> &p) const
    {
      try
        {
          const auto found =
            GridTools::find_active_cell_around_point(*caches[b], p);
          if (found.first.state() == IteratorState::valid &&
              found.first != model.get_blocks()[b]->triangulation.end())
            return found;
        }
      catch (...)
        {
          // Not in this block.
        }
      return {typename Triangulation<dim>::active_cell_iterator(),
              Point<dim>()};
    }

    template <int dim>
    unsigned int
    PointLocator<dim>::block_of(const Point<dim> &p) const
    {
      for (unsigned int b = 0; b < caches.size(); ++b)
        if (inside(b, p))
          return b;
      return numbers::invalid_unsigned_int;
    }

    template <int dim>
    void
    PointLocator<dim>::add_point_force(const unsigned int    b,
                                       const Point<dim>     &p,
                                       const Tensor<1, dim> &force,
                                       Vector<double>       &load) const
    {
      const auto &block = *model.get_blocks()[b];
      const auto  found = find(b, p);
      Assert(found.first.state() == IteratorState::valid, ExcInternalError());
      const typename DoFHandler<dim>::active_cell_iterator cell(
        &block.triangulation,
        found.first->level(),
        found.first->index(),
        &block.dof_handler);
      FEValues<dim> fe_values(block.mapping,
                              block.fe,
                              Quadrature<dim>(
                                std::vector<Point<dim>>{found.second}),
                              update_values);
      fe_values.reinit(cell);
      std::vector<types::global_dof_index> dofs(block.fe.n_dofs_per_cell());
      cell->get_dof_indices(dofs);
      const FEValuesExtractors::Vector displacement(0);
      for (unsigned int i = 0; i < dofs.size(); ++i)
        load[dofs[i]] += fe_values[displacement].value(i, 0) * force;
    }

    template <int dim>
    ReinforcementBlocks
    locate_reinforcement(const Model<dim>        &model,
                         const PointLocator<dim> &locator,
                         const Point<dim>        &head,
                         const Point<dim>        &end,
                         const std::string       &name,
                         const std::string       &head_entry,
                         const std::string       &end_entry,
                         const std::string       &end_word)
    {
      const auto         &blocks = model.get_blocks();
      ReinforcementBlocks found;
      found.head = locator.block_of(head);
      AssertThrow(found.head != numbers::invalid_unsigned_int,
                  ExcMessage(name + ": its head " + point_text(head) +
                             " lies in no block of the mesh; give "
                             "Reinforcement/" +
                             head_entry + " on the sliding mass."));
      AssertThrow(blocks[found.head]->n_free_rigid_modes() > 0,
                  ExcMessage(name + ": its head " + point_text(head) +
                             " lies in block '" + blocks[found.head]->name +
                             "', which is supported and cannot slide; the "
                             "head must be on the sliding mass (a block "
                             "without supports)."));
      found.end = numbers::invalid_unsigned_int;
      for (unsigned int b = 0; b < blocks.size(); ++b)
        if (b != found.head && locator.inside(b, end))
          {
            found.end = b;
            break;
          }
      const bool in_head_block = locator.inside(found.head, end);
      AssertThrow(found.end != numbers::invalid_unsigned_int && !in_head_block,
                  ExcMessage(name + ": its " + end_word + " " +
                             point_text(end) +
                             (in_head_block ?
                                " lies in the head's block '" +
                                  blocks[found.head]->name + "'" :
                                std::string(" lies in no block of the mesh")) +
                             "; give Reinforcement/" + end_entry +
                             " in the stable ground beyond the sliding "
                             "surface."));
      return found;
    }

    template <int dim>
    SurfaceCrossing<dim>
    find_surface_crossing(const Model<dim>        &model,
                          const PointLocator<dim> &locator,
                          const unsigned int       head_block,
                          const Point<dim>        &head,
                          const Point<dim>        &end,
                          const std::string       &name)
    {
      SurfaceCrossing<dim> crossing;
      // Where the straight line leaves the head's block: bisection on the
      // segment between the head (inside) and the end (not).
      double lo = 0, hi = 1;
      for (unsigned int i = 0; i < 60; ++i)
        {
          const double mid = 0.5 * (lo + hi);
          (locator.inside(head_block, head + mid * (end - head)) ? lo : hi) =
            mid;
        }
      crossing.point = head + lo * (end - head);

      // The nearest node pair of a sliding surface on the head's block,
      // within the size of the cell there.
      const auto cell = locator.find(head_block, crossing.point).first;
      Assert(cell.state() == IteratorState::valid, ExcInternalError());
      const double reach      = cell->diameter();
      double       nearest    = std::numeric_limits<double>::infinity();
      const auto  &interfaces = model.get_interfaces();
      for (unsigned int i = 0; i < interfaces.size(); ++i)
        if (model.get_parameters()
              .interfaces.at(interfaces[i].name)
              .sliding_surface &&
            (interfaces[i].block_I == head_block ||
             interfaces[i].block_J == head_block))
          for (unsigned int k = 0; k < interfaces[i].pairs.size(); ++k)
            {
              const auto  &pair = interfaces[i].pairs[k];
              const double distance =
                std::min(crossing.point.distance(pair.position_I),
                         crossing.point.distance(pair.position_J));
              if (distance < nearest)
                {
                  nearest                 = distance;
                  crossing.normal         = pair.frame[0];
                  crossing.interface      = i;
                  crossing.pair           = k;
                  crossing.interface_name = interfaces[i].name;
                }
            }
      AssertThrow(nearest <= reach,
                  ExcMessage(
                    name +
                    " does not cross a sliding surface: it leaves block '" +
                    model.get_blocks()[head_block]->name + "' at " +
                    point_text(crossing.point) +
                    ", where no interface with 'Sliding surface = true' is."));
      const Tensor<1, dim> direction = (end - head) / (end - head).norm();
      if (crossing.normal * direction < 0)
        crossing.normal = -crossing.normal;
      AssertThrow(crossing.normal * direction > 1e-6,
                  ExcMessage(name + " runs along the sliding surface '" +
                             crossing.interface_name + "' at " +
                             point_text(crossing.point) +
                             " instead of crossing it."));
      return crossing;
    }

    template <int dim>
    Point<dim>
    transformed_input_point(const Model<dim>          &model,
                            const std::vector<double> &xyz,
                            const std::string         &what)
    {
      AssertThrow(xyz.size() == dim,
                  ExcMessage(what + " has " + std::to_string(xyz.size()) +
                             " coordinates; this " + std::to_string(dim) +
                             "D model needs " + std::to_string(dim) + "."));
      Point<dim> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = xyz[d];
      return geometry::transformed_point(model.get_parameters().geometry, x);
    }

    template <int dim>
    std::string
    point_text(const Point<dim> &p)
    {
      std::ostringstream out;
      out << std::setprecision(6) << "(" << p << ")";
      return out.str();
    }

    template <int dim>
    std::vector<double>
    coordinates(const Point<dim> &p)
    {
      std::vector<double> x;
      for (unsigned int d = 0; d < dim; ++d)
        x.push_back(p[d]);
      return x;
    }

    template class PointLocator<2>;
    template class PointLocator<3>;
    template ReinforcementBlocks
    locate_reinforcement(const Model<2> &,
                         const PointLocator<2> &,
                         const Point<2> &,
                         const Point<2> &,
                         const std::string &,
                         const std::string &,
                         const std::string &,
                         const std::string &);
    template ReinforcementBlocks
    locate_reinforcement(const Model<3> &,
                         const PointLocator<3> &,
                         const Point<3> &,
                         const Point<3> &,
                         const std::string &,
                         const std::string &,
                         const std::string &,
                         const std::string &);
    template SurfaceCrossing<2>
    find_surface_crossing(const Model<2> &,
                          const PointLocator<2> &,
                          const unsigned int,
                          const Point<2> &,
                          const Point<2> &,
                          const std::string &);
    template SurfaceCrossing<3>
    find_surface_crossing(const Model<3> &,
                          const PointLocator<3> &,
                          const unsigned int,
                          const Point<3> &,
                          const Point<3> &,
                          const std::string &);
    template Point<2>
    transformed_input_point(const Model<2> &,
                            const std::vector<double> &,
                            const std::string &);
    template Point<3>
    transformed_input_point(const Model<3> &,
                            const std::vector<double> &,
                            const std::string &);
    template std::string
    point_text(const Point<2> &);
    template std::string
    point_text(const Point<3> &);
    template std::vector<double>
    coordinates(const Point<2> &);
    template std::vector<double>
    coordinates(const Point<3> &);
  } // namespace analyses
} // namespace fdem
