// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/cases/gmsh_3d.h>
#include <fdem/geometry/cases/slope_3d.h>
#include <fdem/geometry/gmsh_mesh.h>
#include <fdem/parameters/numbers.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    void
    Slope3D::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Slope 3D");
      {
        prm.declare_entry(
          "Slope height",
          "10",
          Patterns::Double(0),
          "Height H of the slope face (m). 3D, x into the slope, y along the "
          "strike, z up: the ground is z_t in front of the toe (0 <= x <= "
          "Toe length), rises at Slope angle to z_t + H at the crest edge "
          "and stays there for Crest length; the model spans 0 <= y <= "
          "Width.");
        prm.declare_entry("Slope angle",
                          "26.565051177",
                          Patterns::Double(0, 90),
                          "Angle beta of the slope face to the horizontal "
                          "(degrees, 0 to 90 excluded).");
        prm.declare_entry("Toe length",
                          "10",
                          Patterns::Double(0),
                          "Length of the ground in front of the toe (m).");
        prm.declare_entry("Crest length",
                          "20",
                          Patterns::Double(0),
                          "Length of the ground behind the crest edge (m).");
        prm.declare_entry("Toe elevation",
                          "25",
                          Patterns::Double(),
                          "Elevation z_t of the toe and of the ground in "
                          "front of it (m).");
        prm.declare_entry("Base depth",
                          "5",
                          Patterns::Double(0),
                          "Depth D of the base (z = z_t - D) below the toe "
                          "(m).");
        prm.declare_entry("Width",
                          "40",
                          Patterns::Double(0),
                          "Width W of the model along the strike (m).");
        prm.declare_entry(
          "Sliding surface",
          "ellipsoid",
          Patterns::Selection("ellipsoid|sphere|cylinder|capsule"),
          "Shape of the sliding surface: an ellipsoid with semi-axes Surface "
          "radius in x and z and Surface half length in y, a sphere of "
          "Surface radius, a cylinder of Surface radius along y through "
          "the whole width (the plane-strain case: set the sides to normal "
          "constraints), or a capsule: a cylinder of Surface radius along y "
          "over Surface straight length, closed at both ends by "
          "half-ellipsoids with semi-axis Surface half length along y (a "
          "long slide with rounded ends).");
        prm.declare_entry("Surface centre",
                          "19.61, 20, 46.32",
                          Patterns::List(Patterns::Double(), 3, 3, ","),
                          "Centre x, y, z of the sliding surface (m); y is "
                          "not used for a cylinder.");
        prm.declare_entry("Surface radius",
                          "21.32",
                          Patterns::Double(0),
                          "Radius R of the sphere or the cylinder, the "
                          "ellipsoid's semi-axes in x and z (m).");
        prm.declare_entry("Surface half length",
                          "15",
                          Patterns::Double(0),
                          "Semi-axis b of the ellipsoid, or of the "
                          "capsule's ends, along y (m); not used for a "
                          "sphere or a cylinder.");
        prm.declare_entry("Surface straight length",
                          "20",
                          Patterns::Double(0),
                          "Length of the capsule's cylindrical part along "
                          "y, centred on Surface centre (m); only used for "
                          "a capsule.");
        prm.declare_entry(
          "Mesh size",
          "2",
          Patterns::Double(0),
          "Element size h near the sliding surface (m): Gmsh meshes "
          "tetrahedra of size 2 h within Surface radius / 4 of the sliding "
          "surface, growing to 6 h further away, and splits each into four "
          "hexahedra (edges about h/3 to h), or with Element shape = "
          "tetrahedron keeps tetrahedra of size h (growing to 3 h).");
        prm.declare_entry(
          "Layers",
          "",
          Patterns::List(Patterns::Anything(), 0),
          "Soil layers from the top down: the material of each, a name of "
          "Materials/Names (a material may come back lower down). The "
          "layers cut across the sliding mass and the foundation alike. "
          "Empty: no layers (each block is of its own material).");
        prm.declare_entry(
          "Layer boundaries",
          "",
          Patterns::Anything(),
          "The boundaries between consecutive layers, from the top down, "
          "separated by '|' (one fewer than Layers): each a polyline "
          "'x,z; x,z; ...' (m) in the section, with increasing x from 0 (or "
          "before) to the end of the crest (or beyond), inside the model (on "
          "or below the ground, above the base) and strictly below the "
          "boundary before it; each runs unchanged along y.");
        prm.declare_entry(
          "Terrain file",
          "",
          Patterns::FileName(),
          "A ground surface from a grid of elevations instead of the "
          "straight slope: a text file of lines 'x, y, z' (m; commas, "
          "semicolons or blanks; '#' comments; an optional header line), one "
          "per point of a rectangular grid (every x of the file with every "
          "y), in any order; a relative name from the folder of the file that "
          "sets it. "
          "The ground is bilinear on each grid cell; the model spans the "
          "grid in x and y (its sides there), with its base Base depth below "
          "the lowest point; Slope height, Slope angle, Toe length, Crest "
          "length, Toe elevation and Width are not used. Cells much smaller "
          "than Mesh size make the mesh finer there. Or a surface for Gmsh "
          "(.msh of triangles or quadrangles, .geo whose surfaces Gmsh "
          "meshes, .stl) covering a rectangle in x and y, one elevation at "
          "each point: sampled on a grid over its extent every Terrain grid "
          "spacing, the ground bilinear between the samples. Empty: the "
          "straight slope.");
        prm.declare_entry(
          "Terrain grid spacing",
          "0",
          Patterns::Double(0),
          "With a Gmsh surface as Terrain file: the largest distance between "
          "the grid lines it is sampled on, in x and in y (m). The ground "
          "follows the surface to within the variation of its slope over a "
          "cell: give the spacing of the surface's features you want kept. "
          "0: Mesh size.");
        prm.declare_entry(
          "Element shape",
          "hexahedron",
          Patterns::Selection("hexahedron|tetrahedron"),
          "Shape of the cells: hexahedra (FE_Q elements, Gmsh's Delaunay "
          "tetrahedra each split into four), or the Delaunay tetrahedra "
          "themselves (FE_SimplexP).");
      }
      prm.leave_subsection();
    }



    void
    Slope3D::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Slope 3D");
      {
        slope_height            = prm.get_double("Slope height");
        slope_angle             = prm.get_double("Slope angle");
        toe_length              = prm.get_double("Toe length");
        crest_length            = prm.get_double("Crest length");
        toe_elevation           = prm.get_double("Toe elevation");
        base_depth              = prm.get_double("Base depth");
        width                   = prm.get_double("Width");
        const std::string shape = prm.get("Sliding surface");
        surface                 = (shape == "ellipsoid") ? Surface::ellipsoid :
                                  (shape == "sphere")    ? Surface::sphere :
                                  (shape == "capsule")   ? Surface::capsule :
                                                           Surface::cylinder;
        const std::vector<double> c = parameters::finite_numbers(
          Utilities::split_string_list(prm.get("Surface centre"), ','));
        centre           = Point<3>(c[0], c[1], c[2]);
        radius           = prm.get_double("Surface radius");
        half_length      = prm.get_double("Surface half length");
        straight_length  = prm.get_double("Surface straight length");
        mesh_size        = prm.get_double("Mesh size");
        element_shape    = case_input::parse_element_shape(prm);
        layers           = Utilities::split_string_list(prm.get("Layers"), ',');
        layer_boundaries = case_input::parse_layer_boundaries(
          prm.get("Layer boundaries"), "Geometry/Slope 3D/Layer boundaries");
        if (surface == Surface::sphere)
          half_length = radius;
        terrain_file    = prm.get("Terrain file");
        terrain_spacing = prm.get_double("Terrain grid spacing");
        terrain         = TerrainGrid();
      }
      prm.leave_subsection();
    }



    void
    Slope3D::load_terrain()
    {
      terrain = TerrainGrid();
      if (terrain_file.empty())
        return;
      const std::string &path  = terrain_file;
      const std::string  entry = "Geometry/Slope 3D/Terrain file";
      if (is_surface_mesh_file(terrain_file))
        {
          case_input::require(mesh_size > 0,
                              "Geometry/Slope 3D/Mesh size: must be positive.");
          terrain = terrain_grid_from_surface(
            path, entry, terrain_spacing > 0 ? terrain_spacing : mesh_size);
        }
      else
        terrain = terrain_grid_from_file(path, entry);
    }



    void
    Slope3D::validate() const
    {
      const std::string path = "Geometry/Slope 3D/";
      for (const auto &[name, value] :
           {std::make_pair("Slope height", slope_height),
            std::make_pair("Slope angle", slope_angle),
            std::make_pair("Base depth", base_depth),
            std::make_pair("Width", width),
            std::make_pair("Surface radius", radius),
            std::make_pair("Surface half length", half_length),
            std::make_pair("Mesh size", mesh_size)})
        case_input::require(value > 0, path + name + ": must be positive.");
      case_input::require(slope_angle < 90,
                          path + "Slope angle: must be less than 90 degrees.");
      case_input::require(surface != Surface::capsule || straight_length > 0,
                          path + "Surface straight length: must be positive "
                                 "for a capsule (zero is the ellipsoid).");
      case_input::validate_layers(layers,
                                  layer_boundaries,
                                  ground_profile(),
                                  base_elevation(),
                                  "Geometry/Slope 3D");

      // Points of the surface 1/720 of a turn apart (in the two angles of
      // the ellipsoid, or around the cylinder's section), and as finely
      // along the capsule: the part below the ground must stay inside the
      // model, with a margin of 1e-3 of its size so that OpenCASCADE meets
      // no tangent faces. The central section is at s = 1/2.
      const double margin  = 1e-3 * (x_max() - x_min() + y_max() - y_min() +
                                    top_elevation() - base_elevation());
      const double z_base  = base_elevation();
      const unsigned int n = 720;
      // The cylinder's sections are all one but under a terrain, which
      // may change along y: there 48 of them across the width.
      const bool         cylinder    = surface == Surface::cylinder;
      const bool         one_section = cylinder && terrain.empty();
      const unsigned int n_s         = surface == Surface::capsule ? 3 * n / 4 :
                                       one_section                 ? 0 :
                                       cylinder                    ? 48 :
                                                                     n / 2;
      bool               below = false, above = false, leaves = false;
      double             x_low = x_max(), x_high = x_min(); // central section
      for (unsigned int i = 0; i <= n_s; ++i)
        for (unsigned int j = 0; j < n; ++j)
          {
            const Point<3> p = surface_point(one_section ? 0.5 : 1. * i / n_s,
                                             2 * numbers::PI * j / n);
            if (p[2] >= ground(p[0], p[1]))
              {
                above = true;
                continue;
              }
            below  = true;
            leaves = leaves || p[0] < x_min() + margin ||
                     p[0] > x_max() - margin || p[2] < z_base + margin ||
                     (!cylinder &&
                      (p[1] < y_min() + margin || p[1] > y_max() - margin));
            if (2 * i == n_s || one_section)
              {
                x_low  = std::min(x_low, p[0]);
                x_high = std::max(x_high, p[0]);
              }
          }
      case_input::require(
        below && above,
        path + "Surface centre: the sliding surface does not cut the ground "
               "surface (it must lie partly below and partly above it).");
      case_input::require(
        !leaves,
        path + "Surface centre: the sliding surface leaves the model below "
               "the ground (it must stay inside 0 < x < L, 0 < y < Width "
               "and above the base; Surface radius and Surface half length "
               "too).");
      // A terrain has no slope face: only that the surface cuts it.
      case_input::require(
        !terrain.empty() || (x_low < crest_x() && x_high > toe_length),
        path + "Surface centre: the sliding surface does not daylight on "
               "the slope face (its central section must cut the ground "
               "between the toe and the crest edge).");
      bool axis_above = true;
      for (const double y :
           terrain.empty() ? std::vector<double>{0} : terrain.y)
        axis_above = axis_above && centre[2] > ground(centre[0], y);
      case_input::require(!cylinder || axis_above,
                          path + "Surface centre: a cylinder's axis must lie "
                                 "above the ground.");
    }



    namespace
    {
      /**
       * Moves the vertices of the face group "sliding surface" of the
       * hexahedra of @p mesh, which Gmsh's split of the tetrahedra left on
       * their flat faces and edges, onto the quadric: along its normal, and
       * those on the ground (where the surface daylights) along the
       * normal's part in the ground's plane, so that they stay on the
       * ground. Vertices whose move would twist a cell stay where they are
       * (gmsh_3d::move_vertices_keeping_cells_valid()).
       */
      void
      move_split_vertices_onto_surface(const Slope3D      &slope,
                                       MeshDescription<3> &mesh)
      {
        const auto vertices_of = [&mesh](const std::string &group) {
          const unsigned int id = std::find(mesh.face_group_names.begin(),
                                            mesh.face_group_names.end(),
                                            group) -
                                  mesh.face_group_names.begin();
          std::vector<bool> in_group(mesh.vertices.size(), false);
          for (const auto &face : mesh.faces)
            if (face.boundary_id == id)
              for (const unsigned int v : face.vertices)
                in_group[v] = true;
          return in_group;
        };
        const std::vector<bool> on_surface = vertices_of("sliding surface");
        const std::vector<bool> on_ground  = vertices_of("ground");
        std::vector<std::pair<unsigned int, Point<3>>> targets;
        for (unsigned int v = 0; v < mesh.vertices.size(); ++v)
          if (on_surface[v])
            {
              const Point<3> &p = mesh.vertices[v];
              Tensor<1, 3>    d = slope.quadric_gradient(p);
              if (on_ground[v])
                {
                  // The ground's plane at p: z = z_0 + g . (x, y).
                  const Tensor<1, 2> g = slope.ground_gradient(p[0], p[1]);
                  Tensor<1, 3>       n;
                  n[0] = -g[0];
                  n[1] = -g[1];
                  n[2] = 1;
                  n /= n.norm();
                  d -= (d * n) * n;
                }
              targets.emplace_back(v, slope.along_onto_surface(p, d));
            }
        // A corner sine of 1e-2 (an angle of 0.6 degrees) at least: on the
        // default ellipsoid (Mesh size 2 m) the same 7 of 313 vertices stay
        // on the facets for any bound from 1e-10 to 2e-2, the smallest sine
        // of the cells before the move.
        gmsh_3d::move_vertices_keeping_cells_valid(mesh, targets, 1e-2);
      }
    } // namespace



    MeshDescription<3>
    make_slope_3d_mesh(const Slope3D &slope)
    {
      namespace occ          = gmsh::model::occ;
      const std::string name = "Geometry/Slope 3D";
      const std::string unexpected =
        name + ": OpenCASCADE did not cut the sliding mass out of the slope "
               "as expected; try a slightly different sliding surface.";
      const double x_0 = slope.x_min(), x_end = slope.x_max();
      const double y_0 = slope.y_min(), y_end = slope.y_max();
      const double z_base = slope.base_elevation();
      const double tolerance =
        1e-7 * (x_end - x_0 + y_end - y_0 + slope.top_elevation() - z_base);
      const Point<3> &c = slope.centre;
      const double    r = slope.radius;

      GmshSession session;
      gmsh::model::add("slope 3d");
      int              mass = 0;
      std::vector<int> foundation;
      GmshSession::run(name + ": Gmsh could not build the model", [&]() {
        const gmsh::vectorpair slope_solid = {{3, add_slope_3d_solid(slope)}};

        // The solid inside the sliding surface. The capsule's is its
        // straight cylinder fused with a half-ellipsoid on each end disk:
        // fusing whole ellipsoids, tangent to the cylinder along its end
        // circles, gave a solid that OpenCASCADE could not intersect with
        // the slope (measured).
        const auto ellipsoid = [&](const double y, const int end) {
          const int tag =
            end == 0 ? occ::addSphere(c[0], y, c[2], r) :
                       occ::addSphere(c[0], y, c[2], r, -1, 0, numbers::PI / 2);
          // The half's pole from +z onto +y (end 1) or -y (end -1).
          if (end != 0)
            occ::rotate(
              {{3, tag}}, c[0], y, c[2], 1, 0, 0, -end * numbers::PI / 2);
          occ::dilate({{3, tag}}, c[0], y, c[2], 1, slope.half_length / r, 1);
          return tag;
        };
        int inside = 0;
        if (slope.surface == Slope3D::Surface::cylinder)
          inside = occ::addCylinder(
            c[0], 2 * y_0 - y_end, c[2], 0, 3 * (y_end - y_0), 0, r);
        else if (slope.surface == Slope3D::Surface::sphere)
          inside = occ::addSphere(c[0], c[1], c[2], r);
        else if (slope.surface == Slope3D::Surface::ellipsoid)
          inside = ellipsoid(c[1], 0);
        else
          {
            const double                  half = slope.straight_length / 2;
            gmsh::vectorpair              fused;
            std::vector<gmsh::vectorpair> fused_origin;
            occ::fuse(
              {{3,
                occ::addCylinder(c[0], c[1] - half, c[2], 0, 2 * half, 0, r)}},
              {{3, ellipsoid(c[1] + half, 1)}, {3, ellipsoid(c[1] - half, -1)}},
              fused,
              fused_origin);
            AssertThrow(fused.size() == 1, ExcMessage(unexpected));
            inside = fused[0].second;
          }
        gmsh::vectorpair              cut_mass, pieces;
        std::vector<gmsh::vectorpair> origin;
        occ::intersect(
          slope_solid, {{3, inside}}, cut_mass, origin, -1, false, true);
        AssertThrow(cut_mass.size() == 1, ExcMessage(unexpected));
        // Fragmenting makes the sliding surface shared by both volumes.
        occ::fragment(slope_solid, cut_mass, pieces, origin);
        occ::synchronize();
        AssertThrow(origin.size() == 2 && origin[1].size() == 1,
                    ExcMessage(unexpected));
        mass = origin[1][0].second;
        for (const auto &piece : pieces)
          if (piece.first == 3 && piece.second != mass)
            foundation.push_back(piece.second);
      });
      AssertThrow(foundation.size() == 1, ExcMessage(unexpected));

      // Soil layers (slope_3d_layers.cc): both blocks split along the layer
      // boundaries, one material region per layer material.
      std::vector<int> mass_volumes = {mass};
      split_into_layers(slope, {&mass_volumes, &foundation});

      // The faces by the volumes they bound: of both blocks, the sliding
      // surface; of one volume only, the outside (base, sides, ground by
      // their place); of two volumes of one block, a layer boundary inside
      // it, in no group.
      std::vector<int> sliding_surface, ground, base, sides;
      GmshSession::run(name + ": Gmsh could not build the model", [&]() {
        std::map<int, std::pair<unsigned int, unsigned int>> volumes_of;
        for (const bool of_mass : {true, false})
          for (const int volume : of_mass ? mass_volumes : foundation)
            {
              gmsh::vectorpair boundary;
              gmsh::model::getBoundary({{3, volume}}, boundary, false, false);
              for (const auto &dim_tag : boundary)
                {
                  auto &count = volumes_of[std::abs(dim_tag.second)];
                  ++(of_mass ? count.first : count.second);
                }
            }
        for (const auto &[face, count] : volumes_of)
          {
            double x0, y0, z0, x1, y1, z1;
            gmsh::model::getBoundingBox(2, face, x0, y0, z0, x1, y1, z1);
            const auto at =
              [&](const double low, const double high, const double value) {
                return std::abs(low - value) < tolerance &&
                       std::abs(high - value) < tolerance;
              };
            if (count.first > 0 && count.second > 0)
              sliding_surface.push_back(face);
            else if (count.first + count.second > 1)
              continue;
            else if (at(z0, z1, z_base))
              base.push_back(face);
            else if (at(x0, x1, x_0) || at(x0, x1, x_end) || at(y0, y1, y_0) ||
                     at(y0, y1, y_end))
              sides.push_back(face);
            else
              ground.push_back(face);
          }
        AssertThrow(!sliding_surface.empty() && !ground.empty() &&
                      !base.empty() && !sides.empty(),
                    ExcMessage(unexpected));
      });
      GmshSession::run(name + ": Gmsh could not build the model", [&]() {
        add_physical_group(3, mass_volumes, "sliding mass");
        add_physical_group(3, foundation, "foundation");
        add_physical_group(2, sliding_surface, "sliding surface");
        add_physical_group(2, ground, "ground");
        add_physical_group(2, base, "base");
        add_physical_group(2, sides, "sides");
      });

      // Tetrahedra of twice the mesh size within R/4 of the sliding surface,
      // growing by a quarter of the further distance up to three times
      // that; each is then split into four hexahedra.
      const bool hexahedra = slope.element_shape == ElementShape::hypercube;
      GmshSession::run(name + ": Gmsh could not mesh the model", [&]() {
        const double near = (hexahedra ? 2 : 1) * slope.mesh_size;
        gmsh_3d::mesh_near_surfaces(
          sliding_surface, near, 3 * near, r / 4, hexahedra);
      });
      MeshDescription<3> mesh =
        extract_current_gmsh_model<3>(name, slope.layers);
      if (hexahedra)
        move_split_vertices_onto_surface(slope, mesh);
      mesh.surface_normals["sliding surface"] = [slope](const Point<3> &p) {
        return slope.quadric_gradient(p);
      };
      return mesh;
    }
  } // namespace geometry
} // namespace fdem
