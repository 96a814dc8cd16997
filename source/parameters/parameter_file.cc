// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/parameters/parameter_file.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>
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

      /// @p text as deal.II reads it: a UTF-8 byte order mark removed, line
      /// endings LF; throws for bytes that are not text.
      std::string
      normalized_text(std::string text, const std::string &context)
      {
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
        return normalized_text(buffer.str(), context);
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

      /**
       * Calls @p f(first_line, last_line, statement) for each statement of
       * @p text as deal.II reads it: lines trimmed, a trailing backslash
       * joining the next line, the comment (from the first '#' not escaped
       * as '\#') removed, blank statements skipped.
       */
      template <typename Function>
      void
      for_each_statement(const std::string &text, const Function &f)
      {
        std::istringstream in(text);
        std::string        raw;
        unsigned int       line_number = 0;
        while (std::getline(in, raw))
          {
            ++line_number;
            const unsigned int first_line = line_number;
            std::string        line       = Utilities::trim(raw);
            while (!line.empty() && line.back() == '\\' &&
                   std::getline(in, raw))
              {
                line.pop_back();
                line += Utilities::trim(raw);
                ++line_number;
              }
            for (std::size_t p = line.find('#'); p != std::string::npos;
                 p             = line.find('#', p + 1))
              if (p == 0 || line[p - 1] != '\\')
                {
                              line.erase(p);
                              break;
                }
            line = Utilities::trim(line);
            if (!line.empty())
              f(first_line, line_number, line);
          }
      }

      /// The key "Section/Subsection/Entry" of a set statement within
      /// @p path, and its value, or an empty key if there is no '='.
      std::pair<std::string, std::string>
      setting(const std::vector<std::string> &path, const std::string &line)
      {
        const std::size_t equal = line.find('=');
        if (equal == std::string::npos)
          return {};
        std::string key;
        for (const std::string &section : path)
          key += section + "/";
        key += collapsed(line.substr(3, equal - 3));
        return {key, Utilities::trim(line.substr(equal + 1))};
      }

      /// Keeps the stack of subsections for a statement; true if it was
      /// subsection or end.
      bool
      follow_sections(std::vector<std::string> &path, const std::string &line)
      {
        if (starts_with_keyword(line, "subsection"))
          path.push_back(collapsed(line.substr(10)));
        else if (starts_with_keyword(line, "end"))
          {
            if (!path.empty())
              path.pop_back();
          }
        else
          return false;
        return true;
      }

      struct Setting
      {
        std::string  file;
        unsigned int line;
      };

      void
      check_text(const std::string        &filename,
                 const std::string        &text,
                 std::vector<std::string> &stack);

      /// Checks the file that line @p line_number of @p filename includes.
      void
      check_included(const std::string        &filename,
                     const unsigned int        line_number,
                     const std::string        &included,
                     std::vector<std::string> &stack)
      {
        const std::string context = file_context(filename) + ", line " +
                                    std::to_string(line_number) +
                                    ": the included file '" + included + "'";
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
                    ExcMessage(
                      context + " is already being read (includes: " + chain +
                      "'" + included + "'); a file cannot include itself."));
        AssertThrow(stack.size() < max_include_depth,
                    ExcMessage(context + " is nested more than " +
                               std::to_string(max_include_depth) +
                               " includes deep."));
        const std::string included_text = read_text(included, context);
        stack.push_back(canonical);
        check_text(included, included_text, stack);
        stack.pop_back();
      }

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
        std::vector<std::string>       path;
        for_each_statement(
          text,
          [&](const unsigned int first_line,
              const unsigned int,
              const std::string &line) {
            if (follow_sections(path, line))
              return;
            if (starts_with_keyword(line, "include"))
              check_included(filename,
                             first_line,
                             path_relative_to_file(
                               filename, Utilities::trim(line.substr(7))),
                             stack);
            if (!starts_with_keyword(line, "set"))
              return;
            const std::string key = setting(path, line).first;
            if (key.empty())
              return; // deal.II says what is wrong
            const auto inserted =
              settings.emplace(key, Setting{filename, first_line});
            const Setting &before = inserted.first->second;
            AssertThrow(inserted.second,
                        ExcMessage(file_context(filename) + ": '" + key +
                                   "' is set twice, on line " +
                                   std::to_string(before.line) + " of '" +
                                   before.file + "' and on line " +
                                   std::to_string(first_line) + " of '" +
                                   filename + "'; keep one."));
          });
      }

      /**
       * @p text of @p filename with the names of its include statements
       * and of its @p file_entries taken from the folder of @p filename. A
       * statement rewritten becomes one line at its last line, blank lines
       * before it, so that deal.II's line numbers stay those of the file.
       */
      std::string
      with_paths_resolved(const std::string              &text,
                          const std::string              &filename,
                          const std::vector<std::string> &file_entries)
      {
        std::vector<std::string> lines;
        {
          std::istringstream in(text);
          for (std::string line; std::getline(in, line);)
            lines.push_back(line);
        }
        std::vector<std::string> path;
        const auto               rewrite = [&](const unsigned int first,
                                 const unsigned int last,
                                 const std::string &statement) {
          for (unsigned int l = first; l < last; ++l)
            lines[l - 1].clear();
          lines[last - 1] = statement;
        };
        for_each_statement(
          text,
          [&](const unsigned int first,
              const unsigned int last,
              const std::string &line) {
            if (follow_sections(path, line))
              return;
            if (starts_with_keyword(line, "include"))
              rewrite(first,
                      last,
                      "include " +
                        path_relative_to_file(filename,
                                              Utilities::trim(line.substr(7))));
            else if (starts_with_keyword(line, "set"))
              {
                const auto [key, value] = setting(path, line);
                if (std::find(file_entries.begin(), file_entries.end(), key) !=
                    file_entries.end())
                  rewrite(first,
                          last,
                          line.substr(0, line.find('=') + 1) + " " +
                            path_relative_to_file(filename, value));
              }
          });
        std::string result;
        for (const std::string &line : lines)
          result += line + "\n";
        return result;
      }

      /// In a JSON or XML file (no include statements): the file entries
      /// taken from the file's folder after deal.II has read them.
      void
      resolve_file_entry(ParameterHandler  &prm,
                         const std::string &entry,
                         const std::string &filename)
      {
        const std::vector<std::string> parts =
          Utilities::split_string_list(entry, '/');
        for (unsigned int i = 0; i + 1 < parts.size(); ++i)
          prm.enter_subsection(parts[i]);
        const std::string value = prm.get(parts.back());
        if (!value.empty())
          prm.set(parts.back(), path_relative_to_file(filename, value));
        for (unsigned int i = 0; i + 1 < parts.size(); ++i)
          prm.leave_subsection();
      }
    } // namespace



    std::string
    path_relative_to_file(const std::string &naming_file,
                          const std::string &name)
    {
      const std::filesystem::path path(name);
      if (name.empty() || path.is_absolute())
        return name;
      return (std::filesystem::path(naming_file).parent_path() / path)
        .lexically_normal()
        .string();
    }



    FileRelativeParameterHandler::FileRelativeParameterHandler(
      std::vector<std::string> file_entries)
      : file_entries(std::move(file_entries))
    {}



    void
    FileRelativeParameterHandler::parse_input(std::istream      &input,
                                              const std::string &filename,
                                              const std::string &last_line,
                                              const bool         skip_undefined)
    {
      // Called for the top file and, by ParameterHandler, for every file it
      // includes (opened by the name this function wrote into the include
      // statement: relative to the includer).
      std::ostringstream buffer;
      buffer << input.rdbuf();
      std::istringstream text(with_paths_resolved(
        normalized_text(buffer.str(), file_context(filename)),
        filename,
        file_entries));
      ParameterHandler::parse_input(text, filename, last_line, skip_undefined);
    }



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
    parse_parameter_file(FileRelativeParameterHandler &prm,
                         const std::string            &filename,
                         const bool                    skip_undefined)
    {
      // The file itself first (missing, a directory, a device, binary),
      // then its name.
      read_text(filename, file_context(filename));
      const std::string extension =
        std::filesystem::path(filename).extension().string();
      if (extension == ".json" || extension == ".xml")
        {
          prm.ParameterHandler::parse_input(filename,
                                            "",
                                            skip_undefined,
                                            false);
          for (const std::string &entry : prm.get_file_entries())
            resolve_file_entry(prm, entry, filename);
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
