// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/anchor_parameters.h>
#include <fdem/parameters/numbers.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <sstream>
#include <string>

namespace fdem
{
  namespace analyses
  {
    using namespace dealii;

    namespace
    {
      /** "x, y; x, y; ..." into points of 2 or 3 numbers, or throws naming @p
       * entry. */
      std::vector<std::vector<double>>
      parse_points(const std::string &text, const std::string &entry)
      {
        std::vector<std::vector<double>> points;
        if (Utilities::trim(text).empty())
          return points;
        for (const std::string &point : Utilities::split_string_list(text, ';'))
          {
            std::vector<double> xyz;
            for (const std::string &number :
                 Utilities::split_string_list(point, ','))
              {
                std::size_t end   = 0;
                double      value = 0;
                try
                  {
                    value = std::stod(number, &end);
                  }
                catch (...)
                  {
                    end = 0;
                  }
                AssertThrow(
                  end == number.size() && end > 0 && std::isfinite(value),
                  ExcMessage(
                    "Reinforcement/" + entry + ": '" + number + "' in point " +
                    std::to_string(points.size() + 1) +
                    " is not a number; give points as 'x, y; x, y' "
                    "(2D) or 'x, y, z; ...' (3D), in the model's length unit."));
                xyz.push_back(value);
              }
            AssertThrow(xyz.size() == 2 || xyz.size() == 3,
                        ExcMessage(
                          "Reinforcement/" + entry + ": point " +
                          std::to_string(points.size() + 1) + " has " +
                          std::to_string(xyz.size()) +
                          " coordinates; give 2 (2D) or 3 (3D), points "
                          "separated by ';'."));
            points.push_back(xyz);
          }
        return points;
      }

      /** A list of numbers of entry @p entry: empty, or one per bar. */
      std::vector<double>
      parse_bar_list(ParameterHandler  &prm,
                     const std::string &entry,
                     const unsigned int n_bars,
                     const double       if_empty)
      {
        const std::string text = Utilities::trim(prm.get(entry));
        if (text.empty())
          return std::vector<double>(n_bars, if_empty);
        const std::vector<double> values =
          parameters::finite_numbers(Utilities::split_string_list(text, ','));
        AssertThrow(values.size() == n_bars,
                    ExcMessage("Reinforcement/" + entry + ": " +
                               std::to_string(values.size()) + " values for " +
                               std::to_string(n_bars) +
                               " bars; give one per bar (Bar heads)."));
        return values;
      }
    } // namespace

    void
    AnchorParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Reinforcement");
      prm.declare_entry(
        "Anchor heads",
        "",
        Patterns::Anything(),
        "The head of each active anchor, on the sliding mass: points "
        "'x, y' (2D) or 'x, y, z' (3D) separated by ';', in the model's "
        "length unit and its coordinates before the Geometry "
        "transformation (scaled, rotated and translated with the mesh). "
        "Empty: no anchors.");
      prm.declare_entry(
        "Anchor bond points",
        "",
        Patterns::Anything(),
        "The bond point of each anchor, in the stable ground beyond the "
        "sliding surface (where the grouted bond length transfers the "
        "force): one point per head, written as those.");
      prm.declare_entry(
        "Anchor forces",
        "",
        Patterns::List(Patterns::Double(), 0, 1000, ","),
        "The prestress force of each anchor, > 0: force per unit width "
        "(out of plane) in 2D, e.g. kN/m, and a force in 3D, e.g. kN. "
        "It pulls the head towards the bond point and the bond point "
        "towards the head, each a point force shared by the vertices of "
        "the cell around it by the shape functions.");
      prm.declare_entry(
        "Anchor force reduced by K",
        "false",
        Patterns::Bool(),
        "false: the anchor forces are loads that K does not reduce "
        "(Duncan & Wright's method A, 'active' support: the anchor "
        "lessens the driving force). true: the shear component of each "
        "anchor force along the sliding surface where it crosses is a "
        "resistance divided by K like c and tan(phi) (method B, "
        "'passive'); its normal component acts in full. Codes differ; "
        "doc/theory.md, \"Anchors\", says what each means for K.");

      prm.declare_entry(
        "Bar heads",
        "",
        Patterns::Anything(),
        "The head of each passive bar, nail or pile, on the sliding mass: "
        "points 'x, y' (2D) or 'x, y, z' (3D) separated by ';', in the "
        "model's length unit and its coordinates before the Geometry "
        "transformation. The straight bar runs from its head to its end "
        "and must cross a sliding surface. Empty: no bars.");
      prm.declare_entry("Bar ends",
                        "",
                        Patterns::Anything(),
                        "The end of each bar in the stable ground beyond the "
                        "sliding surface: one point per head, written as "
                        "those.");
      prm.declare_entry(
        "Bar tensile capacities",
        "",
        Patterns::List(Patterns::Double(), 0, 1000, ","),
        "The axial force at which each bar's steel yields, > 0, in tension "
        "and in compression: force per unit width (out of plane) in 2D, "
        "e.g. kN/m (a row of bars at spacing s: a bar's capacity over s), "
        "and a force in 3D, e.g. kN. The bar's axial capacity is the "
        "least of this and its pull-out resistance on either side of the "
        "surface.");
      prm.declare_entry(
        "Bar pull-out resistances",
        "",
        Patterns::List(Patterns::Double(), 0, 1000, ","),
        "The bond resistance of each bar per unit length, >= 0 (force per "
        "length, per unit width in 2D, e.g. kN/m/m): the bar pulls out of "
        "the sliding mass at this times its length from the head to the "
        "surface, and out of the stable ground at this times its length "
        "from the surface to its end. 0: the bond does not limit the bar. "
        "Empty: 0 for every bar.");
      prm.declare_entry(
        "Bar axial stiffnesses",
        "",
        Patterns::List(Patterns::Double(), 0, 1000, ","),
        "The axial stiffness of each bar across the sliding surface, > 0: "
        "the force per unit relative displacement of the two sides along "
        "the bar (force/length, per unit width in 2D, e.g. kN/m/m), e.g. "
        "E A / L with L the length over which the bar stretches. The "
        "safety factor at yield does not depend on it; the forces below "
        "yield do.");
      prm.declare_entry(
        "Bar shear capacities",
        "",
        Patterns::List(Patterns::Double(), 0, 1000, ","),
        "Piles: the shear force across each bar at which it yields, >= 0 "
        "(force per unit width in 2D). 0: a bar or nail, which carries no "
        "shear. Empty: 0 for every bar. 2D only.");
      prm.declare_entry(
        "Bar shear stiffnesses",
        "",
        Patterns::List(Patterns::Double(), 0, 1000, ","),
        "Piles: the shear stiffness across each bar (force/length, per unit "
        "width in 2D), > 0 where Bar shear capacities is > 0. Empty: 0 for "
        "every bar.");
      prm.declare_entry(
        "Bar capacity reduced by K",
        "false",
        Patterns::Bool(),
        "false: the bars yield at their capacities, which K does not "
        "reduce (as unreduced anchor loads, Duncan & Wright's method A). "
        "true: K divides the bars' capacities as it divides c and "
        "tan(phi), so that K is the factor on every strength, the soil's "
        "and the bars'. doc/theory.md, \"Passive bars\".");
      prm.leave_subsection();
    }

    void
    AnchorParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Reinforcement");
      heads = parse_points(prm.get("Anchor heads"), "Anchor heads");
      bond_points =
        parse_points(prm.get("Anchor bond points"), "Anchor bond points");
      forces.clear();
      const std::string force_text = Utilities::trim(prm.get("Anchor forces"));
      if (!force_text.empty())
        forces = parameters::finite_numbers(
          Utilities::split_string_list(force_text, ','));
      reduced_by_K = prm.get_bool("Anchor force reduced by K");
      AssertThrow(
        heads.size() == forces.size() && bond_points.size() == forces.size(),
        ExcMessage("Reinforcement: " + std::to_string(heads.size()) +
                   " Anchor heads, " + std::to_string(bond_points.size()) +
                   " Anchor bond points and " + std::to_string(forces.size()) +
                   " Anchor forces; give one of each per anchor."));
      for (unsigned int k = 0; k < forces.size(); ++k)
        {
          std::ostringstream force;
          force << forces[k];
          AssertThrow(forces[k] > 0 && std::isfinite(forces[k]),
                      ExcMessage(
                        "Reinforcement/Anchor forces: anchor " +
                        std::to_string(k + 1) + " has force " + force.str() +
                        "; a prestress force must be positive (force per unit "
                        "width in 2D, force in 3D)."));
          AssertThrow(
            heads[k].size() == bond_points[k].size(),
            ExcMessage(
              "Reinforcement: anchor " + std::to_string(k + 1) +
              " has a head and a bond point of different dimensions."));
          AssertThrow(heads[k] != bond_points[k],
                      ExcMessage(
                        "Reinforcement: anchor " + std::to_string(k + 1) +
                        " has its bond point at its head; it must cross the "
                        "sliding surface."));
        }

      bar_heads            = parse_points(prm.get("Bar heads"), "Bar heads");
      bar_ends             = parse_points(prm.get("Bar ends"), "Bar ends");
      const unsigned int n = bar_heads.size();
      AssertThrow(bar_ends.size() == n,
                  ExcMessage("Reinforcement: " + std::to_string(n) +
                             " Bar heads and " +
                             std::to_string(bar_ends.size()) +
                             " Bar ends; give one end per head."));
      bar_tensile_capacities =
        parse_bar_list(prm, "Bar tensile capacities", n, 0);
      bar_pullout_resistances =
        parse_bar_list(prm, "Bar pull-out resistances", n, 0);
      bar_axial_stiffnesses =
        parse_bar_list(prm, "Bar axial stiffnesses", n, 0);
      bar_shear_capacities = parse_bar_list(prm, "Bar shear capacities", n, 0);
      bar_shear_stiffnesses =
        parse_bar_list(prm, "Bar shear stiffnesses", n, 0);
      bar_capacity_reduced_by_K = prm.get_bool("Bar capacity reduced by K");
      const auto check          = [](const bool         ok,
                            const std::string &entry,
                            const unsigned int k,
                            const double       value,
                            const std::string &expected) {
        std::ostringstream text;
        text << value;
        AssertThrow(ok,
                    ExcMessage("Reinforcement/" + entry + ": bar " +
                               std::to_string(k + 1) + " has " + text.str() +
                               "; " + expected));
      };
      for (unsigned int k = 0; k < n; ++k)
        {
          AssertThrow(bar_heads[k].size() == bar_ends[k].size(),
                      ExcMessage("Reinforcement: bar " + std::to_string(k + 1) +
                                 " has a head and an end of different "
                                 "dimensions."));
          AssertThrow(bar_heads[k] != bar_ends[k],
                      ExcMessage("Reinforcement: bar " + std::to_string(k + 1) +
                                 " has its end at its head; it must cross the "
                                 "sliding surface."));
          const double T   = bar_tensile_capacities[k],
                       q   = bar_pullout_resistances[k],
                       k_a = bar_axial_stiffnesses[k],
                       V   = bar_shear_capacities[k],
                       k_s = bar_shear_stiffnesses[k];
          check(T > 0 && std::isfinite(T),
                "Bar tensile capacities",
                k,
                T,
                "a bar's capacity must be a positive force (per unit width "
                "in 2D).");
          check(q >= 0 && std::isfinite(q),
                "Bar pull-out resistances",
                k,
                q,
                "give a force per length >= 0 (0: no pull-out limit).");
          check(k_a > 0 && std::isfinite(k_a),
                "Bar axial stiffnesses",
                k,
                k_a,
                "a bar's axial stiffness must be positive (force per "
                "length, per unit width in 2D).");
          check(V >= 0 && std::isfinite(V),
                "Bar shear capacities",
                k,
                V,
                "give a force >= 0 (0: a bar or nail without shear).");
          check(k_s >= 0 && std::isfinite(k_s) && (V == 0 || k_s > 0),
                "Bar shear stiffnesses",
                k,
                k_s,
                "a pile with a shear capacity needs a positive shear "
                "stiffness (force per length).");
          AssertThrow(V == 0 || bar_heads[k].size() == 2,
                      ExcMessage("Reinforcement/Bar shear capacities: bar " +
                                 std::to_string(k + 1) +
                                 " is a pile in 3D; piles (a shear capacity) "
                                 "are taken in 2D only so far."));
        }
      prm.leave_subsection();
    }
  } // namespace analyses
} // namespace fdem
