// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The methods of slices on a SlicedMass (limit_equilibrium_slices.cc), in the
// frame where the mass moves to the left: the equations of
// tools/limit_equilibrium.py, with Spencer's march generalised to the
// Morgenstern-Price interslice function (doc/limit_equilibrium.md).
#include <fdem/analyses/limit_equilibrium.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>

namespace fdem
{
  namespace analyses
  {
    namespace limit_equilibrium
    {
      using namespace dealii;

      std::string
      method_key(const Method method)
      {
        switch (method)
          {
            case Method::ordinary:
              return "ordinary";
            case Method::bishop:
              return "bishop_simplified";
            case Method::janbu:
              return "janbu_simplified";
            case Method::janbu_corrected:
              return "janbu_corrected";
            case Method::spencer:
              return "spencer";
            case Method::morgenstern_price_constant:
              return "morgenstern_price_constant";
            case Method::morgenstern_price_half_sine:
              return "morgenstern_price_half_sine";
          }
        return "";
      }

      namespace
      {
        constexpr double nan = std::numeric_limits<double>::quiet_NaN();

        /**
         * Whether every slice's normal-force denominator m_alpha = cos(alpha)
         * + sin(alpha) tan(phi)/K (Bishop's; the march's at lambda = 0) is
         * positive at @p K. Where it is not, the base normal forces come
         * from a denominator of the wrong sign: the root is a spurious one
         * (Whitman and Bailey 1967), not a factor of safety.
         */
        bool
        admissible(const SlicedMass &mass, const double K)
        {
          for (const Slice &s : mass.slices)
            if (!(s.cos_alpha + s.sin_alpha * s.tan_phi / K > 0))
              return false;
          return true;
        }

        /**
         * The largest root of f in [0.05, 50] (_root_in_F of the Python
         * yardstick): small spurious roots exist where a slice's normal-force
         * denominator (Bishop's m_alpha) changes sign at a small K; the
         * physical root is the one above them. A root at which some m_alpha
         * is not positive is such a spurious root, and the physical one may
         * then lie above 50 (a very strong soil): it is looked for up to
         * 1e4, and without it there is no factor (an error, not a wrong
         * number).
         */
        double
        root_in_K(const std::function<double(double)> &f,
                  const double                         tolerance,
                  const SlicedMass                    &mass)
        {
          // numpy.geomspace(low, high, n), scanned from the top down: the
          // first sign change met is the largest root's bracket, as the
          // Python yardstick finds it after evaluating them all.
          const auto largest_root =
            [&](const double low, const double high, const unsigned int n) {
              const double start = std::log10(low), stop = std::log10(high);
              const auto   K_at = [&](const unsigned int i) {
                return i == 0 ?
                           low :
                         i == n - 1 ?
                           high :
                           std::pow(10., start + i * ((stop - start) / (n - 1)));
              };
              double upper = f(K_at(n - 1));
              for (int i = n - 2; i >= 0; --i)
                {
                  const double lower = f(K_at(i));
                  if (std::isfinite(lower) && std::isfinite(upper) &&
                      lower * upper <= 0)
                    return find_root(
                      f, K_at(i), K_at(i + 1), tolerance, tolerance);
                  upper = lower;
                }
              return nan;
            };
          const double K = largest_root(0.05, 50., 200);
          if (std::isfinite(K) && admissible(mass, K))
            return K;
          const double K_above = largest_root(50., 1e4, 100);
          AssertThrow(std::isfinite(K_above) && admissible(mass, K_above),
                      ExcMessage(
                        "Limit equilibrium: no factor of safety in [0.05, "
                        "1e4] at which every slice's normal force has a "
                        "positive denominator (m_alpha)."));
          return K_above;
        }

        /**
         * The interslice march of Spencer and Morgenstern-Price: X = lambda
         * f E at each boundary, E = 0 at the toe; slice by slice the effective
         * base normal force from vertical equilibrium, the thrust on its right
         * from horizontal equilibrium. Returns E at the crest end (force
         * residual) and the moment of all forces about the origin (the
         * interslice forces cancel in it). The root searches call it some
         * ten thousand times per method, so a mass without anchors marches
         * without their terms (@p with_anchors false: the same arithmetic,
         * the anchors' zeros left out).
         */
        struct Residuals
        {
          double thrust, moment;
        };

        template <bool with_anchors>
        Residuals
        march(const SlicedMass          &mass,
              const double               K,
              const double               lambda,
              const std::vector<double> &f)
        {
          double             E_left = 0, moment = 0;
          const unsigned int n = mass.slices.size();
          for (unsigned int i = 0; i < n; ++i)
            {
              const Slice &s  = mass.slices[i];
              const double sa = s.sin_alpha, ca = s.cos_alpha;
              const double a = s.c * s.l / K, b = s.tan_phi / K;
              // The crack's water force acts on the last slice, to the left;
              // the seismic force Q on every slice, to the left, and V up.
              // The anchors crossing its base: a force (Fx, Fy) on the slice.
              const double Fx = with_anchors ?
                                  s.anchor_x(K, mass.anchors_reduced) :
                                  0.,
                           Fy = with_anchors ?
                                  s.anchor_y(K, mass.anchors_reduced) :
                                  0.;
              const double Px =
                (i + 1 == n ? -mass.crack_force : 0.) - s.Q + Fx;
              const double g   = a * ca - s.U * sa + Px;
              const double h   = b * ca - sa;
              const double num = (s.U * ca + a * sa - (s.W - s.V - Fy)) +
                                 lambda * (f[i] - f[i + 1]) * E_left -
                                 lambda * f[i + 1] * g;
              const double den = lambda * f[i + 1] * h - (ca + b * sa);
              const double N   = num / den;
              E_left += N * h + g;
              const double S  = a + b * N;
              const double fx = -(N + s.U) * sa + S * ca;
              const double fy = (N + s.U) * ca + S * sa;
              moment += s.xm * fy - s.ym * fx - s.xg * (s.W - s.V) + s.yg * s.Q;
              if (with_anchors)
                moment += s.anchor_moment(K, mass.anchors_reduced, Point<2>());
            }
          if (mass.crack_force != 0)
            moment += mass.crack_point[1] * mass.crack_force;
          return {E_left, moment};
        }

        Residuals
        march(const SlicedMass          &mass,
              const double               K,
              const double               lambda,
              const std::vector<double> &f)
        {
          return mass.has_anchors ? march<true>(mass, K, lambda, f) :
                                    march<false>(mass, K, lambda, f);
        }

        /** K and lambda of force and moment equilibrium for the interslice
         * function @p f (values at the slice boundaries). */
        MethodResult
        interslice_method(const SlicedMass          &mass,
                          const std::vector<double> &f,
                          const double               lambda_min,
                          const double               lambda_max,
                          const unsigned int         n_lambdas,
                          const double               tolerance)
        {
          const auto force_K = [&](const double lambda) {
            return root_in_K(
              [&](const double K) { return march(mass, K, lambda, f).thrust; },
              tolerance,
              mass);
          };
          const auto moment_gap = [&](const double lambda) {
            return march(mass, force_K(lambda), lambda, f).moment;
          };
          std::vector<double> lambdas(n_lambdas), gaps(n_lambdas);
          for (unsigned int i = 0; i < n_lambdas; ++i)
            {
              // numpy.linspace(lambda_min, lambda_max, n_lambdas)
              lambdas[i] = i + 1 == n_lambdas ?
                             lambda_max :
                             lambda_min + i * ((lambda_max - lambda_min) /
                                               (n_lambdas - 1));
              try
                {
                  gaps[i] = moment_gap(lambdas[i]);
                }
              catch (const ExceptionBase &)
                {
                  gaps[i] = nan;
                }
            }
          double W = 0;
          for (const Slice &s : mass.slices)
            W += s.W;
          const double scale = W * (mass.x.back() - mass.x.front());
          // Every sign change is refined; one where the K of force
          // equilibrium jumps (its largest root in [0.05, 50] passes from a
          // spurious branch to the physical one, as at strongly negative
          // lambda) leaves a gap that does not vanish and is no solution. Of
          // the solutions, the one nearest lambda = 0.
          MethodResult result;
          for (unsigned int i = 0; i + 1 < n_lambdas; ++i)
            if (std::isfinite(gaps[i]) && std::isfinite(gaps[i + 1]) &&
                gaps[i] * gaps[i + 1] <= 0)
              {
                const double lambda = find_root(moment_gap,
                                                lambdas[i],
                                                lambdas[i + 1],
                                                10 * tolerance);
                if (std::abs(moment_gap(lambda)) <= 1e-6 * scale &&
                    !(std::abs(lambda) >= std::abs(result.lambda)))
                  result.lambda = lambda;
              }
          if (std::isfinite(result.lambda))
            {
              result.K = force_K(result.lambda);
              return result;
            }
          // A plane without cohesion: every slice's forces are proportional
          // to its weight whatever lambda, so moment equilibrium does not fix
          // lambda (the gap left is the midpoint rule's).
          double smallest = nan, best_lambda = nan, low = nan, high = nan;
          for (unsigned int i = 0; i < n_lambdas; ++i)
            if (std::isfinite(gaps[i]))
              {
                const double size = std::abs(gaps[i]);
                if (!(size >= smallest))
                  {
                    smallest    = size;
                    best_lambda = lambdas[i];
                  }
                low  = std::isnan(low) ? size : std::min(low, size);
                high = std::isnan(high) ? size : std::max(high, size);
              }
          const double spread = high - low;
          AssertThrow(std::isfinite(smallest) && spread < 1e-9 * scale &&
                        smallest < 1e-4 * scale,
                      ExcMessage("Limit equilibrium: no interslice force "
                                 "inclination satisfies both force and moment "
                                 "equilibrium."));
          result.K = force_K(best_lambda);
          return result;
        }

        /** The crack's water force acts on the last slice: its terms. */
        double
        crack_on(const SlicedMass &mass, const unsigned int i)
        {
          return i + 1 == mass.slices.size() ? mass.crack_force : 0.;
        }

        MethodResult
        ordinary(const SlicedMass &mass)
        {
          // Fellenius: N' = W cos(alpha) - U (- P sin(alpha) with the crack's
          // water force P), K = sum (c l + N' tan(phi)) / sum (W sin(alpha)
          // + P cos(alpha)).
          // The anchors' parts along the bases (if reduced by K) apart:
          // K = (R - D_S / K) / D gives K = (R - D_S) / D (their part of R
          // is nil: they are along the base).
          // Passive bars reduced by K (Rx, Ry) add R_R / K to the resisting
          // side and D_R / K to the driving one: K D = R - D_S - D_R +
          // R_R / K, a quadratic in K.
          double     resisting = 0, driving = 0, driving_reduced = 0;
          double     resisting_bars = 0;
          const bool reduced        = mass.anchors_reduced;
          for (unsigned int i = 0; i < mass.slices.size(); ++i)
            {
              const Slice &s  = mass.slices[i];
              const double sa = s.sin_alpha, ca = s.cos_alpha;
              // The seismic force Q pushes left like the crack's water, and
              // the anchors' force (Fx, Fy) pulls.
              const double Fx = (reduced ? s.Nx : s.Nx + s.Sx) + s.Fx;
              const double Fy = (reduced ? s.Ny : s.Ny + s.Sy) + s.Fy;
              const double P = crack_on(mass, i) + s.Q - Fx, W = s.W - s.V - Fy;
              resisting += s.c * s.l + (W * ca - s.U - P * sa) * s.tan_phi;
              driving += W * sa + P * ca;
              if (reduced)
                driving_reduced += -s.Sy * sa - s.Sx * ca;
              driving_reduced += -s.Ry * sa - s.Rx * ca;
              resisting_bars += (-s.Ry * ca + s.Rx * sa) * s.tan_phi;
            }
          MethodResult result;
          const double b = resisting - driving_reduced;
          result.K       = resisting_bars == 0 ?
                             b / driving :
                             (b + std::sqrt(b * b + 4 * driving * resisting_bars)) /
                         (2 * driving);
          return result;
        }

        MethodResult
        bishop(const SlicedMass &mass, const double tolerance)
        {
          AssertThrow(mass.circular,
                      ExcMessage(
                        "Limit equilibrium: Bishop's simplified "
                        "method takes moments about a circle's centre; "
                        "it is not defined for a polyline surface."));
          const auto g = [&](const double K) {
            double resisting = 0, driving = 0;
            for (unsigned int i = 0; i < mass.slices.size(); ++i)
              {
                const Slice &s  = mass.slices[i];
                const double sa = s.sin_alpha, ca = s.cos_alpha;
                const double m     = ca + sa * s.tan_phi / K;
                const double width = s.l * ca;
                const double Fy    = s.anchor_y(K, mass.anchors_reduced);
                resisting +=
                  (s.c * width + (s.W - s.V - Fy - s.U * ca) * s.tan_phi) / m;
                // The weight's moment about the centre, for a mass moving
                // left, the seismic force's (Q to the left at yg) and the
                // anchors' (clockwise positive, as the mass moves).
                driving +=
                  (s.W - s.V) * (s.xg - mass.centre[0]) +
                  s.Q * (mass.centre[1] - s.yg) -
                  s.anchor_moment(K, mass.anchors_reduced, mass.centre);
              }
            driving +=
              mass.crack_force * (mass.centre[1] - mass.crack_point[1]);
            return K - mass.radius * resisting / driving;
          };
          MethodResult result;
          result.K = root_in_K(g, tolerance, mass);
          return result;
        }

        /** Janbu's correction factor f0 = 1 + b1 (d/L - 1.4 (d/L)^2). */
        double
        janbu_f0(const SlicedMass &mass)
        {
          const Point<2> &p = mass.surface.front(), &q = mass.surface.back();
          const double    L = p.distance(q);
          double          d = 0;
          for (const Point<2> &v : mass.surface)
            d = std::max(d,
                         ((q[0] - p[0]) * (p[1] - v[1]) -
                          (q[1] - p[1]) * (p[0] - v[0])) /
                           L);
          bool cohesion = false, friction = false;
          for (const Slice &s : mass.slices)
            {
              cohesion = cohesion || s.c > 0;
              friction = friction || s.tan_phi > 0;
            }
          const double b1 = cohesion && friction ? 0.50 :
                            cohesion             ? 0.69 :
                                                   0.31;
          return 1 + b1 * (d / L - 1.4 * (d / L) * (d / L));
        }
      } // namespace



      MethodResult
      solve(const SlicedMass &mass, const Method method, const double tolerance)
      {
        const unsigned int  n_boundaries = mass.x.size();
        std::vector<double> f(n_boundaries, 1.0);
        MethodResult        result;
        switch (method)
          {
            case Method::ordinary:
              result = ordinary(mass);
              break;
            case Method::bishop:
              result = bishop(mass, tolerance);
              break;
            case Method::janbu:
            case Method::janbu_corrected:
              result.K = root_in_K(
                [&](const double K) { return march(mass, K, 0., f).thrust; },
                tolerance,
                mass);
              if (method == Method::janbu_corrected)
                {
                  result.f0 = janbu_f0(mass);
                  result.K *= result.f0;
                }
              break;
            case Method::spencer:
            case Method::morgenstern_price_constant:
              result = interslice_method(mass, f, -0.6, 1.2, 37, tolerance);
              break;
            case Method::morgenstern_price_half_sine:
              {
                const double x0 = mass.x.front(), x1 = mass.x.back();
                for (unsigned int i = 0; i < n_boundaries; ++i)
                  f[i] = std::sin(M_PI * (mass.x[i] - x0) / (x1 - x0));
                result = interslice_method(mass, f, -1.2, 2.4, 73, tolerance);
                break;
              }
          }
        result.method   = method;
        result.n_slices = mass.slices.size();
        return result;
      }
    } // namespace limit_equilibrium
  }   // namespace analyses
} // namespace fdem
