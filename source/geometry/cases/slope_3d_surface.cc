// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The sliding surface of the 3D slope generator as a function: its
// implicit form (negative inside), its normal, its points by two
// parameters, and the point reached from a point along a direction. The
// generator's checks, its vertex moves, the pairs' exact normals and the
// mesh estimate all read the surface here, so a new shape is added once.

#include <fdem/geometry/cases/slope_3d.h>

#include <deal.II/base/numbers.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    double
    Slope3D::axial_offset(const double y) const
    {
      switch (surface)
        {
          case Surface::cylinder:
            return 0;
          case Surface::capsule:
            {
              // Zero along the straight part, the distance beyond it in
              // the ends: the ends are half-ellipsoids centred at its ends.
              const double d = std::abs(y - centre[1]) - straight_length / 2;
              return d > 0 ? std::copysign(d, y - centre[1]) : 0;
            }
          default:
            return y - centre[1];
        }
    }



    double
    Slope3D::quadric(const Point<3> &p) const
    {
      const double u = (p[0] - centre[0]) / radius,
                   v = axial_offset(p[1]) / half_length,
                   w = (p[2] - centre[2]) / radius;
      return u * u + w * w + v * v - 1;
    }



    Tensor<1, 3>
    Slope3D::quadric_gradient(const Point<3> &p) const
    {
      const double r2 = radius * radius, b2 = half_length * half_length;
      Tensor<1, 3> gradient;
      gradient[0] = (p[0] - centre[0]) / r2;
      gradient[1] = axial_offset(p[1]) / b2;
      gradient[2] = (p[2] - centre[2]) / r2;
      return 2 * gradient;
    }



    Point<3>
    Slope3D::surface_point(const double s, const double phi) const
    {
      // The ring at s: its centre's y and radius. The cylinder runs across
      // the model's width (y_min() to y_max()); the ellipsoid and sphere from
      // pole to pole (theta = pi s); the capsule's ends take the first and last
      // third of s, its straight part the middle third.
      double y = 0, ring = radius;
      if (surface == Surface::cylinder)
        y = y_min() + (y_max() - y_min()) * s;
      else if (surface == Surface::capsule)
        {
          const double half_straight = straight_length / 2;
          if (s < 1. / 3 || s > 2. / 3)
            {
              const double theta =
                numbers::PI * (s < 1. / 3 ? 1.5 * s : 1.5 * s - 0.5);
              ring = radius * std::sin(theta);
              y    = centre[1] + half_length * std::cos(theta) +
                  (s < 1. / 3 ? half_straight : -half_straight);
            }
          else
            y = centre[1] + half_straight * (3 - 6 * s);
        }
      else
        {
          const double theta = numbers::PI * s;
          ring               = radius * std::sin(theta);
          y                  = centre[1] + half_length * std::cos(theta);
        }
      return Point<3>(centre[0] + ring * std::cos(phi),
                      y,
                      centre[2] + ring * std::sin(phi));
    }



    Point<3>
    Slope3D::along_onto_surface(const Point<3> &p, const Tensor<1, 3> &d) const
    {
      // One quadric per piece of the surface (the capsule: its straight
      // part and its two ends; the others: one), each quadratic in t along
      // p + t d: the root nearest to 0 on each, kept if it lands on that
      // piece, the nearest of those.
      struct Piece
      {
        double y_centre, inverse_b;
        double y_low, y_high;
      };
      std::vector<Piece> pieces;
      const double       infinity = std::numeric_limits<double>::infinity();
      const double half = surface == Surface::capsule ? straight_length / 2 : 0;
      if (surface == Surface::cylinder)
        pieces.push_back({centre[1], 0, -infinity, infinity});
      else if (surface == Surface::capsule)
        {
          pieces.push_back({centre[1], 0, centre[1] - half, centre[1] + half});
          pieces.push_back(
            {centre[1] + half, 1 / half_length, centre[1] + half, infinity});
          pieces.push_back(
            {centre[1] - half, 1 / half_length, -infinity, centre[1] - half});
        }
      else
        pieces.push_back({centre[1], 1 / half_length, -infinity, infinity});

      Point<3> best      = p;
      double   best_t    = infinity;
      double   nearest_t = infinity; // on any piece, if none lands on its own
      for (const Piece &piece : pieces)
        {
          const double u0 = (p[0] - centre[0]) / radius,
                       v0 = (p[1] - piece.y_centre) * piece.inverse_b,
                       w0 = (p[2] - centre[2]) / radius;
          const double du = d[0] / radius, dv = d[1] * piece.inverse_b,
                       dw   = d[2] / radius;
          const double a2   = du * du + dv * dv + dw * dw;
          const double a1   = 2 * (u0 * du + v0 * dv + w0 * dw);
          const double a0   = u0 * u0 + v0 * v0 + w0 * w0 - 1;
          const double root = std::sqrt(std::max(a1 * a1 - 4 * a2 * a0, 0.));
          // The root of a2 t^2 + a1 t + a0 nearest to 0, without
          // cancellation.
          const double t = -2 * a0 / (a1 + (a1 < 0 ? -root : root));
          if (!std::isfinite(t))
            continue;
          const double y     = p[1] + t * d[1];
          const double slack = 1e-12 * (std::abs(y) + half_length);
          const bool   lands =
            y >= piece.y_low - slack && y <= piece.y_high + slack;
          if (lands && std::abs(t) < std::abs(best_t))
            {
              best   = p + t * d;
              best_t = t;
            }
          if (!lands && std::abs(t) < std::abs(nearest_t))
            nearest_t = t;
        }
      if (best_t == infinity && std::isfinite(nearest_t))
        best = p + nearest_t * d;
      return best;
    }
  } // namespace geometry
} // namespace fdem
