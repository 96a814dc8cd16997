// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/parameters/geometry_parameters.h>
#include <fdem/parameters/model_parameters.h>

#include <deal.II/base/function.h>

#include <memory>
#include <string>

namespace fdem
{
  namespace blocks
  {
    using namespace dealii;

    /**
     * Hydrostatic water pressure below a piezometric line (2D):
     * p = gamma_w max(0, y_line(x) - y), with y_line interpolated linearly
     * between the line's points and constant beyond its ends. The line is
     * in the input's coordinates, as the ground, the layers, the weak layers
     * and the anchors are, and moves with the mesh (Geometry/Scale factor,
     * Rotation, Translation): a point p of the model is taken back to the
     * input, x0 = (p - t) mapped by (s R)^-1, and its depth below the line
     * along the input's y axis, times s, gives the pressure. The water table
     * thus stays where it was in the slope whatever the transformation; a
     * model rotated with its gravity keeps its K.
     */
    template <int dim>
    class PiezometricPressure : public Function<dim>
    {
    public:
      PiezometricPressure(const parameters::WaterParameters    &water,
                          const parameters::GeometryParameters &geometry);

      double
      value(const Point<dim>  &p,
            const unsigned int component = 0) const override;

    private:
      const parameters::WaterParameters water;
      /** The mesh's transformation x -> A x + t: A^-1, t and s. */
      Tensor<2, dim> to_input;
      Point<dim>     translation;
      double         scale;
    };

    /**
     * A pressure (force/length^2) from a .prm entry: "piezometric" (see
     * PiezometricPressure), or an expression of the model's x, y (, z) for
     * deal.II's FunctionParser (with pi).
     */
    template <int dim>
    std::shared_ptr<const Function<dim>>
    make_pressure_function(const std::string                    &expression,
                           const parameters::WaterParameters    &water,
                           const parameters::GeometryParameters &geometry);

    /**
     * The hydrostatic pressure (force/length^2) of standing water whose
     * surface passes through @p surface_point: gamma_w times the depth below
     * it along the unit vector @p gravity, 0 above it (the water of a
     * tension crack).
     */
    template <int dim>
    std::shared_ptr<const Function<dim>>
    make_standing_water_pressure(const Point<dim>          &surface_point,
                                 const std::vector<double> &gravity,
                                 const parameters::WaterParameters &water);

    /** A traction vector function from an expression with dim components
     * separated by ';'. */
    template <int dim>
    std::shared_ptr<const Function<dim>>
    make_traction_function(const std::string &expression);
  } // namespace blocks
} // namespace fdem
