// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <array>
#include <string>
#include <vector>

namespace fdem
{
  namespace parameters
  {
    /**
     * A material: subsection "Blocks/<block name>" (the block's own
     * material, of its cells outside every material region) or
     * "Materials/<material name>" (a material region, a Gmsh physical group
     * of dimension dim that may overlap the blocks, or a layer of the slope
     * generator). Units are the model's (e.g. kN and m, or N and mm), used
     * consistently.
     */
    struct MaterialParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm, const std::string &path);

      /**
       * Throws naming @p path (e.g. "Blocks/foundation") unless the
       * material has a Young's modulus > 0: required of every material that
       * some cell uses, checked once the mesh says which are used.
       */
      void
      require_elastic_constants(const std::string &path,
                                const std::string &what) const;

      /** Young's modulus E (force/length^2); 0 until given. */
      double youngs_modulus = 0;
      /** Poisson's ratio nu, 0 <= nu < 0.5. */
      double poissons_ratio = 0.3;
      /** Unit weight (force/length^3); acts along the gravity direction. */
      double unit_weight = 0;
      /** Density (mass/length^3); multiplied by the gravitational acceleration.
       */
      double density = 0;
      /**
       * Unit weight below the water table (the material's piezometric line,
       * or Water/Piezometric line) (force/length^3); 0: the same weight as
       * above it.
       */
      double saturated_unit_weight = 0;
      /** Soil strength for interfaces with Strength = material. */
      bool has_strength = false;
      /** Friction angle phi of the soil (degrees), if has_strength. */
      double friction_angle = 0;
      /** Cohesion c of the soil (force/length^2). */
      double cohesion = 0;
      /**
       * A named weak layer (Materials/<name>/Weak layer, 2D): a seam of no
       * thickness along this polyline, in the coordinates before the
       * Geometry transformation. The node pairs of an interface with
       * Strength = material that run along it take this material's c and
       * phi, not those of the cells beside them. Empty: an ordinary
       * material.
       */
      std::vector<dealii::Point<2>> weak_layer;
      /**
       * The material's own piezometric line (Materials/<name>/Piezometric
       * line, "x,y; ..." with increasing x, in the coordinates before the
       * Geometry transformation): used instead of Water/Piezometric line in
       * this material's cells (saturated weight) and on the faces of its
       * cells that carry a 'piezometric' pressure. A perched water table in
       * one layer, a lower one in the next. Empty: Water/Piezometric line.
       */
      std::vector<std::array<double, 2>> piezometric_line;

      /** The weight per unit volume above the water table, with @p g for a
       * density. */
      double
      weight(const double g) const
      {
        return unit_weight + density * g;
      }

      /** The weight per unit volume below the water table. */
      double
      saturated_weight(const double g) const
      {
        return saturated_unit_weight > 0 ? saturated_unit_weight : weight(g);
      }
    };
  } // namespace parameters
} // namespace fdem
