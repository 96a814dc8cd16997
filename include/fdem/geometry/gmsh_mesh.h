// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/geometry/mesh_description.h>

#include <functional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    /**
     * Scope of the Gmsh library (gmsh::initialize() ... gmsh::finalize()),
     * silent on the terminal. Gmsh is a global singleton, so only one
     * session may exist at a time.
     *
     * Gmsh 4.8's C++ API reports an error by throwing the message as a
     * std::string (option General.AbortOnError = 2, which initialize() sets).
     * After such a throw while reading a file, Gmsh stays locked and ignores
     * further files ("I'm busy!") until it is finalized, so the session
     * that saw an error should end: run() converts the error and the
     * destructor finalizes while the exception propagates. Some failures
     * are silent: gmsh::open() of a missing file gives an empty model.
     */
    class GmshSession
    {
    public:
      GmshSession();
      ~GmshSession();

      GmshSession(const GmshSession &) = delete;
      GmshSession &
      operator=(const GmshSession &) = delete;

      /**
       * Call @p gmsh_calls and turn a Gmsh error into an ExcMessage that
       * starts with @p context (e.g. "Gmsh could not read 'slope.msh'").
       */
      template <typename Function>
      static void
      run(const std::string &context, const Function &gmsh_calls)
      {
        try
          {
            gmsh_calls();
          }
        catch (const std::string &gmsh_error)
          {
            throw_error(context, gmsh_error);
          }
      }

    private:
      [[noreturn]] static void
      throw_error(const std::string &context, const std::string &gmsh_error);

      static bool active;
    };

    namespace internal
    {
      /**
       * Index in Gmsh's corner order of deal.II's corner i of a cell with
       * @p n_corners corners: the map is its own inverse (gmsh_mesh.cc reads,
       * gmsh_write.cc writes).
       */
      unsigned int
      gmsh_corner(const int          structdim,
                  const unsigned int n_corners,
                  const unsigned int i);
    } // namespace internal

    /**
     * Read a Gmsh file and convert it with extract_current_gmsh_model(): a
     * mesh (.msh of any version, ASCII or binary) or a geometry (.geo), which
     * is meshed in @p dim dimensions. Opens its own GmshSession. For a
     * geometry, @p before_meshing (if given) is called once Gmsh has read
     * it, before it meshes: it may look at the model, or throw.
     */
    template <int dim>
    MeshDescription<dim>
    read_gmsh_file(const std::string              &file_name,
                   const std::function<void()>    &before_meshing = {},
                   const std::vector<std::string> &material_names = {});

    /**
     * Convert the mesh of the model currently loaded in Gmsh (a GmshSession
     * must be active). Physical groups of dimension @p dim whose names are
     * in @p material_names are material regions, the other ones the blocks
     * (an unnamed group is called "block <tag>"); those of dimension dim-1
     * are the face groups. Every cell lies in exactly one block and in at
     * most one material region; a region's cells must lie in blocks
     * (read_material_groups()). Cells must be quadrilaterals or triangles (2D),
     * hexahedra or tetrahedra (3D), of any order, and all of one shape (a
     * mixed mesh would need hp elements); their corner nodes are used.
     * Only vertices of cells are kept, and the cells are made positively
     * oriented (and consistently ordered, for hypercubes). @p source names
     * the model in messages.
     */
    template <int dim>
    MeshDescription<dim>
    extract_current_gmsh_model(
      const std::string              &source,
      const std::vector<std::string> &material_names = {});

    /**
     * Smallest and largest sine of the corner angles of a hypercube cell
     * @p cell of @p vertices, signed: all positive for a valid cell in
     * deal.II's orientation, all negative for a valid cell of the opposite
     * orientation, mixed for a twisted or non-convex cell, and zero for a
     * degenerate one. In 3D it is the triple product of the unit edges at
     * each corner.
     */
    template <int dim>
    std::pair<double, double>
    corner_sine_range(const std::vector<Point<dim>> &vertices,
                      const CellData<dim>           &cell);

    /**
     * The physical groups of dimension @p dim of the current Gmsh model,
     * those named in @p material_names in @p material_groups, the others in
     * @p block_groups (as (dim, tag) pairs).
     */
    template <int dim>
    void
    split_block_and_material_groups(
      const std::vector<std::string>   &material_names,
      std::vector<std::pair<int, int>> &block_groups,
      std::vector<std::pair<int, int>> &material_groups);

    /**
     * Sets mesh.material_names and mesh.cell_materials from the material
     * groups @p material_groups of the current Gmsh model, whose cells are
     * the elements @p cell_element_tags (in the order of mesh's cells to
     * come). Throws naming @p source for an element in two material groups
     * or in a material group but no block.
     */
    template <int dim>
    void
    read_material_groups(
      const std::string                      &source,
      const std::vector<std::pair<int, int>> &material_groups,
      const std::vector<std::size_t>         &cell_element_tags,
      MeshDescription<dim>                   &mesh);

    /**
     * Write @p mesh as a Gmsh file (format from the extension; .msh is
     * written as version 4 ASCII), with one physical group per block, per
     * material region and per face group. Opens its own GmshSession.
     */
    template <int dim>
    void
    write_gmsh_file(const MeshDescription<dim> &mesh,
                    const std::string          &file_name);
    /**
     * Adds a physical group of the model's entities @p entities (of
     * dimension @p structdim) named @p name; nothing for an empty list.
     */
    void
    add_physical_group(const int               structdim,
                       const std::vector<int> &entities,
                       const std::string      &name);

    /**
     * After an OpenCASCADE fragment of a model's pieces (the first
     * @p n_objects inputs) with one tool per soil layer (input
     * n_objects + k for layer k of @p layers, a material name each):
     * the layer's pieces of dimension @p structdim that are pieces of the
     * model (@p inside) become one physical group per material (a material
     * named twice gets one), the rest of the tools is removed. @p origin is
     * the fragment's map of inputs to pieces; @p message names the entry in
     * Gmsh's errors. Synchronises the model.
     */
    void
    group_layer_pieces(
      const int                                            structdim,
      const std::vector<std::vector<std::pair<int, int>>> &origin,
      const std::size_t                                    n_objects,
      const std::vector<std::string>                      &layers,
      const std::set<int>                                 &inside,
      const std::string                                   &message);
  } // namespace geometry
} // namespace fdem
