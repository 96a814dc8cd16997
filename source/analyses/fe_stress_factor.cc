// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/fe_stress_factor.h>
#include <fdem/analyses/safety_factor_iteration.h>

namespace fdem
{
  namespace analyses
  {
    template <int dim>
    FeStressFactor
    fe_stress_factor(Model<dim> &model)
    {
      const contact::MixedSystem<dim> &system = model.get_mixed_system();
      const std::vector<bool>          on_sliding_surface =
        model.pairs_on_sliding_surface();
      FeStressFactor               result;
      contact::ContactOutcome<dim> stuck;
      stuck.states.resize(system.n_pairs()); // a default state sticks
      // At full strength: the loads that depend on K (the anchors) at K = 1,
      // then back to the model's K.
      model.apply_strength_dependent_loads(1.0);
      stuck.solution = model.solve_all_stick();
      model.apply_strength_dependent_loads(model.get_strength_reduction());
      if (!stuck.solution.solved)
        {
          result.not_computed = "the all-stick state has no solution";
          return result;
        }
      result.all_stick = stuck.solution;
      // The same sums as eq. (11), at full strength.
      const ReducedStrengthSolution sums = resisting_and_sliding_forces(
        system, stuck, model.pair_strengths(1.0), on_sliding_surface);
      for (unsigned int p = 0; p < on_sliding_surface.size(); ++p)
        result.n_pairs_in_tension +=
          on_sliding_surface[p] && stuck.solution.forces[dim * p] > 0;
      result.resisting_force = sums.resisting_force;
      result.sliding_force   = sums.sliding_force;
      if (!(sums.sliding_force > 0))
        {
          result.not_computed =
            "no shear force on the sliding surface in the all-stick state";
          return result;
        }
      result.computed = true;
      result.factor   = sums.resisting_force / sums.sliding_force;
      return result;
    }

    template FeStressFactor
    fe_stress_factor(Model<2> &);
    template FeStressFactor
    fe_stress_factor(Model<3> &);
  } // namespace analyses
} // namespace fdem
