// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/geometry/msh_checks.h>

#include <deal.II/base/exceptions.h>

#include <array>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    using namespace dealii;

      /**
       * Gmsh keeps one of two nodes with the same tag in an ASCII .msh file
       * (format 2 or 4) without a word: a node listed twice at two places
       * is an error here. Binary files are left to Gmsh.
       */
    void
    check_node_tags(const std::string &file_name)
      {
        std::ifstream in(file_name);
        std::string   line;
        double        version = 0;
        while (std::getline(in, line))
          {
            if (line.rfind("$MeshFormat", 0) == 0)
              {
                int binary = 0;
                in >> version >> binary;
                if (binary != 0)
                  return;
              }
            else if (line.rfind("$Nodes", 0) == 0)
              break;
          }
        if (!in)
          return;
        std::map<std::size_t, std::array<double, 3>> seen;
        const auto add = [&](const std::size_t tag, const std::array<double, 3> &x) {
          const auto inserted = seen.emplace(tag, x);
          AssertThrow(inserted.second || inserted.first->second == x,
                      ExcMessage("Gmsh file '" + file_name + "': node " +
                                 std::to_string(tag) +
                                 " is listed twice, at two different places."));
        };
        if (version < 4)
          {
            std::size_t n = 0;
            in >> n;
            for (std::size_t i = 0; i < n && in; ++i)
              {
                std::size_t           tag;
                std::array<double, 3> x;
                in >> tag >> x[0] >> x[1] >> x[2];
                if (in)
                  add(tag, x);
              }
          }
        else
          {
            std::size_t n_blocks = 0, n_nodes, min_tag, max_tag;
            in >> n_blocks >> n_nodes >> min_tag >> max_tag;
            for (std::size_t b = 0; b < n_blocks && in; ++b)
              {
                int         entity_dim, entity_tag, parametric;
                std::size_t n = 0;
                in >> entity_dim >> entity_tag >> parametric >> n;
                std::vector<std::size_t> tags(n);
                for (auto &tag : tags)
                  in >> tag;
                for (std::size_t i = 0; i < n && in; ++i)
                  {
                    std::array<double, 3> x;
                    in >> x[0] >> x[1] >> x[2];
                    for (int p = 0; p < (parametric ? entity_dim : 0); ++p)
                      {
                        double u;
                        in >> u;
                      }
                    if (in)
                      add(tags[i], x);
                  }
              }
          }
      }
  } // namespace geometry
} // namespace fdem
