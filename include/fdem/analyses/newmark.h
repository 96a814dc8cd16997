// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/seismic_results.h>
#include <fdem/parameters/work_estimate.h>

#include <string>
#include <vector>

namespace fdem
{
  namespace analyses
  {
    /** Standard gravity (m/s^2): the g of the records and of k_y g. */
    constexpr double standard_gravity = 9.80665;

    /** An acceleration record: strictly increasing times (s), accelerations
     * (m/s^2). */
    struct AccelerationRecord
    {
      std::vector<double> time, acceleration;
    };

    /**
     * Reads a CSV of time and acceleration (comma or blank separated, '#'
     * comments, blank lines, one optional header line of words) in @p unit
     * ("g" or "m/s^2"). Throws one sentence naming the file (and line) for a
     * missing file, a non-numeric or non-finite value, a line without two
     * values, times that do not increase, or fewer than two samples.
     */
    AccelerationRecord
    read_acceleration_record(const std::string &file, const std::string &unit);

    /**
     * The work of reading @p file as a record and integrating it
     * (parameters/work_estimate.h), from the file's size before it is read:
     * at most one sample per 4 bytes ("0,0" and a line end). Nothing is
     * estimated for a file that cannot be sized (the reader names it).
     */
    parameters::WorkEstimate
    record_work_estimate(const std::string &file);

    /**
     * Newmark's rigid-block sliding displacement (doc/theory.md, "Newmark
     * displacement") of @p record, linear between its samples: the mass
     * slides forwards while its relative velocity v > 0, with dv/dt = a(t) -
     * k_y g, starting where a exceeds k_y g; backwards likewise with dv/dt =
     * a(t) + k_y' g where a < -k_y' g (@p k_y_backward; infinite: never).
     * Integrated exactly for the piecewise linear record (the start and
     * stop times are the roots of the linear and quadratic velocity within
     * an interval), so that the only error is the record's sampling. An
     * infinite or NaN @p k_y gives no result (computed false).
     */
    NewmarkResult
    newmark_displacement(const AccelerationRecord &record,
                         const double              k_y,
                         const double              k_y_backward);
  } // namespace analyses
} // namespace fdem
