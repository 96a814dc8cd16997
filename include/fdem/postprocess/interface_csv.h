// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/contact/interface_pairs.h>
#include <fdem/postprocess/interface_output.h>

#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace fdem
{
  namespace postprocess
  {
    /**
     * The order in which interfaces.csv lists the pairs of one interface,
     * and each pair's coordinate along it (model length unit).
     *
     * In 2D the pairs are chained from one end of the interface to the
     * other, each time to the nearest pair not yet taken, starting at the
     * end that lies higher against gravity (the crest end of a slope's
     * sliding surface); the coordinate is the arc length along the polyline
     * through the pairs, 0 at that end. In 3D a surface has no such order:
     * the pairs are sorted by their distance down the dip of the
     * interface's mean plane (along the steepest descent in that plane,
     * from its highest pair); that distance is the coordinate. @p up is the
     * direction against gravity (any length).
     */
    template <int dim>
    struct SurfaceOrder
    {
      /** Indices of the pairs in the order of the table. */
      std::vector<unsigned int> order;
      /** Coordinate along the surface of each pair, by pair index. */
      std::vector<double> coordinate;
    };

    template <int dim>
    SurfaceOrder<dim>
    surface_order(const std::vector<PairResult<dim>> &results,
                  const dealii::Tensor<1, dim>       &up);

    /**
     * Writes all interfaces' pairs into one CSV table, each interface's
     * pairs in the order of surface_order() with their coordinate as column
     * `arc_length` (2D) or `down_dip_distance` (3D); `pair` is the pair's
     * index in the interface (as in the VTU files).
     */
    template <int dim>
    void
    write_interface_csv(
      const std::string                               &filename,
      const std::vector<contact::Interface<dim>>      &interfaces,
      const std::vector<std::vector<PairResult<dim>>> &results,
      const dealii::Tensor<1, dim>                    &up);
  } // namespace postprocess
} // namespace fdem
