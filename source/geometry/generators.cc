// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/generators.h>
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
       * Element size @p size_near on @p curves and up to @p fine_distance
       * from them, then growing linearly with the distance to @p size_far.
       * The growth rate of 0.25 keeps neighbouring elements within about 25%
       * of each other's size. The sizes are those of the final mesh: for
       * quadrilaterals Gmsh meshes at twice the size and then subdivides
       * (see set_unstructured_quad_options()); triangles (@p subdivided
       * false) are meshed at the size itself.
       */
      void
      set_size_field(const std::vector<int> &curves,
                     const double            size_near,
                     const double            size_far,
                     const double            fine_distance = 0,
                     const bool              subdivided    = true)
      {
        namespace field       = gmsh::model::mesh::field;
        const double growth   = 0.25;
        const double factor   = subdivided ? 2 : 1;
        const double near     = factor * size_near;
        const double far      = factor * size_far;
        const int    distance = field::add("Distance");
        field::setNumbers(distance,
                          "CurvesList",
                          std::vector<double>(curves.begin(), curves.end()));
        field::setNumber(distance, "NumPointsPerCurve", 1000);
        const int threshold = field::add("Threshold");
        field::setNumber(threshold, "InField", distance);
        field::setNumber(threshold, "SizeMin", near);
        field::setNumber(threshold, "SizeMax", far);
        const double fine = std::max(0.5 * near, fine_distance);
        field::setNumber(threshold, "DistMin", fine);
        field::setNumber(threshold,
                         "DistMax",
                         fine + std::abs(far - near) / growth);
        field::setAsBackgroundMesh(threshold);
        // Only the field decides, not the points or the curvature.
        gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
      }

      /**
       * Unstructured quadrilaterals, guaranteed: Frontal-Delaunay triangles,
       * merged into quadrilaterals by the Blossom matching where possible,
       * then every element is subdivided (a quadrilateral into 4, a triangle
       * left over into 3 quadrilaterals), which halves the element size.
       * Recombination alone left triangles in the slope; Algorithm 8
       * (Frontal-Delaunay for quads) crashes in Debian's Gmsh 4.8.4.
       */
      void
      set_unstructured_quad_options()
      {
        gmsh::option::setNumber("Mesh.Algorithm", 6);
        gmsh::option::setNumber("Mesh.RecombineAll", 1);
        gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 1);
        gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 1);
      }

      /**
       * Frontal-Delaunay triangles, neither recombined nor subdivided (Gmsh
       * keeps options from one session to the next in a process, so they
       * are set here, not left at their defaults).
       */
      void
      set_triangle_options()
      {
        gmsh::option::setNumber("Mesh.Algorithm", 6);
        gmsh::option::setNumber("Mesh.RecombineAll", 0);
        gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 0);
      }

      /** OpenCASCADE plane surface bounded by the closed polygon @p corners. */
      int
      add_occ_polygon(const std::vector<Point<2>> &corners)
      {
        std::vector<int> points, lines;
        for (const Point<2> &corner : corners)
          points.push_back(gmsh::model::occ::addPoint(corner[0], corner[1], 0));
        for (unsigned int i = 0; i < points.size(); ++i)
          lines.push_back(
            gmsh::model::occ::addLine(points[i],
                                      points[(i + 1) % points.size()]));
        return gmsh::model::occ::addPlaneSurface(
          {gmsh::model::occ::addCurveLoop(lines)});
      }

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
                image[cell.vertices[triangles ? (i == 0 ? 0 : 3 - i) : (i ^ 1u)]];
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



    MeshDescription<2>
    make_slope_mesh(const parameters::GeometryParameters::Slope &slope)
    {
      using Parameters       = parameters::GeometryParameters;
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
        const int domain = add_occ_polygon(outline);

        // The tool is the region that the sliding mass lies in: the disk,
        // or everything above the polyline.
        int tool = 0;
        if (slope.sliding_surface == Parameters::SlidingSurface::circular)
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
            tool = add_occ_polygon(above);
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

      add_physical_group(2, {mass}, "sliding mass");
      add_physical_group(2, {foundation}, "foundation");
      add_physical_group(1, sliding, "sliding surface");
      add_physical_group(1, ground_curves, "ground");
      add_physical_group(1, left, "left");
      add_physical_group(1, right, "right");
      add_physical_group(1, bottom, "bottom");

      GmshSession::run(name + ": Gmsh could not mesh the model", [&]() {
        const bool triangles =
          slope.element_shape ==
          parameters::GeometryParameters::ElementShape::simplex;
        set_size_field(sliding,
                       slope.mesh_size_on_sliding_surface,
                       slope.mesh_size,
                       0,
                       !triangles);
        if (triangles)
          set_triangle_options();
        else
          set_unstructured_quad_options();
        gmsh::model::mesh::generate(2);
      });
      return extract_current_gmsh_model<2>(name);
    }



    MeshDescription<2>
    make_hertz_mesh(const parameters::GeometryParameters::Hertz &hertz)
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
          const bool triangles =
            hertz.element_shape ==
            parameters::GeometryParameters::ElementShape::simplex;
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
          set_size_field(contact_curves,
                         hertz.contact_zone_width / n,
                         hertz.mesh_size,
                         0.5 * hertz.contact_zone_width,
                         !triangles);
          if (triangles)
            set_triangle_options();
          else
            set_unstructured_quad_options();
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



    MeshDescription<2>
    make_inclined_block_mesh(
      const parameters::GeometryParameters::InclinedBlock &inclined_block)
    {
      namespace geo            = gmsh::model::geo;
      const std::string name   = "Geometry/Inclined block";
      const double      angle  = inclined_block.inclination * numbers::PI / 180;
      const double      length = inclined_block.block_length;
      const double      height = inclined_block.block_height;
      const double      overhang  = inclined_block.foundation_overhang;
      const double      thickness = inclined_block.foundation_thickness;
      // The foundation gets elements of the block's size.
      const unsigned int n_along  = inclined_block.n_elements_along_length;
      const unsigned int n_across = inclined_block.n_elements_across_height;
      const unsigned int n_overhang =
        std::max<long>(1, std::lround(overhang / (length / n_along)));
      const unsigned int n_thickness =
        std::max<long>(1, std::lround(thickness / (height / n_across)));

      GmshSession session;
      gmsh::model::add("inclined block");
      GmshSession::run(
        name + ": Gmsh could not build or mesh the model", [&]() {
          // (s, n): coordinates along and normal to the plane.
          const auto point = [&](const double s, const double n) {
            return geo::addPoint(s * std::cos(angle) - n * std::sin(angle),
                                 s * std::sin(angle) + n * std::cos(angle),
                                 0);
          };
          const auto line =
            [](const int from, const int to, const unsigned int n_elements) {
              const int tag = geo::addLine(from, to);
              geo::mesh::setTransfiniteCurve(tag, n_elements + 1);
              return tag;
            };
          // Structured quadrilaterals, or each split into two triangles
          // (transfinite without recombination).
          const bool triangles =
            inclined_block.element_shape ==
            parameters::GeometryParameters::ElementShape::simplex;
          const auto quadrilateral = [&](const std::vector<int> &curves) {
            const int tag = geo::addPlaneSurface({geo::addCurveLoop(curves)});
            geo::mesh::setTransfiniteSurface(tag);
            if (!triangles)
              geo::mesh::setRecombine(2, tag);
            return tag;
          };

          // Foundation top and base, split at the ends of the block.
          const std::vector<double>       s          = {-overhang,
                                                        0,
                                                        length,
                                                        length + overhang};
          const std::vector<unsigned int> n_segments = {n_overhang,
                                                        n_along,
                                                        n_overhang};
          std::vector<int> top_points, base_points, top, base, across;
          for (const double s_i : s)
            {
              top_points.push_back(point(s_i, 0));
              base_points.push_back(point(s_i, -thickness));
              across.push_back(
                line(base_points.back(), top_points.back(), n_thickness));
            }
          std::vector<int> foundation;
          for (unsigned int i = 0; i < 3; ++i)
            {
              top.push_back(
                line(top_points[i], top_points[i + 1], n_segments[i]));
              base.push_back(
                line(base_points[i], base_points[i + 1], n_segments[i]));
              foundation.push_back(
                quadrilateral({base[i], across[i + 1], -top[i], -across[i]}));
            }

          // The block stands on the middle part of the foundation top.
          const int block_top_right = point(length, height);
          const int block_top_left  = point(0, height);
          const int block_right =
            line(top_points[2], block_top_right, n_across);
          const int block_top  = line(block_top_right, block_top_left, n_along);
          const int block_left = line(block_top_left, top_points[1], n_across);
          const int block =
            quadrilateral({top[1], block_right, block_top, block_left});
          geo::synchronize();

          add_physical_group(2, {block}, "block");
          add_physical_group(2, foundation, "foundation");
          add_physical_group(1, {top[1]}, "sliding surface");
          add_physical_group(1, {block_right, block_top, block_left}, "block surface");
          add_physical_group(1, {top[0], top[2]}, "foundation surface");
          add_physical_group(1, base, "foundation base");
          add_physical_group(1, {across[0], across[3]}, "foundation ends");
          if (triangles)
            set_triangle_options();
          gmsh::model::mesh::generate(2);
        });
      return extract_current_gmsh_model<2>(name);
    }
  } // namespace geometry
} // namespace fdem
