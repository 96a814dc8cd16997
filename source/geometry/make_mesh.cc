// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/cases/block_on_plane.h>
#include <fdem/geometry/cases/hertz.h>
#include <fdem/geometry/cases/hertz_sphere.h>
#include <fdem/geometry/cases/slope.h>
#include <fdem/geometry/cases/slope_3d.h>
#include <fdem/geometry/cases/wedge.h>
#include <fdem/geometry/gmsh_mesh.h>
#include <fdem/geometry/make_mesh.h>
#include <fdem/geometry/mesh_estimate.h>
#include <fdem/postprocess/results_folder.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/tensor.h>
#include <deal.II/physics/transformations.h>

#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstring>
#include <iostream>
#include <sstream>

namespace fdem
{
  namespace geometry
  {
    using Source = parameters::GeometryParameters::Source;

    namespace
    {
      /** The rotation R of x -> R (s x) + t. */
      template <int dim>
      Tensor<2, dim>
      rotation_of(const parameters::GeometryParameters &geometry)
      {
        const double angle = geometry.rotation_angle * numbers::PI / 180;
        if constexpr (dim == 2)
          return Physics::Transformations::Rotations::rotation_matrix_2d(angle);
        else
          return Physics::Transformations::Rotations::rotation_matrix_3d(
            geometry.rotation_axis / geometry.rotation_axis.norm(), angle);
      }

      /** The translation t of x -> R (s x) + t. */
      template <int dim>
      Tensor<1, dim>
      translation_of(const parameters::GeometryParameters &geometry)
      {
        const std::vector<double> &t = geometry.translation;
        Tensor<1, dim>             translation;
        for (unsigned int d = 0; d < std::min<std::size_t>(dim, t.size()); ++d)
          translation[d] = t[d];
        return translation;
      }
    } // namespace

    template <int dim>
    Point<dim>
    transformed_point(const parameters::GeometryParameters &geometry,
                      const Point<dim>                     &x)
    {
      return Point<dim>(rotation_of<dim>(geometry) *
                          (geometry.scale_factor * x) +
                        translation_of<dim>(geometry));
    }

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
      for (Point<dim> &vertex : mesh.vertices)
        vertex = transformed_point(geometry, vertex);
      for (auto &[name, point] : mesh.standing_water)
        point = transformed_point(geometry, point);
      // A normal at x' = R (s x) + t is R times the normal at x (s > 0 keeps
      // its sense).
      const Tensor<2, dim> R           = rotation_of<dim>(geometry);
      const Tensor<1, dim> translation = translation_of<dim>(geometry);
      const double         s           = geometry.scale_factor;
      for (auto &[name, normal] : mesh.surface_normals)
        normal = [R, translation, s, original = normal](const Point<dim> &x) {
          return R * original(Point<dim>(transpose(R) * (x - translation) / s));
        };
    }



    namespace
    {
      // Meshes of more elements than this are announced before they are
      // made: about 2 s of meshing on the paper's slope.
      constexpr double large_mesh = 5e4;

      // The message of the watchdog, made before it is armed: a signal
      // handler may not allocate.
      char timeout_message[2048] = "";

      extern "C" void
      mesh_time_limit_reached(int)
      {
        if (write(STDERR_FILENO,
                  timeout_message,
                  std::strlen(timeout_message)) < 0)
          {
            // Nothing else to tell.
          }
        postprocess::remove_partial_folder();
        _exit(1);
      }

      /**
       * Ends the process with a one-line error if making the mesh takes
       * longer than Geometry/Time limit: Gmsh cannot be interrupted from
       * outside (a .geo loop `For i In {1:1e12}` runs inside its parser), so
       * an alarm is the only bound.
       */
      class MeshWatchdog
      {
      public:
        MeshWatchdog(const double seconds, const std::string &what)
          : armed(seconds > 0)
        {
          if (!armed)
            return;
          const std::string message =
            "fdem-slope: error: Geometry/Time limit: making the mesh (" + what +
            ") took more than " + std::to_string(long(std::ceil(seconds))) +
            " s; a .geo loop that does not end, or a mesh far too fine?\n";
          // Every rank meshes and every rank's alarm ends it; rank 0 says why.
          const bool host =
            !Utilities::MPI::job_supports_mpi() ||
            Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
          std::strncpy(timeout_message,
                       host ? message.c_str() : "",
                       sizeof timeout_message - 1);
          std::signal(SIGALRM, mesh_time_limit_reached);
          alarm(static_cast<unsigned int>(std::ceil(seconds)));
        }
        ~MeshWatchdog()
        {
          if (!armed)
            return;
          alarm(0);
          std::signal(SIGALRM, SIG_DFL);
        }

      private:
        bool armed;
      };
    } // namespace



    template <int dim>
    MeshDescription<dim>
    make_mesh(const parameters::GeometryParameters &geometry,
              const std::string                    &msh_output_file,
              const unsigned int                    fe_degree,
              const std::vector<std::string>       &material_names,
              const bool                            dense_mixed_system)
    {
      // A mesh far too fine for this machine is refused before Gmsh or a
      // generator allocates it (Mesh size = 1e-6 grew without bound); a
      // long one is announced (Mesh size = 0.01 meshed for minutes
      // without a word).
      const bool host = !Utilities::MPI::job_supports_mpi() ||
                        Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      const auto refuse_or_announce = [&](const MeshEstimate &estimate) {
        check_mesh_estimate(
          estimate, geometry, dim, fe_degree, dense_mixed_system);
        if (host && estimate.n_cells > large_mesh)
          {
            std::ostringstream line;
            line.precision(2);
            line << "meshing ("
                 << estimate.entry.substr(0, estimate.entry.find(':'))
                 << "): about " << estimate.n_cells << " elements" << std::endl;
            std::cout << line.str() << std::flush;
          }
      };
      if (geometry.source != Source::mesh_file &&
          geometry.source_is_3d() == (dim == 3))
        refuse_or_announce(estimate_mesh(geometry));
      MeshDescription<dim> mesh;
      const MeshWatchdog   watchdog(geometry.time_limit,
                                  geometry.source == Source::mesh_file ?
                                      "Gmsh file '" + geometry.mesh_file + "'" :
                                      "a built-in generator");
      if (geometry.source == Source::mesh_file)
        {
          const std::string &file = geometry.mesh_file;
          mesh                    = read_gmsh_file<dim>(
            file,
            [&]() { refuse_or_announce(estimate_gmsh_geometry(dim, file)); },
            material_names);
        }
      else if (geometry.source_is_3d())
        {
          AssertThrow(dim == 3,
                      ExcMessage("Geometry/Source: the built-in generators "
                                 "wedge, block on plane, hertz sphere and "
                                 "slope 3d are "
                                 "3D only; set Dimension = 3."));
          if constexpr (dim == 3)
            mesh = (geometry.source == Source::wedge) ?
                     make_wedge_mesh(geometry.wedge) :
                   (geometry.source == Source::hertz_sphere) ?
                     make_hertz_sphere_mesh(geometry.hertz_sphere) :
                   (geometry.source == Source::slope_3d) ?
                     make_slope_3d_mesh(geometry.slope_3d) :
                     make_block_on_plane_mesh(geometry.block_on_plane);
        }
      else
        {
          AssertThrow(dim == 2,
                      ExcMessage("Geometry/Source: the built-in generators "
                                 "slope, hertz and inclined block are 2D "
                                 "only; in 3D use wedge, block on plane, hertz "
                                 "sphere, slope 3d or a mesh file."));
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
                 unsigned int,
                 const std::vector<std::string> &,
                 bool);
    template MeshDescription<3>
    make_mesh<3>(const parameters::GeometryParameters &,
                 const std::string &,
                 unsigned int,
                 const std::vector<std::string> &,
                 bool);
    template void
    apply_transformation<2>(const parameters::GeometryParameters &,
                            MeshDescription<2> &);
    template Point<2>
    transformed_point(const parameters::GeometryParameters &, const Point<2> &);
    template Point<3>
    transformed_point(const parameters::GeometryParameters &, const Point<3> &);
    template void
    apply_transformation<3>(const parameters::GeometryParameters &,
                            MeshDescription<3> &);
  } // namespace geometry
} // namespace fdem
