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
     * Gmsh keeps one of two nodes with the same tag in an ASCII .msh file
     * (format 2 or 4) without a word: a node listed twice at two places is
     * an error (ExcMessage naming the file and the node). Binary files are
     * left to Gmsh.
     */
    void
    check_node_tags(const std::string &file_name);
  } // namespace geometry
} // namespace fdem

#endif
