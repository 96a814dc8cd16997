// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/geometry/cases/case_input.h>
#include <fdem/geometry/mesh_description.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <string>

namespace fdem
{
  namespace geometry
  {
    /**
     * The entries of the case block on plane that only one dimension has:
     * in 2D the inclination and the element shape.
     */
    template <int dim>
    struct BlockOnPlaneOrientation;

    template <>
    struct BlockOnPlaneOrientation<2>
    {
      /** Angle of the plane with the x axis, rising to the right (degrees). */
      double inclination;
      /** Quadrilaterals, or each split into two triangles. */
      ElementShape element_shape = ElementShape::hypercube;
    };

    /** In 3D the plane's dip and dip direction and the block's width. */
    template <>
    struct BlockOnPlaneOrientation<3>
    {
      PlaneOrientation plane;
      /** Block width B along the strike (m). */
      double       block_width;
      unsigned int n_elements_along_width;
    };

    /**
     * The case block on plane: a block on an inclined plane through the
     * origin, structured quadrilaterals (2D) or hexahedra (3D), made by
     * make_block_on_plane_mesh(). In the plane's frame (x along the plane,
     * in 3D y along the strike, and the last axis normal to the plane, up)
     * the block is [0, L] (x [-B/2, B/2]) x [0, H] and the foundation slab
     * [-o, L + o] (x [-B/2 - o, B/2 + o]) x [-T, 0], with o the overhang;
     * rotation() turns that frame into x, y(, z).
     *
     * In 2D it is the source "inclined block", subsection "Geometry/Inclined
     * block": the plane rises to the right by the inclination theta and the
     * frame's x axis runs up the plane. In 3D it is the source "block on
     * plane", subsection "Geometry/Block on plane": the plane has a dip and
     * a dip direction, and the frame's x axis runs down the dip.
     */
    template <int dim>
    struct BlockOnPlane : BlockOnPlaneOrientation<dim>
    {
      /** Block length L along the plane (2D), down the dip (3D) (m). */
      double block_length;
      /** Block height H normal to the plane (m). */
      double block_height;
      /** Thickness T of the foundation slab (m). */
      double foundation_thickness;
      /** Length the foundation extends beyond the block on every side (m). */
      double       foundation_overhang;
      unsigned int n_elements_along_length;
      unsigned int n_elements_across_height;

      /**
       * The rotation from the plane's frame to x, y(, z): in 2D by the
       * inclination about z; in 3D its columns are the down-dip direction,
       * the strike direction (normal x down-dip) and the upward normal.
       */
      Tensor<2, dim>
      rotation() const;

      /** "Inclined block" (2D) or "Block on plane" (3D). */
      static std::string
      subsection_name();

      /** Declare the subsection subsection_name() (inside "Geometry"). */
      static void
      declare_parameters(ParameterHandler &prm);

      /** Read the subsection subsection_name() (inside "Geometry"). */
      void
      parse_parameters(ParameterHandler &prm);

      /** Throw a one-sentence message naming the entry if the data are
       * invalid. */
      void
      validate() const;
    };

    /**
     * A block on a plane through the origin, structured quadrilaterals (2D)
     * or hexahedra (3D). It is built in the plane's frame: the block with
     * the given numbers of elements, and the foundation slab with elements
     * of the block's size (at least one across the overhang o and the
     * thickness T), its top split at the block's edges. Then it is rotated
     * by block_on_plane.rotation(). In 2D with Element shape = triangle
     * each quadrilateral is split into two triangles.
     *
     * Blocks "block" and "foundation". Face groups, in this order:
     * "sliding surface" (the block's bottom = the foundation's top under
     * it, the same vertices), "block surface" (the block's other faces),
     * "foundation surface" (the uncovered top of the slab), "foundation
     * base" (its bottom) and "foundation ends" (its side faces).
     */
    template <int dim>
    MeshDescription<dim>
    make_block_on_plane_mesh(const BlockOnPlane<dim> &block_on_plane);
  } // namespace geometry
} // namespace fdem
