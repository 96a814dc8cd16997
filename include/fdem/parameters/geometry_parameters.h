// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <string>
#include <vector>

namespace fdem
{
  namespace parameters
  {
    using namespace dealii;

    /**
     * Orientation of a plane in 3D by its dip and dip direction, with x =
     * east, y = north and z = up.
     */
    struct PlaneOrientation
    {
      /** Dip psi: angle below the horizontal (degrees, 0 to 90). */
      double dip = 0;
      /**
       * Dip direction alpha: azimuth of the line of steepest descent
       * (degrees clockwise from north, 0 to 360).
       */
      double dip_direction = 0;

      /**
       * The upward unit normal n = (sin psi sin alpha, sin psi cos alpha,
       * cos psi).
       */
      Tensor<1, 3>
      upward_normal() const;

      /**
       * The unit vector down the line of steepest descent,
       * (cos psi sin alpha, cos psi cos alpha, -sin psi); horizontal towards
       * the dip direction for a horizontal plane.
       */
      Tensor<1, 3>
      down_dip_direction() const;
    };

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
        inclined_block,
        wedge,
        block_on_plane,
        hertz_sphere
      };

      /**
       * Shape of the cells a generator makes: quadrilaterals or hexahedra
       * (FE_Q), or triangles or tetrahedra (FE_SimplexP).
       */
      enum class ElementShape
      {
        hypercube,
        simplex
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
        /** Quadrilaterals or triangles. */
        ElementShape element_shape = ElementShape::hypercube;
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
        /** Quadrilaterals or triangles. */
        ElementShape element_shape = ElementShape::hypercube;
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
        /** Quadrilaterals, or each split into two triangles. */
        ElementShape element_shape = ElementShape::hypercube;
      };

      /**
       * Subsection "Wedge": a tetrahedral rock wedge cut from a slope by two
       * joint planes A and B (3D). The apex of the wedge, where the line of
       * intersection of A and B daylights in the slope face, is the origin,
       * on the toe of the slope face (z = 0); the crest passes through the
       * point at height H straight up the face's line of steepest ascent
       * from there, crest_point().
       */
      struct Wedge
      {
        /** Height H of the slope face, from the toe (z = 0) to the crest (m).
         */
        double           slope_height;
        PlaneOrientation slope_face;
        PlaneOrientation upper_slope;
        PlaneOrientation plane_a;
        PlaneOrientation plane_b;
        /**
         * Element size h in and near the wedge (m): tetrahedra of size 2 h,
         * each split into four hexahedra, or tetrahedra of size h.
         */
        double mesh_size;
        /** Hexahedra or tetrahedra. */
        ElementShape element_shape = ElementShape::hypercube;
        /**
         * Least distance from the wedge to the sides, back and base of the
         * rock, and length of the ground in front of the toe (m); 2 H if 0
         * is given.
         */
        double rock_extent;

        /**
         * The point of the crest above the apex, (-H cot psi sin alpha,
         * -H cot psi cos alpha, H) with the slope face's dip psi and dip
         * direction alpha.
         */
        Point<3>
        crest_point() const;

        /**
         * The corners of the wedge: the apex (the origin: slope face, A, B),
         * the top of the line of intersection (upper slope, A, B), and the
         * ends of its crest edge on A (slope face, upper slope, A) and on B
         * (slope face, upper slope, B). Throws if the planes do not form a
         * wedge that daylights in the slope face: the line of intersection
         * must run from the apex up into the rock behind the face and reach
         * the upper slope, and the crest edge must lie above the toe.
         */
        std::array<Point<3>, 4>
        corners() const;
      };

      /**
       * Subsection "Block on plane": a block on an inclined plane in 3D,
       * structured hexahedra. In the plane's frame (x down-dip, y along
       * strike, z normal to the plane, up) the block is
       * [0, L] x [-B/2, B/2] x [0, H] and the foundation slab
       * [-o, L + o] x [-B/2 - o, B/2 + o] x [-T, 0], with o the overhang.
       */
      struct BlockOnPlane
      {
        PlaneOrientation plane;
        /** Block length L down the dip (m). */
        double block_length;
        /** Block width B along the strike (m). */
        double block_width;
        /** Block height H normal to the plane (m). */
        double block_height;
        /** Thickness T of the foundation slab (m). */
        double foundation_thickness;
        /** Length the foundation extends beyond the block on every side (m). */
        double       foundation_overhang;
        unsigned int n_elements_along_length;
        unsigned int n_elements_along_width;
        unsigned int n_elements_across_height;

        /**
         * The rotation from the plane's frame to x, y, z: its columns are
         * the down-dip direction, the strike direction (normal x down-dip)
         * and the upward normal.
         */
        Tensor<2, 3>
        rotation() const;
      };

      /**
       * Subsection "Hertz sphere": a sphere of radius R pressed onto a
       * foundation (3D), as the quarter model x >= 0, y >= 0 with two
       * symmetry planes. The sphere touches the foundation's top z = 0 at
       * the origin; it is truncated by the planes x = S, y = S (free) and
       * z = H (loaded). Lengths in the user's unit (e.g. mm).
       */
      struct HertzSphere
      {
        /** Radius R of the sphere. */
        double radius;
        /** Height H of the sphere's flat, loaded top above the origin. */
        double load_height;
        /** Half width S of the sphere's square plan (x, y <= S). */
        double cap_half_width;
        /** Foundation [0, W] x [0, W] x [-D, 0]. */
        double foundation_width;
        double foundation_depth;
        /**
         * The square [0, Lc]^2 in plan in which both sides have nodes at
         * the same (x, y), n elements along each side, and the depth and
         * height Lc under and above it with elements of the same size.
         */
        double       contact_zone_width;
        unsigned int n_contact_zone_elements;
        /** Ratio of neighbouring element sizes outside that zone. */
        double growth_ratio;
        /** Largest element size. */
        double mesh_size;
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
      Wedge         wedge;
      BlockOnPlane  block_on_plane;
      HertzSphere   hertz_sphere;

      /** Whether the selected source builds 3D models (only). */
      bool
      source_is_3d() const;

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
