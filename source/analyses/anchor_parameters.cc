// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/anchor_parameters.h>

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
        forces = Utilities::string_to_double(
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
      prm.leave_subsection();
    }
  } // namespace analyses
} // namespace fdem
