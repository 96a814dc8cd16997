// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/parameters/geometry_parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <utility>

namespace fdem
{
  namespace parameters
  {
    namespace
    {
      /** Pattern of a list of points "x,y; x,y; ...". */
      Patterns::List
      point_list_pattern(const unsigned int min_n_points)
      {
        return Patterns::List(Patterns::List(Patterns::Double(), 2, 2, ","),
                              min_n_points,
                              Patterns::List::max_int_value,
                              ";");
      }

      Point<2>
      parse_point(const std::string &text)
      {
        const std::vector<double> xy =
          Utilities::string_to_double(Utilities::split_string_list(text, ','));
        return Point<2>(xy[0], xy[1]);
      }

      /**
       * "Element shape" of a 2D generator: quadrilateral or triangle;
       * @p how says how the generator makes each.
       */
      void
      declare_element_shape_2d(ParameterHandler &prm, const std::string &how)
      {
        prm.declare_entry("Element shape",
                          "quadrilateral",
                          Patterns::Selection("quadrilateral|triangle"),
                          "Shape of the cells: " + how);
      }

      /** The shape selected by "Element shape" ("triangle"/"tetrahedron": simplices). */
      GeometryParameters::ElementShape
      parse_element_shape(ParameterHandler &prm)
      {
        using ElementShape      = GeometryParameters::ElementShape;
        const std::string shape = prm.get("Element shape");
        return (shape == "triangle" || shape == "tetrahedron") ? ElementShape::simplex :
                                                                 ElementShape::hypercube;
      }

      std::vector<Point<2>>
      parse_points(const std::string &text)
      {
        std::vector<Point<2>> points;
        for (const std::string &point : Utilities::split_string_list(text, ';'))
          points.push_back(parse_point(point));
        return points;
      }

      GeometryParameters::Source
      source_from_name(const std::string &name)
      {
        using Source = GeometryParameters::Source;
        const std::map<std::string, Source> sources = {
          {"mesh file", Source::mesh_file},
          {"slope", Source::slope},
          {"hertz", Source::hertz},
          {"inclined block", Source::inclined_block},
          {"wedge", Source::wedge},
          {"block on plane", Source::block_on_plane},
          {"hertz sphere", Source::hertz_sphere}};
        return sources.at(name);
      }

      /** Pattern of a plane orientation "dip, dip direction". */
      Patterns::List
      orientation_pattern()
      {
        return Patterns::List(Patterns::Double(), 2, 2, ",");
      }

      /** Help text of a plane orientation entry about @p plane. */
      std::string
      orientation_help(const std::string &plane)
      {
        return "Orientation of " + plane +
               " as 'dip, dip direction' (degrees): the dip psi below the "
               "horizontal (0 to 90) and the dip direction alpha, the "
               "azimuth of the line of steepest descent clockwise from north "
               "(0 to 360). With x = east, y = north, z = up, the plane's "
               "upward unit normal is n = (sin psi sin alpha, sin psi cos "
               "alpha, cos psi).";
      }

      PlaneOrientation
      parse_orientation(const std::string &text)
      {
        const std::vector<double> values =
          Utilities::string_to_double(Utilities::split_string_list(text, ','));
        PlaneOrientation orientation;
        orientation.dip           = values[0];
        orientation.dip_direction = values[1];
        return orientation;
      }

      bool
      is_valid(const PlaneOrientation &orientation)
      {
        return orientation.dip >= 0 && orientation.dip <= 90 &&
               orientation.dip_direction >= 0 &&
               orientation.dip_direction <= 360;
      }

      double
      radians(const double degrees)
      {
        return degrees * numbers::PI / 180;
      }

      /** One-sentence errors that start with the parameter's path. */
      void
      require(const bool condition, const std::string &message)
      {
        AssertThrow(condition, ExcMessage(message));
      }

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
    } // namespace



    void
    GeometryParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      {
        prm.declare_entry(
          "Source",
          "slope",
          Patterns::Selection(
            "mesh file|slope|hertz|inclined block|wedge|block on plane|"
            "hertz sphere"),
          "Where the mesh comes from: a Gmsh file (see Mesh file) or one of "
          "the built-in generators, whose data are in the subsection of the "
          "same name: slope, hertz and inclined block build 2D models "
          "(Dimension = 2), wedge, block on plane and hertz sphere 3D models "
          "(Dimension = 3).");
        prm.declare_entry(
          "Mesh file",
          "",
          Patterns::FileName(),
          "Gmsh file for Source = mesh file: a mesh (.msh, ASCII or binary, "
          "format 2 or 4) or a geometry (.geo, meshed by Gmsh in the model's "
          "dimension). Physical groups of the model's dimension are the "
          "blocks, those one dimension lower the face groups. A relative path "
          "is relative to the directory of the .prm file.");
        prm.declare_entry(
          "Scale factor",
          "1",
          Patterns::Double(0),
          "Factor s of the transformation x -> R (s x) + t applied to every "
          "mesh after it is made (dimensionless, positive).");
        prm.declare_entry(
          "Rotation angle",
          "0",
          Patterns::Double(-360, 360),
          "Angle of the rotation R in x -> R (s x) + t, applied to every mesh "
          "after it is made (degrees, counter-clockwise about the z axis in "
          "2D, right-handed about Rotation axis in 3D).");
        prm.declare_entry("Rotation axis",
                          "0,0,1",
                          Patterns::List(Patterns::Double(), 3, 3, ","),
                          "Axis of the rotation R in 3D (any non-zero length, "
                          "dimensionless; ignored in 2D).");
        prm.declare_entry(
          "Translation",
          "0,0",
          Patterns::List(Patterns::Double(), 2, 3, ","),
          "Translation t in x -> R (s x) + t, applied to every mesh after it "
          "is made (model length unit): 2 or 3 components, and in 2D a third "
          "component must be 0.");

        prm.enter_subsection("Slope");
        {
          prm.declare_entry("Ground surface",
                            "0,25; 10,25; 30,35; 50,35",
                            point_list_pattern(2),
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
          prm.declare_entry(
            "Circle centre",
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
            point_list_pattern(0),
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
          declare_element_shape_2d(
            prm,
            "quadrilaterals (FE_Q elements; Gmsh's "
            "triangles of twice the size recombined and subdivided), or "
            "Gmsh's Frontal-Delaunay triangles of the size itself "
            "(FE_SimplexP).");
        }
        prm.leave_subsection();

        prm.enter_subsection("Hertz");
        {
          prm.declare_entry(
            "Radius",
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
          declare_element_shape_2d(
            prm,
            "quadrilaterals (FE_Q elements; Gmsh's "
            "triangles of twice the size recombined and subdivided), or "
            "Gmsh's Frontal-Delaunay triangles of the size itself "
            "(FE_SimplexP). Either way the contact zone has Elements in "
            "contact zone element edges on each side.");
        }
        prm.leave_subsection();

        prm.enter_subsection("Inclined block");
        {
          prm.declare_entry("Inclination",
                            "30",
                            Patterns::Double(0, 89),
                            "Angle of the plane with the x axis, rising to "
                            "the right (degrees).");
          prm.declare_entry("Block length",
                            "10",
                            Patterns::Double(0),
                            "Length of the block along the plane (m).");
          prm.declare_entry("Block height",
                            "5",
                            Patterns::Double(0),
                            "Height of the block normal to the plane (m).");
          prm.declare_entry("Foundation thickness",
                            "5",
                            Patterns::Double(0),
                            "Thickness of the foundation slab normal to the "
                            "plane (m).");
          prm.declare_entry("Foundation overhang",
                            "5",
                            Patterns::Double(0),
                            "Length the foundation extends beyond each end "
                            "of the block (m).");
          prm.declare_entry(
            "Elements along length",
            "10",
            Patterns::Integer(1),
            "Number of elements of the block along the "
            "plane; the foundation gets elements of that size.");
          prm.declare_entry(
            "Elements across height",
            "5",
            Patterns::Integer(1),
            "Number of elements of the block normal to the "
            "plane; the foundation gets elements of that size.");
          declare_element_shape_2d(
            prm,
            "quadrilaterals (FE_Q elements), or "
            "triangles (FE_SimplexP), two per quadrilateral of the same "
            "structured grid.");
        }
        prm.leave_subsection();

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
                            orientation_pattern(),
                            orientation_help("the slope face") +
                              " The ground in front of the toe is horizontal "
                              "(z = 0).");
          prm.declare_entry("Upper slope",
                            "0, 180",
                            orientation_pattern(),
                            orientation_help("the upper slope, the ground "
                                             "behind the crest"));
          prm.declare_entry("Plane A",
                            "50, 140",
                            orientation_pattern(),
                            orientation_help(
                              "the first joint plane (through the apex)"));
          prm.declare_entry("Plane B",
                            "50, 220",
                            orientation_pattern(),
                            orientation_help(
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

        prm.enter_subsection("Block on plane");
        {
          prm.declare_entry(
            "Dip",
            "30",
            Patterns::Double(0, 90),
            "Dip psi of the plane, below the horizontal (degrees). 3D, x = "
            "east, y = north, z = up: the plane passes through the origin "
            "with the upward unit normal n = (sin psi sin alpha, sin psi cos "
            "alpha, cos psi).");
          prm.declare_entry(
            "Dip direction",
            "120",
            Patterns::Double(0, 360),
            "Dip direction alpha of the plane: azimuth of its line of "
            "steepest descent, clockwise from north (degrees). The block's "
            "length runs down the dip from the origin, its width is centred "
            "on the origin along the strike.");
          prm.declare_entry("Block length",
                            "10",
                            Patterns::Double(0),
                            "Length of the block down the dip (m).");
          prm.declare_entry("Block width",
                            "6",
                            Patterns::Double(0),
                            "Width of the block along the strike (m).");
          prm.declare_entry("Block height",
                            "5",
                            Patterns::Double(0),
                            "Height of the block normal to the plane (m).");
          prm.declare_entry("Foundation thickness",
                            "5",
                            Patterns::Double(0),
                            "Thickness of the foundation slab normal to the "
                            "plane (m).");
          prm.declare_entry("Foundation overhang",
                            "3",
                            Patterns::Double(0),
                            "Length the foundation extends beyond the block "
                            "on each of its four sides (m).");
          prm.declare_entry("Elements along length",
                            "10",
                            Patterns::Integer(1),
                            "Number of elements of the block down the dip; "
                            "the foundation gets elements of that length.");
          prm.declare_entry("Elements along width",
                            "6",
                            Patterns::Integer(1),
                            "Number of elements of the block along the "
                            "strike; the foundation gets elements of that "
                            "width.");
          prm.declare_entry("Elements across height",
                            "5",
                            Patterns::Integer(1),
                            "Number of elements of the block normal to the "
                            "plane; the foundation gets elements of that "
                            "height.");
        }
        prm.leave_subsection();

        prm.enter_subsection("Hertz sphere");
        {
          prm.declare_entry(
            "Radius",
            "100",
            Patterns::Double(0),
            "Radius R of the sphere (model length unit, e.g. mm). 3D quarter "
            "model x >= 0, y >= 0, z up: the sphere touches the foundation's "
            "top z = 0 at the origin; x = 0 and y = 0 are symmetry planes.");
          prm.declare_entry(
            "Load height",
            "60",
            Patterns::Double(0),
            "Height H of the sphere's flat top above the origin, where the "
            "load is applied (model length unit); at most Radius, and above "
            "the sphere's surface at the corner (S, S) of its plan.");
          prm.declare_entry(
            "Cap half width",
            "50",
            Patterns::Double(0),
            "Half width S of the sphere's square plan: the sphere is cut by "
            "the planes x = S and y = S (free faces) (model length unit); "
            "larger than Contact zone width, S sqrt(2) < Radius.");
          prm.declare_entry("Foundation width",
                            "100",
                            Patterns::Double(0),
                            "Width W of the foundation [0, W] x [0, W] in "
                            "plan (model length unit); larger than Cap half "
                            "width.");
          prm.declare_entry("Foundation depth",
                            "100",
                            Patterns::Double(0),
                            "Depth D of the foundation below z = 0 (model "
                            "length unit).");
          prm.declare_entry(
            "Contact zone width",
            "7.5",
            Patterns::Double(0),
            "Side Lc of the square [0, Lc]^2 in plan in which the sphere and "
            "the foundation get nodes at the same (x, y), so that pairs are "
            "found along the vertical (model length unit). It should exceed "
            "the contact radius; the elements keep its size Lc/n down to the "
            "depth Lc and up to the height Lc.");
          prm.declare_entry(
            "Elements in contact zone",
            "6",
            Patterns::Integer(1, 200),
            "Number n of equal elements along each side of the contact zone "
            "(dimensionless).");
          prm.declare_entry(
            "Growth ratio",
            "1.4",
            Patterns::Double(1, 2),
            "Ratio of the sizes of neighbouring elements outside the contact "
            "zone, in plan and in depth (dimensionless, 1 to 2).");
          prm.declare_entry("Mesh size",
                            "25",
                            Patterns::Double(0),
                            "Largest element size, far from the contact "
                            "(model length unit).");
        }
        prm.leave_subsection();
      }
      prm.leave_subsection();
    }



    void
    GeometryParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      {
        source         = source_from_name(prm.get("Source"));
        mesh_file      = prm.get("Mesh file");
        scale_factor   = prm.get_double("Scale factor");
        rotation_angle = prm.get_double("Rotation angle");

        const std::vector<double> axis = Utilities::string_to_double(
          Utilities::split_string_list(prm.get("Rotation axis"), ','));
        rotation_axis = Tensor<1, 3>({axis[0], axis[1], axis[2]});
        translation   = Utilities::string_to_double(
          Utilities::split_string_list(prm.get("Translation"), ','));

        require(
          source != Source::mesh_file || !mesh_file.empty(),
          "Geometry/Mesh file: must be given when Source is 'mesh file'.");
        require(scale_factor > 0, "Geometry/Scale factor: must be positive.");
        require(rotation_axis.norm() > 0,
                "Geometry/Rotation axis: must not be the zero vector.");
        rotation_axis /= rotation_axis.norm();

        prm.enter_subsection("Slope");
        {
          slope.ground_surface  = parse_points(prm.get("Ground surface"));
          slope.base_elevation  = prm.get_double("Base elevation");
          slope.sliding_surface = (prm.get("Sliding surface") == "circular") ?
                                    SlidingSurface::circular :
                                    SlidingSurface::polyline;
          slope.circle_centre   = parse_point(prm.get("Circle centre"));
          slope.circle_radius   = prm.get_double("Circle radius");
          slope.sliding_surface_polyline =
            parse_points(prm.get("Sliding surface polyline"));
          slope.mesh_size = prm.get_double("Mesh size");
          slope.mesh_size_on_sliding_surface =
            prm.get_double("Mesh size on sliding surface");
          if (slope.mesh_size_on_sliding_surface == 0)
            slope.mesh_size_on_sliding_surface = slope.mesh_size;
          slope.element_shape = parse_element_shape(prm);
        }
        prm.leave_subsection();

        prm.enter_subsection("Hertz");
        {
          hertz.radius             = prm.get_double("Radius");
          hertz.foundation_width   = prm.get_double("Foundation width");
          hertz.foundation_depth   = prm.get_double("Foundation depth");
          hertz.contact_zone_width = prm.get_double("Contact zone width");
          hertz.n_contact_zone_elements =
            prm.get_integer("Elements in contact zone");
          hertz.mesh_size  = prm.get_double("Mesh size");
          hertz.full_model = prm.get_bool("Full model");
          hertz.element_shape = parse_element_shape(prm);
        }
        prm.leave_subsection();

        prm.enter_subsection("Inclined block");
        {
          inclined_block.inclination  = prm.get_double("Inclination");
          inclined_block.block_length = prm.get_double("Block length");
          inclined_block.block_height = prm.get_double("Block height");
          inclined_block.foundation_thickness =
            prm.get_double("Foundation thickness");
          inclined_block.foundation_overhang =
            prm.get_double("Foundation overhang");
          inclined_block.n_elements_along_length =
            prm.get_integer("Elements along length");
          inclined_block.n_elements_across_height =
            prm.get_integer("Elements across height");
          inclined_block.element_shape = parse_element_shape(prm);
        }
        prm.leave_subsection();

        prm.enter_subsection("Wedge");
        {
          wedge.slope_height = prm.get_double("Slope height");
          wedge.slope_face   = parse_orientation(prm.get("Slope face"));
          wedge.upper_slope  = parse_orientation(prm.get("Upper slope"));
          wedge.plane_a      = parse_orientation(prm.get("Plane A"));
          wedge.plane_b      = parse_orientation(prm.get("Plane B"));
          wedge.mesh_size    = prm.get_double("Mesh size");
          wedge.rock_extent  = prm.get_double("Rock extent");
          wedge.element_shape = parse_element_shape(prm);
          if (wedge.rock_extent == 0)
            wedge.rock_extent = 2 * wedge.slope_height;
        }
        prm.leave_subsection();

        prm.enter_subsection("Block on plane");
        {
          auto &block                = block_on_plane;
          block.plane.dip            = prm.get_double("Dip");
          block.plane.dip_direction  = prm.get_double("Dip direction");
          block.block_length         = prm.get_double("Block length");
          block.block_width          = prm.get_double("Block width");
          block.block_height         = prm.get_double("Block height");
          block.foundation_thickness = prm.get_double("Foundation thickness");
          block.foundation_overhang  = prm.get_double("Foundation overhang");
          block.n_elements_along_length =
            prm.get_integer("Elements along length");
          block.n_elements_along_width =
            prm.get_integer("Elements along width");
          block.n_elements_across_height =
            prm.get_integer("Elements across height");
        }
        prm.leave_subsection();

        prm.enter_subsection("Hertz sphere");
        {
          auto &sphere              = hertz_sphere;
          sphere.radius             = prm.get_double("Radius");
          sphere.load_height        = prm.get_double("Load height");
          sphere.cap_half_width     = prm.get_double("Cap half width");
          sphere.foundation_width   = prm.get_double("Foundation width");
          sphere.foundation_depth   = prm.get_double("Foundation depth");
          sphere.contact_zone_width = prm.get_double("Contact zone width");
          sphere.n_contact_zone_elements =
            prm.get_integer("Elements in contact zone");
          sphere.growth_ratio = prm.get_double("Growth ratio");
          sphere.mesh_size    = prm.get_double("Mesh size");
        }
        prm.leave_subsection();
      }
      prm.leave_subsection();

      if (source == Source::slope)
        {
          const std::string path   = "Geometry/Slope/";
          const auto       &ground = slope.ground_surface;
          require(x_increases(ground, true),
                  path + "Ground surface: the x coordinates must increase "
                         "from left to right.");
          require(std::all_of(ground.begin(),
                              ground.end(),
                              [&](const Point<2> &p) {
                                return slope.base_elevation < p[1];
                              }),
                  path + "Base elevation: must lie below every point of the "
                         "ground surface.");
          require(slope.mesh_size > 0, path + "Mesh size: must be positive.");
          if (slope.sliding_surface == SlidingSurface::circular)
            require(slope.circle_radius > 0,
                    path + "Circle radius: must be positive.");
          else
            {
              const auto       &line = slope.sliding_surface_polyline;
              const std::string name = path + "Sliding surface polyline: ";
              require(line.size() >= 2,
                      name + "needs at least two points when Sliding "
                             "surface is 'polyline'.");
              require(x_increases(line, false) &&
                        line.back()[0] > line.front()[0],
                      name + "the x coordinates must not decrease from left "
                             "to right.");
              require(on_or_above_ground(ground, line.front()) &&
                        on_or_above_ground(ground, line.back()),
                      name + "its first and last points must lie on or "
                             "above the ground surface.");
            }
        }
      else if (source == Source::hertz)
        {
          const std::string path = "Geometry/Hertz/";
          require(hertz.radius > 0, path + "Radius: must be positive.");
          require(hertz.foundation_width > 0 && hertz.foundation_depth > 0,
                  path + "Foundation width and depth: must be positive.");
          require(hertz.contact_zone_width > 0 &&
                    hertz.contact_zone_width < hertz.radius &&
                    hertz.contact_zone_width < hertz.foundation_width,
                  path + "Contact zone width: must be positive and smaller "
                         "than Radius and Foundation width.");
          require(hertz.n_contact_zone_elements % 2 == 0,
                  path + "Elements in contact zone: must be even (an "
                         "all-quadrilateral mesh needs an even number of "
                         "edges around each region).");
          require(hertz.mesh_size > 0, path + "Mesh size: must be positive.");
        }
      else if (source == Source::inclined_block)
        {
          const auto &block = inclined_block;
          require(block.block_length > 0 && block.block_height > 0,
                  "Geometry/Inclined block/Block length and height: must be "
                  "positive.");
          require(block.foundation_thickness > 0 &&
                    block.foundation_overhang > 0,
                  "Geometry/Inclined block/Foundation thickness and overhang: "
                  "must be positive.");
        }
      else if (source == Source::wedge)
        {
          const std::string path = "Geometry/Wedge/";
          require(wedge.slope_height > 0,
                  path + "Slope height: must be positive.");
          require(wedge.mesh_size > 0, path + "Mesh size: must be positive.");
          require(wedge.rock_extent > 0,
                  path + "Rock extent: must be positive.");
          for (const auto &[name, orientation] :
               {std::make_pair("Slope face", wedge.slope_face),
                std::make_pair("Upper slope", wedge.upper_slope),
                std::make_pair("Plane A", wedge.plane_a),
                std::make_pair("Plane B", wedge.plane_b)})
            require(is_valid(orientation),
                    path + name +
                      ": the dip must lie in [0, 90] and the dip direction "
                      "in [0, 360] degrees.");
          require(wedge.slope_face.dip > 0,
                  path + "Slope face: the dip must be positive.");
          require(wedge.upper_slope.dip < 90,
                  path + "Upper slope: the dip must be less than 90 degrees.");
          (void)wedge.corners(); // throws if the planes form no wedge
        }
      else if (source == Source::block_on_plane)
        {
          const auto &block = block_on_plane;
          require(block.block_length > 0 && block.block_width > 0 &&
                    block.block_height > 0,
                  "Geometry/Block on plane/Block length, width and height: "
                  "must be positive.");
          require(block.foundation_thickness > 0 &&
                    block.foundation_overhang > 0,
                  "Geometry/Block on plane/Foundation thickness and overhang: "
                  "must be positive.");
        }
      else if (source == Source::hertz_sphere)
        {
          const std::string path = "Geometry/Hertz sphere/";
          const auto       &sphere = hertz_sphere;
          const double      r = sphere.radius, s = sphere.cap_half_width;
          require(r > 0, path + "Radius: must be positive.");
          require(sphere.contact_zone_width > 0 &&
                    sphere.contact_zone_width < s,
                  path + "Contact zone width: must be positive and smaller "
                         "than Cap half width.");
          require(s * std::sqrt(2.0) < r,
                  path + "Cap half width: S sqrt(2) must be smaller than "
                         "Radius, so that the sphere's surface spans the "
                         "square plan.");
          require(sphere.load_height <= r &&
                    sphere.load_height >
                      r - std::sqrt(r * r - 2 * s * s) +
                        sphere.contact_zone_width,
                  path + "Load height: must be at most Radius and exceed "
                         "the height of the sphere's surface at the corner "
                         "(S, S) of its plan by more than Contact zone "
                         "width.");
          require(sphere.foundation_width > s,
                  path + "Foundation width: must be larger than Cap half "
                         "width.");
          require(sphere.foundation_depth > sphere.contact_zone_width,
                  path + "Foundation depth: must be larger than Contact "
                         "zone width.");
          require(sphere.mesh_size > 0, path + "Mesh size: must be positive.");
        }
    }



    bool
    GeometryParameters::source_is_3d() const
    {
      return source == Source::wedge || source == Source::block_on_plane ||
             source == Source::hertz_sphere;
    }



    Tensor<1, 3>
    PlaneOrientation::upward_normal() const
    {
      const double psi = radians(dip), alpha = radians(dip_direction);
      return Tensor<1, 3>({std::sin(psi) * std::sin(alpha),
                           std::sin(psi) * std::cos(alpha),
                           std::cos(psi)});
    }



    Tensor<1, 3>
    PlaneOrientation::down_dip_direction() const
    {
      const double psi = radians(dip), alpha = radians(dip_direction);
      return Tensor<1, 3>({std::cos(psi) * std::sin(alpha),
                           std::cos(psi) * std::cos(alpha),
                           -std::sin(psi)});
    }



    Point<3>
    GeometryParameters::Wedge::crest_point() const
    {
      // Up the face's line of steepest ascent by the height H.
      const Tensor<1, 3> up_dip = -slope_face.down_dip_direction();
      return Point<3>(slope_height / up_dip[2] * up_dip);
    }



    std::array<Point<3>, 4>
    GeometryParameters::Wedge::corners() const
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
      require(n_upper * crest > 1e-9 * h,
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
        require(std::abs(determinant(matrix)) > 1e-6, no_wedge);
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
      require(n_face * top < -1e-9 * h && crest_a[2] > 1e-9 * h &&
                crest_b[2] > 1e-9 * h && volume > 1e-9 * h * h * h,
              no_wedge);
      return {{apex, top, crest_a, crest_b}};
    }



    Tensor<2, 3>
    GeometryParameters::BlockOnPlane::rotation() const
    {
      const Tensor<1, 3> down_dip = plane.down_dip_direction();
      const Tensor<1, 3> normal   = plane.upward_normal();
      const Tensor<1, 3> strike   = cross_product_3d(normal, down_dip);
      Tensor<2, 3>       rotation;
      for (unsigned int i = 0; i < 3; ++i)
        {
          rotation[i][0] = down_dip[i];
          rotation[i][1] = strike[i];
          rotation[i][2] = normal[i];
        }
      return rotation;
    }



    std::string
    GeometryParameters::mesh_file_path(const std::string &prm_directory) const
    {
      // operator/ keeps an absolute mesh_file as it is.
      return (std::filesystem::path(prm_directory) / mesh_file).string();
    }
  } // namespace parameters
} // namespace fdem
