// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/newmark.h>
#include <fdem/geometry/cases/case_input.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <system_error>

namespace fdem
{
  namespace analyses
  {
    using namespace dealii;

    namespace
    {
      constexpr double max_acceleration = 100 * standard_gravity; // m/s^2
      constexpr double max_duration     = 86400;                  // s
    }                                                             // namespace

    parameters::WorkEstimate
    record_work_estimate(const std::string &file)
    {
      // Per sample: the record's time and acceleration, up to twice their
      // size while the vectors grow (32 bytes), and the history's four
      // values (32 bytes, twice while they grow).
      constexpr double bytes_per_sample = 96;
      // Reading, integrating and writing newmark.csv: 1.7e-6 s measured
      // (doc/benchmarks.md, "Work estimates").
      constexpr double         seconds_per_sample = 2e-6;
      parameters::WorkEstimate work;
      work.entry = "Yield acceleration/Acceleration record";
      std::error_code      error;
      const std::uintmax_t size = std::filesystem::file_size(file, error);
      if (error)
        return work;
      const double n_samples = std::ceil(size / 4.0);
      work.what    = "up to " + parameters::count_text(n_samples) + " samples";
      work.seconds = n_samples * seconds_per_sample;
      work.memory_MiB = n_samples * bytes_per_sample / (1024. * 1024.);
      return work;
    }

    AccelerationRecord
    read_acceleration_record(const std::string &file, const std::string &unit)
    {
      const std::string where =
        "Yield acceleration/Acceleration record: '" + file + "'";
      const double       scale = unit == "g" ? standard_gravity : 1.0;
      AccelerationRecord record;
      geometry::case_input::for_each_table_row(
        file,
        where,
        [&](const unsigned int /*line_number*/,
            const std::string              &at,
            const std::vector<std::string> &fields) {
          double     t = 0, a = 0;
          const bool numbers =
            fields.size() == 2 &&
            geometry::case_input::parse_number(fields[0], t) &&
            geometry::case_input::parse_number(fields[1], a);
          AssertThrow(fields.size() == 2,
                      ExcMessage(
                        at + "expected two values (time, acceleration), got " +
                        std::to_string(fields.size()) + "."));
          AssertThrow(numbers && std::isfinite(t) && std::isfinite(a),
                      ExcMessage(at + "'" + fields[0] + "', '" + fields[1] +
                                 "' are not two finite numbers."));
          AssertThrow(
            record.time.empty() || t > record.time.back(),
            ExcMessage(
              at + "the time " + fields[0] +
              " is not after the time before it; times must increase."));
          // Checked again in m/s^2: 1e308 g is finite, its product not. An
          // acceleration beyond 100 g, or a record longer than a day, is a
          // unit or column mistake, not an earthquake (the strongest
          // recorded ground motions are below 5 g).
          const double acceleration = a * scale;
          AssertThrow(std::isfinite(acceleration) &&
                        std::abs(acceleration) <= max_acceleration,
                      ExcMessage(at + "the acceleration " + fields[1] + " " +
                                 unit +
                                 " is beyond 100 g; check the record's unit "
                                 "(Acceleration unit) and columns."));
          AssertThrow(record.time.empty() ||
                        t - record.time.front() <= max_duration,
                      ExcMessage(at + "the record runs longer than a day (" +
                                 fields[0] +
                                 " s); check the time column's unit."));
          record.time.push_back(t);
          record.acceleration.push_back(acceleration);
        });
      AssertThrow(record.time.size() >= 2,
                  ExcMessage(where +
                             ": fewer than two samples (time, acceleration)."));
      return record;
    }

    namespace
    {
      /**
       * Within one interval of duration @p dt, a(tau) = a0 + s tau: the
       * forward sliding of a mass with relative velocity v >= 0 (v > 0 or
       * a > a_y to slide), yield acceleration a_y. Advances v and the
       * displacement d exactly; returns the time within the interval at
       * which the motion stops (dt if it does not).
       */
      double
      slide(const double a0,
            const double s,
            const double a_y,
            const double dt,
            double      &v,
            double      &d)
      {
        // v(tau) = v + (a0 - a_y) tau + s tau^2 / 2: its first zero in (0, dt].
        const double b = a0 - a_y, c = v;
        double       stop     = dt;
        const auto   try_root = [&](const double tau) {
          if (tau > 0 && tau < stop)
            stop = tau;
        };
        if (s != 0)
          {
            const double disc = b * b - 2 * s * c;
            if (disc >= 0)
              {
                const double root = std::sqrt(disc);
                // Both roots, the cancellation-free way.
                const double q = -(b + std::copysign(root, b));
                if (q != 0)
                  {
                    try_root(q / s);
                    try_root(2 * c / q);
                  }
              }
          }
        else if (b < 0)
          try_root(-c / b);
        const double tau = stop;
        d += v * tau + b * tau * tau / 2 + s * tau * tau * tau / 6;
        v = stop < dt ? 0.0 : std::max(0.0, v + b * tau + s * tau * tau / 2);
        return stop;
      }
    } // namespace

    NewmarkResult
    newmark_displacement(const AccelerationRecord &record,
                         const double              k_y,
                         const double              k_y_backward)
    {
      NewmarkResult result;
      if (!std::isfinite(k_y))
        return result;
      result.computed  = true;
      const double a_f = k_y * standard_gravity;
      const double a_b = std::isnan(k_y_backward) ?
                           std::numeric_limits<double>::infinity() :
                           k_y_backward * standard_gravity;
      double       v   = 0,
             d = 0; // relative velocity and displacement, forwards positive
      const auto record_point = [&](const unsigned int i) {
        result.time.push_back(record.time[i]);
        result.acceleration.push_back(record.acceleration[i]);
        result.velocity.push_back(v);
        result.displacement.push_back(d);
        if (std::abs(d) > result.max_displacement)
          {
            result.max_displacement = std::abs(d);
            result.time_of_max      = record.time[i];
          }
        result.max_velocity = std::max(result.max_velocity, std::abs(v));
      };
      record_point(0);
      for (unsigned int i = 0; i + 1 < record.time.size(); ++i)
        {
          const double dt  = record.time[i + 1] - record.time[i];
          const double a0  = record.acceleration[i];
          const double s   = (record.acceleration[i + 1] - a0) / dt;
          double       tau = 0;
          // Within the interval: phases of rest, forward and backward sliding.
          while (tau < dt)
            {
              const double a = a0 + s * tau;
              if (v > 0 || (v == 0 && (a > a_f || (a == a_f && s > 0))))
                tau += slide(a, s, a_f, dt - tau, v, d);
              else if (v < 0 || (v == 0 && (a < -a_b || (a == -a_b && s < 0))))
                {
                  // Backwards: the mirror image of forward sliding.
                  double w = -v, e = -d;
                  tau += slide(-a, -s, a_b, dt - tau, w, e);
                  v = -w;
                  d = -e;
                }
              else
                {
                  // At rest: until a reaches a_f (rising) or -a_b (falling).
                  double next = dt;
                  if (s > 0 && std::isfinite(a_f))
                    next = std::min(next, tau + (a_f - a) / s);
                  if (s < 0 && std::isfinite(a_b))
                    next = std::min(next, tau + (-a_b - a) / s);
                  if (!(next > tau))
                    next = dt; // no start within the interval
                  tau = next;
                }
            }
          record_point(i + 1);
        }
      return result;
    }
  } // namespace analyses
} // namespace fdem
