// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/geometry/msh_checks.h>

#include <deal.II/base/exceptions.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    using namespace dealii;

    namespace
    {
      /**
       * Reads the numbers of a $Nodes section, as text or as binary data
       * (native byte order, integers of `int` and `size_t` of the file's
       * data size), the two ways Gmsh writes them.
       */
      class NodeReader
      {
      public:
        NodeReader(std::istream &in, const bool binary, const int size_t_bytes)
          : in(in)
          , binary(binary)
          , size_t_bytes(size_t_bytes)
        {}

        /** An `int` (binary: 4 bytes). */
        long long
        integer()
        {
          if (!binary)
            return text<long long>();
          std::int32_t value = 0;
          in.read(reinterpret_cast<char *>(&value), sizeof value);
          return value;
        }

        /** A `size_t` (binary: the data size of the file's header). */
        std::uint64_t
        size()
        {
          if (!binary)
            return text<std::uint64_t>();
          if (size_t_bytes == 4)
            {
              std::uint32_t value = 0;
              in.read(reinterpret_cast<char *>(&value), sizeof value);
              return value;
            }
          std::uint64_t value = 0;
          in.read(reinterpret_cast<char *>(&value), sizeof value);
          return value;
        }

        double
        real()
        {
          if (!binary)
            return text<double>();
          double value = 0;
          in.read(reinterpret_cast<char *>(&value), sizeof value);
          return value;
        }

      private:
        template <typename T>
        T
        text()
        {
          T value{};
          in >> value;
          return value;
        }

        std::istream &in;
        const bool    binary;
        const int     size_t_bytes;
      };
    } // namespace



    void
    check_node_tags(const std::string &file_name)
    {
      std::ifstream in(file_name, std::ios::binary);
      std::string   line;
      double        version = 0;
      int           binary = 0, size_t_bytes = 8;
      while (std::getline(in, line))
        {
          if (line.rfind("$MeshFormat", 0) == 0)
            {
              in >> version >> binary >> size_t_bytes;
              if (binary != 0)
                {
                  // The line's end, then the number 1 in the writer's byte
                  // order: another byte order is left to Gmsh.
                  in.ignore(1);
                  std::int32_t one = 0;
                  in.read(reinterpret_cast<char *>(&one), sizeof one);
                  if (one != 1 || (size_t_bytes != 4 && size_t_bytes != 8))
                    return;
                }
            }
          else if (line.rfind("$Nodes", 0) == 0)
            break;
        }
      // Format 4.0 orders its nodes otherwise; Gmsh 4.8 writes 4.1.
      if (!in || (version >= 4 && version < 4.1))
        return;
      NodeReader read(in, binary != 0, size_t_bytes);

      std::map<std::size_t, std::array<double, 3>> seen;
      const auto add = [&](const std::size_t            tag,
                           const std::array<double, 3> &x) {
        const auto inserted = seen.emplace(tag, x);
        AssertThrow(inserted.second || inserted.first->second == x,
                    ExcMessage("Gmsh file '" + file_name + "': node " +
                               std::to_string(tag) +
                               " is listed twice, at two different places."));
      };
      // A count larger than the file could hold is left to Gmsh (which
      // calls the file corrupt) rather than allocated here.
      const auto file_size = std::filesystem::file_size(file_name);
      if (version < 4)
        {
          std::uint64_t n = 0;
          in >> n;
          if (binary)
            in.ignore(1); // the end of the line with the count
          for (std::uint64_t i = 0; i < n && in; ++i)
            {
              const std::size_t     tag = read.integer();
              std::array<double, 3> x;
              for (double &c : x)
                c = read.real();
              if (in)
                add(tag, x);
            }
        }
      else
        {
          if (binary)
            in >> std::ws;
          const std::uint64_t n_blocks = read.size();
          read.size(); // nodes, least and largest tag
          read.size();
          read.size();
          for (std::uint64_t b = 0; b < n_blocks && in; ++b)
            {
              const int           entity_dim = read.integer();
              const int           entity_tag = read.integer();
              const int           parametric = read.integer();
              const std::uint64_t n          = read.size();
              (void)entity_tag;
              if (!in || n > file_size)
                return;
              std::vector<std::size_t> tags(n);
              for (auto &tag : tags)
                tag = read.size();
              for (std::uint64_t i = 0; i < n && in; ++i)
                {
                  std::array<double, 3> x;
                  for (double &c : x)
                    c = read.real();
                  for (int p = 0; p < (parametric ? entity_dim : 0); ++p)
                    read.real();
                  if (in)
                    add(tags[i], x);
                }
            }
        }
    }



    namespace
    {
      /**
       * Follows the literal `Include "..."` and `Merge "....geo"` of the
       * .geo file @p file, relative to its folder as Gmsh takes them,
       * depth first; @p open holds the files being read.
       */
      void
      follow_includes(const std::filesystem::path        &file,
                      std::vector<std::filesystem::path> &open)
      {
        namespace fs = std::filesystem;
        std::error_code error;
        const fs::path  canonical = fs::weakly_canonical(file, error);
        for (const fs::path &reading : open)
          if (reading == canonical)
            {
              std::string chain;
              for (const fs::path &f : open)
                chain += "'" + f.string() + "' includes ";
              AssertThrow(false,
                          ExcMessage("Gmsh file '" + open.front().string() +
                                     "': includes itself (" + chain + "'" +
                                     canonical.string() +
                                     "'); Gmsh would read it without end."));
            }
        std::ifstream in(file);
        if (!in)
          return; // Gmsh says which file it cannot open.
        std::stringstream text;
        text << in.rdbuf();
        // Comments out, so that a commented-out Include does not count.
        const std::string code =
          std::regex_replace(text.str(),
                             std::regex(R"(//[^\n]*|/\*[\s\S]*?\*/)"),
                             " ");
        static const std::regex include(R"re(\b(Include|Merge)\s*"([^"]*)")re");
        open.push_back(canonical);
        for (std::sregex_iterator m(code.begin(), code.end(), include), end;
             m != end;
             ++m)
          {
            fs::path target = (*m)[2].str();
            if (target.is_relative())
              target = file.parent_path() / target;
            if ((*m)[1] == "Include" || target.extension() == ".geo")
              follow_includes(target, open);
          }
        open.pop_back();
      }
    } // namespace



    void
    check_geo_includes(const std::string &file_name)
    {
      std::vector<std::filesystem::path> open;
      follow_includes(file_name, open);
    }



    void
    check_before_gmsh(const std::string &file_name)
    {
      namespace fs = std::filesystem;
      if (!std::ifstream(file_name).good() || fs::is_directory(file_name))
        return; // read_gmsh_file() says so
      if (fs::path(file_name).extension() == ".msh")
        check_node_tags(file_name);
      else if (fs::path(file_name).extension() == ".geo")
        check_geo_includes(file_name);
    }
  } // namespace geometry
} // namespace fdem
