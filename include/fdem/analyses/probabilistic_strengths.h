// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/probabilistic_parameters.h>
#include <fdem/model.h>

#include <unordered_map>
#include <utility>
#include <vector>

namespace fdem
{
  namespace analyses
  {
    /**
     * The pair strengths of a sample of the random soil strengths (the
     * variables on the loads are not strengths and are left alone): the
     * model's own (Model::pair_strengths()) with each random c and tan(phi)
     * replaced by the sample's value. A material's strength reaches a node
     * of an interface with Strength = material through the weight of the
     * material at the node (blocks::soil_strength_at_nodes(): the node's
     * c is the weighted mean of its materials' c, tan(phi) likewise), so a
     * random material changes the node's strength by its weight times its
     * change from the model's value.
     */
    template <int dim>
    class SampleStrengths
    {
    public:
      /**
       * Finds each variable's target in @p model and, for materials, their
       * weights at the nodes (from soil_strength_at_nodes() itself, with
       * each material's c set to 1 and the others' to 0 in turn, so that the
       * weights are the model's by construction).
       */
      SampleStrengths(Model<dim>                        &model,
                      const std::vector<RandomVariable> &variables);

      /** Pair strengths of all interfaces at @p K for the variables' @p values.
       */
      std::vector<contact::PairStrength>
      operator()(const std::vector<double> &values, const double K) const;

      /** Whether @p values are soil strengths: c >= 0, 0 <= phi < 90 degrees.
       */
      bool
      physical(const std::vector<double> &values) const;

      /** The model's own value of each variable (its .prm value). */
      std::vector<double>
      model_values() const;

    private:
      const Model<dim>           &model;
      std::vector<RandomVariable> variables;
      /** Per interface: the variable of its own c and of its phi (-1: none). */
      std::vector<int> interface_cohesion, interface_friction;
      /** The random materials: name, model c and tan(phi), their variables. */
      struct Material
      {
        std::string name;
        double      cohesion = 0, friction_coefficient = 0;
        int         cohesion_variable = -1, friction_variable = -1;
      };
      std::vector<Material> materials;
      /** Per interface: node (x dof) -> (index in materials, weight). */
      std::vector<
        std::unordered_map<types::global_dof_index,
                           std::vector<std::pair<unsigned int, double>>>>
        weights;

      /** tan(phi) of variable @p v's value @p x (a friction angle or tan(phi)).
       */
      double
      friction_coefficient(const unsigned int v, const double x) const;
    };
  } // namespace analyses
} // namespace fdem
