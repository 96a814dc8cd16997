// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>

#include <vector>

namespace fdem
{
  namespace blocks
  {
    using namespace dealii;

    /** Number of rigid-body modes: 3 in 2D, 6 in 3D (the paper's eq. 1). */
    template <int dim>
    constexpr unsigned int n_rigid_modes = (dim == 2 ? 3 : 6);

    /**
     * Displacement at @p x of rigid mode @p mode about @p centre (the
     * paper's eq. 1, omega): translations first, then rotations. A rotation
     * column is multiplied by @p length so that all unknowns are lengths and
     * the mixed system does not depend on the units (radians times length).
     */
    template <int dim>
    Tensor<1, dim>
    rigid_mode(const unsigned int mode,
               const Point<dim>  &x,
               const Point<dim>  &centre,
               const double       length);

    /**
     * The rigid motions that the constraints leave free: an orthonormal basis
     * (n_rigid_modes x n_free) of the null space of the constraint rows
     * evaluated on the rigid modes. @p modes_at_dofs holds, for every dof,
     * the values of the rigid modes at that dof (n_dofs x n_rigid_modes).
     */
    FullMatrix<double>
    free_rigid_modes(const AffineConstraints<double> &constraints,
                     const FullMatrix<double>        &modes_at_dofs);

    /**
     * Chooses a minimal, statically determinate support for the free modes
     * @p free_modes: dofs of @p candidates whose rigid motion rows are
     * independent, each time the one least explained by those chosen
     * (pivoted Gram-Schmidt), until they remove every free mode.
     * Returns the chosen dofs (as many as free modes), or fewer if the
     * candidates cannot hold the block.
     */
    std::vector<types::global_dof_index>
    minimal_support_dofs(
      const FullMatrix<double>                   &free_modes,
      const FullMatrix<double>                   &modes_at_dofs,
      const std::vector<types::global_dof_index> &candidates);
  } // namespace blocks
} // namespace fdem
