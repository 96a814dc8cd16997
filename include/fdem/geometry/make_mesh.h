// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/geometry/mesh_description.h>
#include <fdem/parameters/geometry_parameters.h>

#include <string>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    /**
     * The mesh that the subsection "Geometry" describes: read from the mesh
     * file (as named, resolved by the parameter handler) or made by a
     * built-in generator
     * (slope, hertz and inclined block in 2D, wedge and block on plane in
     * 3D; any other combination throws), then transformed by
     * apply_transformation(). If
     * @p msh_output_file is not empty, the final mesh is also written there
     * (Gmsh .msh version 4, ASCII) for the user to look at.
     *
     * A built-in generator's mesh is first estimated (estimate_mesh(), with
     * elements of degree @p fe_degree): beyond Geometry/Memory limit it is
     * refused with a one-line error naming the entry, and a large one is
     * announced on stdout ("meshing (...): about N elements").
     * @p material_names are the names of Materials/Names: the physical
     * groups of dimension dim of a mesh file that are material regions
     * (the generators name their own). @p dense_mixed_system: whether the
     * run forms the dense interface parts (Solver/Mixed system = dense),
     * for the memory estimate.
     */
    template <int dim>
    MeshDescription<dim>
    make_mesh(const parameters::GeometryParameters &geometry,
              const std::string                    &msh_output_file,
              unsigned int                          fe_degree          = 1,
              const std::vector<std::string>       &material_names     = {},
              bool                                  dense_mixed_system = true);

    /**
     * Map every vertex x of @p mesh to R (s x) + t, with the scale factor s,
     * the rotation R (about z in 2D, about the rotation axis in 3D) and the
     * translation t of @p geometry. Orientations are kept since s > 0.
     */
    template <int dim>
    void
    apply_transformation(const parameters::GeometryParameters &geometry,
                         MeshDescription<dim>                 &mesh);

    /**
     * The point @p x of the input as the transformed mesh has it:
     * R (s x) + t with Geometry/Scale factor s, Rotation R and Translation
     * t (of which a 2D model takes the first two numbers).
     */
    template <int dim>
    Point<dim>
    transformed_point(const parameters::GeometryParameters &geometry,
                      const Point<dim>                     &x);
  } // namespace geometry
} // namespace fdem
