// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/geometry/cases/case_input.h>
#include <fdem/geometry/cases/terrain.h>
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
     * The case "slope 3d", subsection "Geometry/Slope 3D": a straight slope
     * extruded along its strike (y), cut by a curved sliding surface, made
     * by Gmsh (make_slope_3d_mesh()). x points into the slope (the toe
     * is at x = Toe length, the crest edge behind it), z up. The section
     * of the ground is (0, z_t), (L_t, z_t), (L_t + H cot beta, z_t + H),
     * (L_t + H cot beta + L_c, z_t + H), the base is at z_t - D, and the
     * model spans 0 <= y <= W. With a terrain file the ground is the
     * terrain's bilinear surface instead, the model spans the terrain's
     * grid in x and y, and its base is Base depth below the terrain's
     * lowest point.
     */
    struct Slope3D
    {
      /** The shape of the sliding surface. */
      enum class Surface
      {
        /** Semi-axes R (x and z) and b (y). */
        ellipsoid,
        /** Radius R. */
        sphere,
        /** Radius R, axis along y through the whole width. */
        cylinder,
        /**
         * A cylinder of radius R along y over the straight length 2 L_0,
         * closed at both ends by half-ellipsoids with semi-axes R (x and
         * z) and b (y): a long slide with rounded ends, Baligh & Azzouz
         * (1975)'s cylinder with ends.
         */
        capsule
      };

      /** Height H of the slope (m). */
      double slope_height;
      /** Angle beta of the slope face to the horizontal (degrees). */
      double slope_angle;
      /** Length L_t of the ground in front of the toe (m). */
      double toe_length;
      /** Length L_c of the ground behind the crest edge (m). */
      double crest_length;
      /** Elevation z_t of the toe (m). */
      double toe_elevation;
      /** Depth D of the base below the toe (m). */
      double base_depth;
      /** Width W along the strike (m). */
      double   width;
      Surface  surface;
      Point<3> centre;
      /** R: radius of the sphere and cylinder, semi-axis in x and z. */
      double radius;
      /** b: the ellipsoid's (and the capsule's ends') semi-axis along y. */
      double half_length;
      /** 2 L_0: the capsule's straight length along y (m). */
      double straight_length = 0;
      /** Element size h near the sliding surface (m). */
      double mesh_size;
      /** Hexahedra or tetrahedra. */
      ElementShape element_shape = ElementShape::hypercube;
      /**
       * Soil layers from the top down, each a material name (Materials/
       * Names); empty: none (each block of its own material).
       */
      std::vector<std::string> layers;
      /**
       * The boundaries between consecutive layers in the section: polylines
       * (x, z) with increasing x, running unchanged along y.
       */
      std::vector<std::vector<Point<2>>> layer_boundaries;

      /**
       * The terrain file's name as given (empty: the straight slope), and
       * the grid read from it (relative to the .prm file's directory).
       */
      std::string terrain_file;
      TerrainGrid terrain;
      /** The grid spacing a Gmsh surface as terrain is sampled at (0: Mesh
       * size). */
      double terrain_spacing = 0;

      /** x of the crest edge, L_t + H cot beta (the straight slope). */
      double
      crest_x() const;

      /** The model's extent: 0 to crest_x() + L_c in x and 0 to W in y, or
       * the terrain grid's. */
      double
      x_min() const;
      double
      x_max() const;
      double
      y_min() const;
      double
      y_max() const;

      /** z of the base: z_t - D, or D below the terrain's lowest point. */
      double
      base_elevation() const;

      /** The highest z of the ground. */
      double
      top_elevation() const;

      /** z of the ground at (@p x, @p y). */
      double
      ground(const double x, const double y) const;

      /**
       * The ground's gradient (dz/dx, dz/dy) at (@p x, @p y): of the plane
       * the point is on, the slope face's only strictly between the toe
       * and the crest edge.
       */
      Tensor<1, 2>
      ground_gradient(const double x, const double y) const;

      /**
       * The lowest ground over y at each x, a polyline with increasing x
       * across the model: the section's ground line of the straight slope.
       */
      std::vector<Point<2>>
      ground_profile() const;

      /** The volume of the model: below the ground, above the base. */
      double
      model_volume() const;

      /**
       * The surface's implicit function at @p p: negative inside the
       * surface, zero on it, ((x - x_c)/R)^2 + (a(y)/b)^2 + ((z - z_c)/R)^2
       * - 1 with the axial offset a(y) = y - y_c (none for the cylinder;
       * for the capsule the distance beyond its straight part, signed).
       * The capsule's is a quadric on each piece, continuous with its
       * gradient (slope_3d_surface.cc).
       */
      double
      quadric(const Point<3> &p) const;

      /** The gradient of quadric() at @p p: normal to the sliding surface
       * there, pointing out of the sliding mass. */
      Tensor<1, 3>
      quadric_gradient(const Point<3> &p) const;

      /**
       * The point of the surface at the parameters @p s in [0, 1] along y
       * (pole to pole; for the cylinder, y = s W) and @p phi (the angle
       * about the axis along y, from +x towards +z).
       */
      Point<3>
      surface_point(const double s, const double phi) const;

      /**
       * The point of the surface reached from @p p along @p d: p + t d on
       * the surface with |t| smallest (on the capsule, of the pieces on
       * which the point lands).
       */
      Point<3>
      along_onto_surface(const Point<3> &p, const Tensor<1, 3> &d) const;

      /** Declare the subsection "Slope 3D" (inside "Geometry"). */
      static void
      declare_parameters(ParameterHandler &prm);

      /** Read the subsection "Slope 3D" (inside "Geometry"). */
      void
      parse_parameters(ParameterHandler &prm);

      /**
       * Read the terrain file, if one is named (before validate()); its name
       * as the parameter handler resolved it (parameter_file.h).
       */
      void
      load_terrain();

      /**
       * Throw a one-sentence message naming the entry if the data are
       * invalid: also if the sliding surface does not cut the ground, does
       * not daylight on the slope face, or leaves the model below the
       * ground (checked on points of the surface 1/720 of a turn apart).
       */
      void
      validate() const;

      /** The axial offset a(y) of quadric(). */
      double
      axial_offset(const double y) const;
    };

    /**
     * The 3D slope of @p slope: the slope solid and the solid inside the
     * sliding surface are intersected (the sliding mass) and fragmented
     * (OpenCASCADE), so that the sliding surface is one conforming set of
     * faces shared by the blocks "sliding mass" and "foundation". Face
     * groups: "sliding surface", "ground" (the free surface), "base"
     * (z = z_t - D) and "sides" (x = 0, x = L, y = 0, y = W; with a
     * cylinder the ends of the sliding mass too). Gmsh's Delaunay
     * tetrahedra of size 2 h near the sliding surface (within R/4),
     * growing to 6 h, each split into four hexahedra (the split's new
     * vertices on the sliding surface moved onto it, but those whose move
     * would twist a cell), or tetrahedra of size h. The face group "sliding
     * surface" carries the surface's exact normal
     * (MeshDescription::surface_normals). Opens its own GmshSession.
     */
    MeshDescription<3>
    make_slope_3d_mesh(const Slope3D &slope);

    /**
     * Adds the solid of @p slope's model to the current Gmsh model
     * (OpenCASCADE) and returns its volume's tag: the section extruded
     * along y, or with a terrain the solid through the grid's sections
     * along x at each y of the grid, joined by ruled faces (bilinear on
     * each cell, as TerrainGrid::elevation()) (slope_3d_ground.cc).
     */
    int
    add_slope_3d_solid(const Slope3D &slope);

    /**
     * Splits the volumes of @p volume_groups of the current Gmsh model
     * (OpenCASCADE, synchronised) by the layer boundaries of @p slope
     * (nothing without layers), each running along y: every volume is
     * replaced in its list by its pieces, and one physical group of
     * dimension 3 per layer material holds the pieces in its layers, across
     * both blocks (slope_3d_layers.cc). The faces are renumbered: classify
     * them afterwards.
     */
    void
    split_into_layers(const Slope3D                         &slope,
                      const std::vector<std::vector<int> *> &volume_groups);
  } // namespace geometry
} // namespace fdem
