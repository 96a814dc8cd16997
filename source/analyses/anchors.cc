// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/anchors.h>
#include <fdem/analyses/reinforcement_geometry.h>
#include <fdem/postprocess/output_file.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>

namespace fdem
{
  namespace analyses
  {
    namespace
    {
      std::string
      anchor_name(const unsigned int k)
      {
        return "Reinforcement: anchor " + std::to_string(k + 1);
      }

      /** How the anchors' force enters, as the screen and summary.json say. */
      std::string
      anchor_convention(const bool reduced)
      {
        return reduced ? "shear component reduced by K" : "unreduced loads";
      }
    } // namespace

    template <int dim>
    std::vector<Anchor<dim>>
    locate_anchors(const Model<dim> &model)
    {
      const AnchorParameters  &given = model.get_parameters().anchors;
      std::vector<Anchor<dim>> anchors;
      if (given.n_anchors() == 0)
        return anchors;
      const PointLocator<dim> locator(model);
      for (unsigned int k = 0; k < given.n_anchors(); ++k)
        {
          const std::string name = anchor_name(k);
          Anchor<dim>       a;
          a.force = given.forces[k];
          a.head =
            transformed_input_point(model, given.heads[k], name + ": its head");
          a.bond = transformed_input_point(model,
                                           given.bond_points[k],
                                           name + ": its bond point");
          const ReinforcementBlocks blocks =
            locate_reinforcement(model,
                                 locator,
                                 a.head,
                                 a.bond,
                                 name,
                                 "Anchor heads",
                                 "Anchor bond points",
                                 "bond point");
          a.head_block = blocks.head;
          a.bond_block = blocks.end;
          a.direction  = (a.bond - a.head) / (a.bond - a.head).norm();
          const SurfaceCrossing<dim> crossing = find_surface_crossing(
            model, locator, a.head_block, a.head, a.bond, name);
          a.crossing     = crossing.point;
          a.normal       = crossing.normal;
          a.interface    = crossing.interface_name;
          a.normal_force = a.force * (a.normal * a.direction);
          a.shear_force =
            (a.force * a.direction - a.normal_force * a.normal).norm();
          anchors.push_back(a);
        }
      return anchors;
    }

    template <int dim>
    std::vector<Anchor<dim>>
    add_anchor_loads(Model<dim> &model)
    {
      const std::vector<Anchor<dim>> anchors = locate_anchors(model);
      if (anchors.empty())
        return anchors;
      const bool reduced = model.get_parameters().anchors.reduced_by_K;
      const PointLocator<dim> locator(model);
      // Case 0: the normal components, case 1: the shear components.
      std::vector<std::vector<Vector<double>>> loads(2);
      for (auto &l : loads)
        for (const auto &block : model.get_blocks())
          l.emplace_back(block->dof_handler.n_dofs());
      // Unreduced, the prestress acts at the head. Reduced by K, the anchor
      // is a resistance mobilised where it crosses the surface, as limit
      // equilibrium programs apply support forces: both parts at the
      // crossing (on the head's block), so that the split force keeps the
      // moment it has on the slices (doc/theory.md, "Anchors").
      for (const Anchor<dim> &a : anchors)
        {
          const Point<dim>    &at     = reduced ? a.crossing : a.head;
          const Tensor<1, dim> normal = a.normal_force * a.normal;
          const Tensor<1, dim> shear  = a.force * a.direction - normal;
          for (unsigned int c = 0; c < 2; ++c)
            {
              const Tensor<1, dim> &f = c == 0 ? normal : shear;
              locator.add_point_force(a.head_block,
                                      at,
                                      f,
                                      loads[c][a.head_block]);
              locator.add_point_force(a.bond_block,
                                      a.bond,
                                      -f,
                                      loads[c][a.bond_block]);
            }
        }
      const unsigned int normal_case = model.add_load_case(loads[0]);
      const unsigned int shear_case  = model.add_load_case(loads[1]);
      // The model keeps the combination it is given (a seismic load, a
      // sample's) and this sets the anchors' two coefficients in it.
      model.set_strength_dependent_loads(
        [&model, normal_case, shear_case, reduced](const double K) {
          std::vector<double> c =
            model.get_mixed_system().get_load_coefficients();
          c.resize(model.get_mixed_system().n_load_cases(), 0.0);
          const double shear = reduced ? 1 / K : 1.0;
          if (c[normal_case] == 1 && c[shear_case] == shear)
            return;
          c[normal_case] = 1;
          c[shear_case]  = shear;
          model.set_load_combination(
            model.get_mixed_system().get_base_load_factor(), c);
        });
      model.apply_strength_dependent_loads(1.0);

      const std::string convention = anchor_convention(reduced);
      double            total      = 0;
      for (const auto &a : anchors)
        total += a.force;
      model.brief << "Anchors: " << anchors.size() << ", total force "
                  << std::setprecision(6) << total << " (" << convention << ")"
                  << std::endl;
      for (unsigned int k = 0; k < anchors.size(); ++k)
        {
          const Anchor<dim> &a = anchors[k];
          model.log << "  anchor " << k + 1 << ": T = " << a.force << " from "
                    << point_text(a.head) << " in '"
                    << model.get_blocks()[a.head_block]->name << "' to "
                    << point_text(a.bond) << " in '"
                    << model.get_blocks()[a.bond_block]->name << "', across '"
                    << a.interface << "' at " << point_text(a.crossing)
                    << ": normal " << a.normal_force << ", shear "
                    << a.shear_force << std::endl;
        }
      return anchors;
    }

    template <int dim>
    nlohmann::json
    reinforcement_output(const Model<dim>               &model,
                         const std::vector<Anchor<dim>> &anchors)
    {
      const bool        reduced = model.get_parameters().anchors.reduced_by_K;
      const std::string convention = anchor_convention(reduced);
      const double      K          = model.get_strength_reduction();
      nlohmann::json    list       = nlohmann::json::array();
      for (const Anchor<dim> &a : anchors)
        list.push_back({{"head", coordinates(a.head)},
                        {"bond_point", coordinates(a.bond)},
                        {"crossing", coordinates(a.crossing)},
                        {"interface", a.interface},
                        {"head_block", model.get_blocks()[a.head_block]->name},
                        {"bond_block", model.get_blocks()[a.bond_block]->name},
                        {"force", a.force},
                        {"normal_force", a.normal_force},
                        {"shear_force", a.shear_force},
                        {"applied_shear_force",
                         reduced ? a.shear_force / K : a.shear_force}});
      const std::string directory = model.get_parameters().output_directory();
      if (model.writes_files() && std::filesystem::is_directory(directory))
        {
          postprocess::OutputFile out(directory + "/anchors.csv");
          const char             *axes[] = {"x", "y", "z"};
          out << "anchor";
          for (const std::string what : {"head", "bond", "crossing"})
            for (unsigned int d = 0; d < dim; ++d)
              out << ',' << what << '_' << axes[d];
          out
            << ",force,normal_force,shear_force,applied_shear_force,interface\n"
            << std::setprecision(12);
          for (unsigned int k = 0; k < anchors.size(); ++k)
            {
              const Anchor<dim> &a = anchors[k];
              out << k + 1;
              for (const Point<dim> *p : {&a.head, &a.bond, &a.crossing})
                for (unsigned int d = 0; d < dim; ++d)
                  out << ',' << (*p)[d];
              out << ',' << a.force << ',' << a.normal_force << ','
                  << a.shear_force << ','
                  << (reduced ? a.shear_force / K : a.shear_force) << ','
                  << a.interface << '\n';
            }
          out.close();
        }
      return nlohmann::json{{"convention", convention},
                            {"reduced_by_K", reduced},
                            {"K_of_state", K},
                            {"anchors", list},
                            {"csv", "anchors.csv"}};
    }

    std::vector<std::pair<std::string, std::string>>
    reinforcement_result_lines(const nlohmann::json &summary)
    {
      std::vector<std::pair<std::string, std::string>> lines;
      if (!summary.contains("reinforcement") ||
          !summary["reinforcement"].is_object())
        return lines;
      const nlohmann::json &r = summary["reinforcement"];
      if (r.contains("anchors"))
        {
          double total = 0;
          for (const auto &a : r["anchors"])
            total += a["force"].get<double>();
          std::ostringstream line;
          line << r["anchors"].size()
               << (r["anchors"].size() == 1 ? " anchor" : " anchors")
               << ", total force " << std::setprecision(6) << total << " ("
               << r["convention"].get<std::string>() << "; anchors.csv)";
          lines.push_back({"Anchors", line.str()});
        }
      if (r.contains("passive_bars"))
        {
          const nlohmann::json &bars      = r["passive_bars"]["bars"];
          unsigned int          n_yielded = 0;
          for (const auto &b : bars)
            n_yielded += b["status"] == "yielded";
          std::ostringstream line;
          line << bars.size() << (bars.size() == 1 ? " bar, " : " bars, ")
               << n_yielded << " yielded (capacities "
               << (r["passive_bars"]["capacity_reduced_by_K"].get<bool>() ?
                     "reduced by K" :
                     "not reduced by K")
               << "; bars.csv)";
          lines.push_back({"Passive bars", line.str()});
        }
      return lines;
    }

    template std::vector<Anchor<2>>
    locate_anchors(const Model<2> &);
    template std::vector<Anchor<3>>
    locate_anchors(const Model<3> &);
    template std::vector<Anchor<2>>
    add_anchor_loads(Model<2> &);
    template std::vector<Anchor<3>>
    add_anchor_loads(Model<3> &);
    template nlohmann::json
    reinforcement_output(const Model<2> &, const std::vector<Anchor<2>> &);
    template nlohmann::json
    reinforcement_output(const Model<3> &, const std::vector<Anchor<3>> &);
  } // namespace analyses
} // namespace fdem
