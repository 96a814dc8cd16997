// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/blocks/element_family.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>

#include <algorithm>

namespace fdem
{
  namespace blocks
  {
    template <int dim>
    bool
    is_simplex_mesh(const geometry::MeshDescription<dim> &mesh)
    {
      const auto is_simplex = [](const CellData<dim> &cell) {
        return cell.vertices.size() == dim + 1;
      };
      const bool simplex =
        !mesh.cells.empty() && is_simplex(mesh.cells.front());
      AssertThrow(std::all_of(mesh.cells.begin(),
                              mesh.cells.end(),
                              [&](const CellData<dim> &cell) {
                                return is_simplex(cell) == simplex;
                              }),
                  ExcMessage(mesh.source + ": the mesh mixes simplices and " +
                             (dim == 2 ? "quadrilaterals" : "hexahedra") +
                             "; only meshes of one element shape are "
                             "supported."));
      return simplex;
    }

    template <int dim>
    ElementFamily<dim>::ElementFamily(
      const geometry::MeshDescription<dim> &mesh,
      const unsigned int                    degree)
      : simplex(is_simplex_mesh(mesh))
      , degree(degree)
    {}

    template <int dim>
    std::unique_ptr<FiniteElement<dim>>
    ElementFamily<dim>::scalar_element() const
    {
      if (simplex)
        return std::make_unique<FE_SimplexP<dim>>(degree);
      return std::make_unique<FE_Q<dim>>(degree);
    }

    template <int dim>
    std::unique_ptr<Mapping<dim>>
    ElementFamily<dim>::mapping() const
    {
      if (simplex)
        return std::make_unique<MappingFE<dim>>(FE_SimplexP<dim>(1));
      return std::make_unique<MappingQ<dim>>(1);
    }

    template <int dim>
    Quadrature<dim>
    ElementFamily<dim>::cell_quadrature(const unsigned int n_points_1d) const
    {
      if (simplex)
        return QGaussSimplex<dim>(n_points_1d);
      return QGauss<dim>(n_points_1d);
    }

    template <int dim>
    Quadrature<dim - 1>
    ElementFamily<dim>::face_quadrature(const unsigned int n_points_1d) const
    {
      // A triangle's faces are lines, like a quadrilateral's.
      if (simplex && dim == 3)
        return QGaussSimplex<dim - 1>(n_points_1d);
      return QGauss<dim - 1>(n_points_1d);
    }

    template struct ElementFamily<2>;
    template struct ElementFamily<3>;
    template bool
    is_simplex_mesh(const geometry::MeshDescription<2> &);
    template bool
    is_simplex_mesh(const geometry::MeshDescription<3> &);
  } // namespace blocks
} // namespace fdem
