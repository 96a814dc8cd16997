// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/cases/case_input.h>
#include <fdem/geometry/cases/hertz_sphere.h>
#include <fdem/geometry/structured_grid.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    namespace
    {
      /**
       * Grid lines from @p from to @p to (either direction), after an
       * element of size @p previous: sizes growing by @p ratio up to
       * @p max_size, their number the one whose sum comes nearest the
       * length, then all scaled to fill it exactly.
       */
      std::vector<double>
      graded_lines(const double from,
                   const double to,
                   const double previous,
                   const double ratio,
                   const double max_size)
      {
        const double        length = std::abs(to - from);
        std::vector<double> sizes;
        double              sum = 0, size = previous;
        while (true)
          {
            size = std::min(size * ratio, std::max(max_size, previous));
            if (!sizes.empty() &&
                std::abs(sum + size - length) > std::abs(sum - length))
              break;
            sizes.push_back(size);
            sum += size;
          }
        std::vector<double> lines;
        double              position = 0;
        for (unsigned int i = 0; i + 1 < sizes.size(); ++i)
          {
            position += sizes[i] * length / sum;
            lines.push_back(from + (to > from ? position : -position));
          }
        lines.push_back(to);
        return lines;
      }
    } // namespace



    void
    HertzSphere::declare_parameters(ParameterHandler &prm)
    {
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



    void
    HertzSphere::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Hertz sphere");
      {
        radius                  = prm.get_double("Radius");
        load_height             = prm.get_double("Load height");
        cap_half_width          = prm.get_double("Cap half width");
        foundation_width        = prm.get_double("Foundation width");
        foundation_depth        = prm.get_double("Foundation depth");
        contact_zone_width      = prm.get_double("Contact zone width");
        n_contact_zone_elements = prm.get_integer("Elements in contact zone");
        growth_ratio            = prm.get_double("Growth ratio");
        mesh_size               = prm.get_double("Mesh size");
      }
      prm.leave_subsection();
    }



    void
    HertzSphere::validate() const
    {
      const std::string path = "Geometry/Hertz sphere/";
      const double      r = radius, s = cap_half_width;
      case_input::require(r > 0, path + "Radius: must be positive.");
      case_input::require(contact_zone_width > 0 && contact_zone_width < s,
                          path +
                            "Contact zone width: must be positive and smaller "
                            "than Cap half width.");
      case_input::require(s * std::sqrt(2.0) < r,
                          path +
                            "Cap half width: S sqrt(2) must be smaller than "
                            "Radius, so that the sphere's surface spans the "
                            "square plan.");
      case_input::require(load_height <= r &&
                            load_height > r - std::sqrt(r * r - 2 * s * s) +
                                            contact_zone_width,
                          path +
                            "Load height: must be at most Radius and exceed "
                            "the height of the sphere's surface at the corner "
                            "(S, S) of its plan by more than Contact zone "
                            "width.");
      case_input::require(foundation_width > s,
                          path +
                            "Foundation width: must be larger than Cap half "
                            "width.");
      case_input::require(foundation_depth > contact_zone_width,
                          path +
                            "Foundation depth: must be larger than Contact "
                            "zone width.");
      case_input::require(mesh_size > 0, path + "Mesh size: must be positive.");
    }



    MeshDescription<3>
    make_hertz_sphere_mesh(const HertzSphere &hertz_sphere)
    {
      const auto        &p     = hertz_sphere;
      const double       r     = p.radius;
      const double       lc    = p.contact_zone_width;
      const unsigned int n     = p.n_contact_zone_elements;
      const double       ratio = p.growth_ratio;

      // Lines in x and y (both blocks): the first n_sphere_xy up to S, all
      // up to W.
      std::vector<double> xy;
      for (unsigned int i = 0; i <= n; ++i)
        xy.push_back(lc * i / n);
      const auto append = [&](std::vector<double> &lines, const double to) {
        const double previous = lines.back() - lines[lines.size() - 2];
        for (const double x :
             graded_lines(lines.back(), to, previous, ratio, p.mesh_size))
          lines.push_back(x);
      };
      append(xy, p.cap_half_width);
      const unsigned int n_sphere_xy = xy.size();
      append(xy, p.foundation_width);
      const unsigned int n_xy = xy.size();

      // Depths below z = 0 and heights above the sphere's surface: the
      // element size Lc/n down to Lc, then growing.
      std::vector<double> depth;
      for (unsigned int i = 0; i <= n; ++i)
        depth.push_back(lc * i / n);
      append(depth, p.foundation_depth);
      // The sphere's layers as fractions of its height H - z_s(x, y) over
      // the axis, where that height is H.
      std::vector<double> height;
      for (unsigned int i = 0; i <= n; ++i)
        height.push_back(lc * i / n);
      append(height, p.load_height);
      const auto surface = [&](const double x, const double y) {
        return r - std::sqrt(r * r - x * x - y * y);
      };

      MeshDescription<3> mesh;
      mesh.source           = "Geometry/Hertz sphere";
      mesh.block_names      = {"sphere", "foundation"};
      mesh.face_group_names = {"contact surface",
                               "load",
                               "symmetry",
                               "bottom",
                               "sphere surface",
                               "foundation surface",
                               "foundation side"};
      enum Group
      {
        contact_surface,
        load,
        symmetry,
        bottom,
        sphere_surface,
        foundation_surface,
        foundation_side
      };

      // Foundation vertices (i, j, k) with k = 0 at the bottom.
      const unsigned int n_depth = depth.size();
      for (unsigned int k = 0; k < n_depth; ++k)
        for (unsigned int j = 0; j < n_xy; ++j)
          for (unsigned int i = 0; i < n_xy; ++i)
            mesh.vertices.emplace_back(xy[i], xy[j], -depth[n_depth - 1 - k]);
      const auto foundation_index =
        [&](const unsigned int i, const unsigned int j, const unsigned int k) {
          return (k * n_xy + j) * n_xy + i;
        };
      // Sphere vertices, k = 0 on its surface; the origin is shared.
      const unsigned int        n_height = height.size();
      std::vector<unsigned int> sphere_vertex;
      for (unsigned int k = 0; k < n_height; ++k)
        for (unsigned int j = 0; j < n_sphere_xy; ++j)
          for (unsigned int i = 0; i < n_sphere_xy; ++i)
            {
              if (i == 0 && j == 0 && k == 0)
                {
                  sphere_vertex.push_back(foundation_index(0, 0, n_depth - 1));
                  continue;
                }
              const double z_s = surface(xy[i], xy[j]);
              const double z =
                z_s + height[k] / p.load_height * (p.load_height - z_s);
              sphere_vertex.push_back(mesh.vertices.size());
              mesh.vertices.emplace_back(xy[i], xy[j], z);
            }
      const auto sphere_index =
        [&](const unsigned int i, const unsigned int j, const unsigned int k) {
          return sphere_vertex[(k * n_sphere_xy + j) * n_sphere_xy + i];
        };

      add_structured_grid(mesh,
                          {{n_sphere_xy - 1, n_sphere_xy - 1, n_height - 1}},
                          sphere_index,
                          0,
                          [&](const unsigned int d,
                              const unsigned int side,
                              const unsigned int i,
                              const unsigned int j) -> types::boundary_id {
                            if (d < 2)
                              return side == 0 ? symmetry : sphere_surface;
                            if (side == 1)
                              return load;
                            return (i < n && j < n) ? contact_surface :
                                                      sphere_surface;
                          });
      add_structured_grid(mesh,
                          {{n_xy - 1, n_xy - 1, n_depth - 1}},
                          foundation_index,
                          1,
                          [&](const unsigned int d,
                              const unsigned int side,
                              const unsigned int i,
                              const unsigned int j) -> types::boundary_id {
                            if (d < 2)
                              return side == 0 ? symmetry : foundation_side;
                            if (side == 0)
                              return bottom;
                            return (i < n && j < n) ? contact_surface :
                                                      foundation_surface;
                          });
      return mesh;
    }
  } // namespace geometry
} // namespace fdem
