// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#ifndef fdem_geometry_mesh_estimate_h
#define fdem_geometry_mesh_estimate_h

#include <fdem/parameters/geometry_parameters.h>

#include <string>

namespace fdem
{
  namespace geometry
  {
    /**
     * The size of the mesh a built-in generator would make, estimated from
     * its parameters alone, before Gmsh or the generator allocates
     * anything: a mesh far too fine (Mesh size = 1e-6, Foundation width =
     * 1e308) would otherwise grow without bound in memory or time.
     */
    struct MeshEstimate
    {
      /** The entry that sets the element size, e.g. "Geometry/Hertz/Mesh size".
       */
      std::string entry;
      /** Cells and vertices of the mesh (not finite: too many to count). */
      double n_cells    = 0;
      double n_vertices = 0;
      /** Node pairs on the interfaces the generator makes. */
      double n_pairs = 0;

      /**
       * The peak memory of a run on this mesh (MiB), with elements of
       * degree @p fe_degree: about 2950 bytes per degree of freedom (the
       * FE part, measured on the paper's slope) plus, with the dense mixed
       * system (@p dense_mixed_system), 150 bytes per entry of a dense
       * (dim pairs)^2 matrix (the dense interface parts: about 15 such
       * matrices alive at the peak, measured on prm/slope_3d.prm, and a
       * margin), or with the iterative one, which never forms them, a
       * fixed amount per pair (measured on prm/block_on_plane_3d.prm up to
       * 10^4 pairs), doc/scaling.md.
       */
      double
      memory_MiB(unsigned int dim,
                 unsigned int fe_degree,
                 bool         dense_mixed_system = true) const;
    };

    /**
     * The estimate for the built-in generator of @p geometry (not for a
     * mesh file: MeshEstimate::entry is then empty).
     */
    MeshEstimate
    estimate_mesh(const parameters::GeometryParameters &geometry);

    /**
     * The estimate for the geometry Gmsh has just read from @p file_name
     * (a .geo file), in the open GmshSession: Gmsh meshes the boundaries
     * (curves in 2D, surfaces in 3D), then each block is taken to hold as
     * many elements as the roundest shape of that boundary would, at the
     * boundary's element size. Interface pairs are not estimated.
     */
    MeshEstimate
    estimate_gmsh_geometry(unsigned int dim, const std::string &file_name);

    /**
     * The memory a mesh may need (MiB): Geometry/Memory limit, or if that is
     * 0 the smaller of this machine's physical memory and the process's
     * address space limit (ulimit -v).
     */
    double
    memory_limit_MiB(const parameters::GeometryParameters &geometry);

    /**
     * Throws a one-line error naming the entry that sets the element size,
     * the estimate and Geometry/Memory limit (the override) if the mesh of
     * the built-in generator would need more memory than allowed; returns
     * the estimate otherwise.
     */
    MeshEstimate
    check_mesh_estimate(const parameters::GeometryParameters &geometry,
                        unsigned int                          dim,
                        unsigned int                          fe_degree,
                        bool dense_mixed_system = true);

    /** The same for the estimate @p estimate. */
    MeshEstimate
    check_mesh_estimate(const MeshEstimate                   &estimate,
                        const parameters::GeometryParameters &geometry,
                        unsigned int                          dim,
                        unsigned int                          fe_degree,
                        bool dense_mixed_system = true);
  } // namespace geometry
} // namespace fdem

#endif
