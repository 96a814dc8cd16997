// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/cases/gmsh_2d.h>
#include <fdem/geometry/cases/slope.h>
#include <fdem/geometry/gmsh_mesh.h>

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

      /** Elevation of the ground polyline at @p x (inside its x range). */
      double
      ground_elevation(const std::vector<Point<2>> &ground, const double x)
      {
        for (unsigned int i = 1; i < ground.size(); ++i)
          if (x <= ground[i][0])
            {
              const double t =
                (x - ground[i - 1][0]) / (ground[i][0] - ground[i - 1][0]);
              return (1 - t) * ground[i - 1][1] + t * ground[i][1];
            }
        return ground.back()[1];
      }

      /** Whether @p p lies on or above the ground, or outside its x range. */
      bool
      on_or_above_ground(const std::vector<Point<2>> &ground, const Point<2> &p)
      {
        if (p[0] <= ground.front()[0] || p[0] >= ground.back()[0])
          return true;
        const double length = ground.back()[0] - ground.front()[0];
        return p[1] >= ground_elevation(ground, p[0]) - 1e-10 * length;
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
        element_shape = case_input::parse_element_shape(prm);
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
      if (sliding_surface == SlidingSurface::circular)
        case_input::require(circle_radius > 0,
                            path + "Circle radius: must be positive.");
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
      GmshSession session;
      gmsh::model::add("slope");

      const std::vector<Point<2>> &ground = slope.ground_surface;
      const double                 x_min  = ground.front()[0];
      const double                 x_max  = ground.back()[0];
      double                       y_max  = ground.front()[1];
      for (const Point<2> &p : ground)
        y_max = std::max(y_max, p[1]);

      int mass = 0, foundation = 0;
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
            std::vector<Point<2>> above = slope.sliding_surface_polyline;
            for (const Point<2> &p : above)
              y_max = std::max(y_max, p[1]);
            const double top = y_max + (x_max - x_min);
            above.emplace_back(above.back()[0], top);
            above.emplace_back(above.front()[0], top);
            tool = gmsh_2d::add_occ_polygon(above);
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
      });

      // Curves on both parts form the sliding surface; the outer boundary is
      // sorted by its bounding box.
      const std::vector<int> mass_curves       = boundary_curves(mass);
      const std::vector<int> foundation_curves = boundary_curves(foundation);
      std::vector<int>       sliding, outer, ground_curves, left, right, bottom;
      std::set_intersection(mass_curves.begin(),
                            mass_curves.end(),
                            foundation_curves.begin(),
                            foundation_curves.end(),
                            std::back_inserter(sliding));
      std::set_symmetric_difference(mass_curves.begin(),
                                    mass_curves.end(),
                                    foundation_curves.begin(),
                                    foundation_curves.end(),
                                    std::back_inserter(outer));
      const double tolerance =
        1e-6 * (x_max - x_min + y_max - slope.base_elevation);
      bool mass_on_ground = false;
      for (const int curve : outer)
        {
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
              mass_on_ground |= std::binary_search(mass_curves.begin(),
                                                   mass_curves.end(),
                                                   curve);
            }
        }
      AssertThrow(!sliding.empty() && mass_on_ground,
                  ExcMessage(not_separated));

      // Soil layers (slope_layers.cc): every part split along the layer
      // boundaries, one material region per layer material.
      std::vector<int> mass_surfaces{mass}, foundation_surfaces{foundation};
      split_into_layers(slope,
                        {&mass_surfaces, &foundation_surfaces},
                        {&sliding, &ground_curves, &left, &right, &bottom});
      add_physical_group(2, mass_surfaces, "sliding mass");
      add_physical_group(2, foundation_surfaces, "foundation");
      add_physical_group(1, sliding, "sliding surface");
      add_physical_group(1, ground_curves, "ground");
      add_physical_group(1, left, "left");
      add_physical_group(1, right, "right");
      add_physical_group(1, bottom, "bottom");

      GmshSession::run(name + ": Gmsh could not mesh the model", [&]() {
        const bool triangles = slope.element_shape == ElementShape::simplex;
        gmsh_2d::set_size_field(sliding,
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
      return extract_current_gmsh_model<2>(name, slope.layers);
    }
  } // namespace geometry
} // namespace fdem
