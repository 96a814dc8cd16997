// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/geometry/cases/case_input.h>
#include <fdem/geometry/mesh_description.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    /**
     * The case "slope" (2D), subsection "Geometry/Slope": a slope cut by one
     * sliding surface, made by Gmsh (make_slope_mesh()).
     */
    struct Slope
    {
      /** Shape of the sliding surface. */
      enum class SlidingSurface
      {
        circular,
        polyline
      };

      /** Interslice surfaces from the interior vertices of the polyline. */
      enum class Interslices
      {
        none,
        vertical,
        bisector,
        inclination
      };

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
      /** Quadrilaterals or triangles. */
      ElementShape element_shape = ElementShape::hypercube;
      /** How the polyline's interior vertices cut the sliding mass. */
      Interslices interslice_surfaces = Interslices::none;
      /** Per interior vertex: inclination from the horizontal (degrees). */
      std::vector<double> interslice_inclinations;
      /** Depth of the vertical tension crack at the crest end (m); 0: none. */
      double tension_crack_depth = 0;
      /** Height of the water in the crack above its bottom (m). */
      double tension_crack_water_depth = 0;
      /**
       * Materials of the soil layers from the top down (names of
       * Materials/Names; one may come back lower down). Empty: no layers.
       */
      std::vector<std::string> layers;
      /**
       * The boundaries between consecutive layers, top down: polylines
       * across the whole model, each strictly below the one before
       * (slope_layers.cc).
       */
      std::vector<std::vector<Point<2>>> layer_boundaries;

      /** Declare the subsection "Slope" (inside "Geometry"). */
      static void
      declare_parameters(ParameterHandler &prm);

      /** Read the subsection "Slope" (inside "Geometry"). */
      void
      parse_parameters(ParameterHandler &prm);

      /** Throw a one-sentence message naming the entry if the data are
       * invalid. */
      void
      validate() const;

      /** The entries of the layers (slope_layers.cc), in "Slope". */
      static void
      declare_layer_parameters(ParameterHandler &prm);
      /** Reads the entries of the layers. */
      void
      parse_layer_parameters(ParameterHandler &prm);
      /** Checks the layers against the model's outline. */
      void
      validate_layers() const;
    };

    /**
     * Splits the model's surfaces by the layer boundaries of @p slope
     * (nothing without layers) in the current Gmsh model (OpenCASCADE,
     * synchronised): every surface of @p surface_groups and every curve of
     * @p curve_groups is replaced in its list by its pieces, and one
     * physical group of dimension 2 per layer material (slope.layers' names)
     * holds the pieces in its layers, across all blocks.
     */
    void
    split_into_layers(const Slope                           &slope,
                      const std::vector<std::vector<int> *> &surface_groups,
                      const std::vector<std::vector<int> *> &curve_groups);

    /**
     * A slope (the ground polyline closed down to the base elevation) split
     * by a circular or polyline sliding surface. Blocks "sliding mass" (the
     * part of the slope inside the circle, or above the polyline) and
     * "foundation". Face groups "sliding surface" (the curve between the two
     * blocks, with the same nodes on both sides), "ground" (the whole top
     * surface), "left", "right", "bottom". With interslices (polyline only)
     * the mass is cut into blocks "sliding mass 1..n" from left to right, on
     * "sliding surface 1..n", with "interslice 1..n-1" between blocks i and
     * i+1 (slope_interslices.h). A tension crack adds the face group
     * "tension crack" (a face of both blocks, not an interface). The elements
     * have the size mesh_size_on_sliding_surface there and grow to mesh_size
     * away from it. With layers, every block is split along the layer
     * boundaries and each layer's cells form a material region named after
     * its material. Opens its own GmshSession.
     */
    MeshDescription<2>
    make_slope_mesh(const Slope &slope);
  } // namespace geometry
} // namespace fdem
