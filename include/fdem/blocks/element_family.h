// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/geometry/mesh_description.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>

#include <memory>

namespace fdem
{
  namespace blocks
  {
    using namespace dealii;

    /**
     * The finite element family of a block, chosen from the shape of its
     * mesh's cells: Lagrange elements FE_Q on quadrilaterals and hexahedra
     * with MappingQ(1) and Gauss rules, FE_SimplexP on triangles and
     * tetrahedra with the linear MappingFE and Gauss rules for simplices.
     * A mesh holds one shape only (geometry::extract_current_gmsh_model()
     * rejects mixed meshes, which would need hp).
     */
    template <int dim>
    struct ElementFamily
    {
      /** The family of the cells of @p mesh (all of one shape). */
      explicit ElementFamily(const geometry::MeshDescription<dim> &mesh,
                             const unsigned int                    degree);

      /** Whether the cells are triangles (2D) or tetrahedra (3D). */
      bool         simplex;
      unsigned int degree;

      /** The scalar element of the given degree (FE_Q or FE_SimplexP). */
      std::unique_ptr<FiniteElement<dim>>
      scalar_element() const;

      /** The (affine or multilinear) mapping of the cells. */
      std::unique_ptr<Mapping<dim>>
      mapping() const;

      /**
       * A cell rule exact for polynomials of degree 2 n - 1: Gauss with n
       * points per direction, or its simplex counterpart.
       */
      Quadrature<dim>
      cell_quadrature(const unsigned int n_points_1d) const;

      /** The same on a face (a line in 2D for both shapes). */
      Quadrature<dim - 1>
      face_quadrature(const unsigned int n_points_1d) const;
    };

    /**
     * Whether every cell of @p mesh is a simplex (dim + 1 vertices); false
     * if every cell is a hypercube. Throws for a mesh with both.
     */
    template <int dim>
    bool
    is_simplex_mesh(const geometry::MeshDescription<dim> &mesh);
  } // namespace blocks
} // namespace fdem
