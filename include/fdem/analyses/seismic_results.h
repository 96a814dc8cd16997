// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <nlohmann/json.hpp>

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace fdem
{
  namespace analyses
  {
    /** The yield acceleration search (yield_acceleration.h). */
    struct YieldAccelerationResult
    {
      bool computed = false;
      /** Why not, or why no k_y was found (empty if found). */
      std::string not_found;
      /** k_y: the horizontal seismic coefficient at which K = 1 (NaN if none).
       */
      double k_y = std::numeric_limits<double>::quiet_NaN();
      /** The bracket of the root: K(low) >= 1 >= K(high), both certified. */
      double bracket_low  = std::numeric_limits<double>::quiet_NaN();
      double bracket_high = std::numeric_limits<double>::quiet_NaN();
      /** One K evaluation of the search: kh, its K, whether certified. */
      struct Point
      {
        double kh = 0, K = std::numeric_limits<double>::quiet_NaN();
        bool   certified = false;
      };
      /** The K(kh) curve: every evaluation, ordered by kh. */
      std::vector<Point> curve;
      /** k_y the other way (two-directional Newmark): -kh; infinite if none up
       * to the limit. */
      double k_y_backward = std::numeric_limits<double>::quiet_NaN();
      /** Wall time of the search (s). */
      double wall_seconds = 0;
    };

    /** The Newmark sliding displacement (newmark.h). */
    struct NewmarkResult
    {
      bool        computed = false;
      std::string record, unit, mode;
      /** Largest |displacement| (m) and its time (s). */
      double max_displacement = 0, time_of_max = 0;
      /** Largest relative velocity (m/s). */
      double max_velocity = 0;
      /** The history at the record's times: t (s), a (m/s^2), v (m/s), d (m).
       */
      std::vector<double> time, acceleration, velocity, displacement;
    };

    /** What the seismic analyses of a run did (seismic.h). */
    struct SeismicResults
    {
      /** A seismic coefficient, k_y or Newmark was asked for. */
      bool   active = false;
      double kh = 0, kv = 0;
      /** The unit horizontal direction of a positive kh, and how it was found.
       */
      std::vector<double>     direction;
      std::string             direction_from;
      bool                    on_pore_water = false;
      YieldAccelerationResult yield;
      NewmarkResult           newmark;
    };

    /** summary.json's "seismic" (without the Newmark history, which goes to
     * newmark.csv). */
    nlohmann::json
    to_json(const SeismicResults &results);

    /**
     * The result block's lines (label, text) for summary.json's "seismic"
     * (none without it): made from the summary alone, as the whole block.
     */
    std::vector<std::pair<std::string, std::string>>
    seismic_result_lines(const nlohmann::json &summary);
  } // namespace analyses
} // namespace fdem
