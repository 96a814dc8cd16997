// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace fdem
{
  namespace parameters
  {
    using namespace dealii;

    /**
     * The subsection "Geometry": where the mesh comes from (a Gmsh file or
     * one of the built-in generators), the data of each generator, and a
     * rigid transformation plus scaling applied to every mesh afterwards
     * (used for the invariance tests of the method).
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
        inclined_block
      };

      /** Shape of the sliding surface of the slope generator. */
      enum class SlidingSurface
      {
        circular,
        polyline
      };

      /** Subsection "Slope": a 2D slope cut by one sliding surface. */
      struct Slope
      {
        /** Ground surface from left to right (m). */
        std::vector<Point<2>> ground_surface;
        /** Elevation of the bottom of the model (m). */
        double         base_elevation;
        SlidingSurface sliding_surface;
        /** Centre of the circular sliding surface (m). */
        Point<2> circle_centre;
        /** Radius of the circular sliding surface (m). */
        double circle_radius;
        /** Polyline sliding surface from left to right (m). */
        std::vector<Point<2>> sliding_surface_polyline;
        /** Element size away from the sliding surface (m). */
        double mesh_size;
        /** Element size on the sliding surface (m); mesh_size if 0 is given. */
        double mesh_size_on_sliding_surface;
      };

      /**
       * Subsection "Hertz": a cylinder pressed onto a foundation, as the
       * half model (x >= 0) or the full model, lengths in the user's unit
       * (e.g. mm).
       */
      struct Hertz
      {
        double radius;
        double foundation_width;
        double foundation_depth;
        /** Length from the axis over which both sides have nodes at equal x. */
        double       contact_zone_width;
        unsigned int n_contact_zone_elements;
        /** Element size far from the contact zone. */
        double mesh_size;
        /**
         * Whether to model the whole width (the half model and its mirror
         * image in x = 0) instead of the half model x >= 0.
         */
        bool full_model = false;
      };

      /** Subsection "Inclined block": a block on an inclined plane. */
      struct InclinedBlock
      {
        /** Angle of the plane with the x axis (degrees). */
        double inclination;
        double block_length;
        double block_height;
        double foundation_thickness;
        /** Length the foundation extends beyond each end of the block. */
        double       foundation_overhang;
        unsigned int n_elements_along_length;
        unsigned int n_elements_across_height;
      };

      Source source = Source::slope;
      /** The mesh file as written in the .prm file: see mesh_file_path(). */
      std::string mesh_file;

      /**
       * The transformation x -> R (s x) + t applied to every mesh; the
       * defaults leave it unchanged.
       */
      double scale_factor = 1;
      /** Angle of R (degrees), about z in 2D and about rotation_axis in 3D. */
      double rotation_angle = 0;
      /** Axis of R in 3D (a unit vector after parsing). */
      Tensor<1, 3> rotation_axis = Tensor<1, 3>({0., 0., 1.});
      /** The translation t, with 2 or 3 components as given. */
      std::vector<double> translation = {0, 0};

      Slope         slope;
      Hertz         hertz;
      InclinedBlock inclined_block;

      /** Declare the entries of the subsection "Geometry". */
      static void
      declare_parameters(ParameterHandler &prm);

      /** Read and check the subsection "Geometry"; throws on invalid data. */
      void
      parse_parameters(ParameterHandler &prm);

      /**
       * The mesh file to open: a relative name is taken relative to the
       * directory of the .prm file, @p prm_directory.
       */
      std::string
      mesh_file_path(const std::string &prm_directory) const;
    };
  } // namespace parameters
} // namespace fdem
