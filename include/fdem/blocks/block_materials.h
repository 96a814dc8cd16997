// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/elastic_block.h>
#include <fdem/geometry/mesh_description.h>
#include <fdem/parameters/parameters.h>

#include <map>
#include <string>

namespace fdem
{
  namespace blocks
  {
    using namespace dealii;

    /**
     * Checks the materials of @p mesh against the .prm file: every material
     * region of the mesh is declared in Materials/Names and every declared
     * one is in the mesh, and every material that a cell uses (a block's
     * own, for its cells outside every region, or a region's) has a
     * Young's modulus. Throws a one-line message naming the entry.
     */
    template <int dim>
    void
    check_materials(const geometry::MeshDescription<dim> &mesh,
                    const parameters::Parameters         &parameters);

    /**
     * Checks that the pore pressure of every interface whose Pore pressure
     * is 'piezometric' is one value at each point: the cells on the two
     * sides of each of its faces must have the same water table (their
     * materials' own piezometric lines, or Water/Piezometric line). Each
     * face takes the line of its cell's material, so two different lines
     * would push the blocks apart by their difference. Throws a one-line
     * message naming the interface and the two materials.
     */
    template <int dim>
    void
    check_interface_water(const geometry::MeshDescription<dim> &mesh,
                          const parameters::Parameters         &parameters);

    /**
     * The materials of block @p b by the material ids its cells get
     * (MeshDescription::material_key()), for ElasticBlock.
     */
    template <int dim>
    std::map<unsigned int, parameters::MaterialParameters>
    block_materials(const geometry::MeshDescription<dim> &mesh,
                    const parameters::Parameters         &parameters,
                    const unsigned int                    b);

    /** The soil strength c and tan(phi) that a node pair takes. */
    struct SoilStrength
    {
      /** Cohesion c (force/length^2). */
      double cohesion = 0;
      /** tan(phi). */
      double friction_coefficient = 0;
    };

    /**
     * A named weak layer (Materials/<name>/Weak layer): a seam of no
     * thickness with its material's c and phi, as the mesh has it (moved by
     * the Geometry transformation).
     */
    struct WeakLayer
    {
      std::string                    name;
      std::vector<Point<2>>          polyline;
      parameters::MaterialParameters material;
    };

    /**
     * The weak layers of @p parameters, their polylines moved as the mesh
     * (geometry::transformed_point()). Throws in 3D, where a polyline is no
     * surface.
     */
    template <int dim>
    std::vector<WeakLayer>
    weak_layers(const parameters::Parameters &parameters);

    /**
     * Strength = material: for each node of @p block on the face group
     * @p group, keyed by its first dof, the mean of the cohesion and of
     * tan(phi) of the materials of the block's cells along the group,
     * weighted by the node's shape function on each face (int phi_k c dGamma
     * / int phi_k dGamma): a node inside one material takes its c and phi, a
     * node at the boundary between two takes each over its share of the
     * node's area. A face along one of @p weak_layers (each of its vertices
     * within 1e-3 of its length of the polyline) takes the weak layer's c
     * and phi instead of its cell's. Throws naming Interfaces/@p
     * interface_name/Strength if a material met has no Friction angle.
     */
    template <int dim>
    std::map<types::global_dof_index, SoilStrength>
    soil_strength_at_nodes(const ElasticBlock<dim>              &block,
                           const types::boundary_id              group,
                           const geometry::MeshDescription<dim> &mesh,
                           const std::string                    &interface_name,
                           const std::vector<WeakLayer> &weak_layers = {});
  } // namespace blocks
} // namespace fdem
