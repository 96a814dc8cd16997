// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/postprocess/interface_output.h>

#include <nlohmann/json.hpp>

#include <vector>

namespace fdem
{
  namespace postprocess
  {
    /**
     * Radius of a circular contact zone centred at @p centre from the
     * pressures of its pairs: the least-squares fit of q^2 = c0 + c1 rho^2
     * (rho the distance from the centre) over the closed pairs in the outer
     * half of the closed zone, rho >= rho_max / 2, and its root
     * sqrt(-c0/c1). The fit has exactly the form of Hertz's profile
     * q = q0 sqrt(1 - rho^2/a^2). NaN if fewer than two pairs qualify or the
     * fit does not fall off.
     */
    double
    contact_radius_from_pressure_fit(const std::vector<PairResult<3>> &results,
                                     const dealii::Point<3>           &centre);

    /**
     * Hertz point contact of a sphere of radius @p radius on a half-space
     * (Johnson 1985, Sec. 4.2), for the quarter model of
     * geometry::make_hertz_sphere_mesh(): P = 4 times the normal force on
     * the interface, a = (3 P R / (4 E*))^(1/3), p0 = 3 P / (2 pi a^2),
     * with @p inverse_E = 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2. The
     * centre is the pair with the smallest initial gap. Returns the exact
     * and computed contact radius (from the pressure fit, and from the
     * closed area, sqrt(4 A / pi)) and maximum pressure with their relative
     * errors, and sets each pair's reference_pressure to
     * p0 sqrt(1 - (rho/a)^2).
     */
    nlohmann::json
    hertz_sphere_reference(std::vector<PairResult<3>> &results,
                           double                      inverse_E,
                           double                      radius);
  } // namespace postprocess
} // namespace fdem
