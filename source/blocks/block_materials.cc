// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/blocks/block_materials.h>
#include <fdem/geometry/cases/polyline_segment.h>
#include <fdem/geometry/make_mesh.h>

#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <type_traits>

namespace fdem
{
  namespace blocks
  {
    namespace
    {
      /** "Blocks/<name>" or "Materials/<name>" of a material key. */
      template <int dim>
      std::string
      material_path(const geometry::MeshDescription<dim> &mesh,
                    const unsigned int                    key)
      {
        return (key < mesh.block_names.size() ? "Blocks/" : "Materials/") +
               mesh.material_key_name(key);
      }

      /**
       * The weak layer that the face @p face runs along, or nullptr. In 2D
       * a face is a segment: along the polyline when both its ends are
       * within 1e-3 of its length of it (a face that crosses the polyline
       * has at most one end on it).
       */
      template <typename FaceIterator>
      const WeakLayer *
      weak_layer_along(const FaceIterator           &face,
                       const std::vector<WeakLayer> &weak_layers,
                       const std::integral_constant<int, 2> &)
      {
        for (const WeakLayer &layer : weak_layers)
          if (geometry::case_input::segment_along_polyline(face->vertex(0),
                                                           face->vertex(1),
                                                           layer.polyline))
            return &layer;
        return nullptr;
      }

      template <typename FaceIterator>
      const WeakLayer *
      weak_layer_along(const FaceIterator &,
                       const std::vector<WeakLayer> &,
                       const std::integral_constant<int, 3> &)
      {
        return nullptr; // check_materials() refuses weak layers in 3D
      }
    } // namespace

    template <int dim>
    std::vector<WeakLayer>
    weak_layers(const parameters::Parameters &parameters)
    {
      std::vector<WeakLayer> layers;
      for (const std::string &name : parameters.material_names)
        {
          const parameters::MaterialParameters &material =
            parameters.materials.at(name);
          if (material.weak_layer.empty())
            continue;
          // check_materials() has refused weak layers in 3D.
          Assert(dim == 2, ExcInternalError());
          WeakLayer layer{name, {}, material};
          for (const Point<2> &point : material.weak_layer)
            layer.polyline.push_back(
              geometry::transformed_point(parameters.geometry, point));
          layers.push_back(layer);
        }
      return layers;
    }

    template <int dim>
    void
    check_materials(const geometry::MeshDescription<dim> &mesh,
                    const parameters::Parameters         &parameters)
    {
      const auto &declared = parameters.material_names;
      for (const std::string &name : mesh.material_names)
        AssertThrow(std::find(declared.begin(), declared.end(), name) !=
                      declared.end(),
                    ExcMessage("Materials/Names: the material '" + name +
                               "' of " + mesh.source +
                               " is not listed; list it and give "
                               "it a subsection with its Young's modulus."));
      for (const std::string &name : declared)
        {
          const bool weak = !parameters.materials.at(name).weak_layer.empty();
          const bool in_mesh = std::find(mesh.material_names.begin(),
                                         mesh.material_names.end(),
                                         name) != mesh.material_names.end();
          AssertThrow(!weak || dim == 2,
                      ExcMessage("Materials/" + name +
                                 "/Weak layer: a polyline is a weak layer "
                                 "of a 2D model only."));
          AssertThrow(!weak || !in_mesh,
                      ExcMessage(
                        "Materials/" + name +
                        "/Weak layer: a weak layer has no cells, but '" + name +
                        "' is a material region (or a layer) of " +
                        mesh.source + "."));
          AssertThrow(weak || in_mesh,
                      ExcMessage("Materials/Names: '" + name +
                                 "' is not a material "
                                 "region (physical group of dimension " +
                                 std::to_string(dim) + ", or a layer) in " +
                                 mesh.source + "."));
        }
      std::set<unsigned int> keys;
      for (unsigned int c = 0; c < mesh.cells.size(); ++c)
        keys.insert(mesh.material_key(c));
      for (const unsigned int key : keys)
        parameters.materials.at(mesh.material_key_name(key))
          .require_elastic_constants(
            material_path(mesh, key),
            key < mesh.block_names.size() ?
              "the block has cells outside every material "
              "region, which take its own material" :
              "the material has cells");
    }

    template <int dim>
    std::map<unsigned int, parameters::MaterialParameters>
    block_materials(const geometry::MeshDescription<dim> &mesh,
                    const parameters::Parameters         &parameters,
                    const unsigned int                    b)
    {
      std::map<unsigned int, parameters::MaterialParameters> materials;
      for (unsigned int c = 0; c < mesh.cells.size(); ++c)
        if (mesh.cells[c].material_id == b)
          {
            const unsigned int key = mesh.material_key(c);
            if (materials.count(key) == 0)
              materials[key] =
                parameters.materials.at(mesh.material_key_name(key));
          }
      return materials;
    }

    template <int dim>
    std::map<types::global_dof_index, SoilStrength>
    soil_strength_at_nodes(const ElasticBlock<dim>              &block,
                           const types::boundary_id              group,
                           const geometry::MeshDescription<dim> &mesh,
                           const std::string                    &interface_name,
                           const std::vector<WeakLayer>         &weak_layers)
    {
      // Per node (its x dof): int phi dGamma, int phi c dGamma, int phi
      // tan(phi) dGamma, and the same with |phi| for nodes whose weights
      // vanish (vertices of quadratic triangles).
      struct Sums
      {
        std::array<double, 3> weighted{}, absolute{};
      };
      std::map<types::global_dof_index, Sums> sums;
      FEFaceValues<dim>                       fe_face_values(block.mapping,
                                       block.fe,
                                       block.element_family.face_quadrature(
                                         block.fe.degree + 2),
                                       update_values | update_JxW_values);
      std::vector<types::global_dof_index>    dofs(block.fe.n_dofs_per_cell());
      for (const auto &cell : block.dof_handler.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == group)
            {
              const WeakLayer *weak =
                weak_layer_along(face,
                                 weak_layers,
                                 std::integral_constant<int, dim>());
              const parameters::MaterialParameters &material =
                weak != nullptr ? weak->material :
                                  block.materials.at(cell->material_id());
              AssertThrow(material.has_strength,
                          ExcMessage(
                            "Interfaces/" + interface_name +
                            "/Strength: the interface runs through '" +
                            mesh.material_key_name(cell->material_id()) +
                            "', which has no soil strength; give " +
                            material_path(mesh, cell->material_id()) +
                            "/Friction angle (and Cohesion)."));
              const double tan_phi =
                std::tan(material.friction_angle * numbers::PI / 180);
              fe_face_values.reinit(cell, face);
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                if (block.fe.system_to_component_index(i).first == 0)
                  for (const unsigned int q :
                       fe_face_values.quadrature_point_indices())
                    {
                      const double phi = fe_face_values.shape_value(i, q) *
                                         fe_face_values.JxW(q);
                      Sums &s = sums[dofs[i]];
                      s.weighted[0] += phi;
                      s.weighted[1] += phi * material.cohesion;
                      s.weighted[2] += phi * tan_phi;
                      s.absolute[0] += std::abs(phi);
                      s.absolute[1] += std::abs(phi) * material.cohesion;
                      s.absolute[2] += std::abs(phi) * tan_phi;
                    }
            }
      std::map<types::global_dof_index, SoilStrength> strengths;
      for (const auto &[dof, s] : sums)
        {
          if (s.absolute[0] == 0)
            continue; // a dof of a face-interior point not on the group
          const bool weighted = std::abs(s.weighted[0]) > 1e-12 * s.absolute[0];
          const auto &w       = weighted ? s.weighted : s.absolute;
          strengths[dof]      = {w[1] / w[0], w[2] / w[0]};
        }
      return strengths;
    }

    template <int dim>
    void
    check_interface_water(const geometry::MeshDescription<dim> &mesh,
                          const parameters::Parameters         &parameters)
    {
      // Without a material's own line every face has the same one.
      if (std::none_of(parameters.materials.begin(),
                       parameters.materials.end(),
                       [](const auto &material) {
                         return !material.second.piezometric_line.empty();
                       }))
        return;
      std::vector<std::vector<unsigned int>> cells_at_vertex(
        mesh.vertices.size());
      for (unsigned int c = 0; c < mesh.cells.size(); ++c)
        for (const unsigned int v : mesh.cells[c].vertices)
          cells_at_vertex[v].push_back(c);
      const auto line_of = [&](const unsigned int c) {
        const auto &own =
          parameters.materials.at(mesh.material_key_name(mesh.material_key(c)))
            .piezometric_line;
        return own.empty() ? parameters.water.piezometric_line : own;
      };
      for (const std::string &name : parameters.interface_names)
        {
          if (parameters.interfaces.at(name).pore_pressure != "piezometric")
            continue;
          const auto id = std::find(mesh.face_group_names.begin(),
                                    mesh.face_group_names.end(),
                                    name) -
                          mesh.face_group_names.begin();
          for (const auto &face : mesh.faces)
            if (face.boundary_id == id)
              {
                // The cells that hold every vertex of the face: one on each
                // side.
                std::vector<unsigned int> sides;
                for (const unsigned int c : cells_at_vertex[face.vertices[0]])
                  {
                    const auto &v = mesh.cells[c].vertices;
                    if (std::all_of(face.vertices.begin(),
                                    face.vertices.end(),
                                    [&](const unsigned int f) {
                                      return std::count(v.begin(), v.end(), f);
                                    }))
                      sides.push_back(c);
                  }
                for (unsigned int k = 1; k < sides.size(); ++k)
                  AssertThrow(
                    line_of(sides[k]) == line_of(sides[0]),
                    ExcMessage(
                      "Interfaces/" + name +
                      "/Pore pressure: 'piezometric' on a face between '" +
                      mesh.material_key_name(mesh.material_key(sides[0])) +
                      "' and '" +
                      mesh.material_key_name(mesh.material_key(sides[k])) +
                      "', which have different piezometric lines; the pore "
                      "pressure at a point of the surface is one value, so "
                      "give both materials the same line."));
              }
        }
    }

    template void
    check_materials(const geometry::MeshDescription<2> &,
                    const parameters::Parameters &);
    template void
    check_materials(const geometry::MeshDescription<3> &,
                    const parameters::Parameters &);
    template void
    check_interface_water(const geometry::MeshDescription<2> &,
                          const parameters::Parameters &);
    template void
    check_interface_water(const geometry::MeshDescription<3> &,
                          const parameters::Parameters &);
    template std::map<unsigned int, parameters::MaterialParameters>
    block_materials(const geometry::MeshDescription<2> &,
                    const parameters::Parameters &,
                    const unsigned int);
    template std::map<unsigned int, parameters::MaterialParameters>
    block_materials(const geometry::MeshDescription<3> &,
                    const parameters::Parameters &,
                    const unsigned int);
    template std::map<types::global_dof_index, SoilStrength>
    soil_strength_at_nodes(const ElasticBlock<2> &,
                           const types::boundary_id,
                           const geometry::MeshDescription<2> &,
                           const std::string &,
                           const std::vector<WeakLayer> &);
    template std::map<types::global_dof_index, SoilStrength>
    soil_strength_at_nodes(const ElasticBlock<3> &,
                           const types::boundary_id,
                           const geometry::MeshDescription<3> &,
                           const std::string &,
                           const std::vector<WeakLayer> &);
    template std::vector<WeakLayer>
    weak_layers<2>(const parameters::Parameters &);
    template std::vector<WeakLayer>
    weak_layers<3>(const parameters::Parameters &);
  } // namespace blocks
} // namespace fdem
