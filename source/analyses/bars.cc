// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Passive bars, nails and piles: placed across a sliding surface as links
// of the mixed system (contact/bar_link.h), and their forces written out.
#include <fdem/analyses/bars.h>
#include <fdem/analyses/reinforcement_geometry.h>
#include <fdem/postprocess/output_file.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>

namespace fdem
{
  namespace analyses
  {
    namespace
    {
      /** Rows: @p axis, then unit vectors across it (the interfaces' rule in
       * 3D: the first in the plane of the axis and the coordinate axis least
       * aligned with it). */
      template <int dim>
      Tensor<2, dim>
      bar_frame(const Tensor<1, dim> &axis)
      {
        Tensor<2, dim> frame;
        frame[0] = axis;
        if (dim == 2)
          {
            frame[1][0] = -axis[1];
            frame[1][1] = axis[0];
            return frame;
          }
        unsigned int least = 0;
        for (unsigned int d = 1; d < dim; ++d)
          if (std::abs(axis[d]) < std::abs(axis[least]))
            least = d;
        Tensor<1, dim> e;
        e[least]               = 1;
        const Tensor<1, dim> t = e - (e * axis) * axis;
        frame[1]               = t / t.norm();
        if constexpr (dim == 3)
          frame[2] = cross_product_3d(frame[0], frame[1]);
        return frame;
      }

      /** The state of the bar's link in the model's current contact state. */
      template <int dim>
      const contact::PairState<dim> *
      bar_state(const Model<dim> &model, const unsigned int pair)
      {
        const auto &states = model.get_contact_outcome().states;
        return pair < states.size() ? &states[pair] : nullptr;
      }
    } // namespace

    template <int dim>
    std::vector<Bar<dim>>
    place_bars(Model<dim> &model)
    {
      const AnchorParameters &given = model.get_parameters().anchors;
      std::vector<Bar<dim>>   bars;
      if (given.n_bars() == 0)
        return bars;
      const PointLocator<dim>            locator(model);
      std::vector<contact::BarLink<dim>> links;
      std::vector<contact::PairStrength> capacities;
      const unsigned int                 n_contact_pairs = model.n_pairs();
      for (unsigned int k = 0; k < given.n_bars(); ++k)
        {
          const std::string name =
            "Reinforcement: bar " + std::to_string(k + 1);
          Bar<dim> b;
          b.head                           = transformed_input_point(model,
                                           given.bar_heads[k],
                                           name + ": its head");
          b.end                            = transformed_input_point(model,
                                          given.bar_ends[k],
                                          name + ": its end");
          const ReinforcementBlocks blocks = locate_reinforcement(model,
                                                                  locator,
                                                                  b.head,
                                                                  b.end,
                                                                  name,
                                                                  "Bar heads",
                                                                  "Bar ends",
                                                                  "end");
          b.head_block                     = blocks.head;
          b.end_block                      = blocks.end;
          b.direction = (b.end - b.head) / (b.end - b.head).norm();
          const SurfaceCrossing<dim> crossing = find_surface_crossing(
            model, locator, b.head_block, b.head, b.end, name);
          b.crossing  = crossing.point;
          b.normal    = crossing.normal;
          b.interface = crossing.interface_name;

          // N_y: the steel, or the bond on the shorter side if it gives first.
          b.tensile_capacity = given.bar_tensile_capacities[k];
          b.axial_capacity   = b.tensile_capacity;
          const double q     = given.bar_pullout_resistances[k];
          if (q > 0)
            {
              b.pullout_in_mass   = q * b.head.distance(b.crossing);
              b.pullout_in_ground = q * b.end.distance(b.crossing);
              b.axial_capacity    = std::min(
                {b.axial_capacity, b.pullout_in_mass, b.pullout_in_ground});
            }
          AssertThrow(b.axial_capacity > 0,
                      ExcMessage(name +
                                 " has no bond length in the sliding "
                                 "mass (its head is on the surface at " +
                                 point_text(b.crossing) +
                                 "); with a pull-out resistance its capacity "
                                 "would be zero: move Reinforcement/Bar "
                                 "heads into the mass."));
          b.shear_capacity = given.bar_shear_capacities[k];
          b.pair           = n_contact_pairs + k;

          const auto &interface = model.get_interfaces()[crossing.interface];
          contact::BarLink<dim> link;
          link.link             = interface.pairs[crossing.pair];
          link.block_I          = interface.block_I;
          link.block_J          = interface.block_J;
          link.surface_frame    = link.link.frame;
          link.link.area        = 0;
          link.link.initial_gap = 0;
          // The axis points from J's side into I's, so that f_0 > 0 (the
          // force I exerts on J pulls J towards I) is tension.
          link.link.frame = bar_frame<dim>(
            b.head_block == interface.block_I ? -b.direction : b.direction);
          link.axial_stiffness = given.bar_axial_stiffnesses[k];
          link.shear_stiffness =
            b.shear_capacity > 0 ? given.bar_shear_stiffnesses[k] : 0.0;
          links.push_back(link);
          contact::PairStrength capacity;
          capacity.bar_axial_capacity = b.axial_capacity;
          capacity.bar_shear_capacity = b.shear_capacity;
          capacities.push_back(capacity);
          bars.push_back(b);
        }
      const bool reduced = given.bar_capacity_reduced_by_K;
      model.set_bar_links(links, capacities, reduced);

      model.brief << "Passive bars: " << bars.size() << " (capacities "
                  << (reduced ? "reduced by K" : "not reduced by K") << ")"
                  << std::endl;
      for (unsigned int k = 0; k < bars.size(); ++k)
        {
          const Bar<dim> &b = bars[k];
          model.log << "  bar " << k + 1 << ": from " << point_text(b.head)
                    << " in '" << model.get_blocks()[b.head_block]->name
                    << "' to " << point_text(b.end) << " in '"
                    << model.get_blocks()[b.end_block]->name << "', across '"
                    << b.interface << "' at " << point_text(b.crossing)
                    << ": axial capacity " << b.axial_capacity
                    << ", shear capacity " << b.shear_capacity << std::endl;
        }
      return bars;
    }

    template <int dim>
    nlohmann::json
    bars_output(const Model<dim> &model, const std::vector<Bar<dim>> &bars)
    {
      const bool reduced =
        model.get_parameters().anchors.bar_capacity_reduced_by_K;
      const double   K      = model.get_strength_reduction();
      const auto    &forces = model.get_contact_outcome().solution.forces;
      nlohmann::json list   = nlohmann::json::array();
      std::vector<std::array<double, 3>> values; // N, V, utilisation
      std::vector<std::string>           statuses;
      for (const Bar<dim> &b : bars)
        {
          Tensor<1, dim> local;
          for (unsigned int i = 0; i < dim && dim * b.pair + i < forces.size();
               ++i)
            local[i] = forces[dim * b.pair + i];
          double shear = 0;
          for (unsigned int i = 1; i < dim; ++i)
            shear += local[i] * local[i];
          const contact::PairState<dim> *state = bar_state(model, b.pair);
          const bool                     yielded =
            state != nullptr && state->status == contact::PairStatus::slip;
          const double applied =
            reduced ? b.axial_capacity / K : b.axial_capacity;
          // At the limit the iteration approaches from below, where a bar
          // is still elastic at its capacity to the tolerance: the
          // utilisation says how much of it is used.
          values.push_back(
            {{local[0], std::sqrt(shear), std::abs(local[0]) / applied}});
          statuses.push_back(yielded ? "yielded" : "elastic");
          list.push_back(
            {{"head", coordinates(b.head)},
             {"end", coordinates(b.end)},
             {"crossing", coordinates(b.crossing)},
             {"interface", b.interface},
             {"head_block", model.get_blocks()[b.head_block]->name},
             {"end_block", model.get_blocks()[b.end_block]->name},
             {"tensile_capacity", b.tensile_capacity},
             {"pullout_in_mass", b.pullout_in_mass},
             {"pullout_in_ground", b.pullout_in_ground},
             {"axial_capacity", b.axial_capacity},
             {"shear_capacity", b.shear_capacity},
             {"applied_axial_capacity",
              reduced ? b.axial_capacity / K : b.axial_capacity},
             {"axial_force", local[0]},
             {"axial_utilisation", values.back()[2]},
             {"shear_force", std::sqrt(shear)},
             {"status", statuses.back()}});
        }
      const std::string directory = model.get_parameters().output_directory();
      if (model.writes_files() && std::filesystem::is_directory(directory))
        {
          postprocess::OutputFile out(directory + "/bars.csv");
          const char             *axes[] = {"x", "y", "z"};
          out << "bar";
          for (const std::string what : {"head", "end", "crossing"})
            for (unsigned int d = 0; d < dim; ++d)
              out << ',' << what << '_' << axes[d];
          out << ",axial_capacity,shear_capacity,applied_axial_capacity,"
                 "axial_force,axial_utilisation,shear_force,status,interface\n"
              << std::setprecision(12);
          for (unsigned int k = 0; k < bars.size(); ++k)
            {
              const Bar<dim> &b = bars[k];
              out << k + 1;
              for (const Point<dim> *p : {&b.head, &b.end, &b.crossing})
                for (unsigned int d = 0; d < dim; ++d)
                  out << ',' << (*p)[d];
              out << ',' << b.axial_capacity << ',' << b.shear_capacity << ','
                  << (reduced ? b.axial_capacity / K : b.axial_capacity) << ','
                  << values[k][0] << ',' << values[k][2] << ',' << values[k][1]
                  << ',' << statuses[k] << ',' << b.interface << '\n';
            }
          out.close();
        }
      return nlohmann::json{{"capacity_reduced_by_K", reduced},
                            {"K_of_state", K},
                            {"bars", list},
                            {"csv", "bars.csv"}};
    }

    template std::vector<Bar<2>>
    place_bars(Model<2> &);
    template std::vector<Bar<3>>
    place_bars(Model<3> &);
    template nlohmann::json
    bars_output(const Model<2> &, const std::vector<Bar<2>> &);
    template nlohmann::json
    bars_output(const Model<3> &, const std::vector<Bar<3>> &);
  } // namespace analyses
} // namespace fdem
