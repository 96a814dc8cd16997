// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    using namespace dealii;

    /**
     * A ground surface given by its elevations on a rectangular grid: z at
     * every pair of the grid lines x_0 < ... < x_m and y_0 < ... < y_n,
     * bilinear on each cell between them (the surface that ruled faces
     * between the grid's sections along x make, see make_slope_3d_mesh()).
     * Read from a text file of lines "x, y, z" (terrain_grid_from_file()).
     */
    struct TerrainGrid
    {
      /** The grid lines in x and y, increasing, at least two each. */
      std::vector<double> x, y;
      /** z (m) at (x[i], y[j]) in z[j * x.size() + i]. */
      std::vector<double> z;

      bool
      empty() const
      {
        return z.empty();
      }

      /** z at the grid point (i, j). */
      double
      at(const unsigned int i, const unsigned int j) const
      {
        return z[j * x.size() + i];
      }

      /** The bilinear elevation at (@p px, @p py), clamped to the grid. */
      double
      elevation(const double px, const double py) const;

      /**
       * The gradient (dz/dx, dz/dy) of elevation() at (@p px, @p py), of
       * the cell the point is in (at a grid line, the cell after it).
       */
      Tensor<1, 2>
      gradient(const double px, const double py) const;

      double
      min_elevation() const;

      double
      max_elevation() const;

      /**
       * The lowest elevation over y at each x, as a polyline with
       * increasing x: at every grid line in x and 16 points between
       * consecutive ones (the exact lowest profile is piecewise linear with
       * kinks where two of the sections along x cross; the polyline through
       * these samples lies at most a sixteenth of a cell's variation above
       * it).
       */
      std::vector<Point<2>>
      lowest_profile() const;

      /** The volume between the surface and the plane z = @p z_base over
       * the grid's rectangle (exact for the bilinear cells). */
      double
      volume_above(const double z_base) const;
    };

    /**
     * Reads the grid from @p file_name: lines "x, y, z" (m; separated by
     * commas, semicolons or blanks; '#' starts a comment; a first line
     * without any number is a header), in any order, one line per point of
     * the grid. Throws a one-line message naming @p entry, the file and
     * the line if a line is not three finite numbers, a point comes twice,
     * a point of the grid is missing, or the grid has fewer than two lines
     * in x or y.
     */
    TerrainGrid
    terrain_grid_from_file(const std::string &file_name,
                           const std::string &entry);

    /** Whether @p file_name is a surface for Gmsh (.msh, .geo, .stl) rather
     * than a grid of lines. */
    bool
    is_surface_mesh_file(const std::string &file_name);

    /**
     * Samples the surface (ground or water) in @p file_name, a Gmsh file (a
     * .msh of triangles or quadrangles, a .geo Gmsh meshes, an .stl), on a
     * grid over its extent in x and y in steps of at most @p spacing (0: 200
     * along the longer side): each grid point takes the elevation of the
     * element above or below it (linear on its flat corners). Throws a
     * one-line message naming @p entry and the file if the file cannot be
     * read, has no surface, does not cover a grid point (the surface must
     * cover the rectangle of its extent), has two elevations at one (an
     * overhang), or the grid would exceed 1e6 points (naming the spacing's
     * entry: @p entry with "file" replaced by "grid spacing").
     */
    TerrainGrid
    terrain_grid_from_surface(const std::string &file_name,
                              const std::string &entry,
                              const double       spacing);
  } // namespace geometry
} // namespace fdem
