// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <deal.II/base/timer.h>

#include <nlohmann/json.hpp>

#include <string>

namespace fdem
{
  namespace postprocess
  {
    using namespace dealii;

    /**
     * Peak resident memory of this process so far (MiB): the high-water
     * mark VmHWM of deal.II's Utilities::System::get_memory_stats(). It counts
     * everything the process holds: Gmsh, the factorisations, the flexibility
     * matrices, and the libraries' baseline.
     */
    double
    peak_memory_mib();

    /**
     * The wall time of every section of @p timer (s), plus "total":
     * @p total_seconds. The model's sections do not nest, so they add up to
     * the total up to the small untimed rest (reading parameters, writing
     * summary.json).
     */
    nlohmann::json
    section_wall_times(const TimerOutput &timer, const double total_seconds);

    /**
     * The prefix of a progress line: elapsed wall time and peak memory, e.g.
     * "[   12.3 s    145 MiB] ".
     */
    std::string
    progress_stamp(const double elapsed_seconds);
  } // namespace postprocess
} // namespace fdem
