// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/blocks/surface_loads.h>
#include <fdem/geometry/make_mesh.h>

#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>

#include <algorithm>

namespace fdem
{
  namespace blocks
  {
    namespace
    {
      /** The line's y at @p x, its points raised by @p shift: linear
       * between them, constant beyond its ends. */
      double
      piecewise_linear(const std::vector<std::array<double, 2>> &line,
                       const double                              x,
                       const double                              shift)
      {
        if (x <= line.front()[0])
          return line.front()[1] + shift;
        for (unsigned int i = 1; i < line.size(); ++i)
          if (x <= line[i][0])
            {
              const double s =
                (x - line[i - 1][0]) / (line[i][0] - line[i - 1][0]);
              return (1 - s) * (line[i - 1][1] + shift) +
                     s * (line[i][1] + shift);
            }
        return line.back()[1] + shift;
      }
    } // namespace

    template <int dim>
    PiezometricPressure<dim>::PiezometricPressure(
      const parameters::WaterParameters    &water,
      const parameters::GeometryParameters &geometry,
      const double                          shift)
      : water(water)
      , shift(shift)
    {
      // The mesh's map x -> A x + t from the images of the origin and of the
      // unit vectors (geometry::transformed_point, the one definition of
      // the transformation): A = s R, so s is the length of A's columns.
      translation = geometry::transformed_point(geometry, Point<dim>());
      Tensor<2, dim> A;
      for (unsigned int j = 0; j < dim; ++j)
        {
          Point<dim> e;
          e[j] = 1;
          const Tensor<1, dim> column =
            geometry::transformed_point(geometry, e) - translation;
          for (unsigned int i = 0; i < dim; ++i)
            A[i][j] = column[i];
        }
      Tensor<1, dim> first_column;
      for (unsigned int i = 0; i < dim; ++i)
        first_column[i] = A[i][0];
      scale    = first_column.norm();
      to_input = invert(A);
    }

    template <int dim>
    double
    PiezometricPressure<dim>::pressure_below(
      const std::vector<std::array<double, 2>> &own_line,
      const Point<dim>                         &p) const
    {
      const std::vector<std::array<double, 2>> &line =
        own_line.empty() ? water.piezometric_line : own_line;
      const Tensor<1, dim> x0 = to_input * (p - translation);
      const double         x = x0[0], y = x0[dim - 1];
      // The shift is added to the points, as a raised line would be given.
      double level = 0;
      if (!line.empty())
        level = piecewise_linear(line, x, shift);
      else if (dim == 3 && !water.piezometric_surface.empty())
        level = water.piezometric_surface.elevation(x0[0], x0[1]) + shift;
      else
        return 0;
      return water.unit_weight * scale * std::max(0.0, level - y);
    }

    template <int dim>
    double
    PiezometricPressure<dim>::value(const Point<dim> &p,
                                    const unsigned int) const
    {
      return pressure_below({}, p);
    }

    template <int dim>
    double
    PiezometricPressure<dim>::value(
      const Point<dim>                     &p,
      const parameters::MaterialParameters &material) const
    {
      return pressure_below(material.piezometric_line, p);
    }

    template <int dim>
    double
    pressure_on_cell(const Function<dim>                  &pressure,
                     const Point<dim>                     &p,
                     const parameters::MaterialParameters &material)
    {
      if (const auto *piezometric =
            dynamic_cast<const PiezometricPressure<dim> *>(&pressure))
        return piezometric->value(p, material);
      return pressure.value(p);
    }

    template <int dim>
    std::shared_ptr<const Function<dim>>
    make_pressure_function(const std::string                    &expression,
                           const parameters::WaterParameters    &water,
                           const parameters::GeometryParameters &geometry)
    {
      if (expression == "piezometric")
        return std::make_shared<PiezometricPressure<dim>>(water, geometry);
      auto function = std::make_shared<FunctionParser<dim>>(1);
      function->initialize(FunctionParser<dim>::default_variable_names(),
                           expression,
                           {{"pi", numbers::PI}});
      return function;
    }

    template <int dim>
    std::shared_ptr<const Function<dim>>
    make_standing_water_pressure(const Point<dim>          &surface_point,
                                 const std::vector<double> &gravity,
                                 const parameters::WaterParameters &water)
    {
      Tensor<1, dim> down;
      for (unsigned int d = 0; d < dim; ++d)
        down[d] = gravity[d];
      const double gamma_w = water.unit_weight;
      return std::make_shared<ScalarFunctionFromFunctionObject<dim>>(
        [gamma_w, down, surface_point](const Point<dim> &p) {
          return gamma_w * std::max(0.0, (p - surface_point) * down);
        });
    }

    template <int dim>
    std::shared_ptr<const Function<dim>>
    make_traction_function(const std::string &expression)
    {
      auto function = std::make_shared<FunctionParser<dim>>(dim);
      function->initialize(FunctionParser<dim>::default_variable_names(),
                           expression,
                           {{"pi", numbers::PI}});
      return function;
    }

    template class PiezometricPressure<2>;
    template class PiezometricPressure<3>;
    template double
    pressure_on_cell(const Function<2> &,
                     const Point<2> &,
                     const parameters::MaterialParameters &);
    template double
    pressure_on_cell(const Function<3> &,
                     const Point<3> &,
                     const parameters::MaterialParameters &);
    template std::shared_ptr<const Function<2>>
    make_pressure_function(const std::string &,
                           const parameters::WaterParameters &,
                           const parameters::GeometryParameters &);
    template std::shared_ptr<const Function<3>>
    make_pressure_function(const std::string &,
                           const parameters::WaterParameters &,
                           const parameters::GeometryParameters &);
    template std::shared_ptr<const Function<2>>
    make_standing_water_pressure(const Point<2> &,
                                 const std::vector<double> &,
                                 const parameters::WaterParameters &);
    template std::shared_ptr<const Function<3>>
    make_standing_water_pressure(const Point<3> &,
                                 const std::vector<double> &,
                                 const parameters::WaterParameters &);
    template std::shared_ptr<const Function<2>>
    make_traction_function(const std::string &);
    template std::shared_ptr<const Function<3>>
    make_traction_function(const std::string &);
  } // namespace blocks
} // namespace fdem
