// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace fdem
{
  namespace postprocess
  {
    /**
     * A VTK XML unstructured grid (.vtu) in binary, zlib-compressed at a
     * fast level, in appended raw form: what ParaView and VTK read fastest,
     * with the two things deal.II's DataOut cannot write, field data
     * (numbers and text for the whole file) and integer arrays (a status
     * that ParaView can colour as categories).
     *
     * Points are 3D (2D models pass z = 0). Arrays hold one value per point
     * or cell times their number of components, component fastest.
     */
    class VtuWriter
    {
    public:
      /** VTK cell types used by the program's output. */
      enum CellType : std::uint8_t
      {
        vtk_line               = 3,
        vtk_triangle           = 5,
        vtk_quad               = 9,
        vtk_tetra              = 10,
        vtk_hexahedron         = 12,
        vtk_quadratic_edge     = 21,
        vtk_quadratic_triangle = 22,
        vtk_quadratic_tetra    = 24
      };

      /** Adds a point; returns its index. */
      std::uint64_t
      add_point(const double x, const double y, const double z);

      /** Adds a cell of @p type on the points @p nodes (VTK's node order). */
      void
      add_cell(const CellType type, const std::vector<std::uint64_t> &nodes);

      std::uint64_t
      n_points() const
      {
        return points.size() / 3;
      }

      std::uint64_t
      n_cells() const
      {
        return types.size();
      }

      /** A point array of doubles written as Float64 (or Float32 if @p single).
       */
      void
      add_point_data(const std::string         &name,
                     const unsigned int         n_components,
                     const std::vector<double> &values,
                     const bool                 single = false);

      /**
       * A point array of one component (Float64) where NaN marks a point
       * without a value (an interface node with no pair: ParaView shows
       * it in its NaN colour); every other value must be finite.
       */
      void
      add_point_data_with_blanks(const std::string         &name,
                                 const std::vector<double> &values);

      /** A point array of integers (Int32). */
      void
      add_point_data(const std::string               &name,
                     const std::vector<std::int32_t> &values);

      /** A cell array of integers (Int32). */
      void
      add_cell_data(const std::string               &name,
                    const std::vector<std::int32_t> &values);

      /** A field-data number (one Float64 tuple). */
      void
      add_field_data(const std::string &name, const double value);

      /**
       * As add_field_data(), where NaN says the value is not available
       * (K* of a state that has none); an infinity is refused all the same.
       */
      void
      add_field_data_or_blank(const std::string &name, const double value);

      /** A field-data text (one String tuple). */
      void
      add_field_data(const std::string &name, const std::string &text);

      /** Writes the file; throws if it cannot. */
      void
      write(const std::string &filename) const;

    private:
      struct Array
      {
        std::string       name, type;
        unsigned int      n_components = 1;
        std::vector<char> bytes;
      };

      /// The first array given a value that is not finite ("" if none):
      /// write() refuses the file, since such a value is a bug.
      std::string                first_non_finite;
      std::vector<double>        points;
      std::vector<std::uint64_t> connectivity, offsets;
      std::vector<std::uint8_t>  types;
      std::vector<Array>         point_data, cell_data;
      /** Field data: numbers, and texts written in ASCII as VTK reads them. */
      std::vector<std::pair<std::string, double>>      field_numbers;
      std::vector<std::pair<std::string, std::string>> field_texts;
    };

    /** What the files of one state (a safety-factor step or the final state)
     * say about it. */
    struct OutputState
    {
      /** The strength reduction factor of the state (1: full strength). */
      double K = 1;
      /** K* = K F_R / F_tau of the state (NaN where not computed). */
      double K_star = std::numeric_limits<double>::quiet_NaN();
      /** In words: "final state" or "safety-factor step 3". */
      std::string description;
    };

    /**
     * Field data common to every VTU file of the program: @p name (a block
     * or interface), K, K_star, the state in words and the units note.
     */
    void
    add_common_field_data(VtuWriter         &writer,
                          const std::string &name,
                          const OutputState &state);
  } // namespace postprocess
} // namespace fdem
