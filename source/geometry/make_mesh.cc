// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/cases/block_on_plane.h>
#include <fdem/geometry/cases/hertz.h>
#include <fdem/geometry/cases/hertz_sphere.h>
#include <fdem/geometry/cases/slope.h>
#include <fdem/geometry/cases/wedge.h>
#include <fdem/geometry/gmsh_mesh.h>
#include <fdem/geometry/make_mesh.h>
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
#include <sstream>

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



    namespace
    {
      // Peak memory per degree of freedom of a run, measured on the paper's
      // slope at 4.1 million dofs (doc/scaling.md: 11590 MiB).
      constexpr double bytes_per_dof = 2950;
      // Nodes per area / h^2 of Gmsh's quadrilaterals there (2.06 million
      // nodes for 1550 m^2 at h = 0.035 m).
      constexpr double nodes_per_cell_area = 1.6;

      /**
       * Refuses a slope whose mesh would need more memory than allowed,
       * before Gmsh starts: Gmsh would otherwise grow without bound (Mesh
       * size = 1e-6) or mesh for minutes (0.01). The estimate: the area
       * between the ground and the base over the element size squared,
       * plus a band of the finer size along the sliding surface; two dofs
       * per node.
       */
      void
      check_slope_size(const parameters::GeometryParameters &geometry)
      {
        const Slope &slope = geometry.slope;
        const auto  &g     = slope.ground_surface;
        double       area = 0, length = 0;
        for (unsigned int i = 1; i < g.size(); ++i)
          {
            area += (g[i][0] - g[i - 1][0]) *
                    (0.5 * (g[i][1] + g[i - 1][1]) - slope.base_elevation);
            length += g[i].distance(g[i - 1]);
          }
        const double h   = slope.mesh_size;
        const double h_s = std::min(slope.mesh_size_on_sliding_surface, h);
        const double n_nodes =
          nodes_per_cell_area *
          std::min(area / (h_s * h_s),
                   area / (h * h) + length * h / (h_s * h_s));
        const double mib   = 2 * n_nodes * bytes_per_dof / (1 << 20);
        double       limit = geometry.memory_limit;
        if (limit == 0)
          limit = double(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGE_SIZE) /
                  (1 << 20);
        std::ostringstream message;
        message.precision(3);
        message << "Geometry/Slope/Mesh size: about " << n_nodes
                << " nodes, which would need about " << mib
                << " MiB, more than the " << limit
                << " MiB allowed (Geometry/Memory limit; 0 is this machine's "
                   "memory); use a coarser mesh or raise the limit.";
        AssertThrow(std::isfinite(mib) && mib <= limit,
                    ExcMessage(message.str()));
      }

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
              const std::string                    &prm_directory,
              const std::string                    &msh_output_file,
              const std::vector<std::string>       &material_names)
    {
      MeshDescription<dim> mesh;
      const MeshWatchdog   watchdog(geometry.time_limit,
                                  geometry.source == Source::mesh_file ?
                                      "Gmsh file '" +
                                      geometry.mesh_file_path(prm_directory) +
                                      "'" :
                                      "a built-in generator");
      if (geometry.source == Source::mesh_file)
        mesh = read_gmsh_file<dim>(geometry.mesh_file_path(prm_directory),
                                   material_names);
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
          if (geometry.source == Source::slope)
            check_slope_size(geometry);
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
                 const std::string &,
                 const std::vector<std::string> &);
    template MeshDescription<3>
    make_mesh<3>(const parameters::GeometryParameters &,
                 const std::string &,
                 const std::string &,
                 const std::vector<std::string> &);
    template void
    apply_transformation<2>(const parameters::GeometryParameters &,
                            MeshDescription<2> &);
    template void
    apply_transformation<3>(const parameters::GeometryParameters &,
                            MeshDescription<3> &);
  } // namespace geometry
} // namespace fdem
