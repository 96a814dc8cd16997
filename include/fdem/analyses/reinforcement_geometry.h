// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/model.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/grid_tools_cache.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace fdem
{
  namespace analyses
  {
    /**
     * Finds points in the cells of a model's blocks (a deal.II cache per
     * block), and spreads a point force over the cell around it: what the
     * anchors and the passive bars need to be placed in the mesh.
     */
    template <int dim>
    class PointLocator
    {
    public:
      explicit PointLocator(const Model<dim> &model);

      /** The cell of block @p b around @p p and p's reference coordinates; an
       * invalid iterator if none. */
      std::pair<typename Triangulation<dim>::active_cell_iterator, Point<dim>>
      find(const unsigned int b, const Point<dim> &p) const;

      /** Whether block @p b holds @p p. */
      bool
      inside(const unsigned int b, const Point<dim> &p) const
      {
        return find(b, p).first.state() == IteratorState::valid;
      }

      /** The first block holding @p p, or invalid_unsigned_int. */
      unsigned int
      block_of(const Point<dim> &p) const;

      /** Adds the point force @p force at @p p to the nodal forces @p load of
       * block @p b (shape functions: exact resultant and moment). */
      void
      add_point_force(const unsigned int    b,
                      const Point<dim>     &p,
                      const Tensor<1, dim> &force,
                      Vector<double>       &load) const;

    private:
      const Model<dim>                                   &model;
      std::vector<std::unique_ptr<GridTools::Cache<dim>>> caches;
    };

    /** The blocks of a reinforcement's two ends. */
    struct ReinforcementBlocks
    {
      unsigned int head = 0, end = 0;
    };

    /**
     * The blocks of a reinforcement @p name (for the messages) from @p head
     * to @p end: the head in a block that can move, the end in another
     * block. Throws one line naming @p head_entry or @p end_entry (the
     * Reinforcement entries; @p end_word is what the end is called) if not.
     */
    template <int dim>
    ReinforcementBlocks
    locate_reinforcement(const Model<dim>        &model,
                         const PointLocator<dim> &locator,
                         const Point<dim>        &head,
                         const Point<dim>        &end,
                         const std::string       &name,
                         const std::string       &head_entry,
                         const std::string       &end_entry,
                         const std::string       &end_word);

    /**
     * Where a straight reinforcement from @p head (in block @p head_block)
     * towards @p end leaves the head's block through a sliding surface.
     */
    template <int dim>
    struct SurfaceCrossing
    {
      /** The point where it leaves the head's block (bisection). */
      Point<dim> point;
      /** The nearest node pair of a sliding surface on the head's block:
       * its interface (index and name) and its index there. */
      unsigned int interface = 0, pair = 0;
      std::string  interface_name;
      /** That pair's unit normal, turned to point out of the head's block. */
      Tensor<1, dim> normal;
    };

    /**
     * The crossing of the reinforcement @p name (for the messages) from @p
     * head in block @p head_block to @p end (outside that block) with a
     * sliding surface; throws one line if it leaves the block elsewhere or
     * runs along the surface.
     */
    template <int dim>
    SurfaceCrossing<dim>
    find_surface_crossing(const Model<dim>        &model,
                          const PointLocator<dim> &locator,
                          const unsigned int       head_block,
                          const Point<dim>        &head,
                          const Point<dim>        &end,
                          const std::string       &name);

    /** A point as the mesh has it: x -> R (s x) + t (the Geometry
     * transformation); throws naming @p what if it has not dim coordinates.
     */
    template <int dim>
    Point<dim>
    transformed_input_point(const Model<dim>          &model,
                            const std::vector<double> &xyz,
                            const std::string         &what);

    /** "(x y)" with 6 digits, for messages. */
    template <int dim>
    std::string
    point_text(const Point<dim> &p);

    /** The coordinates of @p p, for summary.json. */
    template <int dim>
    std::vector<double>
    coordinates(const Point<dim> &p);
  } // namespace analyses
} // namespace fdem
