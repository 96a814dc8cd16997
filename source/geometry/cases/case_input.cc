// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors

#include <fdem/geometry/cases/case_input.h>
#include <fdem/geometry/cases/polyline_segment.h>
#include <fdem/parameters/numbers.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace fdem
{
  namespace geometry
  {
    namespace
    {
      double
      radians(const double degrees)
      {
        return degrees * numbers::PI / 180;
      }
    } // namespace



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



    bool
    PlaneOrientation::is_valid() const
    {
      return dip >= 0 && dip <= 90 && dip_direction >= 0 &&
             dip_direction <= 360;
    }



    namespace case_input
    {
      void
      require(const bool condition, const std::string &message)
      {
        AssertThrow(condition, ExcMessage(message));
      }



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
          parameters::finite_numbers(Utilities::split_string_list(text, ','));
        return Point<2>(xy[0], xy[1]);
      }



      std::vector<Point<2>>
      parse_points(const std::string &text)
      {
        std::vector<Point<2>> points;
        for (const std::string &point : Utilities::split_string_list(text, ';'))
          points.push_back(parse_point(point));
        return points;
      }



      void
      declare_element_shape_2d(ParameterHandler &prm, const std::string &how)
      {
        prm.declare_entry("Element shape",
                          "quadrilateral",
                          Patterns::Selection("quadrilateral|triangle"),
                          "Shape of the cells: " + how);
      }



      ElementShape
      parse_element_shape(ParameterHandler &prm)
      {
        const std::string shape = prm.get("Element shape");
        return (shape == "triangle" || shape == "tetrahedron") ?
                 ElementShape::simplex :
                 ElementShape::hypercube;
      }



      Patterns::List
      orientation_pattern()
      {
        return Patterns::List(Patterns::Double(), 2, 2, ",");
      }



      std::string
      number_text(const double value)
      {
        std::ostringstream out;
        out << value;
        return out.str();
      }


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
          parameters::finite_numbers(Utilities::split_string_list(text, ','));
        PlaneOrientation orientation;
        orientation.dip           = values[0];
        orientation.dip_direction = values[1];
        return orientation;
      }

      double
      polyline_elevation(const std::vector<Point<2>> &line, const double x)
      {
        if (x <= line.front()[0])
          return line.front()[1];
        for (unsigned int i = 1; i < line.size(); ++i)
          if (x <= line[i][0])
            {
              const double t =
                (x - line[i - 1][0]) / (line[i][0] - line[i - 1][0]);
              return (1 - t) * line[i - 1][1] + t * line[i][1];
            }
        return line.back()[1];
      }

      double
      distance_to_polyline(const Point<2> &p, const std::vector<Point<2>> &line)
      {
        double distance = std::numeric_limits<double>::infinity();
        for (unsigned int i = 0; i + 1 < line.size(); ++i)
          {
            const Tensor<1, 2> e = line[i + 1] - line[i];
            const double       t =
              std::clamp((p - line[i]) * e / e.norm_square(), 0.0, 1.0);
            distance = std::min(distance, p.distance(line[i] + t * e));
          }
        return distance;
      }

      bool
      segment_along_polyline(const Point<2>              &a,
                             const Point<2>              &b,
                             const std::vector<Point<2>> &line)
      {
        const double tolerance = 1e-3 * a.distance(b);
        return distance_to_polyline(a, line) <= tolerance &&
               distance_to_polyline(b, line) <= tolerance;
      }

      std::vector<double>
      polyline_breakpoints(const std::vector<Point<2>> &a,
                           const std::vector<Point<2>> &b,
                           const double                 x_min,
                           const double                 x_max)
      {
        std::set<double> x{x_min, x_max};
        for (const auto *line : {&a, &b})
          for (const Point<2> &p : *line)
            if (p[0] > x_min && p[0] < x_max)
              x.insert(p[0]);
        return {x.begin(), x.end()};
      }



      std::vector<std::string>
      split_fields(const std::string &line)
      {
        std::vector<std::string> fields;
        std::string              field;
        for (const char c : line)
          if (c == ',' || c == ';' || c == ' ' || c == '\t' || c == '\r')
            {
              if (!field.empty())
                fields.push_back(field);
              field.clear();
            }
          else
            field += c;
        if (!field.empty())
          fields.push_back(field);
        return fields;
      }



      bool
      parse_number(const std::string &text, double &value)
      {
        return parameters::read_finite_number(text, value);
      }



      void
      for_each_table_row(
        const std::string &file_name,
        const std::string &where,
        const std::function<void(const unsigned int              line_number,
                                 const std::string              &at,
                                 const std::vector<std::string> &fields)> &row)
      {
        AssertThrow(!std::filesystem::is_directory(file_name),
                    ExcMessage(where + " is a folder, not a file."));
        std::ifstream in(file_name);
        AssertThrow(in, ExcMessage(where + " cannot be read (missing file?)."));
        std::string  line;
        unsigned int line_number    = 0;
        bool         header_allowed = true;
        while (std::getline(in, line))
          {
            ++line_number;
            // A spreadsheet's UTF-8 byte order mark before the first field.
            if (line_number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0)
              line.erase(0, 3);
            const std::size_t comment = line.find('#');
            if (comment != std::string::npos)
              line.erase(comment);
            const std::vector<std::string> fields = split_fields(line);
            if (fields.empty())
              continue;
            double ignored;
            if (header_allowed && std::none_of(fields.begin(),
                                               fields.end(),
                                               [&](const std::string &f) {
                                                 return parse_number(f,
                                                                     ignored);
                                               }))
              {
                header_allowed = false;
                continue;
              }
            header_allowed = false;
            row(line_number,
                where + " line " + std::to_string(line_number) + ": ",
                fields);
          }
      }
    } // namespace case_input
  }   // namespace geometry
} // namespace fdem
