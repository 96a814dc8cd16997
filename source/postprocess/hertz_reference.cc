// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/postprocess/hertz_reference.h>
#include <fdem/postprocess/hertz_sphere.h>

#include <cmath>

namespace fdem
{
  namespace postprocess
  {
    template <int dim>
    nlohmann::json
    hertz_reference(const Model<dim>                          &model,
                    std::vector<std::vector<PairResult<dim>>> &results)
    {
      // Plane-strain Hertz contact of a cylinder on a half-space (the paper's
      // example 4.A, its ref. [12]): a = sqrt(4 p r / (pi E')), q_max =
      // 2 p / (pi a), 1/E' = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, and
      // q(x) = q_max sqrt(1 - (x/a)^2). The generator's model is a half model,
      // so p is twice the normal force on its interface. In 3D, the Hertz
      // sphere generator's quarter model: see postprocess/hertz_sphere.h.
      using Source = parameters::GeometryParameters::Source;
      if (model.get_parameters().geometry.source !=
            (dim == 2 ? Source::hertz : Source::hertz_sphere) ||
          model.get_interfaces().size() != 1 ||
          !model.get_contact_outcome().converged())
        return {};
      const auto &cylinder = model.get_parameters().materials.at(
        model.get_blocks()[model.get_interfaces()[0].block_I]->name);
      const auto &foundation = model.get_parameters().materials.at(
        model.get_blocks()[model.get_interfaces()[0].block_J]->name);
      const double inverse_E =
        (1 - std::pow(cylinder.poissons_ratio, 2)) / cylinder.youngs_modulus +
        (1 - std::pow(foundation.poissons_ratio, 2)) /
          foundation.youngs_modulus;
      if constexpr (dim == 3)
        return hertz_sphere_reference(
          results[0],
          inverse_E,
          model.get_parameters().geometry.hertz_sphere.radius *
            model.get_parameters().geometry.scale_factor);
      double half_load = 0;
      for (const auto &r : results[0])
        half_load -= r.normal_force;
      const double p = 2 * half_load,
                   r = model.get_parameters().geometry.hertz.radius *
                       model.get_parameters().geometry.scale_factor;
      const double a_exact = std::sqrt(4 * p * r * inverse_E / numbers::PI);
      const double q_exact = 2 * p / (numbers::PI * a_exact);
      // Distance from the symmetry axis: the pair that touches before loading.
      Point<dim> axis         = results[0][0].position;
      double     smallest_gap = results[0][0].initial_gap;
      for (const auto &pair : results[0])
        if (pair.initial_gap < smallest_gap)
          {
            smallest_gap = pair.initial_gap;
            axis         = pair.position;
          }
      for (auto &pair : results[0])
        {
          const double x = pair.position.distance(axis) / a_exact;
          pair.reference_pressure =
            x < 1 ? q_exact * std::sqrt(1 - x * x) : 0.0;
        }
      double q_max = 0;
      for (const auto &pair : results[0])
        q_max = std::max(q_max, pair.normal_pressure);
      const double a = contact_extent(results[0]);
      return {{"load_per_unit_length", p},
              {"contact_half_width_exact", a_exact},
              {"max_pressure_exact", q_exact},
              {"contact_half_width", a},
              {"max_pressure", q_max},
              {"contact_half_width_error", a / a_exact - 1},
              {"max_pressure_error", q_max / q_exact - 1}};
    }

    template nlohmann::json
    hertz_reference(const Model<2> &,
                    std::vector<std::vector<PairResult<2>>> &);
    template nlohmann::json
    hertz_reference(const Model<3> &,
                    std::vector<std::vector<PairResult<3>>> &);
  } // namespace postprocess
} // namespace fdem
