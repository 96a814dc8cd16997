// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <array>

namespace fdem
{
  namespace blocks
  {
    using namespace dealii;

    /**
     * A node of a block on an interface: a support point of the finite
     * element with its dofs and its consistent nodal weights.
     */
    template <int dim>
    struct InterfaceNode
    {
      Point<dim>                               position;
      std::array<types::global_dof_index, dim> dofs;
      /** Tributary area A = int_Gamma phi dGamma (length in 2D, per unit
       * thickness). */
      double area = 0;
      /** int_Gamma phi n dGamma with n the block's outward normal. */
      Tensor<1, dim> area_normal;
      /**
       * Area of the node's faces in the group: the scale against which a
       * zero weight is recognised. At the vertices of quadratic triangles
       * (faces of P2 tetrahedra) int phi dGamma = 0 on every face; those
       * nodes get area = 0 exactly and no pair (contact::make_interface()).
       */
      double adjacent_area = 0;
    };
  } // namespace blocks
} // namespace fdem
