// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/probabilistic_parameters.h>
#include <fdem/analyses/seismic.h>
#include <fdem/model.h>

#include <deal.II/base/types.h>

#include <set>
#include <vector>

namespace fdem
{
  namespace analyses
  {
    /**
     * The load of a sample of the probabilistic analysis: the random
     * variables that are not strengths (Loads/Unit weight factor lambda,
     * Loads/Horizontal seismic coefficient kh, Water/Piezometric line
     * shift), each a right-hand side on the model's one factorisation.
     * The weight and kh are combinations of the body-force load cases
     * (Model::body_force_cases()): W (lambda g + lambda (kh h - kv g)), the
     * seismic force proportional to the sample's weight, kv, h and the
     * seismic force on the pore water those of the case. The water is one
     * further load case whose parts are replaced per sample
     * (contact::MixedSystem::replace_load_case()): the nodal forces of the
     * shifted line's pore pressures and saturated weights minus those of
     * the line as given (ElasticBlock::water_loads()), solved on the blocks'
     * factorisations: not linear in the shift (the line crosses the
     * faces and cells), so assembled and solved per sample, but never
     * factorised. The blocks' load vectors do not carry the water's change
     * (no output per sample).
     */
    template <int dim>
    class SampleLoads
    {
    public:
      /**
       * Makes the load cases the variables need (collective); @p seismic
       * is the model's seismic load (seismic_analyses()), which a sample's
       * kh or weight changes.
       */
      SampleLoads(Model<dim>                        &model,
                  const std::vector<RandomVariable> &variables,
                  const SeismicResults              &seismic);

      /** Whether a variable changes the load. */
      bool
      active() const
      {
        return weight_variable >= 0 || kh_variable >= 0 || water_variable >= 0;
      }

      /** Whether the water level is random (water_case() then needed). */
      bool
      varies_water() const
      {
        return water_variable >= 0;
      }

      /**
       * The water load case of the variables' @p values: its parts of
       * g_bar and omega^T F. Collective (the blocks' solves).
       */
      typename contact::MixedSystem<dim>::LoadCase
      water_case(const std::vector<double> &values) const;

      /**
       * Sets the model's load to that of @p values; with the water level
       * random, its load case @p water (water_case() of the same values),
       * or computed here (collective) if null.
       */
      void
      set(const std::vector<double>                          &values,
          const typename contact::MixedSystem<dim>::LoadCase *water = nullptr);

      /** Back to the model's own load (seismic_analyses()'s). */
      void
      restore();

    private:
      Model<dim> &model;
      int         weight_variable = -1, kh_variable = -1, water_variable = -1;
      /** The model's seismic load (kh 0 if it has none). */
      SeismicLoad<dim> seismic;
      bool             model_is_seismic = false;
      /** The body-force cases of the weight (saturated) and of kh. */
      std::vector<unsigned int> weight_cases, seismic_cases;
      /** The water's load case, and the faces its pressure acts on. */
      unsigned int                 water_case_index = 0;
      std::set<types::boundary_id> water_faces;
      /** Per block: ElasticBlock::water_loads() of the line as given. */
      std::vector<std::vector<Vector<double>>> water_at_model;
    };
  } // namespace analyses
} // namespace fdem
