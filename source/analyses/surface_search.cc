// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The limit-equilibrium part of the surface search: a grid of circles, each
// checked and sliced, then a pattern search around the grid's minimum. It
// needs the section only, no model: thousands of circles in seconds.
#include <fdem/analyses/limit_equilibrium_model.h>
#include <fdem/analyses/surface_search.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace fdem
{
  namespace analyses
  {
    using namespace dealii;
    namespace le = limit_equilibrium;

    void
    screen_by_limit_equilibrium(const le::Section &section,
                                const le::Surface &surface,
                                const le::Method   method,
                                const unsigned int n_slices,
                                SearchedSurface   &s)
    {
      try
        {
          const le::SlicedMass mass(section, surface, n_slices);
          s.le_K = le::solve(mass, method, 1e-10).K;
          // m_alpha = cos(alpha) + sin(alpha) tan(phi) / K, the factor that
          // divides each base's normal force: where it falls below 0.2 the
          // normal force and with it K are meaningless (Whitman & Bailey
          // 1967; a circle rising steeply out of the toe, or a mass on flat
          // ground with almost no driving moment). Such surfaces are skipped.
          double m_alpha = std::numeric_limits<double>::infinity();
          for (const le::Slice &slice : mass.slices)
            m_alpha = std::min(m_alpha,
                               slice.cos_alpha +
                                 slice.sin_alpha * slice.tan_phi / s.le_K);
          if (m_alpha < 0.2)
            {
              s.status = "m_alpha below 0.2";
              s.le_K   = std::numeric_limits<double>::quiet_NaN();
              return;
            }
          s.valid  = true;
          s.status = "valid";
        }
      catch (const ExceptionBase &error)
        {
          const std::string text  = error.what();
          const auto        start = text.find("Limit equilibrium: ");
          s.status =
            "no limit-equilibrium answer" +
            (start == std::string::npos ?
               std::string() :
               ": " +
                 text.substr(start + 19, text.find('\n', start) - start - 19));
        }
    }

    SearchedSurface
    screen_circle(const le::Section             &section,
                  const double                   base_elevation,
                  const Point<2>                &centre,
                  const double                   radius,
                  const SurfaceSearchParameters &settings)
    {
      const unsigned int n_slices = settings.n_slices;
      SearchedSurface    s;
      s.centre = centre;
      s.radius = radius;
      if (!(radius > 0))
        {
          s.status = "no circle (tangent elevation above the centre)";
          return s;
        }
      le::Surface surface;
      surface.circular = true;
      surface.centre   = centre;
      surface.radius   = radius;
      std::vector<Point<2>> line;
      try
        {
          line =
            le::circle_surface(section.ground, centre, radius, n_slices + 1);
        }
      catch (const ExceptionBase &)
        {
          s.status = "does not cut the ground";
          return s;
        }
      const double x_left  = section.ground.front()[0],
                   x_right = section.ground.back()[0];
      const double slack   = 1e-9 * (x_right - x_left);
      double       lowest = line.front()[1], highest_ground = -1e300, depth = 0;
      for (const Point<2> &q : line)
        {
          const double ground = le::elevation(section.ground, q[0]);
          lowest              = std::min(lowest, q[1]);
          highest_ground      = std::max(highest_ground, ground);
          depth               = std::max(depth, ground - q[1]);
        }
      for (const Point<2> &g : section.ground)
        if (line.front()[0] < g[0] && g[0] < line.back()[0])
          highest_ground = std::max(highest_ground, g[1]);
      if (!(line.front()[0] > x_left - slack &&
            line.back()[0] < x_right + slack))
        s.status = "leaves the model";
      else if (!(lowest > base_elevation))
        s.status = "below the base";
      else if (!(centre[1] > highest_ground))
        // The generator's sliding mass is the part of the slope inside the
        // circle: with ground above the centre it is not the mass above the
        // lower arc that limit equilibrium slices.
        s.status = "centre below the ground it cuts";
      else if (depth < settings.minimum_depth)
        s.status = "shallower than Minimum depth";
      if (!s.status.empty())
        return s;
      screen_by_limit_equilibrium(
        section, surface, settings.method, n_slices, s);
      return s;
    }

    namespace
    {
      /** A length in a message: as few digits as it has. */
      std::string
      str(const double x)
      {
        std::ostringstream text;
        text << x;
        return text.str();
      }

    } // namespace

    std::string
    skip_reason(const std::string &status)
    {
      return status.substr(0, status.find(':'));
    }

    bool
    inside_search_region(const SurfaceSearchParameters &s,
                         const std::array<double, 3>   &circle)
    {
      const double slack = 1e-9 * (s.grid_upper - s.grid_lower).norm();
      for (unsigned int d = 0; d < 2; ++d)
        if (circle[d] < s.grid_lower[d] - slack ||
            circle[d] > s.grid_upper[d] + slack)
          return false;
      if (s.radii == SurfaceSearchParameters::Radii::through_point)
        return true;
      const auto [low, high] = std::minmax_element(s.tangent_elevations.begin(),
                                                   s.tangent_elevations.end());
      const double y_t       = circle[1] - circle[2];
      return y_t >= *low - slack - 1e-9 * std::abs(*low) &&
             y_t <= *high + slack + 1e-9 * std::abs(*high);
    }

    bool
    on_search_region_edge(const SurfaceSearchParameters &s,
                          const std::array<double, 3>   &circle)
    {
      const double slack =
        1e-6 * std::max((s.grid_upper - s.grid_lower).norm(), circle[2]);
      for (unsigned int d = 0; d < 2; ++d)
        if ((d == 0 ? s.n_x : s.n_y) > 1 &&
            (std::abs(circle[d] - s.grid_lower[d]) < slack ||
             std::abs(circle[d] - s.grid_upper[d]) < slack))
          return true;
      if (s.radii == SurfaceSearchParameters::Radii::through_point ||
          s.tangent_elevations.size() < 2)
        return false;
      const auto [low, high] = std::minmax_element(s.tangent_elevations.begin(),
                                                   s.tangent_elevations.end());
      const double y_t       = circle[1] - circle[2];
      return std::abs(y_t - *low) < slack || std::abs(y_t - *high) < slack;
    }

    parameters::WorkEstimate
    search_work_estimate(const SurfaceSearchParameters &settings)
    {
      const double n_circles =
        double(settings.n_x) * settings.n_y *
        (settings.radii == SurfaceSearchParameters::Radii::through_point ?
           1 :
           std::max<std::size_t>(settings.tangent_elevations.size(), 1));
      // The screening of a valid circle took 1.6e-4 s and 1.4e-6 s per
      // slice (doc/benchmarks.md, "Work estimates"); each circle's record
      // (SearchedSurface) stays in memory, in a vector that may hold twice
      // as many while it grows.
      constexpr double seconds_per_circle = 1.6e-4, seconds_per_slice = 1.4e-6;
      parameters::WorkEstimate work;
      work.entry = "Surface search/Centre grid counts";
      work.what  = parameters::count_text(n_circles) + " circles";
      work.seconds =
        n_circles * (seconds_per_circle +
                     std::max(settings.n_slices, settings.min_n_slices) *
                       seconds_per_slice);
      work.memory_MiB =
        n_circles * 2 * sizeof(SearchedSurface) / (1024. * 1024.);
      return work;
    }



    SurfaceSearchResult
    screen_surfaces(const le::Section             &section,
                    const double                   base_elevation,
                    const SurfaceSearchParameters &settings)
    {
      SurfaceSearchResult result;
      result.performed     = true;
      result.method_key    = le::method_key(settings.method);
      result.settings      = settings;
      const double x_left  = section.ground.front()[0],
                   x_right = section.ground.back()[0];
      double top           = base_elevation;
      for (const Point<2> &g : section.ground)
        top = std::max(top, g[1]);

      // Grids that cannot hold a sliding surface: errors, not a long search.
      AssertThrow(
        settings.grid_upper[0] > x_left && settings.grid_lower[0] < x_right,
        ExcMessage("Surface search/Centre grid: the centres (x from " +
                   str(settings.grid_lower[0]) + " to " +
                   str(settings.grid_upper[0]) +
                   ") lie outside the model (x from " + str(x_left) + " to " +
                   str(x_right) + ")."));
      AssertThrow(
        settings.grid_upper[1] > base_elevation,
        ExcMessage(
          "Surface search/Centre grid: the centres lie below the model's "
          "base (Geometry/Slope/Base elevation)."));
      if (settings.radii == SurfaceSearchParameters::Radii::tangent_elevations)
        {
          for (const double y : settings.tangent_elevations)
            AssertThrow(
              y > base_elevation && y < top,
              ExcMessage(
                "Surface search/Tangent elevations: " + str(y) +
                " is not between the model's base and its highest ground "
                "point (" +
                str(base_elevation) + " to " + str(top) + ")."));
        }
      else
        {
          AssertThrow(
            settings.point[0] >= x_left && settings.point[0] <= x_right &&
              settings.point[1] > base_elevation &&
              settings.point[1] <=
                le::elevation(section.ground, settings.point[0]) +
                  1e-9 * (top - base_elevation),
            ExcMessage(
              "Surface search/Point on circles: the point must lie in the "
              "model, on or below the ground and above the base."));
        }

      const auto radius_of = [&](const Point<2> &c, const double y_t) {
        return settings.radii == SurfaceSearchParameters::Radii::through_point ?
                 c.distance(settings.point) :
                 c[1] - y_t;
      };
      const auto screen =
        [&](const Point<2> &c, const double R, const std::string &stage) {
          SearchedSurface s =
            screen_circle(section, base_elevation, c, R, settings);
          s.stage = stage;
          result.surfaces.push_back(s);
          return s;
        };

      Timer               timer;
      const double        dx       = settings.n_x > 1 ?
                                       (settings.grid_upper[0] - settings.grid_lower[0]) /
                            (settings.n_x - 1) :
                                       0;
      const double        dy       = settings.n_y > 1 ?
                                       (settings.grid_upper[1] - settings.grid_lower[1]) /
                            (settings.n_y - 1) :
                                       0;
      std::vector<double> tangents = settings.tangent_elevations;
      if (settings.radii == SurfaceSearchParameters::Radii::through_point)
        tangents = {0.};
      std::sort(tangents.begin(), tangents.end());
      double best = std::numeric_limits<double>::infinity();
      for (unsigned int i = 0; i < settings.n_x; ++i)
        for (unsigned int j = 0; j < settings.n_y; ++j)
          for (const double y_t : tangents)
            {
              const Point<2>        c(settings.grid_lower[0] + i * dx,
                               settings.grid_lower[1] + j * dy);
              const SearchedSurface s = screen(c, radius_of(c, y_t), "grid");
              ++result.n_grid;
              if (s.valid)
                {
                  ++result.n_valid;
                  if (s.le_K < best)
                    {
                      best              = s.le_K;
                      result.le_minimum = result.surfaces.size() - 1;
                    }
                }
              else
                ++result.n_skipped[skip_reason(s.status)];
            }
      result.seconds_screening = timer.wall_time();
      if (result.n_valid == 0)
        {
          std::ostringstream skipped;
          for (const auto &[why, n] : result.n_skipped)
            skipped << (skipped.str().empty() ? "" : ", ") << n << " " << why;
          AssertThrow(
            false,
            ExcMessage(
              "Surface search/Centre grid: none of the " +
              std::to_string(result.n_grid) +
              " circles of the grid is a valid sliding surface (" +
              skipped.str() +
              "); move the centres above the slope or change the radii."));
        }

      // A pattern search from the grid's minimum: steps of one grid spacing
      // in each coordinate (the radius by the tangents' spacing), halved
      // when no neighbour is lower, until below the tolerance.
      timer.restart();
      const bool by_point =
        settings.radii == SurfaceSearchParameters::Radii::through_point;
      const double spacing_t =
        tangents.size() > 1 ?
          (tangents.back() - tangents.front()) / (tangents.size() - 1) :
          0;
      std::vector<double>   step  = {dx, dy, by_point ? 0. : spacing_t};
      const SearchedSurface start = result.surfaces[result.le_minimum];
      // A grid of one centre or one tangent along a coordinate: steps from
      // the circle's size.
      for (unsigned int k = 0; k < 3; ++k)
        if (step[k] == 0 && !(by_point && k == 2))
          step[k] = start.radius / 10;
      const double stop =
        settings.refinement_tolerance * std::max({step[0], step[1], step[2]});
      std::vector<double> x = {start.centre[0], start.centre[1], start.radius};
      double              f = start.le_K;
      const unsigned int  max_evaluations = 5000;
      unsigned int        n_evaluations   = 0;
      const auto          circle_of       = [&](const std::vector<double> &v) {
        const Point<2> c(v[0], v[1]);
        return std::make_pair(c, by_point ? c.distance(settings.point) : v[2]);
      };
      while (std::max({step[0], step[1], step[2]}) > stop &&
             n_evaluations < max_evaluations)
        {
          bool moved = false;
          for (unsigned int k = 0; k < 3 && !moved; ++k)
            for (const double sign : {-1., 1.})
              {
                if (step[k] == 0)
                  continue;
                std::vector<double> y = x;
                y[k] += sign * step[k];
                if (!inside_search_region(settings, {{y[0], y[1], y[2]}}))
                  continue;
                const auto [c, R]       = circle_of(y);
                const SearchedSurface s = screen(c, R, "refinement");
                ++n_evaluations;
                ++result.n_refinement;
                if (s.valid && s.le_K < f)
                  {
                    x                 = y;
                    f                 = s.le_K;
                    moved             = true;
                    result.le_minimum = result.surfaces.size() - 1;
                    break;
                  }
              }
          if (!moved)
            for (double &h : step)
              h /= 2;
        }
      result.seconds_refinement = timer.wall_time();
      result.on_grid_edge =
        on_search_region_edge(settings,
                              {{result.surfaces[result.le_minimum].centre[0],
                                result.surfaces[result.le_minimum].centre[1],
                                result.surfaces[result.le_minimum].radius}});
      result.critical  = result.le_minimum;
      result.chosen_by = result.method_key;
      return result;
    }
  } // namespace analyses
} // namespace fdem
