// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/fe_stress_factor.h>
#include <fdem/analyses/safety_factor_iteration.h>
#include <fdem/model.h>

#include <functional>
#include <optional>
#include <vector>

namespace fdem
{
  namespace analyses
  {
    /**
     * The safety factor of a factorised Model by the paper's eqs. (10)-(13):
     * every step is one contact solve of the model with the sliding
     * surfaces' c and tan(phi) divided by K, on the model's one
     * factorisation. Then, if asked, the sensitivity of K to the stiffness
     * of the moving blocks (contact solves only).
     */
    template <int dim>
    class SafetyFactorAnalysis
    {
    public:
      /**
       * @p on_solved_step(K, K*) is called after each step with a static
       * solution, the model in that state (e.g. to write the step's VTU
       * files); K* is NaN where the step has no sliding force.
       */
      SafetyFactorAnalysis(
        Model<dim>                                  &model,
        std::function<void(double K, double K_star)> on_solved_step = {});

      /**
       * The iteration with its certificate; leaves the model in the last
       * state with a static solution.
       */
      Result
      run();

      /**
       * One step at K, eqs. (10)-(11): the contact solve at the reduced
       * strengths, warm-started from the last informative static state,
       * and F_R, F_tau. Other analyses iterate() on it (yield acceleration).
       */
      ReducedStrengthSolution
      solve(const double K);

      /**
       * The iteration's estimate of K after a failed first K: the FE-stress
       * factor (fe_stress_factor(), every pair stuck), NaN if it has none.
       */
      double
      estimate();

      /**
       * The FE-stress factor if run()'s iteration computed it (estimate()
       * after a failed first K), so that it is not solved again for the
       * run's report; not the stiffness check's, on other compliances.
       */
      const std::optional<FeStressFactor> &
      fe_stress_factor_computed() const
      {
        return fe_stress;
      }

    private:
      Model<dim>                                  &model;
      std::function<void(double K, double K_star)> on_solved_step;
      /** Per pair of all interfaces: on a sliding surface? */
      std::vector<bool> on_sliding_surface;
      /** The latest estimate()'s, and the main iteration's (run()). */
      std::optional<FeStressFactor> latest_fe_stress, fe_stress;

      /**
       * K again with the moving blocks' compliance scaled by 1/factor and
       * by factor (Safety factor/Stiffness check), each from the same
       * initial K as @p base; the model's contact state is put back
       * afterwards.
       */
      StiffnessSensitivity
      stiffness_sensitivity(const Result &base);

      /**
       * The slope d(K*)/dK at @p K for the model's contact state, solved at K
       * with the result @p at_K: the state's statuses and slip directions held,
       * two solves of the mixed system at K -/+ dK (no status iteration; the
       * rows of a 3D slipping pair are the linearisation of its friction
       * law, so each is a Newton step of the contact problem from the
       * solved state), K* of each, their central difference. NaN if either
       * solve has no K*.
       */
      double
      K_star_slope(const double K, const ReducedStrengthSolution &at_K);
    };
  } // namespace analyses
} // namespace fdem
