// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/safety_factor_analysis.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace fdem
{
  namespace analyses
  {
    template <int dim>
    SafetyFactorAnalysis<dim>::SafetyFactorAnalysis(Model<dim> &          model,
                                                    std::function<void()> on_solved_step)
      : model(model)
      , on_solved_step(std::move(on_solved_step))
      , on_sliding_surface(model.pairs_on_sliding_surface())
    {
      AssertThrow(std::find(on_sliding_surface.begin(), on_sliding_surface.end(), true) !=
                    on_sliding_surface.end(),
                  ExcMessage("Interfaces: no interface is a sliding surface; set "
                             "'Sliding surface = true' on one, or Safety factor/"
                             "Compute = false."));
    }

    template <int dim>
    ReducedStrengthSolution
    SafetyFactorAnalysis<dim>::solve(const double K)
    {
      std::ostringstream what;
      what << "safety factor step: K = " << std::setprecision(8) << K;
      model.progress(what.str());
      model.solve_contact(K);
      ReducedStrengthSolution solution;
      {
        TimerOutput::Scope scope(model.phase_timer(), "safety factor");
        solution = resisting_and_sliding_forces(*model.mixed_system, model.contact_outcome,
                                                model.pair_strengths(K), on_sliding_surface);
      }
      if (solution.converged && on_solved_step)
        on_solved_step();
      return solution;
    }

    template <int dim>
    Result
    SafetyFactorAnalysis<dim>::run()
    {
      model.log << "Safety factor (eqs. 10-13):" << std::endl;
      const Result result = iterate([this](const double K) { return solve(K); },
                                    model.parameters.safety_factor, model.log);
      model.restore_last_static_state();
      model.log << "Safety factor: ";
      if (result.converged)
        model.log << std::setprecision(8) << result.safety_factor << " (" << result.reason
                  << "; certified: " << kind_name(result.certificate.kind) << ", "
                  << result.certificate.reason << ")" << std::endl;
      else
        model.log << "not certified (" << result.certificate.reason << ")" << std::endl;
      return result;
    }

    template class SafetyFactorAnalysis<2>;
    template class SafetyFactorAnalysis<3>;
  } // namespace analyses
} // namespace fdem
