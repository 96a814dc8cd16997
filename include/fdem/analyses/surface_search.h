// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/limit_equilibrium.h>
#include <fdem/analyses/surface_search_parameters.h>
#include <fdem/parameters/parameters.h>
#include <fdem/parameters/work_estimate.h>

#include <deal.II/base/point.h>

#include <nlohmann/json.hpp>

#include <array>
#include <limits>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace fdem
{
  namespace analyses
  {
    /**
     * One surface the search looked at, a circle or a polyline: where it came
     * from, its screening factor and, where the contact method evaluated it,
     * its contact K.
     */
    struct SearchedSurface
    {
      /**
       * "grid", "refinement", "contact", "contact refinement" (circles),
       * "polyline start", "polyline", "polyline snapped", "polyline
       * contact" or "polyline contact refined" (polylines).
       */
      std::string      stage;
      dealii::Point<2> centre;
      double           radius = 0;
      /** The polyline from left to right (empty for a circle). */
      std::vector<dealii::Point<2>> polyline;
      /** Whether it is a valid sliding surface with a screening factor. */
      bool valid = false;
      /** The screening method's factor (NaN if none). */
      double le_K = std::numeric_limits<double>::quiet_NaN();
      /** The contact K on the screening mesh (NaN if not evaluated or none). */
      double contact_K = std::numeric_limits<double>::quiet_NaN();
      /** Whether the contact K is certified (safety-factor certificate). */
      bool certified = false;
      /** "valid", why it was skipped, or the contact evaluation's outcome. */
      std::string status;
      /** Wall time of the contact evaluation (s; 0 if none). */
      double contact_seconds = 0;
    };

    /** What the search did and found (summary.json's "surface_search"). */
    struct SurfaceSearchResult
    {
      bool performed = false;
      /** Every surface evaluated, in order. */
      std::vector<SearchedSurface> surfaces;
      /** Index into surfaces of the critical circle. */
      unsigned int critical = 0;
      /** "contact K" or the screening method's key: what chose it. */
      std::string chosen_by;
      /** Index of the screening minimum (grid and refinement). */
      unsigned int le_minimum = 0;
      /** The circle of Geometry/Slope that the search replaced. */
      dealii::Point<2> given_centre;
      double           given_radius = 0;
      unsigned int     n_grid = 0, n_valid = 0, n_refinement = 0, n_contact = 0;
      /** Skipped grid circles by reason. */
      std::map<std::string, unsigned int> n_skipped;
      double seconds_screening = 0, seconds_refinement = 0, seconds_contact = 0;
      std::string method_key;
      double      screening_mesh_size = 0;
      /**
       * Whether the screening minimum lies on the edge of the search region
       * (grid rectangle, tangent range): the minimum may lie beyond it.
       */
      bool on_grid_edge = false;
      /** The search's settings (for the summary). */
      SurfaceSearchParameters settings;

      /** The non-circular stage (Surface search/Non-circular). */
      bool non_circular = false;
      /** Polylines screened by its optimisation, valid among them. */
      unsigned int n_polyline = 0, n_polyline_valid = 0, n_polyline_starts = 0;
      /** Polylines evaluated by the contact method. */
      unsigned int n_polyline_contact = 0;
      /** Skipped polylines by reason. */
      std::map<std::string, unsigned int> n_polyline_skipped;
      /** Index of the polylines' screening minimum (-1: none). */
      int polyline_minimum = -1;
      /** Index of the polyline made from the best circle (-1: none). */
      int polyline_start = -1;
      /**
       * Index of each start's optimum, in the order of the starts: the
       * optimum snapped onto the layer lines (snap_polyline()) where that
       * moved it and left it valid.
       */
      std::vector<unsigned int> polyline_optima;
      /** Snap distance of the optima (length; 0: no snapping). */
      double snap_distance = 0;
      /** Optima that snapping moved and left valid. */
      unsigned int n_polyline_snapped = 0;
      double       seconds_polyline = 0, seconds_polyline_contact = 0;
      std::string  polyline_method_key;

      /**
       * The local refinement of the best polyline by its contact K
       * (Surface search/Non-circular contact refinements,
       * refine_polyline_by_contact()).
       */
      struct PolylineRefinement
      {
        /** Whether it ran (a budget and a certified polyline to start from). */
        bool performed = false;
        /** Why it did not run ("" if it did). */
        std::string why_not;
        /** Index of the polyline it started from and of the best it found. */
        int from = -1, best = -1;
        /** Contact evaluations, moves kept, candidates not certified. */
        unsigned int n_evaluations = 0, n_moves = 0, n_uncertified = 0;
        /** Candidates not admissible, by reason (not evaluated). */
        std::map<std::string, unsigned int> n_skipped;
        /** The first and the last step along the normals (length). */
        double first_step = 0, last_step = 0;
        double seconds = 0;
      } polyline_refinement;
    };

    /**
     * The screening of one polyline on @p section: whether it is a sliding
     * surface of the model (x increasing, its ends within the ground's x
     * range, every interior vertex below the ground and no segment above it,
     * above @p base_elevation, concave upward if asked, at least Minimum depth
     * deep, m_alpha at least 0.2) and, if so, the factor of the
     * non-circular method of @p settings.
     */
    SearchedSurface
    screen_polyline(const limit_equilibrium::Section    &section,
                    const double                         base_elevation,
                    const std::vector<dealii::Point<2>> &polyline,
                    const SurfaceSearchParameters       &settings);

    /**
     * The circle (@p centre, @p radius) as a polyline of @p n_vertices
     * vertices on the arc below the ground, at equal angles between its two
     * ground intersections. Throws if the circle does not cut the ground.
     */
    std::vector<dealii::Point<2>>
    circle_to_polyline(const std::vector<dealii::Point<2>> &ground,
                       const dealii::Point<2>              &centre,
                       const double                         radius,
                       const unsigned int                   n_vertices);

    /**
     * @p polyline (a search's polyline: its ends just above the ground)
     * with its vertices that lie within @p distance of a layer line of
     * @p section (a boundary between two layers, or a named weak layer)
     * moved onto the nearest point of the nearest such line, and each end
     * within @p distance of a point where such a line meets the ground
     * moved along the ground to that point (then lengthened by 1e-6 of its
     * segment, as every end of the search). A surface that runs a few
     * millimetres from a layer boundary leaves sliver cells between the two
     * lines in the mesh; on the line it shares the boundary's edges.
     */
    std::vector<dealii::Point<2>>
    snap_polyline(const limit_equilibrium::Section    &section,
                  const std::vector<dealii::Point<2>> &polyline,
                  const double                         distance);

    /**
     * The limit-equilibrium part of the non-circular stage: from each of
     * the best circles of distinct centres in @p result (Contact
     * candidates of them), the circle as a polyline, its vertices optimised
     * by a coordinate search (surface_search_polyline.cc), the optimum then
     * snapped onto the layer lines within @p snap_distance (0: not) and
     * screened again. Appends every polyline to @p result and sets its
     * counts, minimum and optima.
     */
    void
    screen_polylines(const limit_equilibrium::Section &section,
                     const double                      base_elevation,
                     const SurfaceSearchParameters    &settings,
                     const double                      snap_distance,
                     SurfaceSearchResult              &result);

    /**
     * The base's limit-equilibrium factor of @p surface on @p section by
     * @p method into @p s (le_K, valid, status): skipped where m_alpha =
     * cos(alpha) + sin(alpha) tan(phi) / K falls below 0.2 on a slice, or
     * the method has no answer.
     */
    void
    screen_by_limit_equilibrium(const limit_equilibrium::Section &section,
                                const limit_equilibrium::Surface &surface,
                                const limit_equilibrium::Method   method,
                                const unsigned int                n_slices,
                                SearchedSurface                  &s);

    /**
     * The contact-K refinement of the non-circular stage
     * (surface_search_refinement.cc): from the polyline of lowest certified
     * contact K in @p result, each interior vertex moved in turn by -/+ a
     * step along the normal of the chord between its neighbours, the move
     * snapped onto the layer lines within @p snap_distance, screened for
     * admissibility as every polyline (screen_polyline()) and evaluated by
     * the contact method; a move is kept when its contact K is certified
     * and lower. The step starts at @p first_step and is halved after a
     * sweep of the vertices without a kept move, down to @p snap_distance;
     * at most @p budget contact evaluations. Appends every candidate to
     * @p result (stage "polyline contact refined") with one line each on
     * @p brief, and sets result.polyline_refinement.
     */
    void
    refine_polyline_by_contact(const parameters::Parameters     &parameters,
                               const limit_equilibrium::Section &section,
                               const double                      first_step,
                               const double                      snap_distance,
                               const unsigned int                budget,
                               const std::string                &scratch,
                               SurfaceSearchResult              &result,
                               std::ostream                     &brief);

    /**
     * K of the surface of @p s (its circle or polyline) by the contact
     * method on a model of its own: @p base with that surface and the
     * screening mesh size of @p settings, its mesh written into @p scratch
     * only, no output files. Sets contact_K (NaN unless certified),
     * certified, status and contact_seconds of @p s; never throws.
     */
    void
    evaluate_contact(const parameters::Parameters  &base,
                     const SurfaceSearchParameters &settings,
                     const std::string             &scratch,
                     SearchedSurface               &s);

    /** "polyline of n vertices from (x, y) to (x, y)": the screen's words. */
    std::string
    polyline_words(const std::vector<dealii::Point<2>> &line);

    /**
     * The screen's words for the contact evaluation of @p s: "K = 1.2345"
     * (or its status where K is not certified), then the limit equilibrium
     * factor by @p method_key and the evaluation's time in parentheses.
     */
    std::string
    contact_outcome_words(const SearchedSurface &s,
                          const std::string     &method_key);

    /**
     * @p parameters with the sliding surface @p polyline (Geometry/Slope),
     * its mass cut into blocks as Surface search/Non-circular interslices
     * asks: the blocks 'sliding mass i' and interfaces 'sliding surface i'
     * copy 'sliding mass' and 'sliding surface', the 'interslice i' the
     * sliding surface's strength, reduced by K and not summed in K.
     */
    void
    use_polyline(parameters::Parameters              &parameters,
                 const std::vector<dealii::Point<2>> &polyline);

    /**
     * The screening of one circle on @p section: whether it is a sliding
     * surface of the model (it cuts the ground, its ends within the
     * ground's x range, above @p base_elevation, its centre above the
     * ground it cuts, at least Minimum depth deep) and, if so, the factor of
     * the screening method of @p settings.
     */
    SearchedSurface
    screen_circle(const limit_equilibrium::Section &section,
                  const double                      base_elevation,
                  const dealii::Point<2>           &centre,
                  const double                      radius,
                  const SurfaceSearchParameters    &settings);

    /** The first words of a candidate's status, to count skipped ones by
     * reason. */
    std::string
    skip_reason(const std::string &status);

    /**
     * Whether the circle (x_c, y_c, R) lies in the search region of
     * @p settings: its centre in the grid's rectangle and, by tangent
     * elevations, its lowest point between the lowest and highest tangent.
     * The refinements stay inside it.
     */
    bool
    inside_search_region(const SurfaceSearchParameters &settings,
                         const std::array<double, 3>   &circle);

    /** Whether the circle lies on the edge of the search region. */
    bool
    on_search_region_edge(const SurfaceSearchParameters &settings,
                          const std::array<double, 3>   &circle);

    /**
     * The work of the search's grid, from its parameters alone: circles
     * times slices at the screening's measured time per slice, and the
     * memory of every circle's record (parameters/work_estimate.h).
     */
    parameters::WorkEstimate
    search_work_estimate(const SurfaceSearchParameters &settings);

    /**
     * The limit-equilibrium part of the search, no model needed: the grid
     * of @p settings, then a pattern search around its minimum. Throws a
     * one-sentence error naming the entry when the grid gives no valid
     * surface or lies outside the model.
     */
    SurfaceSearchResult
    screen_surfaces(const limit_equilibrium::Section &section,
                    const double                      base_elevation,
                    const SurfaceSearchParameters    &settings);

    /**
     * The whole search on the model of @p parameters (slope generator,
     * circular surface): the screening, then up to Maximum contact
     * evaluations models solved by the contact method (each its own mesh,
     * no output files) in @p scratch, a folder it makes and removes. Sets
     * @p parameters' circle to the critical one. One line per stage and per
     * contact evaluation on @p brief.
     */
    SurfaceSearchResult
    search_critical_surface(parameters::Parameters &parameters,
                            const std::string      &scratch,
                            std::ostream           &brief);

    /**
     * summary.json's "surface_search", with the critical circle's factors
     * by every method taken from the run's own @p summary (which describes
     * the critical circle at the model's mesh size).
     */
    nlohmann::json
    to_json(const SurfaceSearchResult &result, const nlohmann::json &summary);

    /**
     * After the run on the critical circle: search.csv and
     * critical_surface.prm in @p directory, and "surface_search" added to
     * @p summary and to its summary.json there.
     */
    void
    write_surface_search(const SurfaceSearchResult &result,
                         const std::string         &directory,
                         nlohmann::json            &summary);
  } // namespace analyses
} // namespace fdem
