// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/cases/gmsh_2d.h>
#include <fdem/geometry/cases/slope.h>
#include <fdem/geometry/cases/slope_interslices.h>
#include <fdem/geometry/gmsh_mesh.h>
#include <fdem/parameters/numbers.h>

#include <deal.II/base/exceptions.h>

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace fdem
{
  namespace geometry
  {
    namespace
    {
      bool
      x_increases(const std::vector<Point<2>> &points, const bool strictly)
      {
        for (unsigned int i = 1; i < points.size(); ++i)
          if (points[i][0] < points[i - 1][0] ||
              (strictly && points[i][0] == points[i - 1][0]))
            return false;
        return true;
      }


      /** Whether @p p lies on or above the ground, or outside its x range. */
      bool
      on_or_above_ground(const std::vector<Point<2>> &ground, const Point<2> &p)
      {
        if (p[0] <= ground.front()[0] || p[0] >= ground.back()[0])
          return true;
        const double length = ground.back()[0] - ground.front()[0];
        return p[1] >=
               case_input::polyline_elevation(ground, p[0]) - 1e-10 * length;
      }



      std::vector<int>
      boundary_curves(const int surface)
      {
        gmsh::vectorpair boundary;
        gmsh::model::getBoundary({{2, surface}}, boundary, false, false, false);
        std::vector<int> curves;
        for (const auto &curve : boundary)
          curves.push_back(curve.second);
        std::sort(curves.begin(), curves.end());
        return curves;
      }
    } // namespace



    void
    Slope::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Slope");
      {
        prm.declare_entry("Ground surface",
                          "0,25; 10,25; 30,35; 50,35",
                          case_input::point_list_pattern(2),
                          "Ground surface as points 'x,y; x,y; ...' from "
                          "left to right (m). The model is this polyline "
                          "closed down to Base elevation.");
        prm.declare_entry("Base elevation",
                          "20",
                          Patterns::Double(),
                          "Elevation y of the bottom of the model (m).");
        prm.declare_entry(
          "Sliding surface",
          "circular",
          Patterns::Selection("circular|polyline"),
          "Shape of the sliding surface. The sliding mass is the part of "
          "the model inside the circle, or above the polyline.");
        prm.declare_entry("Circle centre",
                          "19.61, 46.32",
                          Patterns::List(Patterns::Double(), 2, 2, ","),
                          "Centre 'x,y' of the circular sliding surface (m).");
        prm.declare_entry("Circle radius",
                          "21.32",
                          Patterns::Double(0),
                          "Radius of the circular sliding surface (m).");
        prm.declare_entry(
          "Sliding surface polyline",
          "",
          case_input::point_list_pattern(0),
          "Polyline sliding surface as points 'x,y; x,y; ...' with "
          "non-decreasing x (m). Its first and last points lie on or above "
          "the ground surface; the parts above the ground are cut off.");
        prm.declare_entry("Mesh size",
                          "1.0",
                          Patterns::Double(0),
                          "Element size away from the sliding surface (m).");
        prm.declare_entry("Mesh size on sliding surface",
                          "0",
                          Patterns::Double(0),
                          "Element size on the sliding surface (m); 0 means "
                          "equal to Mesh size.");
        prm.declare_entry(
          "Interslice surfaces",
          "none",
          Patterns::Selection("none|vertical|bisector|inclination"),
          "Polyline only: cut the sliding mass into blocks 'sliding mass 1', "
          "'sliding mass 2', ... (left to right) by straight interslice "
          "surfaces from each interior vertex of the polyline up to the "
          "ground: vertical, along the bisector of the angle between the two "
          "segments, or at the angles of Interslice inclinations. Face groups "
          "'sliding surface i' (under block i) and 'interslice i' (between "
          "blocks i and i+1). 'none' keeps one block, 'sliding mass', on "
          "'sliding surface'.");
        prm.declare_entry(
          "Interslice inclinations",
          "",
          Patterns::List(
            Patterns::Double(0, 180), 0, Patterns::List::max_int_value, ","),
          "With Interslice surfaces = inclination: one angle per interior "
          "vertex of the polyline, in degrees from the horizontal measured "
          "counterclockwise (90: vertical; below 90 the interslice leans to "
          "the right, +x), comma-separated.");
        prm.declare_entry(
          "Tension crack depth",
          "0",
          Patterns::Double(0),
          "Polyline only: depth (m) of a vertical tension crack at the crest "
          "end of the sliding surface (the end where the ground is higher), "
          "where the sliding surface lies this deep below the ground; the "
          "crack replaces the sliding surface beyond it. Face group 'tension "
          "crack', a free face of both blocks (not an interface), loaded "
          "with the pressure of the water in it (Tension crack water "
          "depth). 0: no crack.");
        prm.declare_entry(
          "Tension crack water depth",
          "0",
          Patterns::Double(0),
          "Height (m) of the water in the tension crack above its bottom, "
          "at most the crack depth. Both faces of the crack carry its "
          "hydrostatic pressure, Water/Unit weight of water times the depth "
          "below the water level (the mesh gets a node there, at the "
          "pressure's kink); the crack's face group then takes no boundary "
          "Pressure. 0: a dry crack.");
        case_input::declare_element_shape_2d(
          prm,
          "quadrilaterals (FE_Q elements; Gmsh's "
          "triangles of twice the size recombined and subdivided), or "
          "Gmsh's Frontal-Delaunay triangles of the size itself "
          "(FE_SimplexP).");
        declare_layer_parameters(prm);
      }
      prm.leave_subsection();
    }



    void
    Slope::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Slope");
      {
        ground_surface  = case_input::parse_points(prm.get("Ground surface"));
        base_elevation  = prm.get_double("Base elevation");
        sliding_surface = (prm.get("Sliding surface") == "circular") ?
                            SlidingSurface::circular :
                            SlidingSurface::polyline;
        circle_centre   = case_input::parse_point(prm.get("Circle centre"));
        circle_radius   = prm.get_double("Circle radius");
        sliding_surface_polyline =
          case_input::parse_points(prm.get("Sliding surface polyline"));
        mesh_size = prm.get_double("Mesh size");
        mesh_size_on_sliding_surface =
          prm.get_double("Mesh size on sliding surface");
        if (mesh_size_on_sliding_surface == 0)
          mesh_size_on_sliding_surface = mesh_size;
        element_shape                 = case_input::parse_element_shape(prm);
        const std::string interslices = prm.get("Interslice surfaces");
        interslice_surfaces =
          interslices == "vertical"    ? Interslices::vertical :
          interslices == "bisector"    ? Interslices::bisector :
          interslices == "inclination" ? Interslices::inclination :
                                         Interslices::none;
        interslice_inclinations.clear();
        for (const std::string &angle :
             Utilities::split_string_list(prm.get("Interslice inclinations"),
                                          ','))
          interslice_inclinations.push_back(parameters::finite_number(angle));
        tension_crack_depth       = prm.get_double("Tension crack depth");
        tension_crack_water_depth = prm.get_double("Tension crack water depth");
        parse_layer_parameters(prm);
      }
      prm.leave_subsection();
    }



    void
    Slope::validate() const
    {
      const std::string path   = "Geometry/Slope/";
      const auto       &ground = ground_surface;
      case_input::require(x_increases(ground, true),
                          path +
                            "Ground surface: the x coordinates must increase "
                            "from left to right.");
      case_input::require(
        std::all_of(ground.begin(),
                    ground.end(),
                    [&](const Point<2> &p) { return base_elevation < p[1]; }),
        path + "Base elevation: must lie below every point of the "
               "ground surface.");
      case_input::require(mesh_size > 0, path + "Mesh size: must be positive.");
      case_input::require(tension_crack_water_depth <= tension_crack_depth,
                          path + "Tension crack water depth: must not exceed "
                                 "Tension crack depth.");
      if (sliding_surface == SlidingSurface::circular)
        {
          case_input::require(circle_radius > 0,
                              path + "Circle radius: must be positive.");
          case_input::require(
            interslice_surfaces == Interslices::none,
            path + "Interslice surfaces: only a polyline sliding surface "
                   "has interior vertices to cut from; use 'none' with "
                   "'circular' (a circle admits a rigid rotation).");
          case_input::require(tension_crack_depth == 0,
                              path + "Tension crack depth: only with a "
                                     "polyline sliding surface; use 0.");
        }
      else
        {
          const auto       &line = sliding_surface_polyline;
          const std::string name = path + "Sliding surface polyline: ";
          case_input::require(line.size() >= 2,
                              name + "needs at least two points when Sliding "
                                     "surface is 'polyline'.");
          case_input::require(x_increases(line, false) &&
                                line.back()[0] > line.front()[0],
                              name +
                                "the x coordinates must not decrease from left "
                                "to right.");
          case_input::require(on_or_above_ground(ground, line.front()) &&
                                on_or_above_ground(ground, line.back()),
                              name + "its first and last points must lie on or "
                                     "above the ground surface.");
          slope_interslices::slope_cuts(*this); // throws on bad cuts
        }
      validate_layers();
    }



    MeshDescription<2>
    make_slope_mesh(const Slope &slope)
    {
      const std::string name = "Geometry/Slope";
      const std::string not_separated =
        name + ": the sliding surface does not separate a sliding mass from "
               "the foundation.";
      const bool polyline =
        slope.sliding_surface == Slope::SlidingSurface::polyline;
      const slope_interslices::Cuts cuts =
        polyline ? slope_interslices::slope_cuts(slope) :
                   slope_interslices::Cuts();
      GmshSession session;
      gmsh::model::add("slope");

      const std::vector<Point<2>> &ground = slope.ground_surface;
      const double                 x_min  = ground.front()[0];
      const double                 x_max  = ground.back()[0];
      double                       y_max  = ground.front()[1];
      for (const Point<2> &p : ground)
        y_max = std::max(y_max, p[1]);

      int              mass = 0, foundation = 0;
      std::vector<int> masses;
      GmshSession::run(name + ": Gmsh could not build the model", [&]() {
        std::vector<Point<2>> outline = ground;
        outline.emplace_back(x_max, slope.base_elevation);
        outline.emplace_back(x_min, slope.base_elevation);
        const int domain = gmsh_2d::add_occ_polygon(outline);

        // The tool is the region that the sliding mass lies in: the disk,
        // or everything above the polyline.
        int tool = 0;
        if (slope.sliding_surface == Slope::SlidingSurface::circular)
          tool = gmsh::model::occ::addDisk(slope.circle_centre[0],
                                           slope.circle_centre[1],
                                           0,
                                           slope.circle_radius,
                                           slope.circle_radius);
        else
          {
            for (const Point<2> &p : slope.sliding_surface_polyline)
              y_max = std::max(y_max, p[1]);
            tool = gmsh_2d::add_occ_polygon(
              slope_interslices::region_above(cuts, y_max + (x_max - x_min)));
          }

        gmsh::vectorpair              mass_pieces, pieces;
        std::vector<gmsh::vectorpair> origin;
        gmsh::model::occ::intersect(
          {{2, domain}}, {{2, tool}}, mass_pieces, origin, -1, false, true);
        AssertThrow(mass_pieces.size() == 1, ExcMessage(not_separated));
        // Fragmenting makes the curve between the two parts shared.
        gmsh::model::occ::fragment({{2, domain}}, mass_pieces, pieces, origin);
        gmsh::model::occ::synchronize();
        AssertThrow(pieces.size() == 2 && origin[1].size() == 1,
                    ExcMessage(not_separated));
        mass = origin[1][0].second;
        foundation =
          (pieces[0].second == mass) ? pieces[1].second : pieces[0].second;
        // The one step that cuts the sliding mass into blocks.
        masses = slope_interslices::cut_sliding_mass(mass, foundation, cuts);
      });

      // Curves of two surfaces are internal: between a block of the mass and
      // the foundation the sliding surface (or the crack), between two
      // blocks an interslice. The outer boundary is sorted by its bounding
      // box.
      std::vector<int> surfaces = masses;
      surfaces.push_back(foundation);
      std::vector<std::vector<int>> curves_of;
      for (const int s : surfaces)
        curves_of.push_back(boundary_curves(s));
      const unsigned int            n_blocks = masses.size();
      std::vector<std::vector<int>> sliding(n_blocks), interslices(n_blocks);
      std::vector<int> all_internal, ground_curves, left, right, bottom;
      const double     tolerance =
        1e-6 * (x_max - x_min + y_max - slope.base_elevation);
      bool             mass_on_ground = false;
      std::vector<int> all_curves;
      for (const auto &curves : curves_of)
        all_curves.insert(all_curves.end(), curves.begin(), curves.end());
      std::sort(all_curves.begin(), all_curves.end());
      all_curves.erase(std::unique(all_curves.begin(), all_curves.end()),
                       all_curves.end());
      for (const int curve : all_curves)
        {
          std::vector<unsigned int> on;
          for (unsigned int s = 0; s < surfaces.size(); ++s)
            if (std::binary_search(curves_of[s].begin(),
                                   curves_of[s].end(),
                                   curve))
              on.push_back(s);
          if (on.size() == 2)
            {
              all_internal.push_back(curve);
              if (on[1] == n_blocks)
                sliding[on[0]].push_back(curve);
              else
                interslices[std::min(on[0], on[1])].push_back(curve);
              continue;
            }
          double x0, y0, z0, x1, y1, z1;
          gmsh::model::getBoundingBox(1, curve, x0, y0, z0, x1, y1, z1);
          if (x1 < x_min + tolerance)
            left.push_back(curve);
          else if (x0 > x_max - tolerance)
            right.push_back(curve);
          else if (y1 < slope.base_elevation + tolerance)
            bottom.push_back(curve);
          else
            {
              ground_curves.push_back(curve);
              mass_on_ground |= on[0] < n_blocks;
            }
        }
      std::vector<int> crack;
      for (auto &curves : sliding)
        {
          const std::vector<int> c =
            slope_interslices::take_crack_curves(curves, cuts, tolerance);
          crack.insert(crack.end(), c.begin(), c.end());
          AssertThrow(!curves.empty(), ExcMessage(not_separated));
        }
      AssertThrow(mass_on_ground, ExcMessage(not_separated));

      for (unsigned int b = 0; b + 1 < n_blocks; ++b)
        AssertThrow(!interslices[b].empty(),
                    ExcMessage(name + "/Interslice surfaces: blocks " +
                               std::to_string(b + 1) + " and " +
                               std::to_string(b + 2) +
                               " of the sliding mass do not meet."));

      // Soil layers (slope_layers.cc): every part split along the layer
      // boundaries, one material region per layer material.
      std::vector<std::vector<int>> mass_surfaces(n_blocks);
      for (unsigned int b = 0; b < n_blocks; ++b)
        mass_surfaces[b] = {masses[b]};
      std::vector<int>                foundation_surfaces{foundation};
      std::vector<std::vector<int> *> surface_groups{&foundation_surfaces};
      std::vector<std::vector<int> *> curve_groups{
        &crack, &ground_curves, &left, &right, &bottom};
      for (unsigned int b = 0; b < n_blocks; ++b)
        {
          surface_groups.push_back(&mass_surfaces[b]);
          curve_groups.push_back(&sliding[b]);
          curve_groups.push_back(&interslices[b]);
        }
      split_into_layers(slope, surface_groups, curve_groups);
      // The mesh is refined along the curves inside the model, as split.
      all_internal = crack;
      for (unsigned int b = 0; b < n_blocks; ++b)
        {
          all_internal.insert(all_internal.end(),
                              sliding[b].begin(),
                              sliding[b].end());
          all_internal.insert(all_internal.end(),
                              interslices[b].begin(),
                              interslices[b].end());
        }

      const auto numbered = [n_blocks](const std::string &what,
                                       const unsigned int b) {
        return n_blocks == 1 ? what : what + " " + std::to_string(b + 1);
      };
      for (unsigned int b = 0; b < n_blocks; ++b)
        add_physical_group(2, mass_surfaces[b], numbered("sliding mass", b));
      add_physical_group(2, foundation_surfaces, "foundation");
      for (unsigned int b = 0; b < n_blocks; ++b)
        add_physical_group(1, sliding[b], numbered("sliding surface", b));
      for (unsigned int b = 0; b + 1 < n_blocks; ++b)
        add_physical_group(1, interslices[b], numbered("interslice", b));
      if (!crack.empty())
        add_physical_group(1, crack, "tension crack");
      add_physical_group(1, ground_curves, "ground");
      add_physical_group(1, left, "left");
      add_physical_group(1, right, "right");
      add_physical_group(1, bottom, "bottom");

      GmshSession::run(name + ": Gmsh could not mesh the model", [&]() {
        const bool triangles = slope.element_shape == ElementShape::simplex;
        gmsh_2d::set_size_field(all_internal,
                                slope.mesh_size_on_sliding_surface,
                                slope.mesh_size,
                                0,
                                !triangles);
        if (triangles)
          gmsh_2d::set_triangle_options();
        else
          gmsh_2d::set_unstructured_quad_options();
        gmsh::model::mesh::generate(2);
      });
      MeshDescription<2> description =
        extract_current_gmsh_model<2>(name, slope.layers);
      // The crack's water pushes on both of its faces up to its level.
      if (!crack.empty() && slope.tension_crack_water_depth > 0)
        description.standing_water["tension crack"] =
          Point<2>(cuts.crack_bottom[0], cuts.crack_water_level);
      return description;
    }
  } // namespace geometry
} // namespace fdem
