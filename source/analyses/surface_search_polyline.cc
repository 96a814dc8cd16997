// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The non-circular stage of the surface search (doc/surface_search.md): the
// best circles made into polylines, whose vertices a coordinate search with
// halving steps moves to lower the limit-equilibrium factor (the vertex-by-
// vertex search of Celestino & Duncan 1981, with the exploratory moves of
// Hooke & Jeeves 1961), each polyline checked for kinematic admissibility
// first. Like the circles' screening it needs the section only, no model.
#include <fdem/analyses/limit_equilibrium_model.h>
#include <fdem/analyses/surface_search.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace fdem
{
  namespace analyses
  {
    using namespace dealii;
    namespace le = limit_equilibrium;

    SearchedSurface
    screen_polyline(const le::Section             &section,
                    const double                   base_elevation,
                    const std::vector<Point<2>>   &polyline,
                    const SurfaceSearchParameters &settings)
    {
      SearchedSurface s;
      s.polyline = polyline;
      s.radius   = std::numeric_limits<double>::quiet_NaN();
      s.centre   = Point<2>(std::numeric_limits<double>::quiet_NaN(),
                          std::numeric_limits<double>::quiet_NaN());
      const auto        &ground = section.ground;
      const double       x_left = ground.front()[0], x_right = ground.back()[0];
      const double       slack        = 1e-9 * (x_right - x_left);
      const unsigned int n            = polyline.size();
      const auto         below_ground = [&](const Point<2> &p) {
        return le::elevation(ground, p[0]) - p[1];
      };
      double lowest = polyline.front()[1], depth = 0;
      bool   reverse = false, above = false, convex = false;
      for (unsigned int i = 0; i < n; ++i)
        {
          lowest = std::min(lowest, polyline[i][1]);
          depth  = std::max(depth, below_ground(polyline[i]));
          if (i > 0 && !(polyline[i][0] > polyline[i - 1][0]))
            reverse = true;
          // Interior vertices strictly below the ground: a vertex on it
          // would cut the mass in two.
          if (i > 0 && i + 1 < n && !(below_ground(polyline[i]) > slack))
            above = true;
        }
      // No segment above the ground: the ground's own vertices between the
      // ends lie above the polyline (both lines are straight between the
      // vertices of either).
      if (!reverse)
        for (const Point<2> &g : ground)
          if (polyline.front()[0] < g[0] && g[0] < polyline.back()[0] &&
              !(le::elevation(polyline, g[0]) < g[1] - slack))
            above = true;
      if (settings.concave && !reverse)
        for (unsigned int i = 1; i + 1 < n; ++i)
          {
            const Tensor<1, 2> a = polyline[i] - polyline[i - 1],
                               b = polyline[i + 1] - polyline[i];
            // The turn from a to b must be to the left (counterclockwise):
            // the slopes do not decrease. Relative to the segments' lengths.
            if (a[0] * b[1] - a[1] * b[0] < -1e-12 * a.norm() * b.norm())
              convex = true;
          }
      if (reverse)
        s.status = "reverse step";
      else if (!(polyline.front()[0] > x_left - slack &&
                 polyline.back()[0] < x_right + slack))
        s.status = "leaves the model";
      else if (!(lowest > base_elevation))
        s.status = "below the base";
      else if (above)
        s.status = "a vertex or segment above the ground";
      else if (convex)
        s.status = "not concave upward";
      else if (depth < settings.minimum_depth)
        s.status = "shallower than Minimum depth";
      if (!s.status.empty())
        return s;
      le::Surface surface;
      surface.circular = false;
      surface.polyline = polyline;
      screen_by_limit_equilibrium(
        section, surface, settings.polyline_method, settings.n_slices, s);
      return s;
    }

    std::vector<Point<2>>
    circle_to_polyline(const std::vector<Point<2>> &ground,
                       const Point<2>              &centre,
                       const double                 radius,
                       const unsigned int           n_vertices)
    {
      const std::vector<Point<2>> arc =
        le::circle_surface(ground, centre, radius, 3);
      const Tensor<1, 2> a = arc.front() - centre, b = arc.back() - centre;
      const double from = std::atan2(a[1], a[0]), to = std::atan2(b[1], b[0]);
      std::vector<Point<2>> polyline = {arc.front()};
      for (unsigned int i = 1; i + 1 < n_vertices; ++i)
        {
          const double angle = from + (to - from) * i / (n_vertices - 1);
          polyline.emplace_back(centre[0] + radius * std::cos(angle),
                                centre[1] + radius * std::sin(angle));
        }
      polyline.push_back(arc.back());
      return polyline;
    }

    namespace
    {
      /** The point of @p line nearest to @p p. */
      Point<2>
      nearest_on(const std::vector<Point<2>> &line, const Point<2> &p)
      {
        Point<2> best     = line.front();
        double   distance = p.distance(best);
        for (unsigned int i = 1; i < line.size(); ++i)
          {
            const Tensor<1, 2> s  = line[i] - line[i - 1];
            const double       l2 = s.norm_square();
            const double       t =
              l2 > 0 ? std::clamp((p - line[i - 1]) * s / l2, 0., 1.) : 0.;
            const Point<2> q = line[i - 1] + t * s;
            if (p.distance(q) < distance)
              {
                distance = p.distance(q);
                best     = q;
              }
          }
        return best;
      }

      /**
       * The points where @p line meets @p ground (crosses or touches it),
       * within the x range of both.
       */
      std::vector<Point<2>>
      ground_crossings(const std::vector<Point<2>> &ground,
                       const std::vector<Point<2>> &line)
      {
        const double from = std::max(ground.front()[0], line.front()[0]),
                     to   = std::min(ground.back()[0], line.back()[0]);
        std::vector<Point<2>> crossings;
        if (!(from < to))
          return crossings;
        std::set<double> breaks = {from, to};
        for (const auto *l : {&ground, &line})
          for (const Point<2> &p : *l)
            if (p[0] > from && p[0] < to)
              breaks.insert(p[0]);
        const std::vector<double> x(breaks.begin(), breaks.end());
        const auto                gap = [&](const double x) {
          return le::elevation(line, x) - le::elevation(ground, x);
        };
        const auto on_ground = [&](const double x) {
          return Point<2>(x, le::elevation(ground, x));
        };
        // Both lines are straight between the breaks: the gap is linear.
        for (unsigned int i = 0; i < x.size(); ++i)
          {
            const double a = gap(x[i]);
            if (a == 0)
              crossings.push_back(on_ground(x[i]));
            else if (i + 1 < x.size() && a * gap(x[i + 1]) < 0)
              crossings.push_back(
                on_ground(x[i] + (x[i + 1] - x[i]) * a / (a - gap(x[i + 1]))));
          }
        return crossings;
      }

      /**
       * @p line with its end segments lengthened by 1e-6 of their length
       * beyond the ends on the ground: the ends then lie just above it, as
       * the generator and limit equilibrium ask of a polyline (an end
       * computed on the ground may lie below it by round-off), and both
       * cut the surface where it meets the ground, at the ends' places.
       */
      std::vector<Point<2>>
      lengthened(std::vector<Point<2>> line)
      {
        const unsigned int n = line.size();
        line[0] += 1e-6 * (line[0] - line[1]);
        line[n - 1] += 1e-6 * (line[n - 1] - line[n - 2]);
        return line;
      }

      /**
       * The polyline's free coordinates: the ends' x (on the ground), each
       * interior vertex's place t in (0, 1) between the ends and its
       * elevation y. Moving an end stretches the interior vertices with it,
       * so that every move keeps x increasing.
       */
      struct Coordinates
      {
        std::vector<double> v;
        unsigned int        n_interior;

        Coordinates(const std::vector<Point<2>> &polyline)
          : n_interior(polyline.size() - 2)
        {
          const double x0 = polyline.front()[0], x1 = polyline.back()[0];
          v = {x0, x1};
          for (unsigned int i = 1; i + 1 < polyline.size(); ++i)
            v.push_back((polyline[i][0] - x0) / (x1 - x0));
          for (unsigned int i = 1; i + 1 < polyline.size(); ++i)
            v.push_back(polyline[i][1]);
        }

        std::vector<Point<2>>
        polyline(const std::vector<Point<2>> &ground) const
        {
          std::vector<Point<2>> p = {
            Point<2>(v[0], le::elevation(ground, v[0]))};
          for (unsigned int i = 0; i < n_interior; ++i)
            p.emplace_back(v[0] + v[2 + i] * (v[1] - v[0]),
                           v[2 + n_interior + i]);
          p.emplace_back(v[1], le::elevation(ground, v[1]));
          return lengthened(p);
        }
      };
    } // namespace

    std::vector<Point<2>>
    snap_polyline(const le::Section           &section,
                  const std::vector<Point<2>> &polyline,
                  const double                 distance)
    {
      // The lines the mesh has (the boundaries between layers: the tops of
      // all layers but the first) and those limit equilibrium and the
      // contact strengths look for (named weak layers, whose faces must lie
      // on the seam within 1e-3 of their length).
      std::vector<const std::vector<Point<2>> *> lines;
      for (unsigned int k = 1; k < section.layers.size(); ++k)
        if (section.layers[k].top.size() >= 2)
          lines.push_back(&section.layers[k].top);
      for (const le::WeakLayer &weak : section.weak_layers)
        if (weak.line.size() >= 2)
          lines.push_back(&weak.line);
      std::vector<Point<2>> snapped = polyline;
      const unsigned int    n       = polyline.size();
      if (!(distance > 0) || n < 2)
        return snapped;
      for (unsigned int i = 1; i + 1 < n; ++i)
        {
          double nearest = distance;
          for (const auto *line : lines)
            {
              const Point<2> q = nearest_on(*line, polyline[i]);
              if (q.distance(polyline[i]) < nearest)
                {
                  nearest    = q.distance(polyline[i]);
                  snapped[i] = q;
                }
            }
        }
      for (const unsigned int end : {0u, n - 1})
        {
          double nearest = distance;
          bool   moved   = false;
          for (const auto *line : lines)
            for (const Point<2> &c : ground_crossings(section.ground, *line))
              if (c.distance(polyline[end]) < nearest)
                {
                  nearest      = c.distance(polyline[end]);
                  snapped[end] = c;
                  moved        = true;
                }
          // Just above the ground, as every end of the search.
          if (moved)
            snapped[end] +=
              1e-6 * (snapped[end] - snapped[end == 0 ? 1 : n - 2]);
        }
      return snapped;
    }

    void
    screen_polylines(const le::Section             &section,
                     const double                   base_elevation,
                     const SurfaceSearchParameters &settings,
                     const double                   snap_distance,
                     SurfaceSearchResult           &result)
    {
      Timer timer;
      result.non_circular        = true;
      result.snap_distance       = snap_distance;
      result.polyline_method_key = le::method_key(settings.polyline_method);
      const unsigned int n       = settings.n_polyline_vertices;
      const auto         screen  = [&](const std::vector<Point<2>> &line,
                              const std::string           &stage) {
        SearchedSurface s =
          screen_polyline(section, base_elevation, line, settings);
        s.stage = stage;
        ++result.n_polyline;
        if (s.valid)
          ++result.n_polyline_valid;
        else
          ++result.n_polyline_skipped[skip_reason(s.status)];
        result.surfaces.push_back(s);
        if (s.valid && (result.polyline_minimum < 0 ||
                        s.le_K < result.surfaces[result.polyline_minimum].le_K))
          result.polyline_minimum = result.surfaces.size() - 1;
        return s;
      };

      // The starts: the screening minimum and the best valid circles of
      // other centres, Contact candidates in all (as the circles' contact
      // stage): a local search from each, the lowest of them wins.
      std::vector<unsigned int> starts = {result.le_minimum}, order;
      for (unsigned int i = 0; i < result.surfaces.size(); ++i)
        if (result.surfaces[i].valid && result.surfaces[i].stage == "grid" &&
            result.surfaces[i].polyline.empty())
          order.push_back(i);
      std::sort(order.begin(),
                order.end(),
                [&](const unsigned a, const unsigned b) {
                  return result.surfaces[a].le_K < result.surfaces[b].le_K;
                });
      std::set<std::pair<double, double>> centres = {
        {result.surfaces[result.le_minimum].centre[0],
         result.surfaces[result.le_minimum].centre[1]}};
      // A circle whose polyline is not admissible (e.g. through a ground
      // vertex) gives no start: the next one is tried, up to ten times as
      // many as asked.
      for (const unsigned int i : order)
        if (starts.size() < 10 * settings.n_contact_candidates &&
            centres
              .insert(
                {result.surfaces[i].centre[0], result.surfaces[i].centre[1]})
              .second)
          starts.push_back(i);

      const unsigned int max_evaluations = 20000;
      for (const unsigned int start : starts)
        {
          if (result.n_polyline_starts >= settings.n_contact_candidates)
            break;
          const SearchedSurface circle = result.surfaces[start];
          std::vector<Point<2>> line;
          try
            {
              line = circle_to_polyline(section.ground,
                                        circle.centre,
                                        circle.radius,
                                        n);
            }
          catch (const ExceptionBase &)
            {
              continue;
            }
          SearchedSurface s = screen(lengthened(line), "polyline start");
          if (start == result.le_minimum)
            result.polyline_start = result.surfaces.size() - 1;
          if (!s.valid)
            continue;
          ++result.n_polyline_starts;
          unsigned int optimum = result.surfaces.size() - 1;
          // Steps: half the spacing of the vertices along x (lengths) and
          // as a fraction of the span (the places t), halved when no move
          // lowers the factor, down to Refinement tolerance times the
          // first.
          Coordinates  x(line);
          double       f             = s.le_K;
          const double span          = line.back()[0] - line.front()[0];
          const double first         = span / (n - 1) / 2;
          const double stop          = settings.refinement_tolerance * first;
          unsigned int n_evaluations = 0;
          for (double h = first; h > stop && n_evaluations < max_evaluations;)
            {
              bool moved = false;
              // Elevations first (the vertices' depth matters most), then
              // the places along x, then the ends along the ground.
              std::vector<unsigned int> order_k;
              for (unsigned int k = 2 + x.n_interior; k < x.v.size(); ++k)
                order_k.push_back(k);
              for (unsigned int k = 2; k < 2 + x.n_interior; ++k)
                order_k.push_back(k);
              order_k.push_back(0);
              order_k.push_back(1);
              for (const unsigned int k : order_k)
                for (const double sign : {-1., 1.})
                  {
                    Coordinates  y    = x;
                    const double step = (k >= 2 && k < 2 + x.n_interior) ?
                                          h / (x.v[1] - x.v[0]) :
                                          h;
                    y.v[k] += sign * step;
                    const SearchedSurface t =
                      screen(y.polyline(section.ground), "polyline");
                    ++n_evaluations;
                    if (t.valid && t.le_K < f)
                      {
                        optimum = result.surfaces.size() - 1;
                        x       = y;
                        f       = t.le_K;
                        moved   = true;
                        break;
                      }
                  }
              if (!moved)
                h /= 2;
            }
          // The optimum onto the layer lines it runs along: one a few
          // millimetres from a layer boundary leaves sliver cells between
          // the two lines in the contact evaluation's mesh, whose nodes have
          // no normal. Screened again, so that the factor that goes with the
          // evaluated polyline is its own; if snapping makes it inadmissible,
          // the optimum stays as it is.
          if (snap_distance > 0)
            {
              const std::vector<Point<2>> snapped =
                snap_polyline(section,
                              result.surfaces[optimum].polyline,
                              snap_distance);
              if (snapped != result.surfaces[optimum].polyline &&
                  screen(snapped, "polyline snapped").valid)
                {
                  optimum = result.surfaces.size() - 1;
                  ++result.n_polyline_snapped;
                }
            }
          result.polyline_optima.push_back(optimum);
        }
      result.seconds_polyline = timer.wall_time();
    }

    void
    use_polyline(parameters::Parameters      &p,
                 const std::vector<Point<2>> &polyline)
    {
      auto &slope           = p.geometry.slope;
      slope.sliding_surface = geometry::Slope::SlidingSurface::polyline;
      slope.sliding_surface_polyline = polyline;
      using I                        = SurfaceSearchParameters::Interslices;
      const I interslices            = p.surface_search.polyline_interslices;
      if (interslices == I::none)
        {
          slope.interslice_surfaces = geometry::Slope::Interslices::none;
          return;
        }
      slope.interslice_surfaces = interslices == I::vertical ?
                                    geometry::Slope::Interslices::vertical :
                                    geometry::Slope::Interslices::bisector;
      // Blocks 'sliding mass 1..n' and interfaces 'sliding surface 1..n',
      // 'interslice 1..n-1' in place of 'sliding mass' and 'sliding
      // surface'.
      const std::string entry = "Surface search/Non-circular interslices: ";
      const auto        has   = [](const std::vector<std::string> &names,
                          const std::string              &name) {
        return std::find(names.begin(), names.end(), name) != names.end();
      };
      AssertThrow(has(p.block_names, "sliding mass") &&
                    has(p.interface_names, "sliding surface"),
                  ExcMessage(
                    entry +
                    "the blocks are cut from the case's block 'sliding "
                    "mass' and interface 'sliding surface'; name them so."));
      const unsigned int       n_blocks = polyline.size() - 1;
      std::vector<std::string> blocks, interfaces;
      for (const std::string &name : p.block_names)
        if (name == "sliding mass")
          for (unsigned int b = 1; b <= n_blocks; ++b)
            {
              const std::string numbered = name + " " + std::to_string(b);
              blocks.push_back(numbered);
              if (p.materials.count(name))
                p.materials[numbered] = p.materials.at(name);
            }
        else
          blocks.push_back(name);
      const parameters::InterfaceParameters surface =
        p.interfaces.at("sliding surface");
      for (const std::string &name : p.interface_names)
        if (name == "sliding surface")
          for (unsigned int b = 1; b <= n_blocks; ++b)
            {
              interfaces.push_back(name + " " + std::to_string(b));
              p.interfaces[interfaces.back()] = surface;
            }
        else
          interfaces.push_back(name);
      // The interslices: the sliding surface's strength, part of the
      // mechanism (reduced by K) but not of the surface summed in K.
      for (unsigned int b = 1; b < n_blocks; ++b)
        {
          interfaces.push_back("interslice " + std::to_string(b));
          parameters::InterfaceParameters interslice = surface;
          interslice.sliding_surface                 = false;
          interslice.reduced_by_K                    = true;
          p.interfaces[interfaces.back()]            = interslice;
        }
      p.block_names     = blocks;
      p.interface_names = interfaces;
      p.materials.erase("sliding mass");
      p.interfaces.erase("sliding surface");
    }
  } // namespace analyses
} // namespace fdem
