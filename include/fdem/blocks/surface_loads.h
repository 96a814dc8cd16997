// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/parameters/geometry_parameters.h>
#include <fdem/parameters/material_parameters.h>
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
     * Water/Piezometric line, or where a cell's material has a line of its
     * own (MaterialParameters::piezometric_line, a perched water table),
     * that one: value(p, material) is the pressure in or on a cell of that
     * material, value(p) the one of Water/Piezometric line. No line: 0 (a
     * dry material). In 3D the lines are over x and z, unchanged along y,
     * and Water/Piezometric surface file gives the water table as a
     * surface z_w(x, y) instead (bilinear on its grid, clamped beyond it):
     * p = gamma_w max(0, z_w(x, y) - z).
     *
     * The lines are in the input's coordinates, as the ground, the layers,
     * the weak layers and the anchors are, and move with the mesh
     * (Geometry/Scale factor, Rotation, Translation): a point p of the model
     * is taken back to the input, x0 = (p - t) mapped by (s R)^-1, and its
     * depth below the line along the input's y axis, times s, gives the
     * pressure. The water table thus stays where it was in the slope
     * whatever the transformation; a model rotated with its gravity keeps
     * its K. @p shift raises every line (a probabilistic water level).
     */
    template <int dim>
    class PiezometricPressure : public Function<dim>
    {
    public:
      PiezometricPressure(const parameters::WaterParameters    &water,
                          const parameters::GeometryParameters &geometry,
                          const double                          shift = 0);

      /** The pressure below Water/Piezometric line. */
      double
      value(const Point<dim>  &p,
            const unsigned int component = 0) const override;

      /** The pressure in or on a cell of @p material. */
      double
      value(const Point<dim>                     &p,
            const parameters::MaterialParameters &material) const;

    private:
      /** The pressure below @p own_line, or if it is empty below the
       * water table (Water/Piezometric line or surface; none: 0). */
      double
      pressure_below(const std::vector<std::array<double, 2>> &own_line,
                     const Point<dim>                         &p) const;

      const parameters::WaterParameters water;
      const double                      shift;
      /** The mesh's transformation x -> A x + t: A^-1, t and s. */
      Tensor<2, dim> to_input;
      Point<dim>     translation;
      double         scale;
    };

    /**
     * The pressure of @p pressure at @p p on a face of a cell of @p
     * material: a piezometric pressure takes the material's own line.
     */
    template <int dim>
    double
    pressure_on_cell(const Function<dim>                  &pressure,
                     const Point<dim>                     &p,
                     const parameters::MaterialParameters &material);

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
