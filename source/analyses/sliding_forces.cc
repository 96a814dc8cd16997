// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/safety_factor_iteration.h>

#include <cmath>

namespace fdem
{
  namespace analyses
  {
    template <int dim>
    ReducedStrengthSolution
    resisting_and_sliding_forces(
      const contact::MixedSystem<dim>          &system,
      const contact::ContactOutcome<dim>       &outcome,
      const std::vector<contact::PairStrength> &reduced_strengths,
      const std::vector<bool>                  &on_sliding_surface)
    {
      ReducedStrengthSolution s;
      s.converged            = outcome.converged();
      s.mechanism            = outcome.is_mechanism();
      s.result               = contact::result_description(outcome.result);
      s.n_contact_iterations = outcome.iterations.size();
      double                 sum_f_t = 0;
      dealii::Tensor<1, dim> sum_tangential;
      for (unsigned int p = 0; p < on_sliding_surface.size(); ++p)
        {
          if (!on_sliding_surface[p])
            continue;
          const contact::PairStatus status = outcome.states[p].status;
          s.n_stick += status == contact::PairStatus::stick;
          s.n_slip += status == contact::PairStatus::slip;
          s.n_open += status == contact::PairStatus::open;
          if (!s.converged || status == contact::PairStatus::open)
            continue;
          sum_f_t += outcome.solution.forces[dim * p + 1];
          for (unsigned int i = 1; i < dim; ++i)
            sum_tangential +=
              outcome.solution.forces[dim * p + i] * system.pair(p).frame[i];
          s.resisting_force += reduced_strengths[p].shear_capacity(
            outcome.solution.forces[dim * p]);
        }
      s.sliding_force = dim == 2 ? std::abs(sum_f_t) : sum_tangential.norm();
      // The slip rows fix each |f_t| at its reduced strength exactly, so
      // F_tau = F_R holds to round-off of the solve (1e-13 measured);
      // 1e-10 leaves room and is far below any Safety factor/Tolerance.
      s.degenerate = s.converged && s.n_stick == 0 && s.n_slip > 0 &&
                     s.sliding_force >= (1 - 1e-10) * s.resisting_force;
      return s;
    }

    template ReducedStrengthSolution
    resisting_and_sliding_forces(const contact::MixedSystem<2> &,
                                 const contact::ContactOutcome<2> &,
                                 const std::vector<contact::PairStrength> &,
                                 const std::vector<bool> &);
    template ReducedStrengthSolution
    resisting_and_sliding_forces(const contact::MixedSystem<3> &,
                                 const contact::ContactOutcome<3> &,
                                 const std::vector<contact::PairStrength> &,
                                 const std::vector<bool> &);
  } // namespace analyses
} // namespace fdem
