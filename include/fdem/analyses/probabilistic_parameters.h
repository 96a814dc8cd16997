// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/probabilistic_sampling.h>

#include <deal.II/base/parameter_handler.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace fdem
{
  namespace analyses
  {
    /** A random soil strength: c, phi or tan(phi) of an interface or a
     * material. */
    struct RandomVariable
    {
      enum class Owner
      {
        interface,
        material,
        /** The loads: Loads/Unit weight factor, Loads/Horizontal seismic
           coefficient. */
        loads,
        /** The water: Water/Piezometric line shift. */
        water
      };
      enum class Quantity
      {
        cohesion,
        friction_angle,
        tan_phi,
        /** A factor on the weight of every block (Model::body_force_cases()).
         */
        unit_weight_factor,
        /** The pseudo-static kh (analyses/seismic.h): a body force kh W
           towards the free face, a combination of the body-force cases. */
        horizontal_seismic_coefficient,
        /** A vertical shift (length, up) of every point of Water/Piezometric
           line: new pore pressures and saturated weights, a right-hand side.
         */
        water_level_shift
      };
      /** As written: e.g. "Interfaces/sliding surface/Cohesion". */
      std::string target;
      Owner       owner = Owner::interface;
      /** The interface's or the material's name. */
      std::string           name;
      Quantity              quantity = Quantity::cohesion;
      probability::Marginal marginal;
    };

    /**
     * The probabilistic safety factor: subsection "Probabilistic"
     * (probabilistic.h). Random soil strengths with their distributions and
     * correlations, sampled by Monte Carlo or Latin hypercube from a seed;
     * each sample's K on the model's one factorisation.
     */
    struct ProbabilisticParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /**
       * Throws naming Probabilistic/Variables unless each variable's target
       * exists and has a strength of its own: an interface of @p interfaces
       * (name -> whether its strength comes from the materials or it is
       * frictionless), a material of @p materials (name -> whether it has a
       * soil strength).
       */
      void
      check_targets(
        const std::map<std::string, bool> &interfaces_without_own_strength,
        const std::map<std::string, bool> &materials_with_strength) const;

      /** Run the probabilistic analysis (after the safety factor). */
      bool                        compute         = false;
      unsigned int                n_samples       = 1000;
      bool                        latin_hypercube = false;
      std::uint64_t               seed            = 1;
      std::vector<RandomVariable> variables;
      /** The correlation matrix, row-major, n_variables^2 (identity if none
       * given). */
      std::vector<double> correlation;
      /** 1-based index of the variable of the fragility curve (0: none). */
      unsigned int fragility_variable = 0;
      unsigned int n_fragility_bins   = 10;
      /** First-order second-moment estimate beside the samples. */
      bool fosm = true;
      /** Rosenblueth's point estimates beside the samples (2^n solves). */
      bool point_estimate = true;
    };
  } // namespace analyses
} // namespace fdem
