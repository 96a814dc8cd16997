// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/postprocess/output_file.h>
#include <fdem/postprocess/output_files.h>

#include <deal.II/base/exceptions.h>

#include <cstdio>
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
