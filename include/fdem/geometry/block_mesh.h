// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/geometry/mesh_description.h>

#include <deal.II/grid/tria.h>

#include <vector>

namespace fdem
{
  namespace geometry
  {
    /** Boundary id of boundary faces that belong to no named face group. */
    constexpr types::boundary_id unnamed_boundary_id = 999999;

    /**
     * Builds the triangulation of the blocks whose indices are listed in
     * @p blocks (one block: an elastic body of the mixed method; all blocks:
     * the merged mesh of a plain FE model). Vertices shared with other blocks
     * are copied, which duplicates the nodes along the interfaces. Cells get
     * their MeshDescription::material_key() as material id (the block index
     * for cells of the block's own material); boundary faces get the index of
     * their face group as boundary id, or unnamed_boundary_id.
     */
    template <int dim>
    void
    create_block_triangulation(const MeshDescription<dim>      &mesh,
                               const std::vector<unsigned int> &blocks,
                               Triangulation<dim>              &triangulation);
  } // namespace geometry
} // namespace fdem
