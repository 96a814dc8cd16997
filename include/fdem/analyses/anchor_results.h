// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace fdem
{
  namespace analyses
  {
    /** The result block's line for summary.json's "reinforcement"
     * (analyses/anchors.h), if any. */
    std::vector<std::pair<std::string, std::string>>
    reinforcement_result_lines(const nlohmann::json &summary);
  } // namespace analyses
} // namespace fdem
