// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/postprocess/hertz_sphere.h>
#include <fdem/postprocess/json_number.h>

#include <deal.II/base/numbers.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fdem
{
  namespace postprocess
  {
    double
    contact_radius_from_pressure_fit(const std::vector<PairResult<3>> &results,
                                     const dealii::Point<3>           &centre)
    {
      double rho_max = 0;
      for (const auto &r : results)
        if (r.status != contact::PairStatus::open)
          rho_max = std::max(rho_max, r.position.distance(centre));
      // Least squares for y = c0 + c1 x with x = (rho/rho_max)^2, y = q^2.
      double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
      for (const auto &r : results)
        {
          const double rho = r.position.distance(centre);
          if (r.status == contact::PairStatus::open || rho < 0.5 * rho_max)
            continue;
          const double x = std::pow(rho / rho_max, 2);
          const double y = std::pow(std::max(r.normal_pressure, 0.0), 2);
          n += 1;
          sx += x;
          sy += y;
          sxx += x * x;
          sxy += x * y;
        }
      const double determinant = n * sxx - sx * sx;
      if (n < 2 || determinant <= 0)
        return std::numeric_limits<double>::quiet_NaN();
      const double c1 = (n * sxy - sx * sy) / determinant;
      const double c0 = (sy - c1 * sx) / n;
      if (!(c1 < 0 && c0 > 0))
        return std::numeric_limits<double>::quiet_NaN();
      return rho_max * std::sqrt(-c0 / c1);
    }



    nlohmann::json
    hertz_sphere_reference(std::vector<PairResult<3>> &results,
                           const double                inverse_E,
                           const double                radius)
    {
      const double pi = dealii::numbers::PI;
      // The quarter model carries a quarter of the load.
      double quarter_load = 0, closed_area = 0, p_max = 0;
      for (const auto &r : results)
        {
          quarter_load -= r.normal_force;
          if (r.status != contact::PairStatus::open)
            closed_area += r.area;
          p_max = std::max(p_max, r.normal_pressure);
        }
      const double load    = 4 * quarter_load;
      const double a_exact = std::cbrt(0.75 * load * radius * inverse_E);
      const double p_exact = 1.5 * load / (pi * a_exact * a_exact);

      // The centre: the pair that touches before loading.
      dealii::Point<3> centre       = results.at(0).position;
      double           smallest_gap = results[0].initial_gap;
      for (const auto &r : results)
        if (r.initial_gap < smallest_gap)
          {
            smallest_gap = r.initial_gap;
            centre       = r.position;
          }
      for (auto &r : results)
        {
          const double x       = r.position.distance(centre) / a_exact;
          r.reference_pressure = x < 1 ? p_exact * std::sqrt(1 - x * x) : 0.0;
        }

      const double a_fit  = contact_radius_from_pressure_fit(results, centre);
      const double a_area = std::sqrt(4 * closed_area / pi);
      return {{"load", load},
              {"contact_radius_exact", a_exact},
              {"max_pressure_exact", p_exact},
              {"contact_radius", number_or_null(a_fit)},
              {"contact_radius_from_area", a_area},
              {"max_pressure", p_max},
              {"contact_radius_error", number_or_null(a_fit / a_exact - 1)},
              {"contact_radius_from_area_error", a_area / a_exact - 1},
              {"max_pressure_error", p_max / p_exact - 1}};
    }
  } // namespace postprocess
} // namespace fdem
