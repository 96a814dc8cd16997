// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The sliding mass cut into slices: a line-by-line port of SlicedMass and
// circle_surface() of tools/limit_equilibrium.py (doc/limit_equilibrium.md),
// so that the C++ and the Python yardstick slice a surface the same way.
#include <fdem/analyses/limit_equilibrium.h>
#include <fdem/geometry/cases/case_input.h>
#include <fdem/geometry/cases/polyline_segment.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace fdem
{
  namespace analyses
  {
    namespace limit_equilibrium
    {
      using namespace dealii;

      namespace
      {
        constexpr double infinity = std::numeric_limits<double>::infinity();

        /** numpy.linspace(a, b, n): a + i (b - a) / (n - 1), the last one b. */
        std::vector<double>
        linspace(const double a, const double b, const unsigned int n)
        {
          std::vector<double> values(n);
          const double        step = (b - a) / (n - 1);
          for (unsigned int i = 0; i < n; ++i)
            values[i] = a + i * step;
          values.back() = b;
          return values;
        }

        /** The x where two polylines cross inside (x0, x1). */
        std::vector<double>
        crossings(const std::vector<Point<2>> &line_a,
                  const std::vector<Point<2>> &line_b,
                  const double                 x0,
                  const double                 x1)
        {
          const std::vector<double> xs =
            geometry::case_input::polyline_breakpoints(line_a, line_b, x0, x1);
          std::vector<double> found;
          for (unsigned int i = 0; i + 1 < xs.size(); ++i)
            {
              const double a = xs[i], b = xs[i + 1];
              const double da = elevation(line_a, a) - elevation(line_b, a);
              const double db = elevation(line_a, b) - elevation(line_b, b);
              if (da * db < 0)
                found.push_back(a + (b - a) * da / (da - db));
            }
          return found;
        }

        std::vector<Point<2>>
        mirror(const std::vector<Point<2>> &line)
        {
          std::vector<Point<2>> out;
          for (auto p = line.rbegin(); p != line.rend(); ++p)
            out.emplace_back(-(*p)[0], (*p)[1]);
          return out;
        }
      } // namespace



      double
      elevation(const std::vector<Point<2>> &line, const double x)
      {
        // The slope generator's own: the sections see the ground and the
        // layers where the mesh has them.
        return geometry::case_input::polyline_elevation(line, x);
      }



      double
      find_root(const std::function<double(double)> &f,
                double                               a,
                double                               b,
                const double                         xtol,
                const double                         rtol)
      {
        double xpre = a, xcur = b, xblk = 0, fblk = 0, spre = 0, scur = 0;
        double fpre = f(xpre), fcur = f(xcur);
        AssertThrow(!(fpre * fcur > 0),
                    ExcMessage("Limit equilibrium: a root is not bracketed."));
        if (fpre == 0)
          return xpre;
        if (fcur == 0)
          return xcur;
        for (unsigned int i = 0; i < 100; ++i)
          {
            if (fpre != 0 && fcur != 0 &&
                std::signbit(fpre) != std::signbit(fcur))
              {
                xblk = xpre;
                fblk = fpre;
                spre = scur = xcur - xpre;
              }
            if (std::abs(fblk) < std::abs(fcur))
              {
                xpre = xcur;
                xcur = xblk;
                xblk = xpre;
                fpre = fcur;
                fcur = fblk;
                fblk = fpre;
              }
            const double delta = (xtol + rtol * std::abs(xcur)) / 2;
            const double sbis  = (xblk - xcur) / 2;
            if (fcur == 0 || std::abs(sbis) < delta)
              return xcur;
            if (std::abs(spre) > delta && std::abs(fcur) < std::abs(fpre))
              {
                double stry;
                if (xpre == xblk)
                  stry = -fcur * (xcur - xpre) / (fcur - fpre);
                else
                  {
                    const double dpre = (fpre - fcur) / (xpre - xcur);
                    const double dblk = (fblk - fcur) / (xblk - xcur);
                    stry              = -fcur * (fblk * dblk - fpre * dpre) /
                           (dblk * dpre * (fblk - fpre));
                  }
                if (2 * std::abs(stry) <
                    std::min(std::abs(spre), 3 * std::abs(sbis) - delta))
                  {
                    spre = scur;
                    scur = stry;
                  }
                else
                  spre = scur = sbis;
              }
            else
              spre = scur = sbis;
            xpre = xcur;
            fpre = fcur;
            xcur += std::abs(scur) > delta ? scur : (sbis > 0 ? delta : -delta);
            fcur = f(xcur);
          }
        return xcur;
      }



      std::vector<Point<2>>
      circle_surface(const std::vector<Point<2>> &ground,
                     const Point<2>              &centre,
                     const double                 radius,
                     const unsigned int           n_points)
      {
        const double xc = centre[0], yc = centre[1];
        const auto   lower = [&](const double x) {
          return yc -
                 std::sqrt(std::max(radius * radius - (x - xc) * (x - xc), 0.));
        };
        const auto depth = [&](const double x) {
          return elevation(ground, x) - lower(x);
        };
        const std::vector<double> xs =
          linspace(xc - radius, xc + radius, 20001);
        int first = -1, last = -1;
        for (unsigned int i = 0; i < xs.size(); ++i)
          if (depth(xs[i]) > 0)
            {
              if (first < 0)
                first = i;
              last = i;
            }
        AssertThrow(first >= 0,
                    ExcMessage("Limit equilibrium: the circular sliding "
                               "surface does not pass below the ground."));
        const int    n = xs.size();
        const double x0 =
          first > 0 ? find_root(depth, xs[first - 1], xs[first], 1e-13) : xs[0];
        const double          x1 = last < n - 1 ?
                                     find_root(depth, xs[last], xs[last + 1], 1e-13) :
                                     xs[n - 1];
        std::vector<Point<2>> arc;
        for (const double x : linspace(x0, x1, n_points))
          arc.emplace_back(x, lower(x));
        return arc;
      }



      std::vector<Point<2>>
      polyline_in_ground(const std::vector<Point<2>> &ground,
                         const std::vector<Point<2>> &polyline)
      {
        // As surface_in_ground() of benchmarks/le_comparison.py.
        const auto depth = [&](const double x) {
          return elevation(ground, x) - elevation(polyline, x);
        };
        const std::vector<double> grid =
          linspace(polyline.front()[0], polyline.back()[0], 4001);
        int first = -1, last = -1;
        for (unsigned int i = 0; i < grid.size(); ++i)
          if (depth(grid[i]) > 0)
            {
              if (first < 0)
                first = i;
              last = i;
            }
        AssertThrow(first > 0 && last + 1 < static_cast<int>(grid.size()),
                    ExcMessage("Limit equilibrium: the polyline sliding "
                               "surface must start and end on or above the "
                               "ground and pass below it."));
        const double x0 = find_root(depth, grid[first - 1], grid[first], 1e-13);
        const double x1 = find_root(depth, grid[last], grid[last + 1], 1e-13);
        std::vector<Point<2>> out = {Point<2>(x0, elevation(polyline, x0))};
        for (const Point<2> &p : polyline)
          if (x0 < p[0] && p[0] < x1)
            out.push_back(p);
        out.emplace_back(x1, elevation(polyline, x1));
        return out;
      }



      namespace
      {
        /** The top line of layer k (the ground for the first one). */
        const std::vector<Point<2>> &
        top(const SlicedMass &mass, const unsigned int k)
        {
          return k == 0 || mass.layers[k].top.empty() ? mass.ground :
                                                        mass.layers[k].top;
        }

        /** The water table of layer k: its own line, or the section's. */
        const std::vector<Point<2>> &
        water_line(const SlicedMass &mass, const unsigned int k)
        {
          return mass.layers[k].piezometric.empty() ?
                   mass.piezometric :
                   mass.layers[k].piezometric;
        }

        /** The water level of layer k at x; -infinity if it is dry. */
        double
        water_level(const SlicedMass  &mass,
                    const unsigned int k,
                    const double       x)
        {
          const std::vector<Point<2>> &line = water_line(mass, k);
          return line.empty() ? -infinity : elevation(line, x);
        }

        struct Column
        {
          /** Per layer: dry and wet thickness above the surface. */
          std::vector<std::pair<double, double>> parts;
          double                                 y_base;
        };

        Column
        column(const SlicedMass &mass, const double x)
        {
          Column c;
          c.y_base                    = elevation(mass.surface, x);
          const double       yg       = elevation(mass.ground, x);
          const unsigned int n_layers = mass.layers.size();
          for (unsigned int k = 0; k < n_layers; ++k)
            {
              const double t = std::min(elevation(top(mass, k), x), yg);
              double       bottom =
                k + 1 < n_layers ? elevation(top(mass, k + 1), x) : -infinity;
              bottom         = std::max(bottom, c.y_base);
              const double h = std::max(t - bottom, 0.);
              const double wet =
                h > 0 ?
                  std::max(std::min(t, water_level(mass, k, x)) - bottom, 0.) :
                  0.;
              c.parts.emplace_back(h - wet, wet);
            }
          return c;
        }

        /** The index of the layer at (x, y). */
        unsigned int
        layer_at(const SlicedMass &mass, const double x, const double y)
        {
          const unsigned int n_layers = mass.layers.size();
          for (unsigned int k = 0; k < n_layers; ++k)
            {
              const double below =
                k + 1 < n_layers ? elevation(top(mass, k + 1), x) : -infinity;
              if (y >= below)
                return k;
            }
          return n_layers - 1;
        }

        void
        cut_at_crack(SlicedMass  &mass,
                     const double depth,
                     const double water_depth)
        {
          // The crack is at the upper (right) end: the surface ends where it
          // lies depth below the ground.
          const double x0  = mass.surface.front()[0];
          const double x1  = mass.surface.back()[0];
          const auto   gap = [&](const double x) {
            return elevation(mass.ground, x) - elevation(mass.surface, x) -
                   depth;
          };
          AssertThrow(!(gap(x1 - 1e-12 * (x1 - x0)) > 0),
                      ExcMessage(
                        "Limit equilibrium: the sliding surface is not "
                        "Tension crack depth deep at its upper end."));
          const std::vector<double> xs = linspace(x0, x1, 4001);
          int                       k  = -1;
          for (unsigned int i = 0; i + 1 < xs.size(); ++i)
            if (gap(xs[i]) >= 0)
              k = i;
          AssertThrow(k >= 0,
                      ExcMessage("Limit equilibrium: the sliding surface is "
                                 "nowhere as deep as Tension crack depth."));
          const double          xc = find_root(gap, xs[k], xs[k + 1], 1e-14);
          std::vector<Point<2>> cut;
          for (const Point<2> &p : mass.surface)
            if (p[0] < xc)
              cut.push_back(p);
          cut.emplace_back(xc, elevation(mass.surface, xc));
          mass.surface = cut;
          mass.crack_force =
            0.5 * mass.water_unit_weight * water_depth * water_depth;
          // Pushes to the left, a third of the water depth above the bottom.
          mass.crack_point = Point<2>(xc, cut.back()[1] + water_depth / 3.0);
        }

        void
        make_slices(SlicedMass &mass, const unsigned int n_slices)
        {
          const double x0 = mass.surface.front()[0],
                       x1 = mass.surface.back()[0];
          std::vector<const std::vector<Point<2>> *> lines = {&mass.ground,
                                                              &mass.surface};
          for (unsigned int k = 1; k < mass.layers.size(); ++k)
            lines.push_back(&top(mass, k));
          if (!mass.piezometric.empty())
            lines.push_back(&mass.piezometric);
          for (const SoilLayer &layer : mass.layers)
            if (!layer.piezometric.empty())
              lines.push_back(&layer.piezometric);
          std::set<double> breaks = {x0, x1};
          for (const auto *line : lines)
            for (const Point<2> &p : *line)
              if (x0 < p[0] && p[0] < x1)
                breaks.insert(p[0]);
          for (unsigned int i = 0; i < lines.size(); ++i)
            for (unsigned int j = i + 1; j < lines.size(); ++j)
              for (const double x : crossings(*lines[i], *lines[j], x0, x1))
                breaks.insert(x);
          const std::vector<double> sorted(breaks.begin(), breaks.end());
          const double              width = (x1 - x0) / n_slices;
          mass.x.clear();
          for (unsigned int i = 0; i + 1 < sorted.size(); ++i)
            {
              const double a = sorted[i], b = sorted[i + 1];
              const int m = std::max(1, int(std::ceil((b - a) / width - 1e-9)));
              const auto points = linspace(a, b, m + 1);
              mass.x.insert(mass.x.end(), points.begin(), points.end() - 1);
            }
          mass.x.push_back(x1);
        }

        Slice
        make_slice(const SlicedMass &mass, const double a, const double b)
        {
          const Column ca = column(mass, a), cb = column(mass, b);
          double       wa = 0, wb = 0; // weight per unit width at a and b
          for (unsigned int k = 0; k < mass.layers.size(); ++k)
            {
              const SoilLayer &layer = mass.layers[k];
              wa += layer.unit_weight * ca.parts[k].first +
                    layer.saturated_unit_weight * ca.parts[k].second;
              wb += layer.unit_weight * cb.parts[k].first +
                    layer.saturated_unit_weight * cb.parts[k].second;
            }
          Slice s;
          // The seismic weight W' per unit width at a and b and its first
          // moment about y = 0: the column stacked from its base up, each
          // layer wet below the piezometric line, dry above (column()).
          const auto seismic_weight =
            [&mass](const Column &c, double &w, double &m) {
              w = m    = 0;
              double y = c.y_base;
              for (int k = int(mass.layers.size()) - 1; k >= 0; --k)
                {
                  const SoilLayer &layer = mass.layers[k];
                  const double dry = c.parts[k].first, wet = c.parts[k].second;
                  const double wet_weight = mass.seismic_on_pore_water ?
                                              layer.saturated_unit_weight :
                                              layer.unit_weight;
                  w += wet_weight * wet + layer.unit_weight * dry;
                  m += wet_weight * wet * (y + wet / 2) +
                       layer.unit_weight * dry * (y + wet + dry / 2);
                  y += wet + dry;
                }
            };
          if (mass.kh != 0 || mass.kv != 0)
            {
              double w_a, m_a, w_b, m_b;
              seismic_weight(ca, w_a, m_a);
              seismic_weight(cb, w_b, m_b);
              // The trapezoidal rule for int m dx / int w dx.
              const double W_seismic = 0.5 * (w_a + w_b) * (b - a);
              s.yg = w_a + w_b > 0 ? (m_a + m_b) / (w_a + w_b) :
                                     0.5 * (ca.y_base + cb.y_base);
              s.Q  = mass.kh * W_seismic;
              s.V  = mass.kv * W_seismic;
            }
          // A linear load w(x) on [a, b]: its resultant and centroid.
          s.W  = 0.5 * (wa + wb) * (b - a);
          s.xg = wa + wb > 0 ? a + (b - a) * (wa + 2 * wb) / (3 * (wa + wb)) :
                               0.5 * (a + b);
          const double ya = ca.y_base, yb = cb.y_base;
          s.l         = std::hypot(b - a, yb - ya);
          s.alpha     = std::atan2(yb - ya, b - a);
          s.sin_alpha = std::sin(s.alpha);
          s.cos_alpha = std::cos(s.alpha);
          s.xm        = 0.5 * (a + b);
          s.ym        = 0.5 * (ya + yb);
          // The base lies in one layer (slices break where layers cross
          // the surface): its strength and its water table.
          const unsigned int base =
            layer_at(mass, s.xm, s.ym + 1e-9 * (1 + std::abs(s.ym)));
          const SoilLayer &layer = mass.layers[base];
          const double gw = mass.pore_pressure ? mass.water_unit_weight : 0.;
          const double ua = gw * std::max(water_level(mass, base, a) - ya, 0.);
          const double ub = gw * std::max(water_level(mass, base, b) - yb, 0.);
          s.U             = 0.5 * (ua + ub) * s.l;
          s.c             = layer.cohesion;
          s.tan_phi       = std::tan(layer.friction_angle * M_PI / 180);
          for (const WeakLayer &weak : mass.weak_layers)
            if (geometry::case_input::segment_along_polyline(Point<2>(a, ya),
                                                             Point<2>(b, yb),
                                                             weak.line))
              {
                s.c       = weak.cohesion;
                s.tan_phi = std::tan(weak.friction_angle * M_PI / 180);
                break;
              }
          return s;
        }
      } // namespace



      SlicedMass::SlicedMass(const Section     &section,
                             const Surface     &sliding,
                             const unsigned int n_slices)
        : water_unit_weight(section.water_unit_weight)
        , pore_pressure(section.pore_pressure)
        , kh(section.kh)
        , kv(section.kv)
        , seismic_on_pore_water(section.seismic_on_pore_water)
        , circular(sliding.circular)
      {
        AssertThrow(!section.layers.empty(),
                    ExcMessage("Limit equilibrium: the section has no soil."));
        std::vector<Point<2>> line =
          sliding.circular ?
            circle_surface(section.ground,
                           sliding.centre,
                           sliding.radius,
                           n_slices + 1) :
            polyline_in_ground(section.ground, sliding.polyline);
        std::sort(line.begin(),
                  line.end(),
                  [](const Point<2> &p, const Point<2> &q) {
                    return p[0] < q[0] || (p[0] == q[0] && p[1] < q[1]);
                  });
        mirrored = elevation(section.ground, line.front()[0]) >
                   elevation(section.ground, line.back()[0]);
        const auto flip = [&](const std::vector<Point<2>> &l) {
          return mirrored ? mirror(l) : l;
        };
        ground  = flip(section.ground);
        surface = flip(line);
        layers  = section.layers;
        for (SoilLayer &layer : layers)
          {
            if (!layer.top.empty())
              layer.top = flip(layer.top);
            if (!layer.piezometric.empty())
              layer.piezometric = flip(layer.piezometric);
          }
        if (!section.piezometric.empty())
          piezometric = flip(section.piezometric);
        weak_layers = section.weak_layers;
        for (WeakLayer &weak : weak_layers)
          weak.line = flip(weak.line);
        centre = Point<2>(mirrored ? -sliding.centre[0] : sliding.centre[0],
                          sliding.centre[1]);
        radius = sliding.radius;
        if (sliding.crack_depth > 0)
          cut_at_crack(*this, sliding.crack_depth, sliding.crack_water_depth);
        // The frame's mass moves to the left (-x): a kh given along +x or
        // -x of the section pushes it forwards or back.
        if (section.kh_direction != 0)
          kh *= section.kh_direction * (mirrored ? -1.0 : 1.0) * -1.0;
        make_slices(*this, n_slices);
        for (unsigned int i = 0; i + 1 < x.size(); ++i)
          slices.push_back(make_slice(*this, x[i], x[i + 1]));
        anchors_reduced = section.anchors_reduced_by_K;
        has_anchors     = !section.anchors.empty();
        for (unsigned int k = 0; k < section.anchors.size(); ++k)
          {
            const Anchor &a    = section.anchors[k];
            const auto    into = [&](const Point<2> &p) {
              return mirrored ? Point<2>(-p[0], p[1]) : p;
            };
            const Point<2> head = into(a.head), bond = into(a.bond);
            // The first crossing of the anchor with the surface from its head.
            double t_cross = 2;
            for (unsigned int j = 0; j + 1 < surface.size(); ++j)
              {
                const Tensor<1, 2> r = bond - head,
                                   e = surface[j + 1] - surface[j];
                const double det     = r[0] * (-e[1]) - r[1] * (-e[0]);
                if (det == 0)
                  continue;
                const Tensor<1, 2> q = surface[j] - head;
                const double       t = (q[0] * (-e[1]) - q[1] * (-e[0])) / det;
                const double       u = (r[0] * q[1] - r[1] * q[0]) / det;
                if (t >= 0 && t <= 1 && u >= 0 && u <= 1)
                  t_cross = std::min(t_cross, t);
              }
            AssertThrow(
              t_cross <= 1,
              ExcMessage(
                "Limit equilibrium: anchor " + std::to_string(k + 1) +
                " does not cross the sliding surface of the section."));
            const Point<2> c = head + t_cross * (bond - head);
            unsigned int   i = 0;
            while (i + 1 < slices.size() && c[0] > x[i + 1])
              ++i;
            Slice             &s = slices[i];
            const Tensor<1, 2> d = (bond - head) / (bond - head).norm();
            if (a.passive_bar)
              {
                // At its capacity: the steel, or the bond on either side;
                // a pile's shear across the bar, against the slide (to +x
                // here, where the mass moves to -x).
                double N_y = a.force;
                if (a.pullout > 0)
                  N_y = std::min({N_y,
                                  a.pullout * head.distance(c),
                                  a.pullout * bond.distance(c)});
                Tensor<1, 2> across({-d[1], d[0]});
                if (across[0] < 0 || (across[0] == 0 && across[1] < 0))
                  across = -across;
                const Tensor<1, 2> F = N_y * d + a.shear_capacity * across;
                const double       M = c[0] * F[1] - c[1] * F[0];
                (a.reduced ? s.Rx : s.Fx) += F[0];
                (a.reduced ? s.Ry : s.Fy) += F[1];
                (a.reduced ? s.Mr : s.Mf) += M;
                continue;
              }
            const Tensor<1, 2> F = a.force * d;
            const Tensor<1, 2> n({-s.sin_alpha, s.cos_alpha});
            const Tensor<1, 2> N = (F * n) * n, S = F - N;
            s.Nx += N[0];
            s.Ny += N[1];
            s.Sx += S[0];
            s.Sy += S[1];
            s.Mn += c[0] * N[1] - c[1] * N[0];
            s.Ms += c[0] * S[1] - c[1] * S[0];
          }
      }
    } // namespace limit_equilibrium
  }   // namespace analyses
} // namespace fdem
