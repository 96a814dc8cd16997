// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// What the surface search leaves in the results folder: search.csv (every
// circle), critical_surface.prm (the entries to rerun the critical circle)
// and summary.json's "surface_search".
#include <fdem/analyses/surface_search.h>
#include <fdem/postprocess/json_number.h>
#include <fdem/postprocess/output_file.h>
#include <fdem/postprocess/output_files.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace fdem
{
  namespace analyses
  {
    namespace
    {
      nlohmann::json
      circle_json(const SearchedSurface &s)
      {
        if (!s.polyline.empty())
          {
            nlohmann::json points = nlohmann::json::array();
            for (const auto &p : s.polyline)
              points.push_back({p[0], p[1]});
            return {{"shape", "polyline"},
                    {"polyline", points},
                    {"centre", nullptr},
                    {"radius", nullptr},
                    {"stage", s.stage},
                    {"le_K", postprocess::number_or_null(s.le_K)},
                    {"contact_K", postprocess::number_or_null(s.contact_K)},
                    {"status", s.status}};
          }
        return {{"shape", "circular"},
                {"centre", {s.centre[0], s.centre[1]}},
                {"radius", s.radius},
                {"stage", s.stage},
                {"le_K", postprocess::number_or_null(s.le_K)},
                {"contact_K", postprocess::number_or_null(s.contact_K)},
                {"status", s.status}};
      }

      /** "x y; x y; ..." (search.csv's polyline column). */
      std::string
      points_text(const std::vector<dealii::Point<2>> &line,
                  const std::string                   &separator)
      {
        std::ostringstream text;
        text << std::setprecision(12);
        for (unsigned int i = 0; i < line.size(); ++i)
          text << (i == 0 ? "" : "; ") << line[i][0] << separator << line[i][1];
        return text.str();
      }

      /** summary.json's "non_circular": the polylines' stage. */
      nlohmann::json
      non_circular_json(const SurfaceSearchResult &result)
      {
        const SurfaceSearchParameters &s       = result.settings;
        nlohmann::json                 skipped = nlohmann::json::object();
        for (const auto &[why, n] : result.n_polyline_skipped)
          skipped[why] = n;
        unsigned int n_certified = 0;
        for (const auto &surface : result.surfaces)
          n_certified += !surface.polyline.empty() && surface.certified;
        const auto    &r                = result.polyline_refinement;
        nlohmann::json refinement_skips = nlohmann::json::object();
        for (const auto &[why, n] : r.n_skipped)
          refinement_skips[why] = n;
        const nlohmann::json refinement = {
          {"performed", r.performed},
          {"why_not", r.why_not},
          {"contact_refinements", s.n_polyline_contact_refinements},
          {"from",
           r.from >= 0 ? circle_json(result.surfaces[r.from]) :
                         nlohmann::json(nullptr)},
          {"best",
           r.best >= 0 ? circle_json(result.surfaces[r.best]) :
                         nlohmann::json(nullptr)},
          {"first_step", r.first_step},
          {"last_step", r.last_step},
          {"counts",
           {{"contact_evaluations", r.n_evaluations},
            {"moves", r.n_moves},
            {"not_certified", r.n_uncertified},
            {"skipped", refinement_skips}}},
          {"seconds", r.seconds}};
        return {{"method", result.polyline_method_key},
                {"n_vertices", s.n_polyline_vertices},
                {"concave_upward", s.concave},
                {"interslices",
                 s.polyline_interslices ==
                     SurfaceSearchParameters::Interslices::vertical ?
                   "vertical" :
                 s.polyline_interslices ==
                     SurfaceSearchParameters::Interslices::bisector ?
                   "bisector" :
                   "none"},
                {"snap_distance", result.snap_distance},
                {"start",
                 result.polyline_start >= 0 ?
                   circle_json(result.surfaces[result.polyline_start]) :
                   nlohmann::json(nullptr)},
                {"minimum",
                 result.polyline_minimum >= 0 ?
                   circle_json(result.surfaces[result.polyline_minimum]) :
                   nlohmann::json(nullptr)},
                {"counts",
                 {{"starts", result.n_polyline_starts},
                  {"screened", result.n_polyline},
                  {"valid", result.n_polyline_valid},
                  {"skipped", skipped},
                  {"snapped", result.n_polyline_snapped},
                  {"contact_evaluations", result.n_polyline_contact},
                  {"contact_certified", n_certified},
                  {"contact_candidates", s.n_polyline_contact_candidates}}},
                {"contact_refinement", refinement},
                {"timings",
                 {{"screening", result.seconds_polyline},
                  {"contact_evaluations", result.seconds_polyline_contact},
                  {"contact_refinement", r.seconds}}}};
      }
    } // namespace

    nlohmann::json
    to_json(const SurfaceSearchResult &result, const nlohmann::json &summary)
    {
      const SurfaceSearchParameters &s    = result.settings;
      nlohmann::json                 grid = {
                        {"lower_left", {s.grid_lower[0], s.grid_lower[1]}},
                        {"upper_right", {s.grid_upper[0], s.grid_upper[1]}},
                        {"n_x", s.n_x},
                        {"n_y", s.n_y},
                        {"radii",
         s.radii == SurfaceSearchParameters::Radii::through_point ?
                           "through point" :
                           "tangent elevations"}};
      if (s.radii == SurfaceSearchParameters::Radii::through_point)
        grid["point"] = {s.point[0], s.point[1]};
      else
        grid["tangent_elevations"] = s.tangent_elevations;

      nlohmann::json critical = circle_json(result.surfaces[result.critical]);
      critical["chosen_by"]   = result.chosen_by;
      critical["screening_mesh_size"] = result.screening_mesh_size;
      // The run itself is on the critical circle at the model's mesh size:
      // its K, certificate and limit-equilibrium factors are the circle's.
      critical["K"]         = summary.contains("safety_factor") ?
                                summary["safety_factor"] :
                                nlohmann::json(nullptr);
      critical["certified"] = summary.contains("certificate") &&
                              summary["certificate"].value("holds", false);
      nlohmann::json by_method = nlohmann::json::object();
      if (summary.contains("limit_equilibrium") &&
          summary["limit_equilibrium"].contains("methods"))
        for (const auto &[method, value] :
             summary["limit_equilibrium"]["methods"].items())
          by_method[method] =
            value.contains("K") ? value["K"] : nlohmann::json(nullptr);
      critical["limit_equilibrium"] = by_method;

      nlohmann::json skipped = nlohmann::json::object();
      for (const auto &[why, n] : result.n_skipped)
        skipped[why] = n;
      unsigned int n_certified = 0;
      for (const auto &surface : result.surfaces)
        n_certified += surface.certified;
      nlohmann::json out = {
        {"method", result.method_key},
        {"n_slices", s.n_slices},
        {"grid", grid},
        {"given_circle",
         {{"centre", {result.given_centre[0], result.given_centre[1]}},
          {"radius", result.given_radius}}},
        {"critical", critical},
        {"minimum_on_grid_edge", result.on_grid_edge},
        {"screening_minimum", circle_json(result.surfaces[result.le_minimum])},
        {"counts",
         {{"grid", result.n_grid},
          {"valid", result.n_valid},
          {"skipped", skipped},
          {"refinement", result.n_refinement},
          {"contact_evaluations", result.n_contact},
          {"contact_certified", n_certified},
          {"maximum_contact_evaluations", s.max_contact_evaluations}}},
        {"timings",
         {{"screening", result.seconds_screening},
          {"refinement", result.seconds_refinement},
          {"contact_evaluations", result.seconds_contact}}},
        {"files", {"search.csv", "critical_surface.prm"}}};
      if (result.non_circular)
        out["non_circular"] = non_circular_json(result);
      return out;
    }

    void
    write_surface_search(const SurfaceSearchResult &result,
                         const std::string         &directory,
                         nlohmann::json            &summary)
    {
      // summary.json last: it says the run's files are complete.
      postprocess::OutputFile csv(directory + "/search.csv");
      csv << std::setprecision(12);
      csv
        << "stage,centre_x,centre_y,radius,le_K,contact_K,certified,status,contact_seconds,polyline\n";
      const auto cell = [](const double x) {
        std::ostringstream text;
        if (std::isfinite(x))
          text << std::setprecision(12) << x;
        return text.str();
      };
      for (const auto &s : result.surfaces)
        csv << s.stage << "," << cell(s.centre[0]) << "," << cell(s.centre[1])
            << "," << cell(s.radius) << "," << cell(s.le_K) << ","
            << cell(s.contact_K) << "," << (s.certified ? 1 : 0) << ",\""
            << s.status << "\"," << s.contact_seconds << ",\""
            << points_text(s.polyline, " ") << "\"\n";

      csv.close();

      const SearchedSurface  &c = result.surfaces[result.critical];
      postprocess::OutputFile prm(directory + "/critical_surface.prm");
      prm << std::setprecision(12);
      if (c.polyline.empty())
        prm
          << "# The critical circle of the surface search (search.csv; chosen by the "
          << result.chosen_by << ").\n"
          << "# Paste into the case's .prm file, with Surface search/Enabled = false, to\n"
          << "# rerun it.\n"
          << "subsection Geometry\n"
          << "  subsection Slope\n"
          << "    set Sliding surface = circular\n"
          << "    set Circle centre   = " << c.centre[0] << ", " << c.centre[1]
          << "\n"
          << "    set Circle radius   = " << c.radius << "\n"
          << "  end\n"
          << "end\n";
      else
        {
          const auto interslices = result.settings.polyline_interslices;
          using I                = SurfaceSearchParameters::Interslices;
          prm
            << "# The critical polyline of the surface search (search.csv; chosen by the\n# "
            << result.chosen_by << ").\n"
            << "# Paste into the case's .prm file, with Surface search/Enabled = false, to\n"
            << "# rerun it.\n";
          if (interslices != I::none)
            prm
              << "# The search cut its mass into blocks by interslices: to rerun it so,\n"
              << "# name the blocks 'sliding mass 1' to 'sliding mass "
              << c.polyline.size() - 1
              << "', the interfaces 'sliding surface 1'\n# to 'sliding surface "
              << c.polyline.size() - 1 << "' and 'interslice 1' to 'interslice "
              << c.polyline.size() - 2 << "' (doc/surface_search.md).\n";
          prm << "subsection Geometry\n"
              << "  subsection Slope\n"
              << "    set Sliding surface          = polyline\n"
              << "    set Sliding surface polyline = "
              << points_text(c.polyline, ", ") << "\n"
              << "    set Interslice surfaces      = "
              << (interslices == I::vertical ? "vertical" :
                  interslices == I::bisector ? "bisector" :
                                               "none")
              << "\n"
              << "  end\n"
              << "end\n";
        }
      prm.close();

      summary["surface_search"] = to_json(result, summary);
      postprocess::write_json(directory + "/summary.json", summary);
    }
  } // namespace analyses
} // namespace fdem
