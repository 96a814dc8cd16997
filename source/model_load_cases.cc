// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/model.h>

#include <cmath>

namespace fdem
{
  template <int dim>
  unsigned int
  Model<dim>::add_load_case(const std::vector<Vector<double>> &loads)
  {
    AssertThrow(mixed_system,
                ExcMessage(
                  "Load cases need the mixed system (compute_flexibility())."));
    AssertDimension(loads.size(), blocks.size());
    if (base_load_vectors.empty())
      {
        for (const auto &block : blocks)
          base_load_vectors.push_back(block->load_vector);
        base_external_displacements = external_displacements;
      }
    std::vector<Vector<double>> u;
    {
      // One solve per block: the cost of a load case (doc/benchmarks.md).
      TimerOutput::Scope scope(timer, "load cases");
      for (unsigned int b = 0; b < blocks.size(); ++b)
        u.push_back(blocks[b]->solve(loads[b]));
    }
    const unsigned int index = mixed_system->add_load_case(u, loads);
    case_loads.push_back(loads);
    case_displacements.push_back(std::move(u));
    Assert(index + 1 == case_loads.size(), ExcInternalError());
    return index;
  }

  template <int dim>
  std::vector<unsigned int>
  Model<dim>::body_force_cases(const bool saturated)
  {
    std::vector<unsigned int> &indices =
      body_force_case_indices[saturated ? 1 : 0];
    if (indices.empty())
      {
        std::vector<std::vector<Vector<double>>> per_direction(dim);
        for (const auto &block : blocks)
          {
            std::vector<Vector<double>> loads =
              block->unit_body_force_loads(saturated);
            for (unsigned int d = 0; d < dim; ++d)
              per_direction[d].push_back(std::move(loads[d]));
          }
        for (unsigned int d = 0; d < dim; ++d)
          indices.push_back(add_load_case(per_direction[d]));
      }
    return indices;
  }

  template <int dim>
  void
  Model<dim>::set_load_combination(const double               base_factor,
                                   const std::vector<double> &coefficients)
  {
    AssertThrow(coefficients.size() <= case_loads.size(),
                ExcMessage("More load coefficients than load cases."));
    AssertThrow(std::isfinite(base_factor),
                ExcMessage("A load factor is not a finite number."));
    for (const double c : coefficients)
      AssertThrow(std::isfinite(c),
                  ExcMessage("A load coefficient is not a finite number."));
    if (!base_load_vectors.empty())
      for (unsigned int b = 0; b < blocks.size(); ++b)
        {
          Vector<double> &F = blocks[b]->load_vector;
          Vector<double> &u = external_displacements[b];
          F                 = base_load_vectors[b];
          u                 = base_external_displacements[b];
          if (base_factor != 1)
            {
              F *= base_factor;
              u *= base_factor;
            }
          for (unsigned int k = 0; k < coefficients.size(); ++k)
            if (coefficients[k] != 0)
              {
                F.add(coefficients[k], case_loads[k][b]);
                u.add(coefficients[k], case_displacements[k][b]);
              }
        }
    else
      AssertThrow(base_factor == 1 && coefficients.empty(),
                  ExcMessage("A load combination needs its load cases first."));
    mixed_system->set_load_coefficients(base_factor, coefficients);
  }

  template <int dim>
  Vector<double>
  Model<dim>::load_change(const unsigned int b) const
  {
    Vector<double> change(blocks[b]->load_vector.size());
    if (!base_load_vectors.empty())
      {
        change = base_load_vectors[b];
        change -= blocks[b]->load_vector;
      }
    return change;
  }

  template unsigned int
  Model<2>::add_load_case(const std::vector<Vector<double>> &);
  template std::vector<unsigned int>
  Model<2>::body_force_cases(const bool);
  template void
  Model<2>::set_load_combination(const double, const std::vector<double> &);
  template Vector<double>
  Model<2>::load_change(const unsigned int) const;
  template unsigned int
  Model<3>::add_load_case(const std::vector<Vector<double>> &);
  template std::vector<unsigned int>
  Model<3>::body_force_cases(const bool);
  template void
  Model<3>::set_load_combination(const double, const std::vector<double> &);
  template Vector<double>
  Model<3>::load_change(const unsigned int) const;
} // namespace fdem
