// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/geometry/mesh_description.h>

#include <deal.II/base/parameter_handler.h>

namespace fdem
{
  namespace geometry
  {
    using namespace dealii;

    /**
     * The case "hertz sphere" (3D), subsection "Geometry/Hertz sphere": a
     * sphere of radius R pressed onto a foundation, as the quarter model
     * x >= 0, y >= 0 with two symmetry planes, structured hexahedra
     * (make_hertz_sphere_mesh()). The sphere touches the foundation's top
     * z = 0 at the origin; it is truncated by the planes x = S, y = S (free)
     * and z = H (loaded). Lengths in the user's unit (e.g. mm).
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

      /** Declare the subsection "Hertz sphere" (inside "Geometry"). */
      static void
      declare_parameters(ParameterHandler &prm);

      /** Read the subsection "Hertz sphere" (inside "Geometry"). */
      void
      parse_parameters(ParameterHandler &prm);

      /** Throw a one-sentence message naming the entry if the data are
       * invalid. */
      void
      validate() const;
    };

    /**
     * Quarter model (x >= 0, y >= 0) of a sphere of radius R on a
     * foundation, for Hertz point contact, structured hexahedra. Blocks
     * "sphere" (the ball of centre (0, 0, R) cut by the planes x = S,
     * y = S and z = H: points of the ball with x, y in [0, S] and z <= H)
     * and "foundation" ([0, W] x [0, W] x [-D, 0]); they share the vertex
     * at the origin.
     *
     * Both blocks use the same grid lines in x and y: Lc/n apart on
     * [0, Lc] (the contact zone), then growing by the growth ratio up to
     * the mesh size, to S (sphere) and on to W (foundation). The
     * foundation's layers are Lc/n thick down to z = -Lc, then grow to D;
     * the sphere's layers follow its surface z = R - sqrt(R^2 - x^2 - y^2)
     * with the same sizes up to the top z = H. So every node of the
     * sphere's surface in the contact zone lies straight above a node of
     * the foundation's top, at the initial gap of the sphere's surface.
     *
     * Face groups, in this order: "contact surface" (the sphere's surface
     * and the foundation's top over [0, Lc]^2), "load" (z = H), "symmetry"
     * (x = 0 and y = 0, both blocks), "bottom" (z = -D), "sphere surface"
     * (the rest of the sphere's surface and its faces x = S, y = S),
     * "foundation surface" (the rest of z = 0) and "foundation side"
     * (x = W, y = W).
     */
    MeshDescription<3>
    make_hertz_sphere_mesh(const HertzSphere &hertz_sphere);
  } // namespace geometry
} // namespace fdem
