// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/geometry/gmsh_mesh.h>
#include <fdem/geometry/mesh_estimate.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <gmsh.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    using namespace dealii;
    using Source = parameters::GeometryParameters::Source;

    namespace
    {
      constexpr double infinity = std::numeric_limits<double>::infinity();

      /**
       * Cells of size s(d) in a region whose measure (area or volume)
       * within distance d of the fine part is measure(d), up to the total:
       * the integral of d(measure) / s^dim, the fine part's own measure at
       * d = 0 included, then the rest at the far size. Gmsh's Threshold
       * field: s = near up to fine, growing linearly to far at coarse.
       */
      double
      cells_in_graded_region(const unsigned int                   dim,
                             const std::function<double(double)> &measure,
                             const double                         total,
                             const double                         near,
                             const double                         far,
                             const double                         fine,
                             const double                         coarse)
      {
        const auto size = [&](const double d) {
          return d <= fine ? near :
                 d >= coarse ?
                             far :
                             near + (far - near) * (d - fine) / (coarse - fine);
        };
        if (!(coarse > fine)) // one size everywhere
          return total / std::pow(near, dim);
        const auto clipped = [&](const double d) {
          return std::min(total, measure(d));
        };
        double       cells    = clipped(fine) / std::pow(near, dim);
        double       previous = clipped(fine);
        const int    steps    = 200;
        const double step     = (coarse - fine) / steps;
        for (int i = 1; i <= steps; ++i)
          {
            const double d = fine + i * step;
            const double m = clipped(d);
            cells += (m - previous) / std::pow(size(d - 0.5 * step), dim);
            previous = m;
          }
        return cells + (total - previous) / std::pow(far, dim);
      }

      /**
       * The number of lines HertzSphere's graded_lines() makes over
       * @p length after a size @p previous, counted without storing them;
       * infinite beyond @p cap.
       */
      double
      n_graded_lines(const double length,
                     const double previous,
                     const double ratio,
                     const double max_size,
                     const double cap = 1e7)
      {
        double sum = 0, size = previous, n = 0;
        while (n < cap)
          {
            size = std::min(size * ratio, std::max(max_size, previous));
            if (n > 0 && std::abs(sum + size - length) > std::abs(sum - length))
              return n;
            sum += size;
            ++n;
          }
        return infinity;
      }

      MeshEstimate
      estimate_slope(const Slope &slope)
      {
        const auto &g    = slope.ground_surface;
        double      area = 0, length = 0;
        for (unsigned int i = 1; i < g.size(); ++i)
          {
            area += std::abs(g[i][0] - g[i - 1][0]) *
                    (0.5 * (g[i][1] + g[i - 1][1]) - slope.base_elevation);
            length += g[i].distance(g[i - 1]);
          }
        const double h   = slope.mesh_size;
        const double h_s = std::min(slope.mesh_size_on_sliding_surface, h);
        // Gmsh's recombined quadrilaterals there: 1.2 vertices per h^2
        // (10567 on the paper's slope, 550 m^2, at h = 0.25 m; 4.1 million
        // Q2 dofs at h = 0.035 m, doc/scaling.md).
        const double everywhere_fine = area / (h_s * h_s);
        const double banded = area / (h * h) + length * h / (h_s * h_s);
        MeshEstimate e;
        e.entry      = (h_s < h && length * h / (h_s * h_s) > area / (h * h)) ?
                         "Geometry/Slope/Mesh size on sliding surface" :
                         "Geometry/Slope/Mesh size";
        e.n_vertices = 1.2 * std::min(everywhere_fine, banded);
        e.n_cells    = e.n_vertices;
        e.n_pairs    = length / h_s;
        return e;
      }

      MeshEstimate
      estimate_hertz(const Hertz &hertz)
      {
        const double r = hertz.radius, lc = hertz.contact_zone_width;
        const double near = lc / hertz.n_contact_zone_elements;
        // Gmsh's Threshold field takes Mesh size far off even when it is
        // finer than the contact zone's elements.
        const double far   = hertz.mesh_size;
        const double total = numbers::PI * r * r / 4 +
                             hertz.foundation_width * hertz.foundation_depth;
        // Both curves of the contact zone, each with its band on one side.
        const auto band = [&](const double d) {
          return 2 * (lc * d + numbers::PI * d * d / 2);
        };
        const double fine = 0.5 * lc, coarse = fine + 4 * std::abs(far - near);
        const bool   triangles = hertz.element_shape == ElementShape::simplex;
        const double per_size =
          cells_in_graded_region(2, band, total, near, far, fine, coarse);
        const double copies = hertz.full_model ? 2 : 1;
        MeshEstimate e;
        e.entry      = "Geometry/Hertz/Mesh size, Elements in contact zone "
                       "and the lengths";
        e.n_vertices = copies * (triangles ? 1.15 : 1.0) * per_size;
        e.n_cells    = copies * (triangles ? 2.3 : 1.0) * per_size;
        e.n_pairs    = copies * (hertz.n_contact_zone_elements + 1);
        return e;
      }

      template <int dim>
      MeshEstimate
      estimate_block_on_plane(const BlockOnPlane<dim> &b)
      {
        // As make_block_on_plane_mesh(): the block's elements, the
        // foundation's of the same size (at least one across the overhang
        // and the thickness), in doubles so that nothing overflows.
        const auto n_across = [](const double distance, const double size) {
          return std::max(1.0, std::round(distance / size));
        };
        double block =
          b.n_elements_along_length * double(b.n_elements_across_height);
        double plan = b.n_elements_along_length +
                      2 * n_across(b.foundation_overhang,
                                   b.block_length / b.n_elements_along_length);
        double pairs = b.n_elements_along_length + 1.0;
        if constexpr (dim == 3)
          {
            block *= b.n_elements_along_width;
            plan *= b.n_elements_along_width +
                    2 * n_across(b.foundation_overhang,
                                 b.block_width / b.n_elements_along_width);
            pairs *= b.n_elements_along_width + 1.0;
          }
        const double foundation =
          plan * n_across(b.foundation_thickness,
                          b.block_height / b.n_elements_across_height);
        MeshEstimate e;
        e.entry = "Geometry/" + BlockOnPlane<dim>::subsection_name() +
                  ": the numbers of elements and the foundation's size";
        bool split = false;
        if constexpr (dim == 2)
          split = b.element_shape == ElementShape::simplex;
        e.n_cells    = (block + foundation) * (split ? 2 : 1);
        e.n_vertices = block + foundation;
        e.n_pairs    = pairs;
        return e;
      }

      MeshEstimate
      estimate_hertz_sphere(const HertzSphere &p)
      {
        const double n  = p.n_contact_zone_elements;
        const double lc = p.contact_zone_width, size = lc / n;
        const auto   lines = [&](const double to) {
          return n + n_graded_lines(to - lc, size, p.growth_ratio, p.mesh_size);
        };
        const double xy_sphere = lines(p.cap_half_width);
        const double xy        = lines(p.foundation_width);
        MeshEstimate e;
        e.entry   = "Geometry/Hertz sphere: Elements in contact zone, Growth "
                    "ratio, Mesh size and the lengths";
        e.n_cells = xy * xy * lines(p.foundation_depth) +
                    xy_sphere * xy_sphere * lines(p.load_height);
        e.n_vertices = e.n_cells;
        e.n_pairs    = (n + 1) * (n + 1);
        return e;
      }

      MeshEstimate
      estimate_wedge(const Wedge &wedge)
      {
        const std::array<Point<3>, 4> c = wedge.corners();
        const Tensor<1, 3> a = c[1] - c[0], b = c[2] - c[0], d = c[3] - c[0];
        const double       volume = std::abs(a * cross_product_3d(b, d)) / 6;
        double             area = 0, planes = 0;
        for (unsigned int i = 0; i < 4; ++i)
          {
            const Tensor<1, 3> u = c[(i + 1) % 4] - c[i],
                               v = c[(i + 2) % 4] - c[i];
            area += 0.5 * cross_product_3d(u, v).norm();
          }
        // Planes A and B: the faces (apex, top, crest end on A or B).
        planes = 0.5 * (cross_product_3d(c[1] - c[0], c[2] - c[0]).norm() +
                        cross_product_3d(c[1] - c[0], c[3] - c[0]).norm());
        // The rock: the box around the wedge and the crest, the extent
        // beyond it on every side (an upper bound: the air above the slope
        // face is counted).
        Point<3> low = c[0], high = c[0];
        for (const Point<3> &p : {c[1], c[2], c[3], wedge.crest_point()})
          for (unsigned int k = 0; k < 3; ++k)
            {
              low[k]  = std::min(low[k], p[k]);
              high[k] = std::max(high[k], p[k]);
            }
        double box = 1;
        for (unsigned int k = 0; k < 3; ++k)
          box *= high[k] - low[k] + 2 * wedge.rock_extent;
        const bool   hexahedra = wedge.element_shape == ElementShape::hypercube;
        const double near      = (hexahedra ? 2 : 1) * wedge.mesh_size;
        const double far       = 5 * near;
        const double inradius  = 3 * volume / area;
        const auto   grown     = [&](const double r) {
          return volume + area * r + 4 * numbers::PI / 3 * r * r * r;
        };
        // Tetrahedra of edge s: about 8.5 per s^3, 5.5 per vertex.
        const double tetrahedra =
          8.5 * cells_in_graded_region(3,
                                       grown,
                                       box,
                                       near,
                                       far,
                                       inradius,
                                       inradius + 4 * std::abs(far - near));
        MeshEstimate e;
        e.entry = "Geometry/Wedge/Mesh size and Rock extent";
        // Split into four hexahedra each: new vertices on every edge, face
        // and cell, about 24 per vertex of the tetrahedra.
        e.n_cells    = tetrahedra * (hexahedra ? 4 : 1);
        e.n_vertices = tetrahedra / 5.5 * (hexahedra ? 24 : 1);
        e.n_pairs    = 1.15 * planes / std::pow(0.65 * wedge.mesh_size, 2);
        return e;
      }

      /**
       * The area of the part of the sliding surface below the ground and
       * the length of its rim, on an n x n grid of the surface's two
       * parameters (Slope3D::surface_point(): along y and about the axis): the
       * cells whose centre is below the ground, and the edges between such a
       * cell and one above it or the model's side. The rim is a staircase along
       * the grid, longer than the true curve (up to 4/pi for a curve at 45
       * degrees to the grid): a margin.
       */
      std::pair<double, double>
      sliding_surface_area_and_rim(const Slope3D &slope)
      {
        const unsigned int n     = 200;
        const auto         point = [&](const double s, const double t) {
          return slope.surface_point(s / n, 2 * numbers::PI * t / n);
        };
        std::vector<bool> below(n * n);
        double            area = 0, rim = 0;
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              const Point<3> centre = point(i + 0.5, j + 0.5);
              below[i * n + j] = centre[2] < slope.ground(centre[0], centre[1]);
              if (below[i * n + j])
                area +=
                  0.5 * cross_product_3d(point(i + 1, j + 1) - point(i, j),
                                         point(i, j + 1) - point(i + 1, j))
                          .norm();
            }
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            if (below[i * n + j])
              {
                // Across s: the grid's end is the model's side (cylinder)
                // or a pole (an edge of length 0); around t: periodic.
                if (i == 0 || !below[(i - 1) * n + j])
                  rim += point(i, j).distance(point(i, j + 1));
                if (i == n - 1 || !below[(i + 1) * n + j])
                  rim += point(i + 1, j).distance(point(i + 1, j + 1));
                if (!below[i * n + (j + n - 1) % n])
                  rim += point(i, j).distance(point(i + 1, j));
                if (!below[i * n + (j + 1) % n])
                  rim += point(i, j + 1).distance(point(i + 1, j + 1));
              }
        return {area, rim};
      }

      MeshEstimate
      estimate_slope_3d(const Slope3D &slope)
      {
        // An upper bound: the whole model at the size near the sliding
        // surface.
        const bool   hexahedra = slope.element_shape == ElementShape::hypercube;
        const double near      = (hexahedra ? 2 : 1) * slope.mesh_size;
        const double volume    = slope.model_volume();
        const double tetrahedra = 8.5 * volume / (near * near * near);
        // The pairs: Gmsh's triangles of edge s on the sliding surface have
        // 2 / (sqrt(3) s^2) = 1.155 vertices per s^2 inside, and about one
        // per s along the rim. Split into three quadrilaterals each (a
        // vertex more per edge and per triangle, Euler's formula): six times
        // the inner vertices, four times the rim's. The test
        // MeshEstimate.PairsOfTheSlope3DAnUpperBoundWithin30Percent: 7 to 8 %
        // above the count (261 to 441 pairs); 1.2 and the staircase rim
        // (longer than the true one) keep it an upper bound.
        const auto [area, rim] = sliding_surface_area_and_rim(slope);
        MeshEstimate e;
        e.entry      = "Geometry/Slope 3D/Mesh size";
        e.n_cells    = tetrahedra * (hexahedra ? 4 : 1);
        e.n_vertices = tetrahedra / 5.5 * (hexahedra ? 24 : 1);
        e.n_pairs    = (hexahedra ? 6 : 1) * 1.2 * area / (near * near) +
                    (hexahedra ? 4 : 1) * rim / near;
        return e;
      }
    } // namespace



    double
    MeshEstimate::memory_MiB(const unsigned int dim,
                             const unsigned int fe_degree,
                             const bool         dense_mixed_system) const
    {
      const double n_dofs =
        dim * n_vertices * std::pow(double(fe_degree), int(dim));
      // Dense: 150 bytes per (dim n_pairs)^2, 115 to 137 measured on
      // prm/slope_3d.prm at 261 to 624 pairs (doc/scaling.md, "3D: a slope
      // on a sphere"), with a tenth more as a margin. Iterative: what the
      // block on a plane needed beyond 2950 bytes per dof, per pair: 64 to
      // 75 kB at 1681 to 4225 pairs, 184 kB at 10^4 (378000 dofs; the 3D
      // factorisation's fill grows faster than the dofs, and the peak still
      // rose by about 10 MiB per status iteration when the run was
      // stopped, doc/scaling.md). 300 kB keeps the estimate (with the
      // generator's node count, a third below the mesh's there) above
      // those peaks.
      const double interface = dense_mixed_system ?
                                 150.0 * dim * dim * n_pairs * n_pairs :
                                 300e3 * n_pairs;
      return (2950 * n_dofs + interface) / (1 << 20);
    }



    MeshEstimate
    estimate_mesh(const parameters::GeometryParameters &geometry)
    {
      switch (geometry.source)
        {
          case Source::slope:
            return estimate_slope(geometry.slope);
          case Source::hertz:
            return estimate_hertz(geometry.hertz);
          case Source::inclined_block:
            return estimate_block_on_plane(geometry.inclined_block);
          case Source::block_on_plane:
            return estimate_block_on_plane(geometry.block_on_plane);
          case Source::hertz_sphere:
            return estimate_hertz_sphere(geometry.hertz_sphere);
          case Source::wedge:
            return estimate_wedge(geometry.wedge);
          case Source::slope_3d:
            return estimate_slope_3d(geometry.slope_3d);
          default:
            return MeshEstimate();
        }
    }



    double
    memory_limit_MiB(const parameters::GeometryParameters &geometry)
    {
      if (geometry.memory_limit > 0)
        return geometry.memory_limit;
      double limit =
        double(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGE_SIZE) / (1 << 20);
      struct rlimit address_space;
      if (getrlimit(RLIMIT_AS, &address_space) == 0 &&
          address_space.rlim_cur != RLIM_INFINITY)
        limit = std::min(limit, double(address_space.rlim_cur) / (1 << 20));
      return limit;
    }



    MeshEstimate
    estimate_gmsh_geometry(const unsigned int dim, const std::string &file_name)
    {
      // The curves (2D) or surfaces (3D) meshed first: Gmsh then goes on
      // from them when it meshes the rest.
      GmshSession::run("Gmsh could not mesh the boundaries in '" + file_name +
                         "'",
                       [&]() { gmsh::model::mesh::generate(dim - 1); });
      gmsh::vectorpair entities;
      gmsh::model::getEntities(entities, dim);
      MeshEstimate e;
      e.entry = "Geometry/Mesh file '" + file_name + "'";
      for (const auto &entity : entities)
        {
          gmsh::vectorpair boundary;
          gmsh::model::getBoundary({entity}, boundary, false, false, false);
          double n = 0;
          for (const auto &[boundary_dim, tag] : boundary)
            {
              std::vector<int>                      types;
              std::vector<std::vector<std::size_t>> tags, nodes;
              gmsh::model::mesh::getElements(
                types, tags, nodes, boundary_dim, std::abs(tag));
              for (const auto &t : tags)
                n += t.size();
            }
          // A disk has the most area for its boundary: n segments of size h
          // bound at most n^2 h^2 / (4 pi), 2.3 triangles per h^2; a ball
          // bounded by n triangles holds at most 0.227 n^1.5 tetrahedra.
          const double cells = dim == 2 ? 2.3 * n * n / (4 * numbers::PI) :
                                          0.227 * std::pow(n, 1.5);
          e.n_cells += cells;
          e.n_vertices += dim == 2 ? cells / 2 : cells / 5.5;
        }
      return e;
    }



    MeshEstimate
    check_mesh_estimate(const parameters::GeometryParameters &geometry,
                        const unsigned int                    dim,
                        const unsigned int                    fe_degree,
                        const bool dense_mixed_system)
    {
      return check_mesh_estimate(
        estimate_mesh(geometry), geometry, dim, fe_degree, dense_mixed_system);
    }



    MeshEstimate
    check_mesh_estimate(const MeshEstimate                   &e,
                        const parameters::GeometryParameters &geometry,
                        const unsigned int                    dim,
                        const unsigned int                    fe_degree,
                        const bool dense_mixed_system)
    {
      if (e.entry.empty())
        return e;
      const double       mib = e.memory_MiB(dim, fe_degree, dense_mixed_system);
      const double       limit = memory_limit_MiB(geometry);
      std::ostringstream message;
      message.precision(3);
      message << e.entry << ": about " << e.n_cells << " elements";
      if (e.n_pairs > 0)
        message << ", " << e.n_vertices << " nodes and " << e.n_pairs
                << " node pairs";
      else
        message << " and " << e.n_vertices << " nodes";
      message << ", which would need about " << mib << " MiB, more than the "
              << limit
              << " MiB allowed (Geometry/Memory limit; 0 is this machine's "
                 "memory or ulimit -v); use a coarser mesh or raise the limit";
      // The dense interface parts grow as pairs^2: say when the mixed
      // system that never forms them would fit.
      const double iterative_mib = e.memory_MiB(dim, fe_degree, false);
      if (dense_mixed_system && e.n_pairs > 0 && std::isfinite(iterative_mib) &&
          iterative_mib <= limit)
        message << ", or set Solver/Mixed system = iterative (about "
                << iterative_mib << " MiB)";
      message << ".";
      AssertThrow(std::isfinite(mib) && mib <= limit,
                  ExcMessage(message.str()));
      return e;
    }
  } // namespace geometry
} // namespace fdem
