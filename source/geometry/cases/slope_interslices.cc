// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/cases/slope_interslices.h>

#include <deal.II/base/exceptions.h>

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace fdem
{
  namespace geometry
  {
    namespace slope_interslices
    {
      namespace
      {
        const std::string path = "Geometry/Slope/";

        std::string
        point_text(const Point<2> &p)
        {
          std::ostringstream text;
          text.precision(6);
          text << "(" << p[0] << ", " << p[1] << ")";
          return text.str();
        }


        double
        cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
        {
          return a[0] * b[1] - a[1] * b[0];
        }

        /**
         * The parameter s > @p s_min at which the ray o + s d meets the
         * segment [a, b] (closed), or infinity.
         */
        double
        ray_hits(const Point<2>     &o,
                 const Tensor<1, 2> &d,
                 const Point<2>     &a,
                 const Point<2>     &b,
                 const double        s_min)
        {
          const Tensor<1, 2> e   = b - a;
          const double       den = cross(d, e);
          if (std::abs(den) <= 1e-14 * d.norm() * e.norm())
            return std::numeric_limits<double>::infinity();
          const double s = cross(a - o, e) / den, r = cross(a - o, d) / den;
          const double r_tolerance = 1e-12;
          return (s > s_min && r >= -r_tolerance && r <= 1 + r_tolerance) ?
                   s :
                   std::numeric_limits<double>::infinity();
        }

        /** Whether the closed segments [a, b] and [c, d] have a point in
         * common. */
        bool
        segments_meet(const Point<2> &a,
                      const Point<2> &b,
                      const Point<2> &c,
                      const Point<2> &d)
        {
          const Tensor<1, 2> d1 = b - a;
          return ray_hits(a, d1, c, d, -1e-12) <= 1 + 1e-12;
        }

        /** Angle of @p v counterclockwise from @p from, in [0, 2 pi). */
        double
        angle_from(const Tensor<1, 2> &from, const Tensor<1, 2> &v)
        {
          double a = std::atan2(cross(from, v), from * v);
          return a < 0 ? a + 2 * M_PI : a;
        }

        /**
         * The crack on @p line ordered from its far end to the crest (last):
         * the index k of the segment [line[k], line[k+1]] that holds the
         * bottom of the crack, and the bottom itself, the point nearest the
         * crest end whose depth below the ground is @p depth.
         */
        std::pair<unsigned int, Point<2>>
        find_crack(const std::vector<Point<2>> &ground,
                   const std::vector<Point<2>> &line,
                   const double                 depth)
        {
          double deepest = 0;
          for (unsigned int k = line.size() - 1; k-- > 0;)
            {
              // Walk the segment from line[k+1] (crest side) to line[k], in
              // pieces between the ground's vertices.
              const Point<2>     &A = line[k + 1], &B = line[k];
              std::vector<double> ts = {0, 1};
              for (const Point<2> &g : ground)
                if (A[0] != B[0])
                  {
                    const double t = (g[0] - A[0]) / (B[0] - A[0]);
                    if (t > 0 && t < 1)
                      ts.push_back(t);
                  }
              std::sort(ts.begin(), ts.end());
              for (unsigned int i = 1; i < ts.size(); ++i)
                {
                  const Point<2> P = A + ts[i - 1] * (B - A),
                                 Q = A + ts[i] * (B - A);
                  const double dP =
                    case_input::polyline_elevation(ground, P[0]) - P[1];
                  const double dQ =
                    case_input::polyline_elevation(ground, Q[0]) - Q[1];
                  deepest = std::max({deepest, dP, dQ});
                  if (dP < depth && dQ >= depth)
                    return {k, P + (depth - dP) / (dQ - dP) * (Q - P)};
                }
            }
          std::ostringstream message;
          message.precision(6);
          message
            << path << "Tension crack depth: " << depth
            << " m is deeper than the sliding surface lies below the ground "
               "anywhere from its crest end (at most "
            << deepest << " m).";
          AssertThrow(false, ExcMessage(message.str()));
          return {};
        }
      } // namespace



      Cuts
      slope_cuts(const Slope &slope)
      {
        const std::vector<Point<2>> &ground = slope.ground_surface;
        const std::vector<Point<2>> &line   = slope.sliding_surface_polyline;
        Cuts                         cuts;
        cuts.surface = line;
        // Per point of cuts.surface: its index in the polyline (the crack's
        // bottom has none).
        std::vector<int> index(line.size());
        for (unsigned int i = 0; i < line.size(); ++i)
          index[i] = i;
        const double size = ground.back()[0] - ground.front()[0];

        if (slope.tension_crack_depth > 0)
          {
            cuts.crack = true;
            cuts.crack_at_right =
              case_input::polyline_elevation(ground, line.back()[0]) >=
              case_input::polyline_elevation(ground, line.front()[0]);
            std::vector<Point<2>> ordered =
              line; // from the far end to the crest
            std::vector<int> order = index;
            if (!cuts.crack_at_right)
              {
                std::reverse(ordered.begin(), ordered.end());
                std::reverse(order.begin(), order.end());
              }
            const auto [k, bottom] =
              find_crack(ground, ordered, slope.tension_crack_depth);
            ordered.resize(k + 1);
            order.resize(k + 1);
            ordered.push_back(bottom);
            order.push_back(-1);
            if (!cuts.crack_at_right)
              {
                std::reverse(ordered.begin(), ordered.end());
                std::reverse(order.begin(), order.end());
              }
            cuts.surface      = ordered;
            index             = order;
            cuts.crack_bottom = bottom;
            cuts.crack_top =
              Point<2>(bottom[0],
                       case_input::polyline_elevation(ground, bottom[0]));
            cuts.crack_water_level =
              bottom[1] + slope.tension_crack_water_depth;
          }

        if (slope.interslice_surfaces == Slope::Interslices::none)
          return cuts;
        const std::string name = path + "Interslice surfaces: ";
        if (slope.interslice_surfaces == Slope::Interslices::inclination)
          AssertThrow(slope.interslice_inclinations.size() + 2 == line.size(),
                      ExcMessage(
                        path + "Interslice inclinations: " +
                        std::to_string(slope.interslice_inclinations.size()) +
                        " values given; one per interior vertex of the sliding "
                        "surface polyline is needed (" +
                        std::to_string(line.size() - 2) + ")."));
        const std::vector<Point<2>> &surface = cuts.surface;
        for (unsigned int i = 1; i + 1 < surface.size(); ++i)
          {
            const Point<2> &v = surface[i];
            AssertThrow(
              case_input::polyline_elevation(ground, v[0]) - v[1] > 1e-6 * size,
              ExcMessage(
                name + "the vertex " + point_text(v) +
                " of the sliding surface polyline does not lie below the "
                "ground surface, so no interslice can start there."));
            const Tensor<1, 2> u =
              (surface[i - 1] - v) / surface[i - 1].distance(v);
            const Tensor<1, 2> w =
              (surface[i + 1] - v) / surface[i + 1].distance(v);
            Tensor<1, 2> d({0., 1.});
            if (slope.interslice_surfaces == Slope::Interslices::bisector)
              {
                // The bisector of the angle on the mass's side (above).
                d = u + w;
                if (d.norm() < 1e-12)
                  d = Tensor<1, 2>({-w[1], w[0]});
                else if (d[1] < 0)
                  d = -d;
                d /= d.norm();
              }
            else if (slope.interslice_surfaces ==
                     Slope::Interslices::inclination)
              {
                const double a =
                  slope.interslice_inclinations[index[i] - 1] * M_PI / 180;
                d = Tensor<1, 2>({std::cos(a), std::sin(a)});
              }
            // The mass lies counterclockwise from w (forward) to u (back).
            const double to_d = angle_from(w, d);
            AssertThrow(to_d > 1e-9 && to_d < angle_from(w, u) - 1e-9,
                        ExcMessage(
                          name + "the interslice from the vertex " +
                          point_text(v) +
                          " points out of the sliding mass (below the sliding "
                          "surface)."));
            double s_ground    = std::numeric_limits<double>::infinity(),
                   s_other     = s_ground;
            const double s_min = 1e-9 * size;
            for (unsigned int j = 1; j < ground.size(); ++j)
              s_ground =
                std::min(s_ground,
                         ray_hits(v, d, ground[j - 1], ground[j], s_min));
            for (unsigned int j = 1; j < surface.size(); ++j)
              if (j != i && j != i + 1)
                s_other =
                  std::min(s_other,
                           ray_hits(v, d, surface[j - 1], surface[j], s_min));
            if (cuts.crack)
              s_other = std::min(
                s_other,
                ray_hits(v, d, cuts.crack_bottom, cuts.crack_top, s_min));
            AssertThrow(
              std::isfinite(s_ground) && s_ground < s_other,
              ExcMessage(
                name + "the interslice from the vertex " + point_text(v) +
                " does not reach the ground surface inside the sliding "
                "mass (it " +
                (std::isfinite(s_other) ?
                   "meets the sliding surface or the tension crack first" :
                   "leaves the model") +
                ")."));
            const Point<2> top = v + s_ground * d;
            for (const auto &other : cuts.interslices)
              AssertThrow(!segments_meet(other[0], other[1], v, top),
                          ExcMessage(name + "the interslices from " +
                                     point_text(other[0]) + " and " +
                                     point_text(v) + " cross."));
            cuts.interslices.push_back({v, top});
          }
        return cuts;
      }



      std::vector<Point<2>>
      region_above(const Cuts &cuts, const double top)
      {
        std::vector<Point<2>> above = cuts.surface;
        const bool            wet   = cuts.crack &&
                         cuts.crack_water_level > cuts.crack_bottom[1] &&
                         cuts.crack_water_level < cuts.crack_top[1];
        // The water level in the crack is a corner: a mesh node at the kink
        // of its hydrostatic pressure.
        if (cuts.crack && cuts.crack_at_right && wet)
          above.emplace_back(cuts.crack_bottom[0], cuts.crack_water_level);
        above.emplace_back(above.back()[0], top);
        above.emplace_back(cuts.surface.front()[0], top);
        if (cuts.crack && !cuts.crack_at_right && wet)
          above.emplace_back(cuts.crack_bottom[0], cuts.crack_water_level);
        return above;
      }



      std::vector<int>
      cut_sliding_mass(const int mass, int &foundation, const Cuts &cuts)
      {
        if (cuts.interslices.empty())
          return {mass};
        gmsh::vectorpair lines;
        for (const auto &cut : cuts.interslices)
          {
            const int a = gmsh::model::occ::addPoint(cut[0][0], cut[0][1], 0);
            const int b = gmsh::model::occ::addPoint(cut[1][0], cut[1][1], 0);
            lines.emplace_back(1, gmsh::model::occ::addLine(a, b));
          }
        gmsh::vectorpair              pieces;
        std::vector<gmsh::vectorpair> origin;
        gmsh::model::occ::fragment({{2, mass}, {2, foundation}},
                                   lines,
                                   pieces,
                                   origin);
        gmsh::model::occ::synchronize();
        std::vector<std::pair<double, int>> masses;
        for (const auto &piece : origin[0])
          if (piece.first == 2)
            {
              double x, y, z;
              gmsh::model::occ::getCenterOfMass(2, piece.second, x, y, z);
              masses.emplace_back(x, piece.second);
            }
        AssertThrow(
          masses.size() == cuts.interslices.size() + 1 && origin[1].size() == 1,
          ExcMessage(path +
                     "Interslice surfaces: the interslices do not cut the "
                     "sliding mass into one block more than there are "
                     "interslices."));
        foundation = origin[1][0].second;
        std::sort(masses.begin(), masses.end());
        std::vector<int> tags;
        for (const auto &m : masses)
          tags.push_back(m.second);
        return tags;
      }



      std::vector<int>
      take_crack_curves(std::vector<int> &curves,
                        const Cuts       &cuts,
                        const double      tolerance)
      {
        std::vector<int> crack, others;
        for (const int curve : curves)
          {
            double x0, y0, z0, x1, y1, z1;
            gmsh::model::getBoundingBox(1, curve, x0, y0, z0, x1, y1, z1);
            const bool vertical_at_crack =
              cuts.crack && std::abs(x0 - cuts.crack_bottom[0]) < tolerance &&
              std::abs(x1 - cuts.crack_bottom[0]) < tolerance &&
              y0 > cuts.crack_bottom[1] - tolerance;
            (vertical_at_crack ? crack : others).push_back(curve);
          }
        curves = others;
        return crack;
      }
    } // namespace slope_interslices
  }   // namespace geometry
} // namespace fdem
