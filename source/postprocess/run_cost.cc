// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/postprocess/run_cost.h>

#include <deal.II/base/utilities.h>

#include <iomanip>
#include <sstream>

namespace fdem
{
  namespace postprocess
  {
    double
    peak_memory_mib()
    {
      Utilities::System::MemoryStats stats;
      Utilities::System::get_memory_stats(stats);
      return stats.VmHWM / 1024.0; // KiB
    }

    nlohmann::json
    section_wall_times(const TimerOutput &timer, const double total_seconds)
    {
      nlohmann::json times = nlohmann::json::object();
      for (const auto &[section, seconds] :
           timer.get_summary_data(TimerOutput::total_wall_time))
        times[section] = seconds;
      times["total"] = total_seconds;
      return times;
    }

    std::string
    progress_stamp(const double elapsed_seconds)
    {
      std::ostringstream stamp;
      stamp << "[" << std::fixed << std::setprecision(1) << std::setw(8)
            << elapsed_seconds << " s " << std::setprecision(0) << std::setw(6)
            << peak_memory_mib() << " MiB] ";
      return stamp.str();
    }
  } // namespace postprocess
} // namespace fdem
