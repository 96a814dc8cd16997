// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/limit_equilibrium_parameters.h>
#include <fdem/analyses/surface_search_parameters.h>
#include <fdem/parameters/numbers.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cmath>

namespace fdem
{
  namespace analyses
  {
    using namespace dealii;

    namespace
    {
      const std::string path = "Surface search/";

      /** "x, y" into a point, or throws naming @p entry. */
      Point<2>
      parse_xy(const std::string &text, const std::string &entry)
      {
        const std::vector<std::string> xy =
          Utilities::split_string_list(text, ',');
        AssertThrow(xy.size() == 2,
                    ExcMessage(path + entry +
                               ": expected 'x, y' (two numbers), not '" + text +
                               "'."));
        return Point<2>(parameters::finite_number(xy[0]),
                        parameters::finite_number(xy[1]));
      }

      /**
       * "y1, y2, ..." (a list) or "from : to : count" (a range of count
       * equally spaced values), or throws naming the entry.
       */
      std::vector<double>
      elevations(const std::string &text)
      {
        const std::string   entry = path + "Tangent elevations";
        std::vector<double> values;
        if (text.find(':') != std::string::npos)
          {
            const std::vector<std::string> parts =
              Utilities::split_string_list(text, ':');
            AssertThrow(parts.size() == 3,
                        ExcMessage(entry +
                                   ": a range is 'from : to : count', not '" +
                                   text + "'."));
            const double from  = parameters::finite_number(parts[0]);
            const double to    = parameters::finite_number(parts[1]);
            const int    count = Utilities::string_to_int(parts[2]);
            AssertThrow(
              count >= 1 && count <= 10000 && (count == 1 || from != to),
              ExcMessage(entry +
                         ": a range needs a count from 1 to 10000 and two "
                         "different ends, not '" +
                         text + "'."));
            for (int i = 0; i < count; ++i)
              values.push_back(
                count == 1 ? from : from + (to - from) * i / (count - 1));
          }
        else
          for (const std::string &value :
               Utilities::split_string_list(text, ','))
            values.push_back(parameters::finite_number(value));
        for (const double v : values)
          AssertThrow(std::isfinite(v),
                      ExcMessage(entry + ": not a number in '" + text + "'."));
        return values;
      }
    } // namespace

    void
    SurfaceSearchParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Surface search");
      prm.declare_entry(
        "Enabled",
        "false",
        Patterns::Bool(),
        "Search for the critical circle before the run (slope generator with a "
        "circular sliding surface only): circles from a grid of centres, screened "
        "by limit equilibrium, refined around the minimum, the best evaluated by "
        "the contact method; the run then computes K on the critical circle at "
        "the model's mesh size, and the circle given in Geometry/Slope is only "
        "replaced. See doc/surface_search.md.");
      prm.declare_entry(
        "Centre grid",
        "0, 0; 0, 0",
        Patterns::Anything(),
        "Lower-left and upper-right corners of the rectangle of circle centres, "
        "'x1, y1; x2, y2' (length).");
      prm.declare_entry(
        "Centre grid counts",
        "10, 10",
        Patterns::List(Patterns::Integer(1, 1000), 2, 2, ","),
        "Number of centres along x and along y, each from 1 to 1000 "
        "(dimensionless); 1 puts the centres on the lower-left corner's line.");
      prm.declare_entry(
        "Radii",
        "tangent elevations",
        Patterns::Selection("tangent elevations|through point"),
        "How the radii of each centre are chosen: 'tangent elevations', one circle "
        "touching each horizontal line y = y_t (radius y_c - y_t); 'through point', "
        "one circle through Point on circles.");
      prm.declare_entry(
        "Tangent elevations",
        "",
        Patterns::Anything(),
        "Elevations y_t of the circles' lowest points (length): a list 'y1, y2, "
        "...' or a range 'from : to : count' of equally spaced values.");
      prm.declare_entry(
        "Point on circles",
        "0, 0",
        Patterns::Anything(),
        "The point 'x, y' every circle passes through when Radii is 'through "
        "point' (length), e.g. the toe.");
      prm.declare_entry(
        "Minimum depth",
        "0",
        Patterns::Double(0),
        "Circles whose greatest depth below the ground is less than this are "
        "skipped (length); 0: none. On a slope without cohesion the critical "
        "circle is ever shallower (it tends to the infinite-slope plane): this "
        "keeps it a sliding mass that can be meshed.");
      prm.declare_entry(
        "Method",
        "Bishop",
        Patterns::Selection(method_name_selection()),
        "The limit-equilibrium method of the screening (see Limit "
        "equilibrium/Methods); Bishop's simplified method is the usual one for "
        "circles.");
      prm.declare_entry(
        "Number of slices",
        "50",
        Patterns::Integer(1, 100000),
        "Slices of each screened circle, at least 10 (dimensionless); the critical "
        "circle's factors are then recomputed with Limit equilibrium/Number of "
        "slices.");
      prm.declare_entry(
        "Refinement tolerance",
        "1e-3",
        Patterns::Double(1e-9, 1),
        "The pattern search around the grid's minimum stops when its steps in "
        "centre and radius are below this fraction of the grid spacing "
        "(dimensionless).");
      prm.declare_entry(
        "Maximum contact evaluations",
        "10",
        Patterns::Integer(0, 100000),
        "Models solved by the contact method during the search (each its own mesh "
        "and safety-factor iteration), the best screened circles first, then a "
        "local pattern search on the contact K (dimensionless count); 0: the "
        "search is by limit equilibrium alone. With Non-circular, Non-circular "
        "contact candidates and Non-circular contact refinements of them are "
        "kept for the polylines.");
      prm.declare_entry(
        "Contact candidates",
        "3",
        Patterns::Integer(1, 1000),
        "How many of the best distinct screened circles are evaluated by the "
        "contact method before its local refinement (dimensionless count).");
      prm.declare_entry(
        "Screening mesh size",
        "0",
        Patterns::Double(0),
        "Element size of the contact evaluations during the search (length; the "
        "size on the sliding surface is scaled alike); 0: Geometry/Slope/Mesh "
        "size. The critical circle is run at the model's own mesh size.");
      prm.declare_entry(
        "Non-circular",
        "false",
        Patterns::Bool(),
        "After the circles, search for a non-circular (polyline) surface: the "
        "best circle made into a polyline of Polyline vertices, its vertices "
        "optimised by limit equilibrium (Non-circular method), the best "
        "polylines evaluated by the contact method; the run is then on the "
        "surface, circle or polyline, with the lowest certified contact K. See "
        "doc/surface_search.md.");
      prm.declare_entry(
        "Polyline vertices",
        "7",
        Patterns::Integer(3, 100),
        "Vertices of the non-circular search's polylines, their two ends on the "
        "ground included, from 3 to 100 (dimensionless count).");
      prm.declare_entry(
        "Non-circular method",
        "Spencer",
        Patterns::Selection(method_name_selection()),
        "The limit-equilibrium method of the non-circular search (see Limit "
        "equilibrium/Methods); not Bishop, whose simplified method is for "
        "circles. Spencer and Morgenstern-Price satisfy every equilibrium "
        "condition.");
      prm.declare_entry(
        "Concave upward",
        "true",
        Patterns::Bool(),
        "Whether the polylines must be concave upward (their segments' slopes "
        "not decreasing from left to right), as a rigid mass's sliding surface "
        "usually is; false also admits convex kinks.");
      prm.declare_entry(
        "Non-circular contact candidates",
        "2",
        Patterns::Integer(0, 1000),
        "How many of the Maximum contact evaluations are kept for the best "
        "polylines of the non-circular search, the rest going to the circles "
        "(dimensionless count); 0: the polylines are not evaluated by the contact "
        "method.");
      prm.declare_entry(
        "Non-circular contact refinements",
        "0",
        Patterns::Integer(0, 1000),
        "How many of the Maximum contact evaluations are kept for the local "
        "refinement of the best polyline by its contact K, after the "
        "Non-circular contact candidates (dimensionless count): from the "
        "polyline of lowest certified contact K, each interior vertex moved in "
        "turn along the normal of the chord between its neighbours, by steps "
        "from half the element size on the sliding surface down to a tenth of "
        "it; a move is kept when the polyline stays admissible and its contact "
        "K is certified and lower. 0: the polylines' vertices are placed by "
        "limit equilibrium alone.");
      prm.declare_entry(
        "Non-circular interslices",
        "none",
        Patterns::Selection("none|vertical|bisector"),
        "How the sliding mass of a polyline evaluated by the contact method is "
        "cut into blocks (Geometry/Slope/Interslice surfaces), and of the run "
        "when a polyline is critical: 'none' (one block), 'vertical' or "
        "'bisector' cuts from each interior vertex up to the ground, the "
        "interslices with the sliding surface's strength reduced by K and not "
        "summed in K.");
      prm.leave_subsection();
    }

    void
    SurfaceSearchParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Surface search");
      enabled = prm.get_bool("Enabled");
      const std::vector<std::string> corners =
        Utilities::split_string_list(prm.get("Centre grid"), ';');
      AssertThrow(
        corners.size() == 2,
        ExcMessage(path +
                   "Centre grid: expected two corners 'x1, y1; x2, y2', not '" +
                   prm.get("Centre grid") + "'."));
      grid_lower                    = parse_xy(corners[0], "Centre grid");
      grid_upper                    = parse_xy(corners[1], "Centre grid");
      const std::vector<int> counts = Utilities::string_to_int(
        Utilities::split_string_list(prm.get("Centre grid counts")));
      n_x   = counts[0];
      n_y   = counts[1];
      radii = prm.get("Radii") == "through point" ? Radii::through_point :
                                                    Radii::tangent_elevations;
      tangent_elevations = elevations(prm.get("Tangent elevations"));
      point    = parse_xy(prm.get("Point on circles"), "Point on circles");
      method   = method_from_name(prm.get("Method"));
      n_slices = prm.get_integer("Number of slices");
      refinement_tolerance    = prm.get_double("Refinement tolerance");
      max_contact_evaluations = prm.get_integer("Maximum contact evaluations");
      n_contact_candidates    = prm.get_integer("Contact candidates");
      screening_mesh_size     = prm.get_double("Screening mesh size");
      minimum_depth           = prm.get_double("Minimum depth");
      non_circular            = prm.get_bool("Non-circular");
      n_polyline_vertices     = prm.get_integer("Polyline vertices");
      polyline_method = method_from_name(prm.get("Non-circular method"));
      concave         = prm.get_bool("Concave upward");
      n_polyline_contact_candidates =
        prm.get_integer("Non-circular contact candidates");
      n_polyline_contact_refinements =
        prm.get_integer("Non-circular contact refinements");
      const std::string interslices = prm.get("Non-circular interslices");
      polyline_interslices = interslices == "vertical" ? Interslices::vertical :
                             interslices == "bisector" ? Interslices::bisector :
                                                         Interslices::none;
      prm.leave_subsection();
      if (!enabled)
        return;
      AssertThrow(n_slices >= min_n_slices,
                  ExcMessage(path + "Number of slices: at least " +
                             std::to_string(min_n_slices) +
                             " are needed, not " + std::to_string(n_slices) +
                             "."));
      AssertThrow(
        grid_lower[0] <= grid_upper[0] && grid_lower[1] <= grid_upper[1] &&
          (n_x == 1 || grid_lower[0] < grid_upper[0]) &&
          (n_y == 1 || grid_lower[1] < grid_upper[1]),
        ExcMessage(
          path + "Centre grid: the first corner must be the lower-left one and "
                 "the rectangle must have a width and a height where it has "
                 "more than one centre."));
      AssertThrow(
        !non_circular || polyline_method != limit_equilibrium::Method::bishop,
        ExcMessage(path +
                   "Non-circular method: Bishop's simplified method is for "
                   "circles; use Spencer, Morgenstern-Price or Janbu for the "
                   "polylines."));
      AssertThrow(!non_circular || n_polyline_vertices >= min_polyline_vertices,
                  ExcMessage(path + "Polyline vertices: at least " +
                             std::to_string(min_polyline_vertices) +
                             " are needed, not " +
                             std::to_string(n_polyline_vertices) + "."));
      AssertThrow(
        radii == Radii::through_point || !tangent_elevations.empty(),
        ExcMessage(path +
                   "Tangent elevations: give at least one elevation (a list or "
                   "'from : to : count') when Radii is 'tangent elevations'."));
    }
  } // namespace analyses
} // namespace fdem
