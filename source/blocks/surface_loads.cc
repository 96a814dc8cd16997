// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/blocks/surface_loads.h>

#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>

#include <algorithm>

namespace fdem
{
  namespace blocks
  {
    template <int dim>
    PiezometricPressure<dim>::PiezometricPressure(
      const parameters::WaterParameters &water)
      : water(water)
    {
      AssertThrow(water.piezometric_line.size() >= 2,
                  ExcMessage(
                    "Water/Piezometric line: a pressure is 'piezometric' "
                    "but no line is given."));
    }

    template <int dim>
    double
    PiezometricPressure<dim>::value(const Point<dim> &p,
                                    const unsigned int) const
    {
      const auto  &line = water.piezometric_line;
      const double x = p[0], y = p[dim - 1];
      double       level = line.front()[1];
      if (x >= line.back()[0])
        level = line.back()[1];
      else if (x > line.front()[0])
        for (unsigned int i = 1; i < line.size(); ++i)
          if (x <= line[i][0])
            {
              const double s =
                (x - line[i - 1][0]) / (line[i][0] - line[i - 1][0]);
              level = (1 - s) * line[i - 1][1] + s * line[i][1];
              break;
            }
      return water.unit_weight * std::max(0.0, level - y);
    }

    template <int dim>
    std::shared_ptr<const Function<dim>>
    make_pressure_function(const std::string                 &expression,
                           const parameters::WaterParameters &water)
    {
      if (expression == "piezometric")
        return std::make_shared<PiezometricPressure<dim>>(water);
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
    template std::shared_ptr<const Function<2>>
    make_pressure_function(const std::string &,
                           const parameters::WaterParameters &);
    template std::shared_ptr<const Function<3>>
    make_pressure_function(const std::string &,
                           const parameters::WaterParameters &);
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
