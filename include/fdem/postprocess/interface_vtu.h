// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/elastic_block.h>
#include <fdem/contact/interface_pairs.h>
#include <fdem/postprocess/interface_output.h>
#include <fdem/postprocess/vtu_writer.h>

#include <string>
#include <vector>

namespace fdem
{
  namespace postprocess
  {
    /**
     * Values of the integer field "status" of the interface files: a
     * pair's status (contact::PairStatus: 0 stick, 1 slip, 2 open), or
     * a node of the interface's faces that is no pair of it.
     */
    enum class NodeStatus : std::int32_t
    {
      stick = 0,
      slip  = 1,
      open  = 2,
      /** A node without a partner on the other side. */
      unpaired = 3,
      /**
       * A node paired on an interface listed before (the line where two
       * planes of a wedge meet): its pair is in that interface's file.
       */
      paired_elsewhere = 4
    };

    /** The meaning of each value of "status", as written into the files' field
     * data. */
    std::string
    node_status_meaning();

    /**
     * Writes the interface as a surface (a line in 2D) on block J's faces
     * (doc/output.md): the pair results at the nodes of the pairs, NaN at
     * the other nodes; the integer status (NodeStatus); the displacement of
     * block J, and the mechanism displacement if @p mechanism_J is given,
     * at every node, so that the surface moves with block J when warped;
     * and the field data of @p state. @p shared_positions are the nodes
     * paired on an interface listed before. Returns the file name; only
     * rank 0 of block J's communicator writes (not collective).
     */
    template <int dim>
    std::string
    write_interface_vtu(const blocks::ElasticBlock<dim>       &block_J,
                        const contact::Interface<dim>         &interface,
                        const std::vector<PairResult<dim>>    &results,
                        const std::vector<dealii::Point<dim>> &shared_positions,
                        const dealii::Vector<double>          &displacement_J,
                        const dealii::Vector<double>          *mechanism_J,
                        const OutputState                     &state,
                        const std::string                     &directory,
                        const std::string                     &suffix);
  } // namespace postprocess
} // namespace fdem
