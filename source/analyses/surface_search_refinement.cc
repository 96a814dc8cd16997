// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The last step of the non-circular search (doc/surface_search.md): the best
// polyline's vertices moved by its contact K, not by limit equilibrium. Each
// candidate is its own model (a new mesh and factorisation), so the moves
// are few and coarse: a compass search on the interior vertices along the
// surface's normal, within the budget of contact evaluations.
#include <fdem/analyses/surface_search.h>

#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace fdem
{
  namespace analyses
  {
    using namespace dealii;
    namespace le = limit_equilibrium;

    namespace
    {
      /**
       * The unit normal at interior vertex @p i of @p line, pointing up
       * (into the sliding mass): the chord between its two neighbours
       * turned by a quarter to the left. At a vertex of a circle's polyline
       * it is the radius; on a straight run, the run's normal.
       */
      Tensor<1, 2>
      normal_at(const std::vector<Point<2>> &line, const unsigned int i)
      {
        const Tensor<1, 2> chord = line[i + 1] - line[i - 1];
        Tensor<1, 2>       n;
        n[0] = -chord[1];
        n[1] = chord[0];
        return n / n.norm();
      }

      /**
       * Whether @p a and @p b are the same polyline to @p tolerance in
       * every vertex: snapping a vertex that lies on a layer line again
       * moves it by round-off, which is no new surface.
       */
      bool
      same_polyline(const std::vector<Point<2>> &a,
                    const std::vector<Point<2>> &b,
                    const double                 tolerance)
      {
        if (a.size() != b.size())
          return false;
        for (unsigned int i = 0; i < a.size(); ++i)
          if (a[i].distance(b[i]) > tolerance)
            return false;
        return true;
      }
    } // namespace

    void
    refine_polyline_by_contact(const parameters::Parameters &parameters,
                               const le::Section            &section,
                               const double                  first_step,
                               const double                  snap_distance,
                               unsigned int                  budget,
                               const std::string            &scratch,
                               SurfaceSearchResult          &result,
                               std::ostream                 &brief)
    {
      const SurfaceSearchParameters &settings   = parameters.surface_search;
      auto                          &refinement = result.polyline_refinement;
      if (settings.n_polyline_contact_refinements == 0)
        return;
      // The start: the polyline of lowest certified contact K (a candidate
      // of the stage before).
      for (unsigned int i = 0; i < result.surfaces.size(); ++i)
        if (!result.surfaces[i].polyline.empty() &&
            std::isfinite(result.surfaces[i].contact_K) &&
            (refinement.from < 0 ||
             result.surfaces[i].contact_K <
               result.surfaces[refinement.from].contact_K))
          refinement.from = i;
      if (budget == 0)
        refinement.why_not = "no contact evaluation left";
      else if (refinement.from < 0)
        refinement.why_not = "no polyline with a certified contact K";
      if (!refinement.why_not.empty())
        {
          brief << "Surface search: polyline contact refinement: none ("
                << refinement.why_not << ")" << std::endl;
          return;
        }
      refinement.performed  = true;
      refinement.best       = refinement.from;
      refinement.first_step = first_step;
      Timer timer;

      // Polylines already looked at (a move and its reverse come back to
      // one): not evaluated twice.
      std::vector<std::vector<Point<2>>> seen = {
        result.surfaces[refinement.from].polyline};
      const unsigned int n     = seen.front().size();
      double             step  = first_step;
      const double       start = result.surfaces[refinement.from].contact_K;
      // Far below the smallest step (the snap distance), far above
      // round-off: relative to the polyline's span.
      const double tolerance =
        1e-9 * (seen.front().back()[0] - seen.front().front()[0]);
      // The steps stop at the snap distance: a shorter move of a vertex on
      // a layer line is snapped back onto it.
      while (budget > 0 && !(step < snap_distance))
        {
          bool moved = false;
          for (unsigned int i = 1; i + 1 < n && budget > 0; ++i)
            for (const double sign : {-1., 1.})
              {
                if (budget == 0)
                  break;
                const std::vector<Point<2>> &line =
                  result.surfaces[refinement.best].polyline;
                std::vector<Point<2>> moved_line = line;
                moved_line[i] += sign * step * normal_at(line, i);
                // Onto the layer lines as every evaluated polyline, so that
                // the mesh has no slivers between the surface and a line.
                moved_line = snap_polyline(section, moved_line, snap_distance);
                if (std::any_of(seen.begin(),
                                seen.end(),
                                [&](const std::vector<Point<2>> &other) {
                                  return same_polyline(other,
                                                       moved_line,
                                                       tolerance);
                                }))
                  continue;
                seen.push_back(moved_line);
                SearchedSurface s =
                  screen_polyline(section,
                                  parameters.geometry.slope.base_elevation,
                                  moved_line,
                                  settings);
                s.stage = "polyline contact refined";
                if (!s.valid)
                  {
                    // Not a sliding surface of the model: recorded, not
                    // evaluated, no budget spent.
                    ++refinement
                        .n_skipped[s.status.substr(0, s.status.find(':'))];
                    result.surfaces.push_back(s);
                    continue;
                  }
                evaluate_contact(parameters, settings, scratch, s);
                --budget;
                ++result.n_contact;
                ++result.n_polyline_contact;
                ++refinement.n_evaluations;
                if (!s.certified)
                  ++refinement.n_uncertified;
                std::ostringstream text;
                text << "  contact " << result.n_contact << "/"
                     << settings.max_contact_evaluations
                     << " (polyline refinement): vertex " << i << " by "
                     << std::setprecision(3) << sign * step << " along its "
                     << "normal: "
                     << contact_outcome_words(s, result.polyline_method_key);
                brief << text.str() << std::endl;
                result.surfaces.push_back(s);
                if (s.certified &&
                    s.contact_K < result.surfaces[refinement.best].contact_K)
                  {
                    refinement.best = result.surfaces.size() - 1;
                    ++refinement.n_moves;
                    moved = true;
                    // The next vertex: the reverse move would go back.
                    break;
                  }
              }
          refinement.last_step = step;
          if (!moved)
            step /= 2;
        }
      refinement.seconds = timer.wall_time();
      std::ostringstream text;
      text << "Surface search: polyline contact refinement: K "
           << std::setprecision(5) << start << " to "
           << result.surfaces[refinement.best].contact_K << " by "
           << refinement.n_moves << " moves of " << refinement.n_evaluations
           << " contact evaluations (" << refinement.n_uncertified
           << " not certified";
      for (const auto &[why, count] : refinement.n_skipped)
        text << ", " << count << " " << why;
      text << "), steps " << std::setprecision(3) << refinement.first_step
           << " to " << refinement.last_step << ", " << refinement.seconds
           << " s";
      brief << text.str() << std::endl;
    }
  } // namespace analyses
} // namespace fdem
