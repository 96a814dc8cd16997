// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    using namespace dealii;

    /**
     * The one representation of a model's geometry, whatever made it: a Gmsh
     * file (.msh or .geo) or one of the built-in generators. It is a plain
     * unstructured mesh of quadrilaterals or triangles (2D), hexahedra or
     * tetrahedra (3D), all of one shape, in which
     * every cell carries the index of its block and every named face group
     * (a Gmsh physical group of dimension dim-1) lists its faces.
     *
     * A face group is either a boundary part (Dirichlet conditions, pressures)
     * or an interface between two blocks; the .prm file says which. The
     * vertices are shared between blocks here: the program duplicates the
     * nodes along each interface when it splits the mesh into blocks.
     */
    template <int dim>
    struct MeshDescription
    {
      /** Vertex coordinates (model length units). */
      std::vector<Point<dim>> vertices;

      /**
       * Cells in deal.II's vertex ordering (lexicographic for quadrilaterals
       * and hexahedra, consistently oriented), with positive measure: 2^dim
       * vertices for hypercubes, dim + 1 for simplices. `material_id` is
       * the block index into block_names.
       */
      std::vector<CellData<dim>> cells;

      /** Block names (Gmsh physical groups of dimension dim), by index. */
      std::vector<std::string> block_names;

      /**
       * Names of the material regions, by index: Gmsh physical groups of
       * dimension dim whose names are declared in Materials/Names (or the
       * layers of the slope generator). They may overlap the blocks: a block
       * (a kinematic unit) is made of one or more materials.
       */
      std::vector<std::string> material_names;

      /**
       * Per cell (same order as `cells`): the index of its material region
       * into material_names, or no_material for a cell in none, which takes
       * its block's own material. Empty when there are no material regions.
       */
      std::vector<unsigned int> cell_materials;

      /** The entry of cell_materials of a cell outside every material region.
       */
      static constexpr unsigned int no_material = static_cast<unsigned int>(-1);

      /**
       * The material of cell @p c as one number, unique per block and
       * material, used as the material id of the cells of a triangulation:
       * the block index b for the block's own material, b + n_blocks (1 + m)
       * for the block's part of material region m.
       */
      unsigned int
      material_key(const unsigned int c) const
      {
        const unsigned int b = cells[c].material_id;
        return (cell_materials.empty() || cell_materials[c] == no_material) ?
                 b :
                 b + block_names.size() * (1 + cell_materials[c]);
      }

      /** The block of a material_key(). */
      unsigned int
      block_of_key(const unsigned int key) const
      {
        return key % block_names.size();
      }

      /** The material region of a material_key(), or no_material. */
      unsigned int
      material_of_key(const unsigned int key) const
      {
        return key < block_names.size() ? no_material :
                                          key / block_names.size() - 1;
      }

      /** The name of a material_key()'s material: a block's or a region's. */
      const std::string &
      material_key_name(const unsigned int key) const
      {
        return key < block_names.size() ? block_names[key] :
                                          material_names[material_of_key(key)];
      }

      /**
       * Faces of named groups: `vertices` are indices into `vertices`,
       * `boundary_id` is the group index into face_group_names. A face that
       * belongs to several groups appears once per group.
       */
      std::vector<CellData<dim - 1>> faces;

      /** Names of the face groups (Gmsh physical groups of dimension dim-1). */
      std::vector<std::string> face_group_names;

      /**
       * Face groups that a generator fills with standing water, by name: a
       * point of the water's surface (moved with the mesh by Geometry/Scale
       * factor, Rotation and Translation). Their faces carry the hydrostatic
       * pressure of Water/Unit weight of water times the depth below that
       * point along Loads/Gravity direction (the slope generator's
       * water-filled tension crack). Empty for Gmsh files.
       */
      std::map<std::string, Point<dim>> standing_water;

      /**
       * Face groups that lie on a surface the generator knows exactly, by
       * name: a vector normal to that surface at a point of it (any length,
       * either sense), moved with the mesh by Geometry/Scale factor,
       * Rotation and Translation. The node pairs of such a group take it as
       * their normal instead of the mean normal of the mesh's facets: on a
       * sphere, a cylinder or a spheroid the body's rotation about the
       * surface's axis then opens no pair, as on the surface itself, where
       * the facets' normals tilt by the mesh's irregularity and turn the
       * mechanism into one the blocks can only follow by deforming
       * (doc/theory.md, "The 3D slope"). Empty for Gmsh files.
       */
      std::map<std::string, std::function<Tensor<1, dim>(const Point<dim> &)>>
        surface_normals;

      /** Where the description came from (file name or generator), for
       * messages. */
      std::string source;
    };
  } // namespace geometry
} // namespace fdem
