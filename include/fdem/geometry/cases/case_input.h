// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <functional>
#include <string>
#include <vector>

namespace fdem
{
  namespace geometry
  {
    using namespace dealii;

    /**
     * Shape of the cells a generator makes: quadrilaterals or hexahedra
     * (FE_Q), or triangles or tetrahedra (FE_SimplexP).
     */
    enum class ElementShape
    {
      hypercube,
      simplex
    };

    /**
     * Orientation of a plane in 3D by its dip and dip direction, with x =
     * east, y = north and z = up.
     */
    struct PlaneOrientation
    {
      /** Dip psi: angle below the horizontal (degrees, 0 to 90). */
      double dip = 0;
      /**
       * Dip direction alpha: azimuth of the line of steepest descent
       * (degrees clockwise from north, 0 to 360).
       */
      double dip_direction = 0;

      /**
       * The upward unit normal n = (sin psi sin alpha, sin psi cos alpha,
       * cos psi).
       */
      Tensor<1, 3>
      upward_normal() const;

      /**
       * The unit vector down the line of steepest descent,
       * (cos psi sin alpha, cos psi cos alpha, -sin psi); horizontal towards
       * the dip direction for a horizontal plane.
       */
      Tensor<1, 3>
      down_dip_direction() const;

      /** Whether the dip lies in [0, 90] and the dip direction in [0, 360]. */
      bool
      is_valid() const;
    };

    /**
     * Pieces that the geometry cases share to declare, read and check their
     * .prm entries (see the case headers in this folder).
     */
    namespace case_input
    {
      /** Throw ExcMessage(@p message) unless @p condition holds; messages
       * start with the entry's path, e.g. "Geometry/Slope/Mesh size: ...". */
      void
      require(const bool condition, const std::string &message);

      /** Pattern of a list of points "x,y; x,y; ..." of at least
       * @p min_n_points points. */
      Patterns::List
      point_list_pattern(const unsigned int min_n_points);

      /** The point "x,y". */
      Point<2>
      parse_point(const std::string &text);

      /** The fields of a line of a data file, split at commas, semicolons
       * and blanks (empty fields dropped). */
      std::vector<std::string>
      split_fields(const std::string &line);

      /**
       * Calls @p row for each data line of the text table @p file_name:
       * with the line's number N, "@p where line N: " for its messages and
       * its fields (split_fields()). '#' starts a comment, blank lines are
       * skipped, and a first line none of whose fields is a number is a header.
       * Throws
       * "@p where cannot be read" if the file cannot be opened.
       */
      void
      for_each_table_row(
        const std::string &file_name,
        const std::string &where,
        const std::function<void(const unsigned int              line_number,
                                 const std::string              &at,
                                 const std::vector<std::string> &fields)> &row);

      /** Whether @p text is a whole number (strtod, nothing left over, no
       * overflow); the number in @p value. */
      bool
      parse_number(const std::string &text, double &value);

      /** The points "x,y; x,y; ...". */
      std::vector<Point<2>>
      parse_points(const std::string &text);

      /**
       * Declare "Element shape" of a 2D generator: quadrilateral or
       * triangle; @p how says how the generator makes each.
       */
      void
      declare_element_shape_2d(ParameterHandler &prm, const std::string &how);

      /** The shape selected by "Element shape" ("triangle"/"tetrahedron":
       * simplices). */
      ElementShape
      parse_element_shape(ParameterHandler &prm);

      /** Pattern of a plane orientation "dip, dip direction". */
      Patterns::List
      orientation_pattern();

      /** @p value as a message shows it (the stream's default format). */
      std::string
      number_text(const double value);

      /** Help text of a plane orientation entry about @p plane. */
      std::string
      orientation_help(const std::string &plane);

      /** The orientation "dip, dip direction". */
      PlaneOrientation
      parse_orientation(const std::string &text);

      /** y of the polyline @p line (points with increasing x) at @p x,
       * linear between its points and constant beyond its ends. */
      double
      polyline_elevation(const std::vector<Point<2>> &line, const double x);

      /** The distance from @p p to the polyline @p line (any points). */
      double
      distance_to_polyline(const Point<2>              &p,
                           const std::vector<Point<2>> &line);

      /** The x of the points of @p a and @p b strictly inside
       * (x_min, x_max), and the two ends, in increasing order: where two
       * polylines may change slope, so that between two of these x they can
       * cross at most once. */
      std::vector<double>
      polyline_breakpoints(const std::vector<Point<2>> &a,
                           const std::vector<Point<2>> &b,
                           const double                 x_min,
                           const double                 x_max);

      /**
       * Layer boundaries "x,y; x,y; ... | x,y; ..." (polylines separated by
       * '|'); @p entry names the entry in messages. Empty: none.
       */
      std::vector<std::vector<Point<2>>>
      parse_layer_boundaries(const std::string &text, const std::string &entry);

      /**
       * Checks soil layers (material names from the top down) and the
       * boundaries between them against a model whose section is bounded
       * above by the polyline @p ground (increasing x, spanning the model)
       * and below by the elevation @p base: one boundary fewer than layers,
       * each spanning the model, inside it (on or below the ground, above
       * the base) and strictly below the one before it. @p path is the
       * subsection ("Geometry/Slope").
       */
      void
      validate_layers(const std::vector<std::string>           &layers,
                      const std::vector<std::vector<Point<2>>> &boundaries,
                      const std::vector<Point<2>>              &ground,
                      const double                              base,
                      const std::string                        &path);
    } // namespace case_input
  }   // namespace geometry
} // namespace fdem
