// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/probabilistic_loads.h>
#include <fdem/blocks/surface_loads.h>

#include <algorithm>

namespace fdem
{
  namespace analyses
  {
    template <int dim>
    SampleLoads<dim>::SampleLoads(Model<dim>                        &model,
                                  const std::vector<RandomVariable> &variables,
                                  const SeismicResults &model_seismic)
      : model(model)
    {
      using Quantity = RandomVariable::Quantity;
      for (unsigned int v = 0; v < variables.size(); ++v)
        if (variables[v].quantity == Quantity::unit_weight_factor)
          weight_variable = v;
        else if (variables[v].quantity ==
                 Quantity::horizontal_seismic_coefficient)
          kh_variable = v;
        else if (variables[v].quantity == Quantity::water_level_shift)
          water_variable = v;
      if (!active())
        return; // the model's load, untouched
      // The model's seismic load (seismic_analyses(): kh, kv, the
      // direction), which a sample changes: its kh, or its weight (and
      // with it the seismic force kh W).
      const parameters::LoadParameters &loads = model.get_parameters().loads;
      seismic.kh            = loads.horizontal_seismic_coefficient;
      seismic.kv            = loads.vertical_seismic_coefficient;
      seismic.on_pore_water = loads.seismic_on_pore_water;
      model_is_seismic      = model_seismic.active;
      if (model_seismic.active)
        for (unsigned int d = 0; d < dim; ++d)
          seismic.direction[d] = model_seismic.direction[d];
      else if (kh_variable >= 0)
        {
          std::string from;
          seismic.direction = seismic_direction(model, from);
        }
      // Made once on the blocks' factorisations (collective).
      weight_cases = model.body_force_cases(true);
      if (kh_variable >= 0 || model_is_seismic)
        seismic_cases = model.body_force_cases(seismic.on_pore_water);
      if (water_variable >= 0)
        {
          // The faces whose pressure is the piezometric line's.
          const auto face_group = [&](const std::string &name) {
            const auto &names = model.get_mesh().face_group_names;
            return types::boundary_id(
              std::find(names.begin(), names.end(), name) - names.begin());
          };
          for (const std::string &name : model.get_parameters().boundary_names)
            if (model.get_parameters().boundaries.at(name).pressure ==
                "piezometric")
              water_faces.insert(face_group(name));
          for (const std::string &name : model.get_parameters().interface_names)
            if (model.get_parameters().interfaces.at(name).pore_pressure ==
                "piezometric")
              water_faces.insert(face_group(name));
          const blocks::PiezometricPressure<dim> table(
            model.get_parameters().water, model.get_parameters().geometry);
          std::vector<Vector<double>> zero;
          for (const auto &block : model.get_blocks())
            {
              water_at_model.push_back(block->water_loads(table, water_faces));
              zero.emplace_back(block->load_vector.size());
            }
          // Its parts are replaced per sample (set()).
          water_case_index = model.add_load_case(zero);
        }
    }

    template <int dim>
    typename contact::MixedSystem<dim>::LoadCase
    SampleLoads<dim>::water_case(const std::vector<double> &values) const
    {
      Assert(water_variable >= 0, ExcInternalError());
      // Every line raised by the sample's value: Water/Piezometric line and
      // the materials' own.
      const blocks::PiezometricPressure<dim> table(
        model.get_parameters().water,
        model.get_parameters().geometry,
        values[water_variable]);
      // The excess of the saturated weight carries what the weight does:
      // lambda g, and the seismic force if it acts on the pore water.
      const double lambda =
        weight_variable >= 0 ? values[weight_variable] : 1.0;
      const double kh = kh_variable >= 0 ? values[kh_variable] : seismic.kh;
      const std::vector<double> &g =
        model.get_parameters().loads.gravity_direction;
      std::vector<double> c(dim);
      for (unsigned int d = 0; d < dim; ++d)
        c[d] = lambda * g[d] +
               (seismic.on_pore_water ?
                  lambda * (kh * seismic.direction[d] - seismic.kv * g[d]) :
                  0.0);
      std::vector<Vector<double>> loads, displacements;
      for (unsigned int b = 0; b < model.get_blocks().size(); ++b)
        {
          const std::vector<Vector<double>> parts =
            model.get_blocks()[b]->water_loads(table, water_faces);
          // The change from the line as given: zero for a zero shift.
          Vector<double> F = parts[0];
          F -= water_at_model[b][0];
          for (unsigned int d = 0; d < dim; ++d)
            if (c[d] != 0)
              {
                F.add(c[d], parts[1 + d]);
                F.add(-c[d], water_at_model[b][1 + d]);
              }
          displacements.push_back(model.get_blocks()[b]->solve(F));
          loads.push_back(std::move(F));
        }
      return model.get_mixed_system().load_case(displacements, loads);
    }

    template <int dim>
    void
    SampleLoads<dim>::set(
      const std::vector<double>                          &values,
      const typename contact::MixedSystem<dim>::LoadCase *water)
    {
      if (!active())
        return;
      const double lambda =
        weight_variable >= 0 ? values[weight_variable] : 1.0;
      const double kh = kh_variable >= 0 ? values[kh_variable] : seismic.kh;
      std::vector<double> coefficients(model.get_mixed_system().n_load_cases(),
                                       0.0);
      const std::vector<double> &g =
        model.get_parameters().loads.gravity_direction;
      for (unsigned int d = 0; d < dim; ++d)
        {
          coefficients[weight_cases[d]] += (lambda - 1) * g[d];
          if (!seismic_cases.empty())
            coefficients[seismic_cases[d]] +=
              lambda * (kh * seismic.direction[d] - seismic.kv * g[d]);
        }
      if (water_variable >= 0)
        {
          if (water != nullptr)
            model.replace_load_case(water_case_index, *water);
          else
            model.replace_load_case(water_case_index, water_case(values));
          coefficients[water_case_index] = 1;
        }
      model.set_load_combination(1, coefficients);
    }

    template <int dim>
    void
    SampleLoads<dim>::restore()
    {
      if (active())
        {
          if (model_is_seismic)
            set_seismic_load(model, seismic);
          else
            model.set_load_combination(1, {});
        }
      // The loads that depend on K (the anchors) at the model's K.
      model.apply_strength_dependent_loads(model.get_strength_reduction());
    }

    template class SampleLoads<2>;
    template class SampleLoads<3>;
  } // namespace analyses
} // namespace fdem
