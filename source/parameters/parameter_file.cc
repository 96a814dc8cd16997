// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/parameters/parameter_file.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace fdem
{
  namespace parameters
  {
    using namespace dealii;

    namespace
    {
      // Far above any case (the shipped ones have a few kB); a file this
      // large is not a parameter file, and reading /dev/zero must end.
      constexpr std::uintmax_t max_file_size = 16u << 20;
      // Files included within files; a real case uses one or two.
      constexpr unsigned int max_include_depth = 16;

      std::string
      file_context(const std::string &filename)
      {
        return "Parameter file '" + filename + "'";
      }

      /// The file's bytes as text: a regular file, not binary, BOM removed,
      /// line endings LF.
      std::string
      read_text(const std::string &filename, const std::string &context)
      {
        namespace fs = std::filesystem;
        std::error_code       error;
        const fs::file_status status = fs::status(filename, error);
        AssertThrow(fs::exists(status),
                    ExcMessage(context + ": no such file."));
        AssertThrow(!fs::is_directory(status),
                    ExcMessage(context + ": is a directory, not a parameter "
                                         "file."));
        AssertThrow(fs::is_regular_file(status),
                    ExcMessage(context + ": is not a regular file (a device "
                                         "or a pipe); give a .prm file."));
        AssertThrow(fs::file_size(filename, error) <= max_file_size,
                    ExcMessage(context + ": larger than 16 MiB; binary or "
                                         "corrupt file."));
        std::ifstream file(filename, std::ios::binary);
        AssertThrow(file.good(), ExcMessage(context + ": cannot be read."));
        std::ostringstream buffer;
        buffer << file.rdbuf();
        std::string text = buffer.str();

        // A UTF-8 byte order mark, as some editors write it, is no content.
        if (text.compare(0, 3, "\xEF\xBB\xBF") == 0)
          text.erase(0, 3);

        std::string  normalized;
        unsigned int line = 1;
        normalized.reserve(text.size());
        for (std::size_t i = 0; i < text.size(); ++i)
          {
            const unsigned char c = text[i];
            if (c == '\r')
              {
                // CRLF (Windows) and CR alone (old Mac) end a line as LF does.
                if (i + 1 < text.size() && text[i + 1] == '\n')
                  ++i;
                normalized += '\n';
                ++line;
                continue;
              }
            if (c == '\n')
              ++line;
            AssertThrow(c >= 0x20 || c == '\n' || c == '\t' || c == '\f' ||
                          c == '\v',
                        ExcMessage(context + ": binary or corrupt file (byte " +
                                   std::to_string(int(c)) + " on line " +
                                   std::to_string(line) +
                                   "); a parameter file is text."));
            normalized += char(c);
          }
        return normalized;
      }

      bool
      starts_with_keyword(const std::string &line, const std::string &word)
      {
        // deal.II takes the keywords in lower or upper case, followed by a
        // blank (or alone, for 'end').
        std::string upper = word;
        for (char &c : upper)
          c = char(std::toupper(static_cast<unsigned char>(c)));
        for (const std::string &w : {word, upper})
          if (line.compare(0, w.size(), w) == 0 &&
              (line.size() == w.size() || line[w.size()] == ' ' ||
               line[w.size()] == '\t'))
            return true;
        return false;
      }

      /// Whitespace runs as one blank, as deal.II compares names.
      std::string
      collapsed(const std::string &name)
      {
        std::string result;
        for (const char c : Utilities::trim(name))
          if ((c != ' ' && c != '\t') ||
              (!result.empty() && result.back() != ' '))
            result += (c == '\t') ? ' ' : c;
        return Utilities::trim(result);
      }

      struct Setting
      {
        std::string  file;
        unsigned int line;
      };

      /**
       * Checks @p text of @p filename and, recursively, the files it
       * includes: @p stack holds the files being read (for a cycle). An
       * entry set twice within one file is an error; a file may set again
       * what a file it includes sets (that is how a case varies a shipped
       * one), so each file has its own record of settings.
       */
      void
      check_text(const std::string        &filename,
                 const std::string        &text,
                 std::vector<std::string> &stack)
      {
        std::map<std::string, Setting> settings;
        std::istringstream             in(text);
        std::string                    raw;
        std::vector<std::string>       path;
        unsigned int                   line_number = 0;
        while (std::getline(in, raw))
          {
            ++line_number;
            const unsigned int first_line = line_number;
            // A trailing backslash continues the line.
            std::string line = raw;
            while (!line.empty() && line.back() == '\\' &&
                   std::getline(in, raw))
              {
                line.pop_back();
                line += Utilities::trim(raw);
                ++line_number;
              }
            // A comment starts at the first '#' not escaped as '\#'.
            for (std::size_t p = line.find('#'); p != std::string::npos;
                 p             = line.find('#', p + 1))
              if (p == 0 || line[p - 1] != '\\')
                {
                              line.erase(p);
                              break;
                }
            line = Utilities::trim(line);
            if (line.empty())
              continue;
            const std::string where =
              "line " + std::to_string(first_line) + " of '" + filename + "'";
            if (starts_with_keyword(line, "subsection"))
              path.push_back(collapsed(line.substr(10)));
            else if (starts_with_keyword(line, "end"))
              {
                if (!path.empty())
                  path.pop_back();
              }
            else if (starts_with_keyword(line, "set"))
              {
                const std::size_t equal = line.find('=');
                if (equal == std::string::npos)
                  continue; // deal.II says what is wrong
                std::string key;
                for (const std::string &section : path)
                  key += section + "/";
                key += collapsed(line.substr(3, equal - 3));
                const auto inserted =
                  settings.emplace(key, Setting{filename, first_line});
                const Setting &before = inserted.first->second;
                AssertThrow(inserted.second,
                            ExcMessage(file_context(filename) + ": '" + key +
                                       "' is set twice, on line " +
                                       std::to_string(before.line) + " of '" +
                                       before.file + "' and on " + where +
                                       "; keep one."));
              }
            else if (starts_with_keyword(line, "include"))
              {
                // deal.II opens the name as written (relative to the
                // working directory).
                const std::string included = Utilities::trim(line.substr(7));
                const std::string context = file_context(filename) + ", line " +
                                            std::to_string(first_line) +
                                            ": the included file '" + included +
                                            "'";
                std::error_code   error;
                const std::string canonical =
                  std::filesystem::weakly_canonical(included, error).string();
                std::string chain;
                bool        cycle = false;
                for (const std::string &open : stack)
                  {
                    chain += "'" + open + "' -> ";
                    cycle = cycle || (open == canonical);
                  }
                AssertThrow(!cycle,
                            ExcMessage(context +
                                       " is already being read ("
                                       "includes: " +
                                       chain + "'" + included +
                                       "'); a file cannot include itself."));
                AssertThrow(stack.size() < max_include_depth,
                            ExcMessage(context + " is nested more than " +
                                       std::to_string(max_include_depth) +
                                       " includes deep."));
                const std::string included_text = read_text(included, context);
                stack.push_back(canonical);
                check_text(included, included_text, stack);
                stack.pop_back();
              }
          }
      }
    } // namespace



    std::string
    checked_parameter_text(const std::string &filename)
    {
      const std::string text = read_text(filename, file_context(filename));
      std::error_code   error;
      std::vector<std::string> stack = {
        std::filesystem::weakly_canonical(filename, error).string()};
      check_text(filename, text, stack);
      return text;
    }



    void
    parse_parameter_file(ParameterHandler  &prm,
                         const std::string &filename,
                         const bool         skip_undefined)
    {
      // The file itself first (missing, a directory, a device, binary),
      // then its name.
      read_text(filename, file_context(filename));
      const std::string extension =
        std::filesystem::path(filename).extension().string();
      if (extension == ".json" || extension == ".xml")
        {
          prm.parse_input(filename, "", skip_undefined, false);
          return;
        }
      AssertThrow(extension == ".prm",
                  ExcMessage(file_context(filename) +
                             ": the name must end in .prm (or .json, .xml)."));
      std::istringstream text(checked_parameter_text(filename));
      prm.parse_input(text, filename, "", skip_undefined);
    }
  } // namespace parameters
} // namespace fdem
