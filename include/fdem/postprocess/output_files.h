// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace fdem
{
  namespace postprocess
  {
    /** One dataset of a ParaView .pvd collection. */
    struct PvdEntry
    {
      /** The safety factor step's K (1 for a run at full strength). */
      double       time = 0;
      unsigned int part = 0;
      /** The block's or interface's name: what ParaView shows for the dataset.
       */
      std::string name;
      std::string file;
    };

    /**
     * Writes a .pvd collection; datasets with the same time are parts of one
     * step, each with its name.
     */
    void
    write_pvd(const std::string           &filename,
              const std::vector<PvdEntry> &entries);

    /**
     * Writes @p summary to @p filename through a temporary file and a rename,
     * so that a summary.json is either complete or absent.
     */
    void
    write_json(const std::string &filename, const nlohmann::json &summary);

    /** A file-name-safe form of a block or interface name. */
    std::string
    file_stem(const std::string &name);
  } // namespace postprocess
} // namespace fdem
