// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/elastic_block.h>
#include <fdem/postprocess/vtu_writer.h>

#include <string>

namespace fdem
{
  namespace postprocess
  {
    /**
     * Writes one block's VTU file (doc/output.md): displacement, the
     * mechanism displacement if @p mechanism is given, the Cauchy stress as
     * a 3 x 3 tensor (sigma_zz of plane strain in its zz entry in 2D, and
     * again as "stress_zz"), the block index as cell data, and the field
     * data of @p state. Every cell is written on its own points (the
     * support points of its element), so that the stress, discontinuous
     * between cells, is shown cell by cell. Returns the file name relative
     * to @p directory. Writes only on rank 0 of the block's communicator
     * (every rank holds the whole block); not collective.
     */
    template <int dim>
    std::string
    write_block_vtu(const blocks::ElasticBlock<dim> &block,
                    const unsigned int               block_index,
                    const dealii::Vector<double>    &displacement,
                    const dealii::Vector<double>    *mechanism,
                    const OutputState               &state,
                    const std::string               &directory,
                    const std::string               &suffix);

    /**
     * Points of the reference cell (or face) at which the output evaluates
     * the fields, and the cells (VTK type and nodes) made of them: the
     * support points of the element of @p degree (the lexicographic grid of
     * FE_Q, the vertices and edge midpoints of FE_SimplexP), cut into
     * linear cells on hypercubes and written as linear or quadratic cells on
     * simplices.
     */
    template <int celldim>
    struct ReferencePatch
    {
      ReferencePatch(const bool simplex, const unsigned int degree);

      std::vector<dealii::Point<celldim>> points;
      std::vector<std::pair<VtuWriter::CellType, std::vector<unsigned int>>>
        cells;
    };
  } // namespace postprocess
} // namespace fdem
