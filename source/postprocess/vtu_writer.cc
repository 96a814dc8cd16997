// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/postprocess/output_file.h>
#include <fdem/postprocess/vtu_writer.h>

#include <deal.II/base/exceptions.h>

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

namespace fdem
{
  namespace postprocess
  {
    namespace
    {
      template <typename T>
      std::vector<char>
      bytes_of(const std::vector<T> &values)
      {
        std::vector<char> bytes(values.size() * sizeof(T));
        if (!values.empty())
          std::memcpy(bytes.data(), values.data(), bytes.size());
        return bytes;
      }

      bool
      all_finite(const std::vector<double> &values)
      {
        return std::all_of(values.begin(), values.end(), [](const double x) {
          return std::isfinite(x);
        });
      }

      /**
       * VTK's zlib format: a header of UInt64 (number of blocks, block size,
       * size of the last block, compressed size of each block) and the
       * blocks compressed one by one. Z_BEST_SPEED: output is a small part of
       * a run, and the best compression costs several times as long for
       * files a tenth smaller.
       */
      std::string
      compressed(const std::vector<char> &data)
      {
        constexpr std::uint64_t block_size = 1 << 20;
        const std::uint64_t     n_blocks =
          (data.size() + block_size - 1) / block_size;
        std::vector<std::uint64_t> header = {n_blocks,
                                             block_size,
                                             data.size() % block_size == 0 &&
                                                 !data.empty() ?
                                               block_size :
                                               data.size() % block_size};
        std::string                blocks;
        for (std::uint64_t b = 0; b < n_blocks; ++b)
          {
            const std::uint64_t size =
              std::min<std::uint64_t>(block_size, data.size() - b * block_size);
            uLongf      length = compressBound(size);
            std::string out(length, '\0');
            AssertThrow(compress2(reinterpret_cast<Bytef *>(&out[0]),
                                  &length,
                                  reinterpret_cast<const Bytef *>(
                                    data.data() + b * block_size),
                                  size,
                                  Z_BEST_SPEED) == Z_OK,
                        dealii::ExcMessage(
                          "zlib could not compress VTU data."));
            header.push_back(length);
            blocks.append(out.data(), length);
          }
        std::string result(reinterpret_cast<const char *>(header.data()),
                           header.size() * sizeof(std::uint64_t));
        return result + blocks;
      }

      std::string
      escaped(const std::string &text)
      {
        std::string out;
        for (const char c : text)
          switch (c)
            {
              case '&':
                out += "&amp;";
                break;
              case '<':
                out += "&lt;";
                break;
              case '>':
                out += "&gt;";
                break;
              case '"':
                out += "&quot;";
                break;
              default:
                out += c;
            }
        return out;
      }
    } // namespace

    std::uint64_t
    VtuWriter::add_point(const double x, const double y, const double z)
    {
      if (first_non_finite.empty() && !all_finite({x, y, z}))
        first_non_finite = "Points";
      points.insert(points.end(), {x, y, z});
      return n_points() - 1;
    }

    void
    VtuWriter::add_cell(const CellType                    type,
                        const std::vector<std::uint64_t> &nodes)
    {
      connectivity.insert(connectivity.end(), nodes.begin(), nodes.end());
      offsets.push_back(connectivity.size());
      types.push_back(type);
    }

    void
    VtuWriter::add_point_data(const std::string         &name,
                              const unsigned int         n_components,
                              const std::vector<double> &values,
                              const bool                 single)
    {
      Assert(values.size() == n_points() * n_components,
             dealii::ExcInternalError());
      if (first_non_finite.empty() && !all_finite(values))
        first_non_finite = name;
      if (single)
        point_data.push_back(
          {name,
           "Float32",
           n_components,
           bytes_of(std::vector<float>(values.begin(), values.end()))});
      else
        point_data.push_back({name, "Float64", n_components, bytes_of(values)});
    }

    void
    VtuWriter::add_point_data_with_blanks(const std::string         &name,
                                          const std::vector<double> &values)
    {
      Assert(values.size() == n_points(), dealii::ExcInternalError());
      if (first_non_finite.empty() &&
          std::any_of(values.begin(), values.end(), [](const double x) {
            return std::isinf(x);
          }))
        first_non_finite = name;
      point_data.push_back({name, "Float64", 1, bytes_of(values)});
    }

    void
    VtuWriter::add_point_data(const std::string               &name,
                              const std::vector<std::int32_t> &values)
    {
      Assert(values.size() == n_points(), dealii::ExcInternalError());
      point_data.push_back({name, "Int32", 1, bytes_of(values)});
    }

    void
    VtuWriter::add_cell_data(const std::string               &name,
                             const std::vector<std::int32_t> &values)
    {
      Assert(values.size() == n_cells(), dealii::ExcInternalError());
      cell_data.push_back({name, "Int32", 1, bytes_of(values)});
    }

    void
    VtuWriter::add_field_data(const std::string &name, const double value)
    {
      if (first_non_finite.empty() && !std::isfinite(value))
        first_non_finite = name;
      field_numbers.emplace_back(name, value);
    }

    void
    VtuWriter::add_field_data_or_blank(const std::string &name,
                                       const double       value)
    {
      if (first_non_finite.empty() && std::isinf(value))
        first_non_finite = name;
      field_numbers.emplace_back(name, value);
    }

    void
    VtuWriter::add_field_data(const std::string &name, const std::string &text)
    {
      field_texts.emplace_back(name, text);
    }

    void
    VtuWriter::write(const std::string &filename) const
    {
      AssertThrow(first_non_finite.empty(),
                  dealii::ExcMessage(non_finite_output_error(
                    filename,
                    "a value that is not finite in its array '" +
                      first_non_finite + "'")));
      std::string header, appended;
      const auto  array = [&](const std::string       &tag,
                             const std::string       &type,
                             const std::string       &name,
                             const std::string       &extra,
                             const std::vector<char> &bytes) {
        header += "      <" + tag + " type=\"" + type + "\" Name=\"" +
                  escaped(name) + "\"" + extra +
                  " format=\"appended\" offset=\"" +
                  std::to_string(appended.size()) + "\"/>\n";
        appended += compressed(bytes);
      };
      header +=
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
        "header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">\n"
        "  <UnstructuredGrid>\n    <FieldData>\n";
      for (const auto &[name, value] : field_numbers)
        array("DataArray",
              "Float64",
              name,
              " NumberOfTuples=\"1\"",
              bytes_of(std::vector<double>{value}));
      for (const auto &[name, text] : field_texts)
        array("Array",
              "String",
              name,
              " NumberOfTuples=\"1\"",
              std::vector<char>(text.c_str(), text.c_str() + text.size() + 1));
      header += "    </FieldData>\n    <Piece NumberOfPoints=\"" +
                std::to_string(n_points()) + "\" NumberOfCells=\"" +
                std::to_string(n_cells()) + "\">\n      <PointData>\n";
      const auto components = [](const unsigned int n) {
        return " NumberOfComponents=\"" + std::to_string(n) + "\"";
      };
      for (const Array &a : point_data)
        array("DataArray", a.type, a.name, components(a.n_components), a.bytes);
      header += "      </PointData>\n      <CellData>\n";
      for (const Array &a : cell_data)
        array("DataArray", a.type, a.name, components(a.n_components), a.bytes);
      header += "      </CellData>\n      <Points>\n";
      array("DataArray", "Float64", "Points", components(3), bytes_of(points));
      header += "      </Points>\n      <Cells>\n";
      array("DataArray", "UInt64", "connectivity", "", bytes_of(connectivity));
      array("DataArray", "UInt64", "offsets", "", bytes_of(offsets));
      array("DataArray", "UInt8", "types", "", bytes_of(types));
      header += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
                "  <AppendedData encoding=\"raw\">\n_";

      OutputFile out(filename, std::ios::binary);
      out << header;
      out.write(appended.data(), appended.size());
      out << "\n  </AppendedData>\n</VTKFile>\n";
      out.close();
    }

    void
    add_common_field_data(VtuWriter         &writer,
                          const std::string &name,
                          const OutputState &state)
    {
      writer.add_field_data("name", name);
      writer.add_field_data("K", state.K);
      writer.add_field_data_or_blank("K_star", state.K_star);
      writer.add_field_data("state", state.description);
      writer.add_field_data(
        "units",
        "The input's units: fdem-slope has none built in (doc/units.md). With F the force "
        "and L the length unit: coordinates, displacement, mechanism_displacement, gap and "
        "slip in L; stress, stress_zz, normal_pressure and shear_stress in F/L^2 (stress "
        "positive in tension, normal_pressure positive in compression); normal_force and "
        "tangential_force in F (2D: F/L, per unit thickness); K, K_star and "
        "local_safety_factor dimensionless.");
    }
  } // namespace postprocess
} // namespace fdem
