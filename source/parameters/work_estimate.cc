// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/parameters/work_estimate.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <sstream>

namespace fdem
{
  namespace parameters
  {
    namespace
    {
      std::string
      rounded(const double x)
      {
        if (x >= 100)
          return std::to_string(std::llround(x));
        std::ostringstream text;
        text.precision(x < 10 ? 2 : 3);
        text << x;
        return text.str();
      }

      std::string
      memory_text(const double MiB)
      {
        return MiB < 1024 ? rounded(MiB) + " MiB" :
                            rounded(MiB / 1024) + " GiB";
      }
    } // namespace



    std::string
    duration_text(const double seconds)
    {
      if (!std::isfinite(seconds))
        return "longer than a computer runs";
      if (seconds < 120)
        return rounded(seconds) + " s";
      if (seconds < 2 * 3600)
        return rounded(seconds / 60) + " min";
      if (seconds < 2 * 86400)
        return rounded(seconds / 3600) + " h";
      return rounded(seconds / 86400) + " days";
    }



    std::string
    count_text(const double n)
    {
      std::ostringstream text;
      if (n < 1e6)
        text << static_cast<long long>(n);
      else
        {
          text.precision(2);
          text << n;
        }
      return text.str();
    }



    void
    check_work_estimate(const WorkEstimate &work,
                        const double        memory_limit_MiB,
                        const double        time_budget_seconds)
    {
      AssertThrow(
        !(work.memory_MiB > memory_limit_MiB),
        dealii::ExcMessage(
          work.entry + ": " + work.what + " would need about " +
          memory_text(work.memory_MiB) + " of memory, more than the " +
          memory_text(memory_limit_MiB) +
          " allowed (Geometry/Memory limit; 0 is this machine's memory): ask "
          "for fewer, or raise Geometry/Memory limit to run them anyway."));
      AssertThrow(
        time_budget_seconds <= 0 || !(work.seconds > time_budget_seconds),
        dealii::ExcMessage(
          work.entry + ": " + work.what + " would take about " +
          duration_text(work.seconds) + ", longer than Geometry/Time budget (" +
          duration_text(time_budget_seconds) +
          "): ask for fewer, or raise Geometry/Time budget (0: no limit) to "
          "run them anyway."));
    }
  } // namespace parameters
} // namespace fdem
