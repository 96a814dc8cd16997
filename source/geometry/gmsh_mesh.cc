// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/gmsh_mesh.h>
#include <fdem/geometry/msh_checks.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/grid/grid_tools.h>

#include <gmsh.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <map>
#include <sstream>
#include <unordered_map>

namespace fdem
{
  namespace geometry
  {
    bool GmshSession::active = false;

    GmshSession::GmshSession()
    {
      AssertThrow(!active,
                  ExcMessage("Only one GmshSession may exist at a time: Gmsh "
                             "is a global singleton."));
      gmsh::initialize(0, nullptr, false);
      active = true;
      gmsh::option::setNumber("General.Terminal", 0);
      // 2 = throw the error message as a std::string; run() converts it.
      gmsh::option::setNumber("General.AbortOnError", 2);
      // Gmsh keeps its options from one session to the next within a
      // process: put those the generators change back to Gmsh's defaults,
      // so that e.g. a .geo file of triangles read after the slope
      // generator is not recombined, nor split after the wedge generator.
      for (const auto &[option, value] :
           std::initializer_list<std::pair<const char *, double>>{
             {"Mesh.Algorithm", 6},
             {"Mesh.Algorithm3D", 1},
             {"Mesh.RecombineAll", 0},
             {"Mesh.RecombinationAlgorithm", 1},
             {"Mesh.SubdivisionAlgorithm", 0},
             {"Mesh.MeshSizeExtendFromBoundary", 1},
             {"Mesh.MeshSizeFromPoints", 1},
             {"Mesh.MeshSizeFromCurvature", 0}})
        gmsh::option::setNumber(option, value);
    }



    GmshSession::~GmshSession()
    {
      try
        {
          gmsh::finalize();
        }
      catch (...)
        {
          // A destructor must not throw; Gmsh has nothing left to report.
        }
      active = false;
    }



    void
    GmshSession::throw_error(const std::string &context,
                             const std::string &gmsh_error)
    {
      AssertThrow(false, ExcMessage(context + ": " + gmsh_error + "."));
      std::abort(); // not reached
    }



    namespace internal
    {
      /**
       * Index in Gmsh's corner order of deal.II's corner i of a cell with
       * @p n_corners corners: the map is its own inverse. deal.II numbers the
       * corners of a quadrilateral or hexahedron lexicographically; those of
       * lines, triangles and tetrahedra are in Gmsh's order.
       */
      unsigned int
      gmsh_corner(const int          structdim,
                  const unsigned int n_corners,
                  const unsigned int i)
      {
        static constexpr std::array<unsigned int, 8> quad_or_hex = {
          {0, 1, 3, 2, 4, 5, 7, 6}};
        const bool hypercube = (n_corners == (1u << structdim));
        return (structdim == 1 || !hypercube) ? i : quad_or_hex[i];
      }

    } // namespace internal

    namespace
    {
      /**
       * Corners of an element type of dimension @p structdim that deal.II
       * takes: a line, a quadrilateral or triangle, a hexahedron or
       * tetrahedron (of any order). 0 for other types (prisms, pyramids,
       * points, or an element of another dimension).
       */
      unsigned int
      n_corners_if_supported(const int element_type, const int structdim)
      {
        std::string         name;
        int                 element_dim, order, n_nodes, n_primary_nodes;
        std::vector<double> local_coordinates;
        gmsh::model::mesh::getElementProperties(element_type,
                                                name,
                                                element_dim,
                                                order,
                                                n_nodes,
                                                local_coordinates,
                                                n_primary_nodes);
        return (element_dim == structdim &&
                (n_primary_nodes == (1 << structdim) ||
                 n_primary_nodes == structdim + 1)) ?
                 n_primary_nodes :
                 0;
      }

      /**
       * Elements of a physical group as corner node tags in deal.II order,
       * with their element tags. Higher-order elements give their corners,
       * which Gmsh lists first. Throws @p error_prefix for elements deal.II
       * does not take.
       */
      template <int structdim>
      void
      get_group_elements(const int                              group_tag,
                         const std::string                     &error_prefix,
                         std::vector<std::size_t>              &element_tags,
                         std::vector<std::vector<std::size_t>> &corner_tags)
      {
        std::vector<int> entities;
        gmsh::model::getEntitiesForPhysicalGroup(structdim,
                                                 group_tag,
                                                 entities);
        for (const int entity : entities)
          {
            std::vector<int>                      types;
            std::vector<std::vector<std::size_t>> tags, nodes;
            gmsh::model::mesh::getElements(
              types, tags, nodes, structdim, entity);
            for (unsigned int t = 0; t < types.size(); ++t)
              {
                const unsigned int n_corners =
                  n_corners_if_supported(types[t], structdim);
                AssertThrow(n_corners > 0, ExcMessage(error_prefix));
                const std::size_t n_nodes = nodes[t].size() / tags[t].size();
                for (unsigned int e = 0; e < tags[t].size(); ++e)
                  {
                    element_tags.push_back(tags[t][e]);
                    std::vector<std::size_t> corners(n_corners);
                    for (unsigned int i = 0; i < n_corners; ++i)
                      corners[i] =
                        nodes[t][e * n_nodes + internal::gmsh_corner(
                                                 structdim, n_corners, i)];
                    corner_tags.push_back(corners);
                  }
              }
          }
      }

      std::string
      group_name(const int structdim, const int tag, const std::string &unnamed)
      {
        std::string name;
        gmsh::model::getPhysicalName(structdim, tag, name);
        return name.empty() ? unnamed + " " + std::to_string(tag) : name;
      }

      /**
       * Signed measure of a simplex relative to the product of its edges
       * from corner 0: positive in deal.II's orientation, negative in the
       * opposite one, about zero for a degenerate simplex.
       */
      template <int dim>
      double
      relative_simplex_measure(const std::vector<Point<dim>> &vertices,
                               const CellData<dim>           &cell)
      {
        Tensor<2, dim> edges;
        double         scale = 1;
        for (unsigned int d = 0; d < dim; ++d)
          {
            edges[d] =
              vertices[cell.vertices[d + 1]] - vertices[cell.vertices[0]];
            scale *= edges[d].norm();
          }
        return (scale > 0) ? determinant(edges) / scale : 0.;
      }
    } // namespace



    template <int dim>
    std::pair<double, double>
    corner_sine_range(const std::vector<Point<dim>> &vertices,
                      const CellData<dim>           &cell)
    {
      std::pair<double, double> range(1, -1);
      for (unsigned int v = 0; v < cell.vertices.size(); ++v)
        {
          Tensor<2, dim> edges; // rows: unit edges along x, y (, z)
          for (unsigned int d = 0; d < dim; ++d)
            {
              const unsigned int neighbor = v ^ (1u << d);
              Tensor<1, dim>     edge =
                vertices[cell.vertices[neighbor]] - vertices[cell.vertices[v]];
              if ((v >> d) & 1u)
                edge *= -1;
              edges[d] = (edge.norm() > 0) ? edge / edge.norm() : edge;
            }
          const double sine = determinant(edges);
          range.first       = std::min(range.first, sine);
          range.second      = std::max(range.second, sine);
        }
      return range;
    }



    template std::pair<double, double>
    corner_sine_range<2>(const std::vector<Point<2>> &, const CellData<2> &);
    template std::pair<double, double>
    corner_sine_range<3>(const std::vector<Point<3>> &, const CellData<3> &);



    template <int dim>
    MeshDescription<dim>
    extract_current_gmsh_model(const std::string              &source,
                               const std::vector<std::string> &material_names)
    {
      static_assert(dim == 2 || dim == 3, "Only 2D and 3D meshes.");
      const std::string hypercubes =
        (dim == 2) ? "quadrilaterals" : "hexahedra";
      const std::string simplices = (dim == 2) ? "triangles" : "tetrahedra";

      MeshDescription<dim> mesh;
      mesh.source = source;

      const int model_dim = gmsh::model::getDimension();
      AssertThrow(model_dim == dim,
                  ExcMessage(source + ": the model is " +
                             std::to_string(model_dim) +
                             "-dimensional, but a " + std::to_string(dim) +
                             "-dimensional mesh was asked for."));

      // Groups named in material_names are material regions, the others
      // blocks (gmsh_materials.cc).
      gmsh::vectorpair block_groups, material_groups;
      split_block_and_material_groups<dim>(material_names,
                                           block_groups,
                                           material_groups);
      const std::string kind_of_group = (dim == 2) ? "Surface" : "Volume";
      AssertThrow(!block_groups.empty(),
                  ExcMessage(source + ": there is no physical group of " +
                             "dimension " + std::to_string(dim) +
                             " (the blocks), e.g. Physical " + kind_of_group +
                             "(\"rock\") = {...}."));

      // Cells by block; an element may be listed in one block only.
      std::map<std::size_t, unsigned int>   block_of_element;
      std::vector<std::vector<std::size_t>> cell_corner_tags;
      std::vector<unsigned int>             cell_blocks;
      std::vector<std::size_t>              cell_element_tags;
      for (const auto &group : block_groups)
        {
          const unsigned int block = mesh.block_names.size();
          mesh.block_names.push_back(group_name(dim, group.second, "block"));
          std::vector<std::size_t> element_tags;
          get_group_elements<dim>(group.second,
                                  source + ": block '" +
                                    mesh.block_names.back() +
                                    "' has elements that are neither " +
                                    simplices + " nor " + hypercubes +
                                    (dim == 3 ? " (prisms or pyramids)." : "."),
                                  element_tags,
                                  cell_corner_tags);
          for (const std::size_t tag : element_tags)
            {
              const auto inserted = block_of_element.emplace(tag, block);
              AssertThrow(inserted.second,
                          ExcMessage(
                            source + ": element " + std::to_string(tag) +
                            " belongs to two blocks, '" +
                            mesh.block_names[inserted.first->second] +
                            "' and '" + mesh.block_names[block] +
                            "' (if one is a material region, list it in "
                            "Materials/Names)."));
              cell_blocks.push_back(block);
              cell_element_tags.push_back(tag);
            }
        }

      read_material_groups(source, material_groups, cell_element_tags, mesh);

      // Keep only the vertices of cells, numbered in the order of their tags.
      std::map<std::size_t, unsigned int> vertex_of_node;
      for (const auto &corners : cell_corner_tags)
        for (const std::size_t tag : corners)
          vertex_of_node.emplace(tag, 0);
      {
        std::vector<std::size_t> node_tags;
        std::vector<double>      coordinates, parametric_coordinates;
        gmsh::model::mesh::getNodes(
          node_tags, coordinates, parametric_coordinates, -1, -1, false, false);
        std::unordered_map<std::size_t, std::size_t> position_of_node;
        for (std::size_t i = 0; i < node_tags.size(); ++i)
          {
            // A coordinate that is not a number, or a node listed twice at
            // two places, would give a distorted mesh that runs silently.
            for (unsigned int d = 0; d < 3; ++d)
              AssertThrow(std::isfinite(coordinates[3 * i + d]),
                          ExcMessage(source + ": node " +
                                     std::to_string(node_tags[i]) +
                                     " has a coordinate that is not a finite "
                                     "number."));
            const auto inserted = position_of_node.emplace(node_tags[i], i);
            const std::size_t j = inserted.first->second;
            AssertThrow(inserted.second ||
                          (coordinates[3 * i] == coordinates[3 * j] &&
                           coordinates[3 * i + 1] == coordinates[3 * j + 1] &&
                           coordinates[3 * i + 2] == coordinates[3 * j + 2]),
                        ExcMessage(source + ": node " +
                                   std::to_string(node_tags[i]) +
                                   " is listed twice, at two different "
                                   "places."));
          }
        for (auto &[tag, vertex] : vertex_of_node)
          {
            vertex              = mesh.vertices.size();
            const std::size_t i = position_of_node.at(tag);
            Point<dim>        p;
            for (unsigned int d = 0; d < dim; ++d)
              p[d] = coordinates[3 * i + d];
            mesh.vertices.push_back(p);
          }
      }

      // One element shape: a mesh of simplices and hypercubes would need
      // hp finite elements (FE_SimplexP and FE_Q on one mesh).
      const bool simplex =
        !cell_corner_tags.empty() && cell_corner_tags[0].size() == dim + 1;
      for (unsigned int c = 0; c < cell_corner_tags.size(); ++c)
        AssertThrow((cell_corner_tags[c].size() == dim + 1) == simplex,
                    ExcMessage(source + ": the mesh mixes " + simplices +
                               " and " + hypercubes + " (block '" +
                               mesh.block_names[cell_blocks[c]] +
                               "'); mixed meshes are not supported: mesh "
                               "all blocks with Recombine, or none."));

      for (unsigned int c = 0; c < cell_corner_tags.size(); ++c)
        {
          const unsigned int n_corners = cell_corner_tags[c].size();
          CellData<dim>      cell(n_corners);
          for (unsigned int i = 0; i < n_corners; ++i)
            cell.vertices[i] = vertex_of_node.at(cell_corner_tags[c][i]);
          cell.material_id = cell_blocks[c];

          // Gmsh's cells may have either orientation (it follows each
          // surface's normal); a cell that has neither is unusable. A
          // simplex of the other orientation is turned over here (corners
          // 1 and 2 swapped); hypercubes by deal.II below.
          const double tolerance = 1e-10;
          bool         valid     = true;
          if (simplex)
            {
              const double measure =
                relative_simplex_measure(mesh.vertices, cell);
              valid = std::abs(measure) > tolerance;
              if (measure < 0)
                std::swap(cell.vertices[1], cell.vertices[2]);
            }
          else
            {
              const auto sines = corner_sine_range(mesh.vertices, cell);
              valid = (sines.first > -tolerance && sines.second > tolerance) ||
                      (sines.second < tolerance && sines.first < -tolerance);
            }
          if (!valid)
            {
              std::ostringstream where;
              where << mesh.vertices[cell.vertices[0]];
              AssertThrow(false,
                          ExcMessage(source + ": a cell of block '" +
                                     mesh.block_names[cell_blocks[c]] +
                                     "' near (" + where.str() +
                                     ") is degenerate or twisted (zero "
                                     "measure or a non-convex corner)."));
            }
          mesh.cells.push_back(cell);
        }

      // Face groups: faces are stored by vertex indices, so that the
      // reordering of the cells below leaves them valid.
      gmsh::vectorpair face_groups;
      gmsh::model::getPhysicalGroups(face_groups, dim - 1);
      for (const auto &group : face_groups)
        {
          const unsigned int face_group = mesh.face_group_names.size();
          const std::string  name =
            group_name(dim - 1, group.second, "face group");
          mesh.face_group_names.push_back(name);
          std::vector<std::size_t>              element_tags;
          std::vector<std::vector<std::size_t>> corner_tags;
          get_group_elements<dim - 1>(group.second,
                                      source + ": face group '" + name +
                                        "' has elements that are not " +
                                        (dim == 2 ? "lines." :
                                         simplex  ? "triangles." :
                                                    "quadrilaterals."),
                                      element_tags,
                                      corner_tags);
          for (const auto &corners : corner_tags)
            {
              AssertThrow(dim == 2 || (corners.size() == dim) == simplex,
                          ExcMessage(
                            source + ": face group '" + name + "' has " +
                            (simplex ? "quadrilaterals" : "triangles") +
                            ", but the cells are " +
                            (simplex ? simplices : hypercubes) + "."));
              CellData<dim - 1> face(corners.size());
              for (unsigned int i = 0; i < corners.size(); ++i)
                {
                  const auto vertex = vertex_of_node.find(corners[i]);
                  AssertThrow(vertex != vertex_of_node.end(),
                              ExcMessage(
                                source + ": face group '" + name +
                                "' has faces that are not on any cell."));
                  face.vertices[i] = vertex->second;
                }
              face.boundary_id = face_group;
              mesh.faces.push_back(face);
            }
        }

      // deal.II orients the faces of simplices itself.
      if (!simplex)
        {
          GridTools::invert_cells_with_negative_measure(mesh.vertices,
                                                        mesh.cells);
          GridTools::consistently_order_cells(mesh.cells);
        }
      return mesh;
    }



    template <int dim>
    MeshDescription<dim>
    read_gmsh_file(const std::string              &file_name,
                   const std::function<void()>    &before_meshing,
                   const std::vector<std::string> &material_names)
    {
      check_before_gmsh(file_name);
      AssertThrow(std::ifstream(file_name).good() &&
                    !std::filesystem::is_directory(file_name),
                  ExcMessage("Gmsh file '" + file_name +
                             "': is missing or cannot be read."));
      GmshSession session;
      GmshSession::run("Gmsh could not read '" + file_name + "'",
                       [&]() { gmsh::open(file_name); });
      // Anything but a mesh file (.geo, or a CAD file) is only geometry.
      if (std::filesystem::path(file_name).extension() != ".msh" &&
          gmsh::model::getDimension() == dim)
        {
          // Rather an error than the segmentation fault of Debian's Gmsh.
          double algorithm = 0;
          gmsh::option::getNumber("Mesh.Algorithm", algorithm);
          AssertThrow(algorithm != 8,
                      ExcMessage("Gmsh file '" + file_name +
                                 "': Mesh.Algorithm = 8 (Frontal-Delaunay for "
                                 "quads) crashes Gmsh 4.8.4; use 6 with "
                                 "Recombine instead."));
          if (before_meshing)
            before_meshing();
          GmshSession::run("Gmsh could not mesh '" + file_name + "'",
                           [&]() { gmsh::model::mesh::generate(dim); });
        }
      return extract_current_gmsh_model<dim>("Gmsh file '" + file_name + "'",
                                             material_names);
    }



    template MeshDescription<2>
    extract_current_gmsh_model<2>(const std::string &,
                                  const std::vector<std::string> &);
    template MeshDescription<3>
    extract_current_gmsh_model<3>(const std::string &,
                                  const std::vector<std::string> &);
    template MeshDescription<2>
    read_gmsh_file<2>(const std::string &,
                      const std::function<void()> &,
                      const std::vector<std::string> &);
    template MeshDescription<3>
    read_gmsh_file<3>(const std::string &,
                      const std::function<void()> &,
                      const std::vector<std::string> &);
    void
    add_physical_group(const int               structdim,
                       const std::vector<int> &entities,
                       const std::string      &name)
    {
      if (!entities.empty())
        gmsh::model::setPhysicalName(
          structdim, gmsh::model::addPhysicalGroup(structdim, entities), name);
    }



    void
    group_layer_pieces(
      const int                                            structdim,
      const std::vector<std::vector<std::pair<int, int>>> &origin,
      const std::size_t                                    n_objects,
      const std::vector<std::string>                      &layers,
      const std::set<int>                                 &inside,
      const std::string                                   &message)
    {
      std::map<std::string, std::vector<int>> by_material;
      gmsh::vectorpair                        outside;
      for (unsigned int k = 0; k < layers.size(); ++k)
        for (const auto &piece : origin[n_objects + k])
          if (piece.first == structdim)
            {
              if (inside.count(piece.second) == 1)
                by_material[layers[k]].push_back(piece.second);
              else
                outside.push_back(piece);
            }
      GmshSession::run(message, [&]() {
        gmsh::model::occ::remove(outside, true);
        gmsh::model::occ::synchronize();
        for (const std::string &name : layers)
          if (by_material.count(name) == 1)
            {
              add_physical_group(structdim, by_material[name], name);
              by_material.erase(name);
            }
      });
    }

  } // namespace geometry
} // namespace fdem
