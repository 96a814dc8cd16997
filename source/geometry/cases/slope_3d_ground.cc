// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The ground of the 3D slope generator: the straight slope's section
// extruded along y, or a terrain from a grid of elevations. Everything that
// asks where the ground is (the checks of the sliding surface, the layers,
// the split vertices' moves, the size estimate) asks here.

#include <fdem/geometry/cases/gmsh_3d.h>
#include <fdem/geometry/cases/slope_3d.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <gmsh.h>

#include <cmath>

namespace fdem
{
  namespace geometry
  {
    double
    Slope3D::crest_x() const
    {
      return toe_length +
             slope_height / std::tan(slope_angle * numbers::PI / 180);
    }



    double
    Slope3D::x_min() const
    {
      return terrain.empty() ? 0 : terrain.x.front();
    }



    double
    Slope3D::x_max() const
    {
      return terrain.empty() ? crest_x() + crest_length : terrain.x.back();
    }



    double
    Slope3D::y_min() const
    {
      return terrain.empty() ? 0 : terrain.y.front();
    }



    double
    Slope3D::y_max() const
    {
      return terrain.empty() ? width : terrain.y.back();
    }



    double
    Slope3D::base_elevation() const
    {
      return (terrain.empty() ? toe_elevation : terrain.min_elevation()) -
             base_depth;
    }



    double
    Slope3D::top_elevation() const
    {
      return terrain.empty() ? toe_elevation + slope_height :
                               terrain.max_elevation();
    }



    double
    Slope3D::ground(const double x, const double y) const
    {
      if (!terrain.empty())
        return terrain.elevation(x, y);
      const double x_toe = toe_length, x_crest = crest_x();
      if (x <= x_toe)
        return toe_elevation;
      if (x >= x_crest)
        return toe_elevation + slope_height;
      return toe_elevation + slope_height * (x - x_toe) / (x_crest - x_toe);
    }



    Tensor<1, 2>
    Slope3D::ground_gradient(const double x, const double y) const
    {
      if (!terrain.empty())
        return terrain.gradient(x, y);
      Tensor<1, 2> g;
      if (x > toe_length && x < crest_x())
        g[0] = slope_height / (crest_x() - toe_length);
      return g;
    }



    std::vector<Point<2>>
    Slope3D::ground_profile() const
    {
      if (!terrain.empty())
        return terrain.lowest_profile();
      const double z_top = toe_elevation + slope_height;
      return {Point<2>(0, toe_elevation),
              Point<2>(toe_length, toe_elevation),
              Point<2>(crest_x(), z_top),
              Point<2>(x_max(), z_top)};
    }



    double
    Slope3D::model_volume() const
    {
      if (!terrain.empty())
        return terrain.volume_above(base_elevation());
      // The section: the rectangle up to the toe and the slope above it.
      const double h = slope_height;
      return width * (x_max() * base_depth +
                      h * (x_max() - 0.5 * (crest_x() + toe_length)));
    }



    int
    add_slope_3d_solid(const Slope3D &slope)
    {
      namespace occ       = gmsh::model::occ;
      const double z_base = slope.base_elevation();
      if (slope.terrain.empty())
        {
          const double z_toe = slope.toe_elevation;
          const double z_top = z_toe + slope.slope_height;
          return gmsh_3d::add_extruded_polygon(
            {Point<2>(0, z_base),
             Point<2>(slope.x_max(), z_base),
             Point<2>(slope.x_max(), z_top),
             Point<2>(slope.crest_x(), z_top),
             Point<2>(slope.toe_length, z_toe),
             Point<2>(0, z_toe)},
            0,
            slope.width);
        }
      // One closed wire per grid line in y, with the same edges in the same
      // order (base, back, the ground from the back to the front, front),
      // so that the ruled faces join corresponding edges: between two ground
      // edges the straight lines from (x, y_j) to (x, y_j+1) sweep the
      // bilinear cell.
      const TerrainGrid &t = slope.terrain;
      const unsigned int m = t.x.size();
      std::vector<int>   wires;
      for (unsigned int j = 0; j < t.y.size(); ++j)
        {
          std::vector<int> points;
          points.push_back(occ::addPoint(t.x[0], t.y[j], z_base));
          points.push_back(occ::addPoint(t.x[m - 1], t.y[j], z_base));
          for (unsigned int i = m; i-- > 0;)
            points.push_back(occ::addPoint(t.x[i], t.y[j], t.at(i, j)));
          std::vector<int> lines;
          for (unsigned int k = 0; k < points.size(); ++k)
            lines.push_back(
              occ::addLine(points[k], points[(k + 1) % points.size()]));
          wires.push_back(occ::addWire(lines, -1, true));
        }
      gmsh::vectorpair solid;
      occ::addThruSections(wires, solid, -1, true, true);
      for (const auto &dim_tag : solid)
        if (dim_tag.first == 3)
          return dim_tag.second;
      AssertThrow(false,
                  ExcMessage("Geometry/Slope 3D/Terrain file: OpenCASCADE "
                             "could not make a solid of the terrain."));
      return 0;
    }
  } // namespace geometry
} // namespace fdem
