// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#ifndef fdem_parameters_parameter_file_h
#define fdem_parameters_parameter_file_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace fdem
{
  namespace parameters
  {
    /**
     * @p name, a file that @p naming_file names (in an include statement
     * or a file entry), as the program opens it: an absolute name as it is,
     * a relative one from the folder of @p naming_file (so that a case and
     * the files it names can be moved together, and a file included from
     * another folder names its own neighbours). Empty stays empty.
     */
    std::string
    path_relative_to_file(const std::string &naming_file,
                          const std::string &name);

    /**
     * A ParameterHandler that reads the names of included files and of the
     * file entries @p file_entries (keys like "Geometry/Mesh file")
     * relative to the file that writes them, not to the working directory
     * as ParameterHandler does: in each .prm file it reads, the top one and
     * every one included, those names are resolved by
     * path_relative_to_file() before ParameterHandler sees the text (the
     * values it returns are the resolved names). Included files are read
     * with the top file's normalisation too (BOM, line endings).
     */
    class FileRelativeParameterHandler : public dealii::ParameterHandler
    {
    public:
      explicit FileRelativeParameterHandler(
        std::vector<std::string> file_entries);

      using dealii::ParameterHandler::parse_input;

      void
      parse_input(std::istream      &input,
                  const std::string &filename       = "input file",
                  const std::string &last_line      = "",
                  const bool         skip_undefined = false) override;

      /** The entries whose values name files. */
      const std::vector<std::string> &
      get_file_entries() const
      {
        return file_entries;
      }

    private:
      std::vector<std::string> file_entries;
    };

    /**
     * Reads the parameter file @p filename into @p prm, after checks that
     * deal.II's ParameterHandler does not make:
     * - the file is a regular, readable text file (not a directory, a device
     *   such as /dev/zero, an empty file, or a file with NUL or other control
     *   bytes: "binary or corrupt file");
     * - a UTF-8 byte order mark is skipped, and CRLF and CR-only line endings
     *   are read as LF;
     * - `include` statements are followed (relative to the including file)
     *   with the stack of files being read, so that a file that includes
     *   itself (directly or through others) is an error naming the files,
     *   not an endless recursion;
     * - an entry set twice in one subsection is an error naming both lines
     *   (otherwise the last would silently win).
     * Every error is an ExcMessage naming the file and, where there is one,
     * the line. JSON and XML parameter files go to deal.II unchanged, their
     * file entries resolved afterwards.
     */
    void
    parse_parameter_file(FileRelativeParameterHandler &prm,
                         const std::string            &filename,
                         bool                          skip_undefined);

    /**
     * The text of the parameter file @p filename after the checks of
     * parse_parameter_file() (BOM removed, line endings LF). Throws on the
     * same errors.
     */
    std::string
    checked_parameter_text(const std::string &filename);
  } // namespace parameters
} // namespace fdem

#endif
