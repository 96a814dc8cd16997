// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/parameters/material_parameters.h>
#include <fdem/parameters/model_parameters.h>
#include <fdem/parameters/numbers.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cmath>

namespace fdem
{
  namespace parameters
  {
    using namespace dealii;

    void
    MaterialParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Young's modulus",
        "0",
        Patterns::Double(0),
        "Young's modulus E of the material (force/length^2, "
        "e.g. kPa with kN and m). Must be given (> 0) for every "
        "material that a cell uses; a block whose cells all lie "
        "in material regions (Materials) needs none of its own.");
      prm.declare_entry("Poisson's ratio",
                        "0.3",
                        Patterns::Double(0, 0.5),
                        "Poisson's ratio of the material (dimensionless, 0 <= "
                        "nu < 0.5). 2D models are in plane strain.");
      prm.declare_entry("Unit weight",
                        "0",
                        Patterns::Double(0),
                        "Unit weight of the material (force/length^3, e.g. "
                        "kN/m^3); acts along Loads/Gravity direction.");
      prm.declare_entry("Density",
                        "0",
                        Patterns::Double(0),
                        "Density of the material (mass/length^3); its weight "
                        "is density times Loads/Gravitational acceleration. "
                        "Give either a unit weight or a density, not both.");
      prm.declare_entry(
        "Saturated unit weight",
        "0",
        Patterns::Double(0),
        "Unit weight below the water table (the material's own "
        "Piezometric line, or Water/Piezometric line or surface) "
        "(force/length^3, e.g. kN/m^3), evaluated at each "
        "quadrature point; 0: the same weight as above it. It "
        "is the total weight (soil and water): give the water "
        "pressure on interfaces as Pore pressure = piezometric.");
      prm.declare_entry(
        "Friction angle",
        "",
        Patterns::Anything(),
        "Friction angle phi of the soil (degrees, 0 <= phi < "
        "90), used by interfaces with Strength = material where "
        "they run through this material. Empty: none given.");
      prm.declare_entry("Cohesion",
                        "0",
                        Patterns::Double(0),
                        "Cohesion c of the soil (force/length^2, e.g. kPa), "
                        "used with its Friction angle by interfaces with "
                        "Strength = material.");
      prm.declare_entry(
        "Weak layer",
        "",
        Patterns::Anything(),
        "Materials only, 2D: makes this material a named weak layer, a seam "
        "of no thickness along the polyline 'x,y; x,y; ...' (length, in the "
        "coordinates before the Geometry transformation, moved with the "
        "mesh). Every face of an interface with Strength = material that "
        "runs along it (both ends within 1e-3 of the face's length of the "
        "polyline) takes this material's Cohesion and Friction angle instead "
        "of those of the cells beside it; limit equilibrium does the same "
        "for a slice base along it. The material has no cells: it is not a "
        "region of the mesh nor a layer. Empty: an ordinary material.");
      prm.declare_entry(
        "Piezometric line",
        "",
        Patterns::Anything(),
        "This material's own water table, points 'x,y; x,y; ...' with "
        "increasing x (length, in the coordinates before the Geometry "
        "transformation, moved with the mesh): used instead of "
        "Water/Piezometric line (or surface) in this material's cells (the saturated unit "
        "weight below it) and on the faces of its cells where a pressure or "
        "pore pressure is 'piezometric' (gamma_w times the depth under this "
        "line); limit equilibrium does the same for the slices' layers and "
        "bases. A perched water table: the upper layer's line above a "
        "low-permeability layer, the lower layers on Water/Piezometric line "
        "or their own. Where neither this nor Water/Piezometric line (or "
        "surface) is given, the material is dry. Empty: Water/Piezometric "
        "line (or surface).");
    }

    void
    MaterialParameters::parse_parameters(ParameterHandler  &prm,
                                         const std::string &path)
    {
      youngs_modulus        = prm.get_double("Young's modulus");
      poissons_ratio        = prm.get_double("Poisson's ratio");
      unit_weight           = prm.get_double("Unit weight");
      density               = prm.get_double("Density");
      saturated_unit_weight = prm.get_double("Saturated unit weight");
      cohesion              = prm.get_double("Cohesion");
      AssertThrow(poissons_ratio < 0.5,
                  ExcMessage(path + "/Poisson's ratio: must be below 0.5."));
      AssertThrow(unit_weight == 0 || density == 0,
                  ExcMessage(path +
                             ": give either 'Unit weight' or 'Density', not "
                             "both."));
      const std::string phi = Utilities::trim(prm.get("Friction angle"));
      has_strength          = !phi.empty();
      if (has_strength)
        {
          bool number = true;
          try
            {
              friction_angle = parameters::finite_number(phi);
            }
          catch (...)
            {
              number = false;
            }
          AssertThrow(number && friction_angle >= 0 && friction_angle < 90,
                      ExcMessage(path + "/Friction angle: '" + phi +
                                 "' is not an angle in degrees from 0 to below "
                                 "90."));
        }
      else
        AssertThrow(cohesion == 0,
                    ExcMessage(path + "/Cohesion: give the Friction angle too "
                                      "(0 for a purely cohesive soil)."));
      weak_layer.clear();
      for (const std::string &point :
           Utilities::split_string_list(prm.get("Weak layer"), ';'))
        {
          const std::vector<double> xy =
            parse_vector(point, 2, path + "/Weak layer");
          weak_layer.emplace_back(xy[0], xy[1]);
          AssertThrow(weak_layer.size() == 1 ||
                        weak_layer.back() != weak_layer[weak_layer.size() - 2],
                      ExcMessage(path + "/Weak layer: two consecutive points "
                                        "are the same."));
        }
      piezometric_line = parse_piezometric_line(prm.get("Piezometric line"),
                                                path + "/Piezometric line");
      if (!weak_layer.empty())
        {
          AssertThrow(piezometric_line.empty(),
                      ExcMessage(path +
                                 "/Piezometric line: a weak layer has no "
                                 "cells to hold water; give the line to the "
                                 "layers around it."));
          AssertThrow(path.rfind("Materials/", 0) == 0,
                      ExcMessage(path +
                                 "/Weak layer: a block's own material fills "
                                 "its cells; list the weak layer under "
                                 "Materials/Names."));
          AssertThrow(weak_layer.size() >= 2,
                      ExcMessage(path +
                                 "/Weak layer: give at least two points."));
          AssertThrow(has_strength,
                      ExcMessage(path + "/Weak layer: a weak layer needs its "
                                        "Friction angle (and Cohesion)."));
        }
    }

    void
    MaterialParameters::require_elastic_constants(const std::string &path,
                                                  const std::string &what) const
    {
      AssertThrow(youngs_modulus > 0,
                  ExcMessage(path + "/Young's modulus: " + what +
                             "; give a Young's modulus > 0."));
    }
  } // namespace parameters
} // namespace fdem
