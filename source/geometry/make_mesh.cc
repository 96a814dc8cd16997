// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/cases/block_on_plane.h>
#include <fdem/geometry/cases/hertz.h>
#include <fdem/geometry/cases/hertz_sphere.h>
#include <fdem/geometry/cases/slope.h>
#include <fdem/geometry/cases/wedge.h>
#include <fdem/geometry/gmsh_mesh.h>
#include <fdem/geometry/make_mesh.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/tensor.h>
#include <deal.II/physics/transformations.h>

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

      const double   angle = geometry.rotation_angle * numbers::PI / 180;
      Tensor<2, dim> rotation;
      if constexpr (dim == 2)
        rotation =
          Physics::Transformations::Rotations::rotation_matrix_2d(angle);
      else
        rotation = Physics::Transformations::Rotations::rotation_matrix_3d(
          geometry.rotation_axis / geometry.rotation_axis.norm(), angle);

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
                     make_block_on_plane_mesh(geometry.inclined_block);
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
