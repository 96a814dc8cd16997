// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/probabilistic_strengths.h>
#include <fdem/blocks/block_materials.h>

#include <cmath>

namespace fdem
{
  namespace analyses
  {
    template <int dim>
    SampleStrengths<dim>::SampleStrengths(
      Model<dim>                        &model,
      const std::vector<RandomVariable> &variables)
      : model(model)
      , variables(variables)
      , interface_cohesion(model.get_interfaces().size(), -1)
      , interface_friction(model.get_interfaces().size(), -1)
      , weights(model.get_interfaces().size())
    {
      using Quantity = RandomVariable::Quantity;
      for (unsigned int v = 0; v < variables.size(); ++v)
        {
          const RandomVariable &variable = variables[v];
          if (variable.owner == RandomVariable::Owner::loads ||
              variable.owner == RandomVariable::Owner::water)
            continue; // not a strength
          const bool cohesion = variable.quantity == Quantity::cohesion;
          if (variable.owner == RandomVariable::Owner::interface)
            {
              for (unsigned int i = 0; i < model.get_interfaces().size(); ++i)
                if (model.get_interfaces()[i].name == variable.name)
                  (cohesion ? interface_cohesion : interface_friction)[i] = v;
              continue;
            }
          unsigned int m = 0;
          while (m < materials.size() && materials[m].name != variable.name)
            ++m;
          if (m == materials.size())
            {
              const parameters::MaterialParameters &p =
                model.get_parameters().materials.at(variable.name);
              materials.push_back(
                {variable.name,
                 p.cohesion,
                 std::tan(p.friction_angle * numbers::PI / 180),
                 -1,
                 -1});
            }
          (cohesion ? materials[m].cohesion_variable :
                      materials[m].friction_variable) = v;
        }

      // Each random material's weight at the nodes of every interface with
      // Strength = material: its c set to 1, every other material's to 0.
      for (unsigned int i = 0; i < model.get_interfaces().size(); ++i)
        {
          const auto &interface = model.get_interfaces()[i];
          if (!model.get_parameters()
                 .interfaces.at(interface.name)
                 .strength_from_material)
            continue;
          auto      &block = *model.get_blocks()[interface.block_I];
          const auto saved = block.materials;
          auto weak_layers = blocks::weak_layers<dim>(model.get_parameters());
          for (unsigned int m = 0; m < materials.size(); ++m)
            {
              for (auto &[key, material] : block.materials)
                material.cohesion =
                  model.get_mesh().material_key_name(key) == materials[m].name ?
                    1 :
                    0;
              for (auto &layer : weak_layers)
                layer.material.cohesion = layer.name == materials[m].name;
              for (const auto &[dof, strength] :
                   blocks::soil_strength_at_nodes(block,
                                                  interface.face_group,
                                                  model.get_mesh(),
                                                  interface.name,
                                                  weak_layers))
                if (strength.cohesion != 0)
                  weights[i][dof].emplace_back(m, strength.cohesion);
            }
          block.materials = saved;
        }
    }

    template <int dim>
    double
    SampleStrengths<dim>::friction_coefficient(const unsigned int v,
                                               const double       x) const
    {
      return variables[v].quantity == RandomVariable::Quantity::friction_angle ?
               std::tan(x * numbers::PI / 180) :
               x;
    }

    template <int dim>
    std::vector<contact::PairStrength>
    SampleStrengths<dim>::operator()(const std::vector<double> &values,
                                     const double               K) const
    {
      // The random materials' changes from the model's values.
      std::vector<blocks::SoilStrength> change(materials.size());
      for (unsigned int m = 0; m < materials.size(); ++m)
        {
          if (materials[m].cohesion_variable >= 0)
            change[m].cohesion =
              values[materials[m].cohesion_variable] - materials[m].cohesion;
          if (materials[m].friction_variable >= 0)
            change[m].friction_coefficient =
              friction_coefficient(materials[m].friction_variable,
                                   values[materials[m].friction_variable]) -
              materials[m].friction_coefficient;
        }
      const auto soil = [&](const unsigned int            i,
                            const contact::NodePair<dim> &pair) {
        blocks::SoilStrength s = model.soil_strength(i, pair);
        if (interface_cohesion[i] >= 0)
          s.cohesion = values[interface_cohesion[i]];
        if (interface_friction[i] >= 0)
          s.friction_coefficient =
            friction_coefficient(interface_friction[i],
                                 values[interface_friction[i]]);
        if (!weights[i].empty())
          {
            auto it = weights[i].find(pair.dofs_I[0]);
            if (it == weights[i].end())
              it = weights[i].find(pair.dofs_J[0]);
            if (it != weights[i].end())
              for (const auto &[m, w] : it->second)
                {
                  s.cohesion += w * change[m].cohesion;
                  s.friction_coefficient += w * change[m].friction_coefficient;
                }
          }
        return s;
      };
      return model.pair_strengths(K, soil);
    }

    template <int dim>
    bool
    SampleStrengths<dim>::physical(const std::vector<double> &values) const
    {
      for (unsigned int v = 0; v < variables.size(); ++v)
        {
          const double x = values[v];
          switch (variables[v].quantity)
            {
              case RandomVariable::Quantity::cohesion:
              case RandomVariable::Quantity::tan_phi:
                if (!(x >= 0))
                  return false;
                break;
              case RandomVariable::Quantity::friction_angle:
                if (!(x >= 0 && x < 90))
                  return false;
                break;
              case RandomVariable::Quantity::unit_weight_factor:
                if (!(x > 0))
                  return false;
                break;
              case RandomVariable::Quantity::horizontal_seismic_coefficient:
                // Either sign is a load (towards or away from the free
                // face); one without equilibrium is a failure, not
                // nonphysical.
                if (!std::isfinite(x))
                  return false;
                break;
              case RandomVariable::Quantity::water_level_shift:
                // Any level: below the model, no water.
                if (!std::isfinite(x))
                  return false;
                break;
            }
        }
      return true;
    }

    template <int dim>
    std::vector<double>
    SampleStrengths<dim>::model_values() const
    {
      std::vector<double> values;
      for (const RandomVariable &variable : variables)
        {
          if (variable.owner == RandomVariable::Owner::water)
            {
              values.push_back(0); // the line as given
              continue;
            }
          if (variable.owner == RandomVariable::Owner::loads)
            {
              values.push_back(
                variable.quantity ==
                    RandomVariable::Quantity::unit_weight_factor ?
                  1 : // the case's own weight
                  model.get_parameters().loads.horizontal_seismic_coefficient);
              continue;
            }
          const bool interface =
            variable.owner == RandomVariable::Owner::interface;
          const double c =
            interface ?
              model.get_parameters().interfaces.at(variable.name).cohesion :
              model.get_parameters().materials.at(variable.name).cohesion;
          const double phi =
            interface ?
              model.get_parameters()
                .interfaces.at(variable.name)
                .friction_angle :
              model.get_parameters().materials.at(variable.name).friction_angle;
          switch (variable.quantity)
            {
              case RandomVariable::Quantity::cohesion:
                values.push_back(c);
                break;
              case RandomVariable::Quantity::friction_angle:
                values.push_back(phi);
                break;
              case RandomVariable::Quantity::tan_phi:
                values.push_back(std::tan(phi * numbers::PI / 180));
                break;
              case RandomVariable::Quantity::unit_weight_factor:
              case RandomVariable::Quantity::horizontal_seismic_coefficient:
              case RandomVariable::Quantity::water_level_shift:
                break;
            }
        }
      return values;
    }

    template class SampleStrengths<2>;
    template class SampleStrengths<3>;
  } // namespace analyses
} // namespace fdem
