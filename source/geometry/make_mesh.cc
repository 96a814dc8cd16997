// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/generators.h>
#include <fdem/geometry/generators_3d.h>
#include <fdem/geometry/gmsh_mesh.h>
#include <fdem/geometry/make_mesh.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cmath>

namespace fdem
{
  namespace geometry
  {
    using Source = parameters::GeometryParameters::Source;

    template <int dim>
    void
    apply_transformation(const parameters::GeometryParameters &geometry,
                         MeshDescription<dim>                 &mesh)
    {
      const std::vector<double> &t = geometry.translation;
      AssertThrow(dim == 3 || t.size() < 3 || t[2] == 0,
                  ExcMessage("Geometry/Translation: a 2D model has no z "
                             "component to translate, so a third number must "
                             "be 0."));
      Tensor<1, dim> translation;
      for (unsigned int d = 0; d < std::min<std::size_t>(dim, t.size()); ++d)
        translation[d] = t[d];

      // Rodrigues' formula R = cos a I + sin a [k]x + (1 - cos a) k k^T,
      // with k = e_z in 2D (the upper left 2x2 block).
      const double angle = geometry.rotation_angle * numbers::PI / 180;
      Tensor<1, 3> axis;
      if (dim == 2)
        axis[2] = 1;
      else
        axis = geometry.rotation_axis / geometry.rotation_axis.norm();
      Tensor<2, 3> cross_product_matrix; // [k]x v = k x v
      cross_product_matrix[0][1] = -axis[2];
      cross_product_matrix[0][2] = axis[1];
      cross_product_matrix[1][0] = axis[2];
      cross_product_matrix[1][2] = -axis[0];
      cross_product_matrix[2][0] = -axis[1];
      cross_product_matrix[2][1] = axis[0];
      const Tensor<2, 3> rotation_3d =
        std::cos(angle) * Tensor<2, 3>(unit_symmetric_tensor<3>()) +
        std::sin(angle) * cross_product_matrix +
        (1 - std::cos(angle)) * outer_product(axis, axis);
      Tensor<2, dim> rotation;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          rotation[i][j] = rotation_3d[i][j];

      for (Point<dim> &vertex : mesh.vertices)
        vertex =
          Point<dim>(rotation * (geometry.scale_factor * vertex) + translation);
    }



    template <int dim>
    MeshDescription<dim>
    make_mesh(const parameters::GeometryParameters &geometry,
              const std::string                    &prm_directory,
              const std::string                    &msh_output_file)
    {
      MeshDescription<dim> mesh;
      if (geometry.source == Source::mesh_file)
        mesh = read_gmsh_file<dim>(geometry.mesh_file_path(prm_directory));
      else if (geometry.source_is_3d())
        {
          AssertThrow(dim == 3,
                      ExcMessage("Geometry/Source: the built-in generators "
                                 "wedge, block on plane and hertz sphere are "
                                 "3D only; set Dimension = 3."));
          if constexpr (dim == 3)
            mesh = (geometry.source == Source::wedge) ?
                     make_wedge_mesh(geometry.wedge) :
                   (geometry.source == Source::hertz_sphere) ?
                     make_hertz_sphere_mesh(geometry.hertz_sphere) :
                     make_block_on_plane_mesh(geometry.block_on_plane);
        }
      else
        {
          AssertThrow(dim == 2,
                      ExcMessage("Geometry/Source: the built-in generators "
                                 "slope, hertz and inclined block are 2D "
                                 "only; in 3D use wedge, block on plane, hertz "
                                 "sphere or a mesh file."));
          if constexpr (dim == 2)
            mesh = (geometry.source == Source::slope) ?
                     make_slope_mesh(geometry.slope) :
                   (geometry.source == Source::hertz) ?
                     make_hertz_mesh(geometry.hertz) :
                     make_inclined_block_mesh(geometry.inclined_block);
        }

      apply_transformation(geometry, mesh);
      if (!msh_output_file.empty())
        write_gmsh_file(mesh, msh_output_file);
      return mesh;
    }



    template MeshDescription<2>
    make_mesh<2>(const parameters::GeometryParameters &,
                 const std::string &,
                 const std::string &);
    template MeshDescription<3>
    make_mesh<3>(const parameters::GeometryParameters &,
                 const std::string &,
                 const std::string &);
    template void
    apply_transformation<2>(const parameters::GeometryParameters &,
                            MeshDescription<2> &);
    template void
    apply_transformation<3>(const parameters::GeometryParameters &,
                            MeshDescription<3> &);
  } // namespace geometry
} // namespace fdem
