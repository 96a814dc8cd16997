// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/cases/gmsh_2d.h>
#include <fdem/geometry/cases/hertz.h>
#include <fdem/geometry/gmsh_mesh.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/grid/grid_tools.h>

#include <gmsh.h>

#include <algorithm>
#include <cmath>

namespace fdem
{
  namespace geometry
  {
    namespace
    {
      /**
       * The 2D mesh @p half (in x >= 0) joined to its mirror image in the
       * axis x = 0: the vertices of the faces of @p axis_group are shared,
       * that group is removed (the axis lies inside the blocks), and every
       * block and every other face group holds its part and its mirror
       * image. The cells of the image are flipped back to positive measure.
       */
      MeshDescription<2>
      join_mirror_image(const MeshDescription<2> &half,
                        const std::string        &axis_group)
      {
        const auto found = std::find(half.face_group_names.begin(),
                                     half.face_group_names.end(),
                                     axis_group);
        Assert(found != half.face_group_names.end(), ExcInternalError());
        const types::boundary_id axis = found - half.face_group_names.begin();

        constexpr unsigned int    none = numbers::invalid_unsigned_int;
        std::vector<unsigned int> image(half.vertices.size(), none);
        for (const auto &face : half.faces)
          if (face.boundary_id == axis)
            for (const unsigned int v : face.vertices)
              image[v] = v;

        MeshDescription<2> full = half;
        for (unsigned int v = 0; v < half.vertices.size(); ++v)
          if (image[v] == none)
            {
              image[v] = full.vertices.size();
              full.vertices.emplace_back(-half.vertices[v][0],
                                         half.vertices[v][1]);
            }

        // Swapping the vertices along the cell's first direction (two
        // corners of a triangle) undoes the change of orientation of the
        // reflection.
        const bool triangles =
          !half.cells.empty() && half.cells[0].vertices.size() == 3;
        for (const auto &cell : half.cells)
          {
            CellData<2> mirrored = cell;
            for (unsigned int i = 0; i < cell.vertices.size(); ++i)
              mirrored.vertices[i] =
                image[cell
                        .vertices[triangles ? (i == 0 ? 0 : 3 - i) : (i ^ 1u)]];
            full.cells.push_back(mirrored);
          }

        full.faces.clear();
        for (const auto &face : half.faces)
          if (face.boundary_id != axis)
            {
              CellData<1> renumbered = face;
              renumbered.boundary_id -= (face.boundary_id > axis);
              full.faces.push_back(renumbered);
              CellData<1> mirrored = renumbered;
              mirrored.vertices[0] = image[face.vertices[1]];
              mirrored.vertices[1] = image[face.vertices[0]];
              full.faces.push_back(mirrored);
            }
        full.face_group_names.erase(full.face_group_names.begin() + axis);

        if (!triangles)
          GridTools::consistently_order_cells(full.cells);
        return full;
      }
    } // namespace



    void
    Hertz::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Hertz");
      {
        prm.declare_entry("Radius",
                          "100",
                          Patterns::Double(0),
                          "Radius of the cylinder (model length unit, "
                          "e.g. mm). The half model holds the lower quarter.");
        prm.declare_entry("Foundation width",
                          "500",
                          Patterns::Double(0),
                          "Width of the foundation from the symmetry axis "
                          "(model length unit).");
        prm.declare_entry("Foundation depth",
                          "500",
                          Patterns::Double(0),
                          "Depth of the foundation (model length unit).");
        prm.declare_entry(
          "Contact zone width",
          "15",
          Patterns::Double(0),
          "Length from the symmetry axis over which the cylinder and the "
          "foundation get nodes at the same x positions (model length "
          "unit); smaller than Radius and Foundation width.");
        prm.declare_entry(
          "Elements in contact zone",
          "60",
          Patterns::Integer(2),
          "Number of equal elements along x in the contact zone on each "
          "side; even, since an all-quadrilateral mesh needs an even number "
          "of edges around each region.");
        prm.declare_entry("Mesh size",
                          "20",
                          Patterns::Double(0),
                          "Element size far from the contact zone (model "
                          "length unit).");
        prm.declare_entry(
          "Full model",
          "false",
          Patterns::Bool(),
          "Model the whole cylinder width (x from -r to r) on a foundation "
          "from -W to W instead of the half model x >= 0; needed for "
          "tangential loads, e.g. Cattaneo-Mindlin partial slip.");
        case_input::declare_element_shape_2d(
          prm,
          "quadrilaterals (FE_Q elements; Gmsh's "
          "triangles of twice the size recombined and subdivided), or "
          "Gmsh's Frontal-Delaunay triangles of the size itself "
          "(FE_SimplexP). Either way the contact zone has Elements in "
          "contact zone element edges on each side.");
      }
      prm.leave_subsection();
    }



    void
    Hertz::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Hertz");
      {
        radius                  = prm.get_double("Radius");
        foundation_width        = prm.get_double("Foundation width");
        foundation_depth        = prm.get_double("Foundation depth");
        contact_zone_width      = prm.get_double("Contact zone width");
        n_contact_zone_elements = prm.get_integer("Elements in contact zone");
        mesh_size               = prm.get_double("Mesh size");
        full_model              = prm.get_bool("Full model");
        element_shape           = case_input::parse_element_shape(prm);
      }
      prm.leave_subsection();
    }



    void
    Hertz::validate() const
    {
      const std::string path = "Geometry/Hertz/";
      case_input::require(radius > 0, path + "Radius: must be positive.");
      case_input::require(foundation_width > 0 && foundation_depth > 0,
                          path +
                            "Foundation width and depth: must be positive.");
      case_input::require(contact_zone_width > 0 &&
                            contact_zone_width < radius &&
                            contact_zone_width < foundation_width,
                          path +
                            "Contact zone width: must be positive and smaller "
                            "than Radius and Foundation width.");
      case_input::require(n_contact_zone_elements % 2 == 0,
                          path +
                            "Elements in contact zone: must be even (an "
                            "all-quadrilateral mesh needs an even number of "
                            "edges around each region).");
      case_input::require(mesh_size > 0, path + "Mesh size: must be positive.");
    }



    MeshDescription<2>
    make_hertz_mesh(const Hertz &hertz)
    {
      namespace geo           = gmsh::model::geo;
      const std::string  name = "Geometry/Hertz";
      const double       r    = hertz.radius;
      const unsigned int n    = hertz.n_contact_zone_elements;
      GmshSession        session;
      gmsh::model::add("hertz");

      std::vector<int> contact_curves;
      GmshSession::run(
        name + ": Gmsh could not build or mesh the model", [&]() {
          const auto point = [](const double x, const double y) {
            return geo::addPoint(x, y, 0);
          };
          // The contact zone: x_i = i Lc / N on both sides. Gmsh meshes with
          // one segment between geometry points at the even x_i and subdivides
          // it at its parametric middle (on the arc not at x_{2k+1}), so all
          // nodes of the zone are put at x_i afterwards. The origin is shared.
          const auto contact_x = [&](const long i) {
            return hertz.contact_zone_width * i / n;
          };
          const auto arc_y = [&](const double x) {
            return r - std::sqrt(r * r - x * x);
          };
          const int        origin     = point(0, 0);
          const int        centre     = point(0, r);
          std::vector<int> arc_points = {origin}, top_points = {origin};
          for (unsigned int i = 2; i <= n; i += 2)
            {
              arc_points.push_back(point(contact_x(i), arc_y(contact_x(i))));
              top_points.push_back(point(contact_x(i), 0));
            }
          std::vector<int> arc_loop, top_loop;
          for (unsigned int k = 0; k < n / 2; ++k)
            {
              arc_loop.push_back(
                geo::addCircleArc(arc_points[k], centre, arc_points[k + 1]));
              top_loop.push_back(
                geo::addLine(top_points[k], top_points[k + 1]));
            }
          const std::vector<int> contact_arcs  = arc_loop,
                                 contact_lines = top_loop;
          contact_curves                       = contact_arcs;
          contact_curves.insert(contact_curves.end(),
                                top_loop.begin(),
                                top_loop.end());

          // Cylinder: arc up to (r, r), top back to the centre, axis down.
          const int arc_end = point(r, r);
          const int cylinder_surface =
            geo::addCircleArc(arc_points.back(), centre, arc_end);
          const int load          = geo::addLine(arc_end, centre);
          const int cylinder_axis = geo::addLine(centre, origin);
          arc_loop.insert(arc_loop.end(),
                          {cylinder_surface, load, cylinder_axis});
          const int cylinder =
            geo::addPlaneSurface({geo::addCurveLoop(arc_loop)});

          // Foundation: top to the right, side, bottom, axis up.
          const int top_end = point(hertz.foundation_width, 0);
          const int bottom_end =
            point(hertz.foundation_width, -hertz.foundation_depth);
          const int bottom_start = point(0, -hertz.foundation_depth);
          const int foundation_surface =
            geo::addLine(top_points.back(), top_end);
          const int foundation_side = geo::addLine(top_end, bottom_end);
          const int bottom          = geo::addLine(bottom_end, bottom_start);
          const int foundation_axis = geo::addLine(bottom_start, origin);
          top_loop.insert(
            top_loop.end(),
            {foundation_surface, foundation_side, bottom, foundation_axis});
          const int foundation =
            geo::addPlaneSurface({geo::addCurveLoop(top_loop)});
          geo::synchronize();

          // Quadrilaterals: one segment, halved by the subdivision;
          // triangles: the two segments themselves.
          const bool triangles = hertz.element_shape == ElementShape::simplex;
          for (const int curve : contact_curves)
            gmsh::model::mesh::setTransfiniteCurve(curve, triangles ? 3 : 2);

          add_physical_group(2, {cylinder}, "cylinder");
          add_physical_group(2, {foundation}, "foundation");
          add_physical_group(1, contact_curves, "contact surface");
          add_physical_group(1, {load}, "load");
          add_physical_group(1, {cylinder_axis, foundation_axis}, "symmetry");
          add_physical_group(1, {bottom}, "bottom");
          add_physical_group(1, {cylinder_surface}, "cylinder surface");
          add_physical_group(1, {foundation_surface}, "foundation surface");
          add_physical_group(1, {foundation_side}, "foundation side");

          // The contact stresses reach about one contact width into both
          // bodies: keep the mesh as fine as the contact zone there, so that
          // refining the contact zone refines where the solution varies.
          gmsh_2d::set_size_field(contact_curves,
                                  hertz.contact_zone_width / n,
                                  hertz.mesh_size,
                                  0.5 * hertz.contact_zone_width,
                                  !triangles);
          if (triangles)
            gmsh_2d::set_triangle_options();
          else
            gmsh_2d::set_unstructured_quad_options();
          gmsh::model::mesh::generate(2);

          for (const int curve : contact_curves)
            {
              const bool on_arc =
                std::count(contact_arcs.begin(), contact_arcs.end(), curve);
              std::vector<std::size_t> nodes;
              std::vector<double>      coordinates, parametric_coordinates;
              gmsh::model::mesh::getNodes(nodes,
                                          coordinates,
                                          parametric_coordinates,
                                          1,
                                          curve,
                                          true,
                                          false);
              for (unsigned int j = 0; j < nodes.size(); ++j)
                {
                  const double x = contact_x(std::lround(
                    coordinates[3 * j] / hertz.contact_zone_width * n));
                  gmsh::model::mesh::setNode(nodes[j],
                                             {x, on_arc ? arc_y(x) : 0, 0},
                                             {});
                }
            }
        });
      // The full model is the half model and its mirror image: the same
      // size field on both sides, the contact zone at x_{-i} = -x_i exactly,
      // and a symmetric mesh for symmetric loads.
      const MeshDescription<2> half = extract_current_gmsh_model<2>(name);
      return hertz.full_model ? join_mirror_image(half, "symmetry") : half;
    }
  } // namespace geometry
} // namespace fdem
