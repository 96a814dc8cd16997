// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#ifndef fdem_parameters_work_estimate_h
#define fdem_parameters_work_estimate_h

#include <string>

namespace fdem
{
  namespace parameters
  {
    /**
     * The work of a phase whose size the input sets (the circles of a
     * surface search, the samples of a probabilistic analysis, the points
     * of a terrain grid), estimated before the phase starts: 1e9 circles
     * or 1e8 samples are a typing error far more often than a plan, and
     * would otherwise run for days or end in an out-of-memory error that
     * blames something else.
     */
    struct WorkEstimate
    {
      /// The entry that sets the size, e.g. "Probabilistic/Number of samples".
      std::string entry;
      /// What is counted, with its count, e.g. "1e+08 samples".
      std::string what;
      /// Wall time (s) and peak memory (MiB) of the phase; 0 if not known.
      double seconds    = 0;
      double memory_MiB = 0;
    };

    /**
     * Throws one line naming the entry, the estimate and the override when
     * @p work needs more than @p memory_limit_MiB (Geometry/Memory limit's
     * value for this machine) or takes longer than @p time_budget_seconds
     * (Geometry/Time budget; 0: no limit).
     */
    void
    check_work_estimate(const WorkEstimate &work,
                        double              memory_limit_MiB,
                        double              time_budget_seconds);

    /// @p seconds as a person reads them: "40 s", "12 min", "3.5 h", "2.1 days".
    std::string
    duration_text(double seconds);

    /// @p n in the form "120" below a million, "3.2e+07" above.
    std::string
    count_text(double n);
  } // namespace parameters
} // namespace fdem

#endif
