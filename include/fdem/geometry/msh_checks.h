// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#ifndef fdem_geometry_msh_checks_h
#define fdem_geometry_msh_checks_h

#include <string>

namespace fdem
{
  namespace geometry
  {
    /**
     * Gmsh keeps one of two nodes with the same tag in a .msh file without
     * a word, so the distorted mesh would run silently: a node listed twice
     * at two places is an error (ExcMessage naming the file and the node).
     * Reads ASCII and binary files of format 2 and 4.1 (binary in the
     * machine's byte order, as written here); format 4.0 and binary files
     * of the other byte order are left to Gmsh.
     */
    void
    check_node_tags(const std::string &file_name);

    /**
     * Gmsh reads a .geo file that includes itself, directly or through
     * others, until it runs out of file handles and then says "Unable to
     * open file": such a cycle of literal `Include "..."` (or `Merge` of a
     * .geo file) is an error naming the files. Names built at run time
     * (Sprintf) are not followed; Geometry/Time limit bounds those.
     */
    void
    check_geo_includes(const std::string &file_name);

    /**
     * The check of the two above that fits the file's extension (.msh or
     * .geo); nothing for a file that cannot be read.
     */
    void
    check_before_gmsh(const std::string &file_name);
  } // namespace geometry
} // namespace fdem

#endif
