// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/checks/layout_checks.h>
#include <fdem/postprocess/run_log.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/grid/reference_cell.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace fdem
{
  namespace checks
  {
    namespace
    {
      /** A face by its sorted (merged) vertex indices, unused slots last. */
      using FaceKey = std::array<unsigned int, 4>;

      /**
       * Index of each vertex after merging vertices that coincide: a mesh
       * whose blocks were meshed apart (each with its own nodes along a
       * common face) touches there as much as one with shared vertices.
       * Two vertices coincide within 1e-9 of the model's size.
       */
      template <int dim>
      std::vector<unsigned int>
      merged_vertices(const std::vector<Point<dim>> &vertices)
      {
        const unsigned int        n = vertices.size();
        std::vector<unsigned int> merged(n);
        std::iota(merged.begin(), merged.end(), 0u);
        if (n == 0)
          return merged;
        Point<dim> low = vertices[0], high = vertices[0];
        for (const auto &x : vertices)
          for (unsigned int d = 0; d < dim; ++d)
            {
              low[d]  = std::min(low[d], x[d]);
              high[d] = std::max(high[d], x[d]);
            }
        const double              tolerance = 1e-9 * low.distance(high);
        std::vector<unsigned int> order(merged);
        std::sort(order.begin(),
                  order.end(),
                  [&](const unsigned int a, const unsigned int b) {
                    return vertices[a][0] < vertices[b][0];
                  });
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = i + 1;
               j < n &&
               vertices[order[j]][0] - vertices[order[i]][0] <= tolerance;
               ++j)
            if (vertices[order[i]].distance(vertices[order[j]]) <= tolerance)
              merged[order[j]] = std::min(merged[order[j]], merged[order[i]]);
        // Chains (a = b = c within the tolerance): follow to the smallest.
        for (unsigned int v = 0; v < n; ++v)
          while (merged[merged[v]] != merged[v])
            merged[v] = merged[merged[v]];
        return merged;
      }

      template <typename Container>
      FaceKey
      face_key(const Container                 &face_vertices,
               const std::vector<unsigned int> &merged)
      {
        FaceKey key;
        key.fill(numbers::invalid_unsigned_int);
        unsigned int i = 0;
        for (const unsigned int v : face_vertices)
          key[i++] = merged[v];
        std::sort(key.begin(), key.end());
        return key;
      }

      /** Length (2D) or area (3D) and centre of a face given by its vertices in
       * order. */
      template <int dim>
      std::pair<double, Point<dim>>
      measure_and_centre(const std::vector<Point<dim>> &x)
      {
        Point<dim> centre;
        for (const auto &p : x)
          centre += p / static_cast<double>(x.size());
        double measure = 0;
        if constexpr (dim == 2)
          measure = x[0].distance(x[1]);
        else if (x.size() == 3)
          measure = 0.5 * cross_product_3d(x[1] - x[0], x[2] - x[0]).norm();
        else // a quadrilateral in lexicographic order: half the diagonals'
             // cross product
          measure = 0.5 * cross_product_3d(x[3] - x[0], x[2] - x[1]).norm();
        return {measure, centre};
      }

      /** Every face of the mesh's cells: its blocks (one or two) and geometry.
       */
      template <int dim>
      struct FaceTable
      {
        struct Face
        {
          unsigned int block_a = 0, block_b = numbers::invalid_unsigned_int;
          double       measure = 0;
          Point<dim>   centre;
        };
        std::vector<unsigned int> merged;
        std::map<FaceKey, Face>   faces;
        /** Face groups of each face in mesh.faces. */
        std::map<FaceKey, std::set<types::boundary_id>> groups;

        explicit FaceTable(const geometry::MeshDescription<dim> &mesh)
          : merged(merged_vertices(mesh.vertices))
        {
          for (const auto &cell : mesh.cells)
            {
              const ReferenceCell shape =
                ReferenceCell::n_vertices_to_type(dim, cell.vertices.size());
              for (const unsigned int f : shape.face_indices())
                {
                  std::vector<unsigned int> vertices;
                  for (const unsigned int i :
                       shape.face_reference_cell(f).vertex_indices())
                    vertices.push_back(
                      cell.vertices[shape.face_to_cell_vertices(f, i, 1)]);
                  const auto [it, inserted] =
                    faces.emplace(face_key(vertices, merged), Face());
                  if (inserted)
                    {
                      std::vector<Point<dim>> x;
                      for (const unsigned int v : vertices)
                        x.push_back(mesh.vertices[v]);
                      std::tie(it->second.measure, it->second.centre) =
                        measure_and_centre(x);
                      it->second.block_a = cell.material_id;
                    }
                  else if (it->second.block_a != cell.material_id)
                    it->second.block_b = cell.material_id;
                }
            }
          for (const auto &face : mesh.faces)
            groups[face_key(face.vertices, merged)].insert(face.boundary_id);
        }
      };

      std::string
      number_text(const double x)
      {
        std::ostringstream text;
        text.precision(4);
        text << x;
        return text.str();
      }
    } // namespace

    namespace internal
    {
      template <int dim>
      std::string
      point_text(const Point<dim> &x)
      {
        std::ostringstream text;
        text.precision(6);
        text << "(" << x[0];
        for (unsigned int d = 1; d < dim; ++d)
          text << ", " << x[d];
        text << ")";
        return text.str();
      }

      template std::string
      point_text(const Point<2> &);
      template std::string
      point_text(const Point<3> &);
    } // namespace internal

    template <int dim>
    std::vector<std::string>
    check_mesh_layout(const geometry::MeshDescription<dim> &mesh,
                      const std::vector<std::string>       &interface_names,
                      const std::vector<std::string>       &boundary_names)
    {
      const FaceTable<dim>         table(mesh);
      std::set<types::boundary_id> declared;
      for (unsigned int g = 0; g < mesh.face_group_names.size(); ++g)
        if (std::count(interface_names.begin(),
                       interface_names.end(),
                       mesh.face_group_names[g]) ||
            std::count(boundary_names.begin(),
                       boundary_names.end(),
                       mesh.face_group_names[g]))
          declared.insert(g);

      // Undeclared faces between two blocks, gathered per pair of blocks.
      struct Stretch
      {
        double                       measure = 0;
        Point<dim>                   weighted_centre;
        std::vector<Point<dim>>      centres;
        std::set<types::boundary_id> groups;
      };
      std::map<std::pair<unsigned int, unsigned int>, Stretch> stretches;
      for (const auto &[key, face] : table.faces)
        {
          if (face.block_b == numbers::invalid_unsigned_int)
            continue;
          const auto it = table.groups.find(key);
          if (it != table.groups.end() &&
              std::any_of(it->second.begin(),
                          it->second.end(),
                          [&](const auto g) { return declared.count(g) > 0; }))
            continue;
          Stretch &stretch = stretches[std::minmax(face.block_a, face.block_b)];
          stretch.measure += face.measure;
          stretch.weighted_centre += face.measure * face.centre;
          stretch.centres.push_back(face.centre);
          if (it != table.groups.end())
            stretch.groups.insert(it->second.begin(), it->second.end());
        }
      if (!stretches.empty())
        {
          // The largest stretch, located by the face centre nearest to its
          // centroid (on the faces themselves, also where the stretch is
          // curved).
          const auto &[blocks, stretch] =
            *std::max_element(stretches.begin(),
                              stretches.end(),
                              [](const auto &a, const auto &b) {
                                return a.second.measure < b.second.measure;
                              });
          const Point<dim> centroid = stretch.weighted_centre / stretch.measure;
          const Point<dim> where =
            *std::min_element(stretch.centres.begin(),
                              stretch.centres.end(),
                              [&](const auto &a, const auto &b) {
                                return a.distance(centroid) <
                                       b.distance(centroid);
                              });
          std::string groups;
          for (const auto g : stretch.groups)
            groups += (groups.empty() ? "" : ", ") +
                      ("'" + mesh.face_group_names[g] + "'");
          const std::string others = stretches.size() > 1 ?
                                       " (and " +
                                         std::to_string(stretches.size() - 1) +
                                         " more pairs of blocks)" :
                                       "";
          AssertThrow(
            false,
            ExcMessage(
              "Blocks '" + mesh.block_names[blocks.first] + "' and '" +
              mesh.block_names[blocks.second] + "' of " + mesh.source +
              " share faces of total " + (dim == 2 ? "length " : "area ") +
              number_text(stretch.measure) + " around " +
              internal::point_text(where) +
              (groups.empty() ? " in no face group" :
                                " in face groups not listed (" + groups + ")") +
              others +
              ": list them under Interfaces/Names for contact, or under "
              "Boundaries/Names to leave an open crack."));
        }
      return {};
    }

    template <int dim>
    std::vector<std::string>
    check_interfaces(
      const geometry::MeshDescription<dim>                          &mesh,
      const std::vector<std::unique_ptr<blocks::ElasticBlock<dim>>> &blocks,
      const std::vector<contact::Interface<dim>>                    &interfaces,
      const std::map<std::string, parameters::InterfaceParameters>  &parameters)
    {
      // The pairs' count and support first: an interface of one pair is
      // better told so than that its sides overlap little.
      std::vector<std::string> warnings =
        internal::check_support(blocks, interfaces, parameters);
      const FaceTable<dim> table(mesh);
      for (const auto &interface : interfaces)
        {
          // The face group's measure on each side, and the measure its pairs
          // stand for (their tributary areas on side J).
          double side_I = 0, side_J = 0;
          for (const auto &[key, groups] : table.groups)
            if (groups.count(interface.face_group))
              {
                const auto it = table.faces.find(key);
                if (it == table.faces.end())
                  continue;
                const auto &face = it->second;
                if (face.block_a == interface.block_I ||
                    face.block_b == interface.block_I)
                  side_I += face.measure;
                if (face.block_a == interface.block_J ||
                    face.block_b == interface.block_J)
                  side_J += face.measure;
              }
          double paired = 0;
          for (const auto &pair : interface.pairs)
            paired += pair.area;
          for (const auto &shared : interface.shared_nodes)
            paired += shared.area;
          const double      shorter = std::min(side_I, side_J);
          const std::string measures =
            std::string(dim == 2 ? "length" : "area") + " " +
            number_text(paired) + " against " + number_text(side_I) + " on '" +
            blocks[interface.block_I]->name + "' and " + number_text(side_J) +
            " on '" + blocks[interface.block_J]->name + "'";
          AssertThrow(paired >= 0.5 * shorter,
                      ExcMessage(
                        "Interfaces/" + interface.name +
                        ": its two sides face each other over much less than "
                        "their extent (its node pairs cover a " +
                        measures +
                        "); the blocks touch only in places: check that both "
                        "sides of the face group are the same surface, or "
                        "raise 'Search distance' if they are apart."));
          if (paired < 0.9 * shorter)
            warnings.push_back(postprocess::warning_text(
              "partial-contact",
              "Interfaces/" + interface.name + ": its node pairs cover only " +
                number_text(100 * paired / shorter) +
                " % of its shorter side (" + measures + ")."));
        }
      return warnings;
    }

    void
    report(const std::vector<std::string> &found,
           std::vector<std::string>       &warnings,
           std::ostream                   &log)
    {
      for (const std::string &warning : found)
        {
          log << "warning: " << warning << std::endl;
          warnings.push_back(warning);
        }
    }

    void
    report(const std::vector<std::string> &lines, std::ostream &log)
    {
      for (const std::string &line : lines)
        log << line << std::endl;
    }

    template std::vector<std::string>
    check_mesh_layout(const geometry::MeshDescription<2> &,
                      const std::vector<std::string> &,
                      const std::vector<std::string> &);
    template std::vector<std::string>
    check_mesh_layout(const geometry::MeshDescription<3> &,
                      const std::vector<std::string> &,
                      const std::vector<std::string> &);
    template std::vector<std::string>
    check_interfaces(
      const geometry::MeshDescription<2> &,
      const std::vector<std::unique_ptr<blocks::ElasticBlock<2>>> &,
      const std::vector<contact::Interface<2>> &,
      const std::map<std::string, parameters::InterfaceParameters> &);
    template std::vector<std::string>
    check_interfaces(
      const geometry::MeshDescription<3> &,
      const std::vector<std::unique_ptr<blocks::ElasticBlock<3>>> &,
      const std::vector<contact::Interface<3>> &,
      const std::map<std::string, parameters::InterfaceParameters> &);
  } // namespace checks
} // namespace fdem
