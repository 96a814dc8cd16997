// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#ifndef fdem_parameters_parameter_file_h
#define fdem_parameters_parameter_file_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace fdem
{
  namespace parameters
  {
    /**
     * Reads the parameter file @p filename into @p prm, after checks that
     * deal.II's ParameterHandler does not make:
     * - the file is a regular, readable text file (not a directory, a device
     *   such as /dev/zero, an empty file, or a file with NUL or other control
     *   bytes: "binary or corrupt file");
     * - a UTF-8 byte order mark is skipped, and CRLF and CR-only line endings
     *   are read as LF;
     * - `include` statements are followed with the stack of files being
     *   read, so that a file that includes itself (directly or through
     *   others) is an error naming the files, not an endless recursion;
     * - an entry set twice in one subsection is an error naming both lines
     *   (otherwise the last would silently win).
     * Every error is an ExcMessage naming the file and, where there is one,
     * the line. JSON and XML parameter files go to deal.II unchanged.
     */
    void
    parse_parameter_file(dealii::ParameterHandler &prm,
                         const std::string        &filename,
                         bool                      skip_undefined);

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
