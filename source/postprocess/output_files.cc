// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/postprocess/output_file.h>
#include <fdem/postprocess/output_files.h>

#include <deal.II/base/exceptions.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>

namespace fdem
{
  namespace postprocess
  {
    namespace
    {
      std::string
      xml_escaped(const std::string &text)
      {
        std::string out;
        for (const char c : text)
          out += c == '&' ? "&amp;" :
                 c == '<' ? "&lt;" :
                 c == '>' ? "&gt;" :
                 c == '"' ? "&quot;" :
                            std::string(1, c);
        return out;
      }



      /// The path of the first number in @p value that is not finite ("" if
      /// none): JSON would write it as null, the form of a missing value, so
      /// a NaN that reached the summary would pass for one.
      std::string
      non_finite_entry(const nlohmann::json &value, const std::string &path)
      {
        if (value.is_number_float())
          return std::isfinite(value.get<double>()) ? "" : path;
        if (value.is_object())
          for (const auto &entry : value.items())
            {
              const std::string found =
                non_finite_entry(entry.value(), path + "/" + entry.key());
              if (!found.empty())
                return found;
            }
        if (value.is_array())
          for (std::size_t i = 0; i < value.size(); ++i)
            {
              const std::string found =
                non_finite_entry(value[i], path + "/" + std::to_string(i));
              if (!found.empty())
                return found;
            }
        return "";
      }
    } // namespace

    void
    write_pvd(const std::string &filename, const std::vector<PvdEntry> &entries)
    {
      OutputFile out(filename);
      out << "<?xml version=\"1.0\"?>\n"
          << "<VTKFile type=\"Collection\" version=\"0.1\" "
             "byte_order=\"LittleEndian\">\n  <Collection>\n";
      // K to 12 digits: steps of the iteration closer than that are one time.
      out << std::setprecision(12);
      for (const PvdEntry &entry : entries)
        out << "    <DataSet timestep=\"" << entry.time
            << "\" group=\"\" part=\"" << entry.part << "\" name=\""
            << xml_escaped(entry.name) << "\" file=\"" << entry.file
            << "\"/>\n";
      out << "  </Collection>\n</VTKFile>\n";
      out.close();
    }



    void
    write_json(const std::string &filename, const nlohmann::json &summary)
    {
      const std::string non_finite = non_finite_entry(summary, "");
      AssertThrow(non_finite.empty(),
                  dealii::ExcMessage(non_finite_output_error(
                    filename, "a value that is not finite at " + non_finite)));
      const std::string temporary = filename + ".part";
      {
        OutputFile out(temporary);
        out << std::setw(2) << summary << '\n';
        out.close();
      }
      AssertThrow(std::rename(temporary.c_str(), filename.c_str()) == 0,
                  dealii::ExcMessage("cannot write the output file '" +
                                     filename + "': " + std::strerror(errno) +
                                     "."));
    }

    std::string
    file_stem(const std::string &name)
    {
      std::string stem = name;
      for (char &c : stem)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' &&
            c != '_')
          c = '_';
      return stem;
    }
  } // namespace postprocess
} // namespace fdem
