// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/geometry/cases/block_on_plane.h>
#include <fdem/geometry/cases/case_input.h>
#include <fdem/geometry/cases/hertz.h>
#include <fdem/geometry/cases/hertz_sphere.h>
#include <fdem/geometry/cases/slope.h>
#include <fdem/geometry/cases/slope_3d.h>
#include <fdem/geometry/cases/wedge.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace fdem
{
  namespace parameters
  {
    using namespace dealii;

    using PlaneOrientation = geometry::PlaneOrientation;

    /**
     * The subsection "Geometry": where the mesh comes from (a Gmsh file or
     * one of the built-in cases), and a rigid transformation plus scaling
     * applied to every mesh afterwards (used for the invariance tests of the
     * method). Each built-in case is one unit in geometry/cases/ with its
     * own subsection, parameters and generator; this struct holds one of
     * each and dispatches on Source.
     *
     * Only the subsection of the selected source is validated, so that a
     * .prm file can keep the data of other cases around.
     */
    struct GeometryParameters
    {
      /** Where the mesh comes from. */
      enum class Source
      {
        mesh_file,
        slope,
        hertz,
        inclined_block,
        wedge,
        block_on_plane,
        hertz_sphere,
        slope_3d
      };

      using ElementShape   = geometry::ElementShape;
      using Slope          = geometry::Slope;
      using SlidingSurface = geometry::Slope::SlidingSurface;
      using Hertz          = geometry::Hertz;
      /** The 2D block on plane (source "inclined block"). */
      using InclinedBlock = geometry::BlockOnPlane<2>;
      using Wedge         = geometry::Wedge;
      /** The 3D block on plane (source "block on plane"). */
      using BlockOnPlane = geometry::BlockOnPlane<3>;
      using HertzSphere  = geometry::HertzSphere;
      using Slope3D      = geometry::Slope3D;

      Source source = Source::slope;
      /** The mesh file, resolved relative to the file that names it. */
      std::string mesh_file;

      /**
       * The transformation x -> R (s x) + t applied to every mesh; the
       * defaults leave it unchanged.
       */
      double scale_factor = 1;
      /// Memory a built-in mesh may need (MiB); 0: the machine's memory.
      double memory_limit = 0;
      /// Time making the mesh may take (s); 0: no limit.
      double time_limit = 600;
      /// Time the work of a search or of the samples may be estimated to
      /// take (s); 0: no limit (parameters/work_estimate.h).
      double time_budget = 86400;
      /** Angle of R (degrees), about z in 2D and about rotation_axis in 3D. */
      double rotation_angle = 0;
      /** Axis of R in 3D (a unit vector after parsing). */
      Tensor<1, 3> rotation_axis = Tensor<1, 3>({0., 0., 1.});
      /** The translation t, with 2 or 3 components as given. */
      std::vector<double> translation = {0, 0};

      Slope         slope;
      Hertz         hertz;
      InclinedBlock inclined_block;
      Wedge         wedge;
      BlockOnPlane  block_on_plane;
      HertzSphere   hertz_sphere;
      Slope3D       slope_3d;

      /** Whether the selected source builds 3D models (only). */
      bool
      source_is_3d() const;

      /** Declare the entries of the subsection "Geometry". */
      static void
      declare_parameters(ParameterHandler &prm);

      /**
       * Read and check the subsection "Geometry"; throws on invalid data.
       * Files it names (a mesh, a terrain) are as the handler gives them,
       * resolved relative to the file that names them (parameter_file.h).
       */
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace parameters
} // namespace fdem
