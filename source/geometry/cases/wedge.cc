// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/cases/gmsh_3d.h>
#include <fdem/geometry/cases/wedge.h>
#include <fdem/geometry/gmsh_mesh.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    namespace
    {
      /**
       * OpenCASCADE solid bounded by plane polygons: @p faces lists, for
       * each face, the indices of its corners in @p corners, in order
       * around it. Neighbouring faces share their edges.
       */
      int
      add_occ_polyhedron(const std::vector<Point<3>>              &corners,
                         const std::vector<std::vector<unsigned>> &faces)
      {
        namespace occ = gmsh::model::occ;
        std::vector<int> points;
        for (const Point<3> &corner : corners)
          points.push_back(occ::addPoint(corner[0], corner[1], corner[2]));
        std::map<std::pair<unsigned int, unsigned int>, int> lines;
        const auto line = [&](const unsigned int a, const unsigned int b) {
          const auto key = std::make_pair(std::min(a, b), std::max(a, b));
          auto       it  = lines.find(key);
          if (it == lines.end())
            it = lines
                   .emplace(key,
                            occ::addLine(points[key.first], points[key.second]))
                   .first;
          return (a < b) ? it->second : -it->second;
        };
        std::vector<int> surfaces;
        for (const auto &face : faces)
          {
            std::vector<int> loop;
            for (unsigned int i = 0; i < face.size(); ++i)
              loop.push_back(line(face[i], face[(i + 1) % face.size()]));
            surfaces.push_back(occ::addPlaneSurface({occ::addCurveLoop(loop)}));
          }
        return occ::addVolume({occ::addSurfaceLoop(surfaces)});
      }

      /** Solid with the eight @p corners in deal.II's (lexicographic) order. */
      int
      add_occ_hexahedron(const std::array<Point<3>, 8> &corners)
      {
        return add_occ_polyhedron(std::vector<Point<3>>(corners.begin(),
                                                        corners.end()),
                                  {{0, 1, 3, 2},
                                   {4, 5, 7, 6},
                                   {0, 1, 5, 4},
                                   {2, 3, 7, 6},
                                   {0, 2, 6, 4},
                                   {1, 3, 7, 5}});
      }

      /** Tags of the entities of dimension dim-1 that bound @p entity. */
      std::vector<int>
      boundary_tags(const int dim, const int entity)
      {
        gmsh::vectorpair boundary;
        gmsh::model::getBoundary({{dim, entity}}, boundary, false, false);
        std::vector<int> tags;
        for (const auto &dim_tag : boundary)
          tags.push_back(std::abs(dim_tag.second));
        std::sort(tags.begin(), tags.end());
        tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
        return tags;
      }

      /** Coordinates of the corners of the (plane) surface @p surface. */
      std::vector<Point<3>>
      surface_corners(const int surface)
      {
        gmsh::vectorpair points;
        gmsh::model::getBoundary({{2, surface}}, points, false, false, true);
        std::vector<Point<3>> corners;
        for (const auto &point : points)
          {
            std::vector<double> xyz;
            gmsh::model::getValue(0, std::abs(point.second), {}, xyz);
            corners.emplace_back(xyz[0], xyz[1], xyz[2]);
          }
        return corners;
      }
    } // namespace



    void
    Wedge::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Wedge");
      {
        prm.declare_entry(
          "Slope height",
          "20",
          Patterns::Double(0),
          "Height H of the slope face (m). 3D, x = east, y = north, z = "
          "up: the apex of the wedge (where the line of intersection of "
          "Plane A and Plane B daylights in the slope face) is the origin, "
          "on the toe of the face at z = 0; the crest passes through the "
          "point at z = H straight up the face's line of steepest ascent "
          "from the apex.");
        prm.declare_entry("Slope face",
                          "65, 180",
                          case_input::orientation_pattern(),
                          case_input::orientation_help("the slope face") +
                            " The ground in front of the toe is horizontal "
                            "(z = 0).");
        prm.declare_entry("Upper slope",
                          "0, 180",
                          case_input::orientation_pattern(),
                          case_input::orientation_help(
                            "the upper slope, the ground "
                            "behind the crest"));
        prm.declare_entry("Plane A",
                          "50, 140",
                          case_input::orientation_pattern(),
                          case_input::orientation_help(
                            "the first joint plane (through the apex)"));
        prm.declare_entry("Plane B",
                          "50, 220",
                          case_input::orientation_pattern(),
                          case_input::orientation_help(
                            "the second joint plane (through the apex)"));
        prm.declare_entry(
          "Mesh size",
          "2",
          Patterns::Double(0),
          "Element size h in and near the wedge (m): Gmsh meshes "
          "tetrahedra of size 2 h and splits each into four hexahedra, "
          "whose edges are about h/3 to h long (0.65 h on average), or "
          "with Element shape = tetrahedron keeps tetrahedra of size h. In "
          "the rock the size grows with the distance from the wedge (by a "
          "quarter of the distance) up to 5 h.");
        prm.declare_entry(
          "Element shape",
          "hexahedron",
          Patterns::Selection("hexahedron|tetrahedron"),
          "Shape of the cells: hexahedra (FE_Q elements, Gmsh's Delaunay "
          "tetrahedra each split into four), or the Delaunay tetrahedra "
          "themselves (FE_SimplexP).");
        prm.declare_entry(
          "Rock extent",
          "0",
          Patterns::Double(0),
          "Least distance from the wedge to the sides, the back and the "
          "base of the rock box, and length of the ground in front of the "
          "toe (m); 0 means 2 Slope height.");
      }
      prm.leave_subsection();
    }



    void
    Wedge::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Wedge");
      {
        slope_height  = prm.get_double("Slope height");
        slope_face    = case_input::parse_orientation(prm.get("Slope face"));
        upper_slope   = case_input::parse_orientation(prm.get("Upper slope"));
        plane_a       = case_input::parse_orientation(prm.get("Plane A"));
        plane_b       = case_input::parse_orientation(prm.get("Plane B"));
        mesh_size     = prm.get_double("Mesh size");
        rock_extent   = prm.get_double("Rock extent");
        element_shape = case_input::parse_element_shape(prm);
        if (rock_extent == 0)
          rock_extent = 2 * slope_height;
      }
      prm.leave_subsection();
    }



    void
    Wedge::validate() const
    {
      const std::string path = "Geometry/Wedge/";
      case_input::require(slope_height > 0,
                          path + "Slope height: must be positive.");
      case_input::require(mesh_size > 0, path + "Mesh size: must be positive.");
      case_input::require(rock_extent > 0,
                          path + "Rock extent: must be positive.");
      for (const auto &[name, orientation] :
           {std::make_pair("Slope face", slope_face),
            std::make_pair("Upper slope", upper_slope),
            std::make_pair("Plane A", plane_a),
            std::make_pair("Plane B", plane_b)})
        case_input::require(
          orientation.is_valid(),
          path + name +
            ": the dip must lie in [0, 90] and the dip direction "
            "in [0, 360] degrees.");
      case_input::require(slope_face.dip > 0,
                          path + "Slope face: the dip must be positive.");
      case_input::require(
        upper_slope.dip < 90,
        path + "Upper slope: the dip must be less than 90 degrees.");
      (void)corners(); // throws if the planes form no wedge
    }



    Point<3>
    Wedge::crest_point() const
    {
      // Up the face's line of steepest ascent by the height H.
      const Tensor<1, 3> up_dip = -slope_face.down_dip_direction();
      return Point<3>(slope_height / up_dip[2] * up_dip);
    }



    std::array<Point<3>, 4>
    Wedge::corners() const
    {
      const std::string  no_wedge = "Geometry/Wedge: the planes do not form a "
                                    "wedge that daylights in the slope face.";
      const double       h        = slope_height;
      const Tensor<1, 3> n_face   = slope_face.upward_normal();
      const Tensor<1, 3> n_upper  = upper_slope.upward_normal();
      const Tensor<1, 3> n_a      = plane_a.upward_normal();
      const Tensor<1, 3> n_b      = plane_b.upward_normal();
      const Point<3>     crest    = crest_point();
      // The toe (and the apex) must lie below the upper slope.
      case_input::require(
        n_upper * crest > 1e-9 * h,
        "Geometry/Wedge/Upper slope: must dip less steeply than the "
        "slope face in the face's dip direction, so that the two meet "
        "in a crest above the toe.");

      // The point on three planes n_i . x = d_i (the face, A and B pass
      // through the origin, the upper slope through the crest point).
      const auto meet = [&](const std::array<Tensor<1, 3>, 3> &normals,
                            const std::array<double, 3>       &offsets) {
        Tensor<2, 3> matrix;
        for (unsigned int i = 0; i < 3; ++i)
          matrix[i] = normals[i];
        case_input::require(std::abs(determinant(matrix)) > 1e-6, no_wedge);
        return Point<3>(invert(matrix) *
                        Tensor<1, 3>({offsets[0], offsets[1], offsets[2]}));
      };
      const double   d_upper = n_upper * crest;
      const Point<3> apex;
      const Point<3> top = meet({{n_a, n_b, n_upper}}, {{0, 0, d_upper}});
      const Point<3> crest_a =
        meet({{n_face, n_upper, n_a}}, {{0, d_upper, 0}});
      const Point<3> crest_b =
        meet({{n_face, n_upper, n_b}}, {{0, d_upper, 0}});

      // The line of intersection runs from the apex into the rock behind
      // the face, and the face of the wedge lies between the toe level and
      // the crest; then the tetrahedron is the wedge if it is not flat.
      Tensor<2, 3> edges; // rows: the edges from the apex
      edges[0]            = top - apex;
      edges[1]            = crest_a - apex;
      edges[2]            = crest_b - apex;
      const double volume = std::abs(determinant(edges)) / 6;
      case_input::require(n_face * top < -1e-9 * h && crest_a[2] > 1e-9 * h &&
                            crest_b[2] > 1e-9 * h && volume > 1e-9 * h * h * h,
                          no_wedge);
      return {{apex, top, crest_a, crest_b}};
    }



    MeshDescription<3>
    make_wedge_mesh(const Wedge &wedge)
    {
      namespace occ                        = gmsh::model::occ;
      const std::string             name   = "Geometry/Wedge";
      const std::array<Point<3>, 4> apexes = wedge.corners(); // or throws
      const std::vector<Point<3>>   corners(apexes.begin(), apexes.end());
      const Point<3>                crest   = wedge.crest_point();
      const Tensor<1, 3>            n_face  = wedge.slope_face.upward_normal();
      const Tensor<1, 3>            n_upper = wedge.upper_slope.upward_normal();
      const Tensor<1, 3>            n_a     = wedge.plane_a.upward_normal();
      const Tensor<1, 3>            n_b     = wedge.plane_b.upward_normal();
      const double                  extent  = wedge.rock_extent;
      Assert(wedge.slope_face.dip > 0 && wedge.upper_slope.dip < 90,
             ExcMessage("parse_parameters() checks the dips."));
      // OpenCASCADE's Boolean operations should give one rock body and the
      // wedge, bounded by the planes as expected; say so if they do not.
      const std::string unexpected =
        name + ": OpenCASCADE did not cut the wedge out of the rock as "
               "expected; try slightly different orientations.";

      // The frame of the face's strike: e_r horizontal towards the dip
      // direction (out of the slope), e_s along the strike, e_s x e_r = e_z.
      const double alpha = wedge.slope_face.dip_direction * numbers::PI / 180;
      const Tensor<1, 3> e_r({std::sin(alpha), std::cos(alpha), 0.});
      const Tensor<1, 3> e_s({std::cos(alpha), -std::sin(alpha), 0.});
      const Tensor<1, 3> e_z({0., 0., 1.});
      const auto point = [&](const double s, const double r, const double z) {
        return Point<3>(s * e_s + r * e_r + z * e_z);
      };

      // The box reaches the extent beyond the wedge along the strike, behind
      // it and below it (the apex is the lowest point, at z = 0), and in
      // front of the toe (the apex is the foremost point, at r = 0).
      double s_min = 0, s_max = 0, r_min = 0;
      for (const Point<3> &p : corners)
        {
          s_min = std::min(s_min, p * e_s);
          s_max = std::max(s_max, p * e_s);
          r_min = std::min(r_min, p * e_r);
        }
      const double s_low = s_min - extent, s_high = s_max + extent;
      const double r_back = r_min - extent, r_front = extent;
      const double z_base = -extent;
      // The box's top lies above the upper slope everywhere.
      double z_top = crest[2];
      for (const double s : {s_low, s_high})
        for (const double r : {r_back, r_front})
          {
            const Point<3> p = point(s, r, 0);
            z_top            = std::max(z_top,
                             crest[2] - (n_upper[0] * (p[0] - crest[0]) +
                                         n_upper[1] * (p[1] - crest[1])) /
                                          n_upper[2]);
          }
      z_top += extent;
      const double size = (s_high - s_low) + (r_front - r_back) +
                          (z_top - z_base) + crest.distance(Point<3>());
      const double tolerance = 1e-9 * size;

      GmshSession session;
      gmsh::model::add("wedge");
      int              wedge_volume = 0;
      std::vector<int> rock_volumes;
      GmshSession::run(name + ": Gmsh could not build the model", [&]() {
        const int box = add_occ_hexahedron({{point(s_low, r_back, z_base),
                                             point(s_high, r_back, z_base),
                                             point(s_low, r_front, z_base),
                                             point(s_high, r_front, z_base),
                                             point(s_low, r_back, z_top),
                                             point(s_high, r_back, z_top),
                                             point(s_low, r_front, z_top),
                                             point(s_high, r_front, z_top)}});

        // Everything above the upper slope: a large box on it.
        Tensor<1, 3> t_1 = cross_product_3d(e_z, n_upper);
        t_1              = (t_1.norm() > 1e-12) ? t_1 / t_1.norm() : e_s;
        const Tensor<1, 3>      t_2 = cross_product_3d(n_upper, t_1);
        std::array<Point<3>, 8> above;
        for (unsigned int i = 0; i < 8; ++i)
          above[i] =
            crest + 2 * size *
                      (((i & 1) ? 1. : -1.) * t_1 + ((i & 2) ? 1. : -1.) * t_2 +
                       ((i & 4) ? 1. : 0.) * n_upper);
        const int above_upper_slope = add_occ_hexahedron(above);

        // Everything in front of the slope face and above the toe: a prism
        // along the strike on the section toe, front, front top, face top.
        const double cot_psi =
          1 / std::tan(wedge.slope_face.dip * numbers::PI / 180);
        const double            z_high = 2 * size;
        std::array<Point<3>, 8> front;
        for (const unsigned int i : {0u, 1u})
          {
            const double s = (i == 0) ? s_low - size : s_high + size;
            front[i]       = point(s, 0, 0);
            front[i + 2]   = point(s, r_front + size, 0);
            front[i + 4]   = point(s, -z_high * cot_psi, z_high);
            front[i + 6]   = point(s, r_front + size, z_high);
          }
        const int in_front = add_occ_hexahedron(front);

        gmsh::vectorpair              slope, pieces;
        std::vector<gmsh::vectorpair> origin;
        occ::cut({{3, box}},
                 {{3, above_upper_slope}, {3, in_front}},
                 slope,
                 origin);
        AssertThrow(slope.size() == 1, ExcMessage(unexpected));

        const int tetrahedron =
          add_occ_polyhedron(corners,
                             {{0, 2, 3}, {1, 2, 3}, {0, 1, 2}, {0, 1, 3}});
        // Fragmenting makes the faces on A and B shared by both volumes.
        occ::fragment(slope, {{3, tetrahedron}}, pieces, origin);
        occ::synchronize();
        AssertThrow(origin.size() == 2 && origin[1].size() == 1,
                    ExcMessage(unexpected));
        wedge_volume = origin[1][0].second;
        for (const auto &piece : pieces)
          if (piece.first == 3 && piece.second != wedge_volume)
            rock_volumes.push_back(piece.second);
      });
      AssertThrow(!rock_volumes.empty(), ExcMessage(unexpected));

      // Sort the surfaces by the plane they lie in.
      std::vector<int> wedge_surfaces;
      double           inradius = 0;
      GmshSession::run(name + ": Gmsh could not build the model", [&]() {
        const auto on_plane = [&](const std::vector<Point<3>> &points,
                                  const Tensor<1, 3>          &normal,
                                  const Point<3>              &origin) {
          return std::all_of(points.begin(),
                             points.end(),
                             [&](const Point<3> &p) {
                               return std::abs(normal * (p - origin)) <
                                      tolerance;
                             });
        };
        wedge_surfaces = boundary_tags(3, wedge_volume);
        std::vector<int> rock_surfaces;
        for (const int volume : rock_volumes)
          for (const int surface : boundary_tags(3, volume))
            rock_surfaces.push_back(surface);
        std::sort(rock_surfaces.begin(), rock_surfaces.end());
        std::vector<int> all_surfaces;
        std::set_union(wedge_surfaces.begin(),
                       wedge_surfaces.end(),
                       rock_surfaces.begin(),
                       rock_surfaces.end(),
                       std::back_inserter(all_surfaces));

        enum Group
        {
          plane_a,
          plane_b,
          slope_face,
          upper_slope,
          base,
          sides,
          n_groups
        };
        const std::array<std::string, n_groups> group_names = {
          {"plane A", "plane B", "slope face", "upper slope", "base", "sides"}};
        std::array<std::vector<int>, n_groups> groups;
        unsigned int                           n_wedge_faces = 0;
        for (const int surface : all_surfaces)
          {
            const std::vector<Point<3>> points = surface_corners(surface);
            const bool of_wedge = std::binary_search(wedge_surfaces.begin(),
                                                     wedge_surfaces.end(),
                                                     surface);
            const bool of_rock  = std::binary_search(rock_surfaces.begin(),
                                                    rock_surfaces.end(),
                                                    surface);
            Group      group    = sides;
            if (of_wedge && of_rock)
              {
                AssertThrow(on_plane(points, n_a, Point<3>()) ||
                              on_plane(points, n_b, Point<3>()),
                            ExcMessage(unexpected));
                group = on_plane(points, n_a, Point<3>()) ? plane_a : plane_b;
              }
            else if (on_plane(points, n_face, Point<3>()))
              group = slope_face;
            else if (on_plane(points, n_upper, crest))
              group = upper_slope;
            else if (on_plane(points, e_z, Point<3>()))
              group = slope_face; // the ground in front of the toe
            else if (on_plane(points, e_z, Point<3>(0, 0, z_base)))
              group = base;
            AssertThrow(!of_wedge || group < base, ExcMessage(unexpected));
            n_wedge_faces += of_wedge;
            groups[group].push_back(surface);
          }
        AssertThrow(n_wedge_faces == 4, ExcMessage(unexpected));

        add_physical_group(3, {wedge_volume}, "wedge");
        add_physical_group(3, rock_volumes, "rock");
        for (unsigned int g = 0; g < n_groups; ++g)
          {
            AssertThrow(!groups[g].empty(), ExcMessage(unexpected));
            add_physical_group(2, groups[g], group_names[g]);
          }

        // The inradius 3 V / A: no point of the wedge lies further from
        // its faces.
        double area = 0;
        for (const int surface : wedge_surfaces)
          {
            double mass;
            occ::getMass(2, surface, mass);
            area += mass;
          }
        double volume;
        occ::getMass(3, wedge_volume, volume);
        inradius = 3 * volume / area;
      });

      // Tetrahedra of twice the mesh size in the wedge and up to its
      // inradius from its faces, growing by a quarter of the further
      // distance up to 5 times that size; each is then split into four
      // hexahedra. Tetrahedra that are kept have the mesh size.
      const bool hexahedra = wedge.element_shape == ElementShape::hypercube;
      GmshSession::run(name + ": Gmsh could not mesh the model", [&]() {
        const double near = (hexahedra ? 2 : 1) * wedge.mesh_size;
        gmsh_3d::mesh_near_surfaces(
          wedge_surfaces, near, 5 * near, inradius, hexahedra);
      });
      return extract_current_gmsh_model<3>(name);
    }
  } // namespace geometry
} // namespace fdem
