// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The contact part of the surface search: each candidate circle is its own
// model (the slope generator with that circle, its own mesh), solved for K
// without output files, stress recovery, stiffness check or report; then a
// pattern search on the contact K around the best candidate.
#include <fdem/analyses/limit_equilibrium_model.h>
#include <fdem/analyses/safety_factor_analysis.h>
#include <fdem/analyses/surface_search.h>
#include <fdem/model.h>
#include <fdem/postprocess/run_log.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <set>
#include <sstream>

namespace fdem
{
  namespace analyses
  {
    using namespace dealii;
    namespace le = limit_equilibrium;

    std::string
    polyline_words(const std::vector<Point<2>> &line)
    {
      std::ostringstream text;
      text << std::setprecision(6) << "polyline of " << line.size()
           << " vertices from (" << line.front()[0] << ", " << line.front()[1]
           << ") to (" << line.back()[0] << ", " << line.back()[1] << ")";
      return text.str();
    }

    std::string
    contact_outcome_words(const SearchedSurface &s,
                          const std::string     &method_key)
    {
      std::ostringstream text;
      if (std::isfinite(s.contact_K))
        text << "K = " << std::fixed << std::setprecision(4) << s.contact_K
             << std::defaultfloat;
      else
        text << s.status;
      text << " (" << method_key << " " << std::fixed << std::setprecision(4)
           << s.le_K << ", " << std::setprecision(1) << s.contact_seconds
           << " s)";
      return text.str();
    }

    void
    evaluate_contact(const parameters::Parameters  &base,
                     const SurfaceSearchParameters &settings,
                     const std::string             &scratch,
                     SearchedSurface               &s)
    {
      parameters::Parameters p     = base;
      auto                  &slope = p.geometry.slope;
      if (s.polyline.empty())
        {
          slope.circle_centre = s.centre;
          slope.circle_radius = s.radius;
        }
      else
        use_polyline(p, s.polyline);
      if (settings.screening_mesh_size > 0)
        {
          const double ratio = settings.screening_mesh_size / slope.mesh_size;
          slope.mesh_size    = settings.screening_mesh_size;
          slope.mesh_size_on_sliding_surface *= ratio;
        }
      // What the search does not need: files, pictures, the stiffness
      // check's two more iterations, limit equilibrium (screened already).
      p.output.directory              = scratch;
      p.output.write_vtu              = false;
      p.output.write_steps            = false;
      p.output.report                 = false;
      p.safety_factor.compute         = true;
      p.safety_factor.stiffness_check = false;
      p.limit_equilibrium.enabled     = false;
      p.surface_search.enabled        = false;
      Timer              timer;
      std::ostringstream sink;
      try
        {
          Model<2> model(p, sink, &sink);
          model.make_geometry();
          model.setup_blocks();
          model.assemble_and_factorize();
          model.build_interfaces();
          model.compute_flexibility();
          const Result r = SafetyFactorAnalysis<2>(model).run();
          s.contact_K    = r.safety_factor;
          s.certified = r.certificate.holds && std::isfinite(r.safety_factor);
          s.status    = s.certified      ? "certified" :
                        r.no_equilibrium ? "no equilibrium" :
                                           "not certified: " + r.reason;
          if (!s.certified)
            s.contact_K = std::numeric_limits<double>::quiet_NaN();
        }
      catch (const std::exception &error)
        {
          s.status = "failed: " + postprocess::one_line(error);
        }
      s.contact_seconds = timer.wall_time();
    }

    namespace
    {
      std::string
      circle_words(const Point<2> &centre, const double radius)
      {
        std::ostringstream text;
        text << std::setprecision(6) << "centre (" << centre[0] << ", "
             << centre[1] << "), radius " << radius;
        return text.str();
      }


      /**
       * The non-circular stage: the polylines' screening, then the optima
       * of the starts evaluated by the contact method (at most @p budget),
       * and the critical surface chosen again among circles and polylines.
       */
      void
      search_polylines(const parameters::Parameters &parameters,
                       const le::Section            &section,
                       unsigned int                  budget,
                       const std::string            &scratch,
                       SurfaceSearchResult          &result,
                       std::ostream                 &brief)
      {
        const SurfaceSearchParameters &settings = parameters.surface_search;
        const auto                    &slope    = parameters.geometry.slope;
        const double                   base     = slope.base_elevation;
        // The optima's vertices within a tenth of the element size on the
        // sliding surface (the screening mesh's or the run's, the larger)
        // of a layer line are snapped onto it: a thinner gap leaves cells
        // of aspect ratio above 10 between the two lines (measured, doc/
        // surface_search.md).
        const double on_surface =
          std::max(slope.mesh_size_on_sliding_surface,
                   settings.screening_mesh_size > 0 ?
                     slope.mesh_size_on_sliding_surface *
                       settings.screening_mesh_size / slope.mesh_size :
                     0.);
        screen_polylines(section, base, settings, 0.1 * on_surface, result);
        {
          std::ostringstream line;
          line << "Surface search: non-circular: " << result.n_polyline
               << " polylines of " << settings.n_polyline_vertices
               << " vertices screened by " << result.polyline_method_key
               << " from " << result.n_polyline_starts << " circles ("
               << result.n_polyline_valid << " valid";
          for (const auto &[why, n] : result.n_polyline_skipped)
            line << ", " << n << " " << why;
          line << "), " << std::setprecision(3) << result.seconds_polyline
               << " s";
          if (result.polyline_minimum >= 0)
            {
              const SearchedSurface &m =
                result.surfaces[result.polyline_minimum];
              line << "; minimum " << std::setprecision(5) << m.le_K << " on a "
                   << polyline_words(m.polyline);
            }
          else
            line << "; no valid polyline";
          brief << line.str() << std::endl;
        }

        // The candidates: each start's optimum, the lowest first, distinct.
        std::vector<unsigned int> candidates;
        for (const unsigned int i : result.polyline_optima)
          if (result.surfaces[i].valid &&
              std::none_of(candidates.begin(),
                           candidates.end(),
                           [&](const unsigned int j) {
                             return result.surfaces[j].polyline ==
                                    result.surfaces[i].polyline;
                           }))
            candidates.push_back(i);
        std::sort(candidates.begin(),
                  candidates.end(),
                  [&](const unsigned a, const unsigned b) {
                    return result.surfaces[a].le_K < result.surfaces[b].le_K;
                  });
        Timer              timer;
        const unsigned int n_candidates =
          std::min<unsigned int>(candidates.size(),
                                 settings.n_polyline_contact_candidates);
        for (unsigned int c = 0; c < n_candidates && budget > 0; ++c, --budget)
          {
            SearchedSurface s = result.surfaces[candidates[c]];
            s.stage           = "polyline contact";
            evaluate_contact(parameters, settings, scratch, s);
            ++result.n_contact;
            ++result.n_polyline_contact;
            std::ostringstream line;
            line << "  contact " << result.n_contact << "/"
                 << settings.max_contact_evaluations
                 << " (polyline): " << polyline_words(s.polyline) << ": "
                 << contact_outcome_words(s, result.polyline_method_key);
            brief << line.str() << std::endl;
            result.surfaces.push_back(s);
          }
        result.seconds_polyline_contact = timer.wall_time();

        // The best polyline's vertices moved by its contact K: steps from
        // half the element size on the sliding surface down to the snap
        // distance, below which a move near a layer line is snapped back
        // and one elsewhere changes K by less than the mesh does.
        refine_polyline_by_contact(
          parameters,
          section,
          on_surface / 2,
          result.snap_distance,
          std::min(budget, settings.n_polyline_contact_refinements),
          scratch,
          result,
          brief);

        // The critical surface: the lowest certified contact K of all; with
        // none, the lower screening factor of the circles' and the
        // polylines' minima (two methods, but each the rigorous one its
        // shape admits).
        int best = -1;
        for (unsigned int i = 0; i < result.surfaces.size(); ++i)
          if (std::isfinite(result.surfaces[i].contact_K) &&
              (best < 0 ||
               result.surfaces[i].contact_K < result.surfaces[best].contact_K))
            best = i;
        if (best >= 0)
          {
            result.critical  = best;
            result.chosen_by = "contact K";
          }
        else
          {
            // The lowest of the optima as snapped (the polylines the
            // contact method would have evaluated), not the unsnapped
            // minimum: the run meshes it too.
            int lowest = -1;
            for (const unsigned int i : result.polyline_optima)
              if (result.surfaces[i].valid &&
                  (lowest < 0 ||
                   result.surfaces[i].le_K < result.surfaces[lowest].le_K))
                lowest = i;
            if (lowest >= 0 && result.surfaces[lowest].le_K <
                                 result.surfaces[result.le_minimum].le_K)
              {
                result.critical  = lowest;
                result.chosen_by = result.polyline_method_key;
              }
          }
      }
    } // namespace

    SurfaceSearchResult
    search_critical_surface(parameters::Parameters &parameters,
                            const std::string      &scratch,
                            std::ostream           &brief)
    {
      const SurfaceSearchParameters &settings = parameters.surface_search;
      auto                          &slope    = parameters.geometry.slope;
      AssertThrow(slope.sliding_surface ==
                    geometry::Slope::SlidingSurface::circular,
                  ExcMessage(
                    "Surface search/Enabled: the search is for circles; set "
                    "Geometry/Slope/Sliding surface = circular."));
      le::Section              section;
      le::Surface              surface;
      std::string              why_not;
      std::vector<std::string> notes;
      AssertThrow(
        model_section(parameters, section, surface, why_not, notes, false),
        ExcMessage(
          "Surface search/Enabled: the search screens by limit equilibrium, "
          "which is not available here because " +
          why_not + "."));

      SurfaceSearchResult result =
        screen_surfaces(section, slope.base_elevation, settings);
      result.given_centre        = slope.circle_centre;
      result.given_radius        = slope.circle_radius;
      result.screening_mesh_size = settings.screening_mesh_size > 0 ?
                                     settings.screening_mesh_size :
                                     slope.mesh_size;
      {
        std::ostringstream line;
        line << "Surface search: " << result.n_grid << " circles screened by "
             << result.method_key << " (" << result.n_valid << " valid";
        for (const auto &[why, n] : result.n_skipped)
          line << ", " << n << " " << why;
        const SearchedSurface &m = result.surfaces[result.le_minimum];
        line << "), " << result.n_refinement << " more in the refinement, "
             << std::setprecision(3)
             << result.seconds_screening + result.seconds_refinement
             << " s; minimum " << std::setprecision(5) << m.le_K << " at "
             << circle_words(m.centre, m.radius);
        brief << line.str() << std::endl;
        if (result.on_grid_edge)
          brief
            << "Surface search: note: the minimum lies on the edge of the search region "
               "(Centre grid, Tangent elevations); a lower one may lie beyond it"
            << std::endl;
      }

      // Of the contact evaluations, Non-circular contact candidates and
      // refinements are kept for the polylines (the candidates first).
      const unsigned int polyline_budget =
        settings.non_circular ?
          std::min(settings.n_polyline_contact_candidates +
                     settings.n_polyline_contact_refinements,
                   settings.max_contact_evaluations) :
          0;
      const unsigned int circle_budget =
        settings.max_contact_evaluations - polyline_budget;
      if (settings.max_contact_evaluations > 0)
        std::filesystem::create_directories(scratch);
      if (circle_budget > 0)
        {
          Timer        timer;
          unsigned int budget = circle_budget;
          // Circles already solved (the pattern search comes back to them).
          std::map<std::array<double, 3>, unsigned int> done;
          const auto                                    contact =
            [&](const Point<2> &c, const double R, const std::string &stage) {
              const std::array<double, 3> key = {{c[0], c[1], R}};
              if (done.count(key))
                return done[key];
              SearchedSurface s =
                screen_circle(section, slope.base_elevation, c, R, settings);
              s.stage = stage;
              --budget;
              ++result.n_contact;
              if (s.valid)
                evaluate_contact(parameters, settings, scratch, s);
              std::ostringstream line;
              line << "  contact " << result.n_contact << "/"
                   << settings.max_contact_evaluations << " (" << stage
                   << "): " << circle_words(c, R) << ": "
                   << contact_outcome_words(s, result.method_key);
              brief << line.str() << std::endl;
              result.surfaces.push_back(s);
              done[key] = result.surfaces.size() - 1;
              return done[key];
            };

          // The candidates: the screening minimum, then the best grid
          // circles of other centres.
          std::vector<unsigned int> order;
          for (unsigned int i = 0; i < result.surfaces.size(); ++i)
            if (result.surfaces[i].valid && result.surfaces[i].stage == "grid")
              order.push_back(i);
          std::sort(order.begin(),
                    order.end(),
                    [&](const unsigned a, const unsigned b) {
                      return result.surfaces[a].le_K < result.surfaces[b].le_K;
                    });
          std::vector<unsigned int>           candidates = {result.le_minimum};
          std::set<std::pair<double, double>> centres    = {
               {result.surfaces[result.le_minimum].centre[0],
                result.surfaces[result.le_minimum].centre[1]}};
          for (const unsigned int i : order)
            if (candidates.size() < settings.n_contact_candidates &&
                centres
                  .insert({result.surfaces[i].centre[0],
                           result.surfaces[i].centre[1]})
                  .second)
              candidates.push_back(i);
          int        best   = -1;
          const auto better = [&](const unsigned int i) {
            const double K = result.surfaces[i].contact_K;
            return std::isfinite(K) &&
                   (best < 0 || K < result.surfaces[best].contact_K);
          };
          for (const unsigned int i : candidates)
            if (budget > 0)
              {
                const SearchedSurface c = result.surfaces[i];
                const unsigned int j = contact(c.centre, c.radius, "contact");
                if (better(j))
                  best = j;
              }
          // A pattern search on the contact K from the best candidate, in
          // steps of half the grid spacing (the screening has placed it
          // within one), halved when no neighbour is lower.
          if (best >= 0)
            {
              const double dx =
                settings.n_x > 1 ?
                  (settings.grid_upper[0] - settings.grid_lower[0]) /
                    (settings.n_x - 1) :
                  result.surfaces[best].radius / 10;
              const double dy =
                settings.n_y > 1 ?
                  (settings.grid_upper[1] - settings.grid_lower[1]) /
                    (settings.n_y - 1) :
                  result.surfaces[best].radius / 10;
              const bool by_point =
                settings.radii == SurfaceSearchParameters::Radii::through_point;
              std::vector<double> step = {dx / 2,
                                          dy / 2,
                                          by_point ? 0. : std::min(dx, dy) / 2};
              const double        stop =
                settings.refinement_tolerance * std::max(dx, dy);
              while (budget > 0 && std::max({step[0], step[1], step[2]}) > stop)
                {
                  bool moved = false;
                  for (unsigned int k = 0; k < 3 && !moved && budget > 0; ++k)
                    for (const double sign : {-1., 1.})
                      {
                        if (step[k] == 0 || budget == 0)
                          continue;
                        const SearchedSurface &b = result.surfaces[best];
                        std::array<double, 3>  y = {
                           {b.centre[0], b.centre[1], b.radius}};
                        y[k] += sign * step[k];
                        if (!inside_search_region(settings, y))
                          continue;
                        const Point<2> c(y[0], y[1]);
                        const double   R =
                          by_point ? c.distance(settings.point) : y[2];
                        const unsigned int j =
                          contact(c, R, "contact refinement");
                        if (better(j))
                          {
                            best  = j;
                            moved = true;
                            break;
                          }
                      }
                  if (!moved)
                    for (double &h : step)
                      h /= 2;
                }
              result.critical  = best;
              result.chosen_by = "contact K";
            }
          result.seconds_contact = timer.wall_time();
        }

      if (settings.non_circular)
        search_polylines(
          parameters, section, polyline_budget, scratch, result, brief);
      // Only rank 0 writes meshes there (Model's writes_files).
      if (settings.max_contact_evaluations > 0 &&
          Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::filesystem::remove_all(scratch);

      const SearchedSurface &critical = result.surfaces[result.critical];
      if (critical.polyline.empty())
        {
          slope.circle_centre = critical.centre;
          slope.circle_radius = critical.radius;
        }
      else
        use_polyline(parameters, critical.polyline);
      brief << "Surface search: critical "
            << (critical.polyline.empty() ?
                  "circle " + circle_words(critical.centre, critical.radius) :
                  polyline_words(critical.polyline))
            << " (chosen by the " << result.chosen_by
            << "); the run computes K on it" << std::endl;
      return result;
    }
  } // namespace analyses
} // namespace fdem
