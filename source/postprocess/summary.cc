// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/linear_algebra/blas_threads.h>
#include <fdem/postprocess/json_number.h>
#include <fdem/postprocess/summary.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fdem
{
  namespace postprocess
  {
    namespace
    {
      nlohmann::json
      certificate_json(const analyses::Certificate &c)
      {
        return {{"kind", analyses::kind_name(c.kind)},
                {"holds", c.holds},
                {"conservative", c.conservative},
                {"K", number_or_null(c.K)},
                {"K_star", number_or_null(c.K_star)},
                {"relative_difference", number_or_null(c.relative_difference)},
                {"relative_distance_left",
                 number_or_null(c.relative_distance_left)},
                {"K_failed", number_or_null(c.K_failed)},
                {"failure", c.failure},
                {"tolerance", c.tolerance},
                {"reason", c.reason}};
      }

      /**
       * "completed", or why not: "no static equilibrium: ..." (exit code 3)
       * when every solve failed as a mechanism, else "safety factor not
       * certified: ..." or "contact problem not solved: ..." (exit code 4).
       */
      template <int dim>
      std::string
      status(const Model<dim> &model, const analyses::Result *safety_factor)
      {
        const auto &outcome = model.get_contact_outcome();
        if (safety_factor != nullptr)
          {
            if (safety_factor->converged)
              return "completed";
            if (safety_factor->no_equilibrium)
              return "no static equilibrium: " + safety_factor->reason;
            return "safety factor not certified: " +
                   safety_factor->certificate.reason;
          }
        if (outcome.converged())
          return "completed";
        if (outcome.is_mechanism())
          return "no static equilibrium: " +
                 contact::result_description(outcome.result);
        return "contact problem not solved: " +
               contact::result_description(outcome.result);
      }
    } // namespace

    template <int dim>
    nlohmann::json
    make_summary(const Model<dim>                &model,
                 const analyses::AnalysisResults &analyses_results,
                 const std::vector<std::vector<PairResult<dim>>> &results,
                 const nlohmann::json                            &hertz,
                 const std::vector<double>                       &reactions)
    {
      const analyses::Result *safety_factor =
        analyses_results.has_safety_factor ? &analyses_results.safety_factor :
                                             nullptr;
      nlohmann::json summary = nlohmann::json::object();
      summary["case"]        = model.get_parameters().case_name;
      summary["dimension"]   = dim;
      summary["fe_degree"]   = model.get_parameters().fe_degree;
      summary["n_mpi_ranks"] = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
      // 0: the BLAS does not say (not OpenBLAS).
      summary["n_blas_threads"] = linear_algebra::n_blas_threads();
      unsigned int n_dofs       = 0;
      summary["blocks"]         = nlohmann::json::array();
      for (unsigned int b = 0; b < model.get_blocks().size(); ++b)
        {
          const auto &block = *model.get_blocks()[b];
          n_dofs += block.dof_handler.n_dofs();
          double volume = 0;
          for (const auto &cell : block.triangulation.active_cell_iterators())
            volume += cell->measure();
          summary["blocks"].push_back(
            {{"name", block.name},
             {"volume", volume},
             {"n_cells", block.triangulation.n_active_cells()},
             {"n_dofs", block.dof_handler.n_dofs()},
             {"free_rigid_modes", block.n_free_rigid_modes()},
             {"max_support_reaction", reactions[b]},
             {"max_load", block.load_vector.linfty_norm()}});
        }
      summary["n_dofs"]     = n_dofs;
      summary["interfaces"] = nlohmann::json::array();
      for (unsigned int i = 0; i < model.get_interfaces().size(); ++i)
        {
          unsigned int n_status[3]  = {0, 0, 0};
          double       max_pressure = 0, normal_force = 0, tangential_force = 0;
          Tensor<1, dim> tangential_resultant;
          for (unsigned int k = 0; k < results[i].size(); ++k)
            {
              const auto &r = results[i][k];
              ++n_status[static_cast<int>(r.status)];
              max_pressure = std::max(max_pressure, r.normal_pressure);
              normal_force += r.normal_force;
              tangential_force += r.tangential_force[0];
              for (unsigned int t = 0; t + 1 < dim; ++t)
                tangential_resultant +=
                  r.tangential_force[t] *
                  model.get_interfaces()[i].pairs[k].frame[t + 1];
            }
          // In 3D the pairs' tangents differ: the magnitude of the resultant.
          if (dim == 3)
            tangential_force = tangential_resultant.norm();
          const double extent = postprocess::contact_extent(results[i]);
          // The full-strength (c, phi) of the pairs, one entry per distinct
          // pair of values (pairs where two materials meet take their means).
          nlohmann::json strengths = nlohmann::json::array();
          for (const auto &r : results[i])
            {
              const auto same = [](const double a, const double b) {
                return std::abs(a - b) <=
                       1e-9 * std::max({1.0, std::abs(a), std::abs(b)});
              };
              std::size_t e = 0;
              while (e < strengths.size() &&
                     !(same(strengths[e]["cohesion"], r.cohesion) &&
                       same(strengths[e]["friction_angle"], r.friction_angle)))
                ++e;
              if (e == strengths.size())
                strengths.push_back({{"cohesion", r.cohesion},
                                     {"friction_angle", r.friction_angle},
                                     {"n_pairs", 0},
                                     {"area", 0.0}});
              auto &entry = strengths[e];
              entry["n_pairs"] =
                entry["n_pairs"].template get<unsigned int>() + 1;
              entry["area"] = entry["area"].template get<double>() + r.area;
            }
          summary["interfaces"].push_back(
            {{"name", model.get_interfaces()[i].name},
             {"block_I",
              model.get_blocks()[model.get_interfaces()[i].block_I]->name},
             {"block_J",
              model.get_blocks()[model.get_interfaces()[i].block_J]->name},
             {"n_pairs", model.get_interfaces()[i].pairs.size()},
             {"area",
              std::accumulate(results[i].begin(),
                              results[i].end(),
                              0.0,
                              [](const double a, const auto &r) {
                                return a + r.area;
                              }) +
                std::accumulate(model.get_interfaces()[i].shared_nodes.begin(),
                                model.get_interfaces()[i].shared_nodes.end(),
                                0.0,
                                [](const double a, const auto &n) {
                                  return a + n.area;
                                })},
             {"n_unpaired_nodes",
              model.get_interfaces()[i].n_unpaired_I +
                model.get_interfaces()[i].n_unpaired_J},
             {"n_nodes_paired_in_an_earlier_interface",
              model.get_interfaces()[i].n_shared_nodes},
             {"n_stick", n_status[0]},
             {"n_slip", n_status[1]},
             {"n_open", n_status[2]},
             {"max_normal_pressure", max_pressure},
             {"contact_extent", extent},
             {"total_normal_force", normal_force},
             {"total_tangential_force", tangential_force},
             {"strengths", strengths}});
        }
      if (!hertz.empty())
        summary["hertz"] = hertz;
      summary["model.strength_reduction"] = model.get_strength_reduction();
      if (safety_factor != nullptr)
        {
          const auto &sf                   = *safety_factor;
          summary["safety_factor"]         = number_or_null(sf.safety_factor);
          summary["converged"]             = sf.converged;
          summary["safety_factor_reason"]  = sf.reason;
          summary["safety_factor_bracket"] = {number_or_null(sf.bracket_low),
                                              number_or_null(sf.bracket_high)};
          nlohmann::json steps             = nlohmann::json::array();
          for (const auto &step : sf.steps)
            steps.push_back(
              {{"K", step.K},
               {"K_star", number_or_null(step.K_star)},
               {"K_next", step.K_next},
               {"K_star_slope", number_or_null(step.solution.K_star_slope)},
               {"F_R", step.solution.resisting_force},
               {"F_tau", step.solution.sliding_force},
               {"n_stick", step.solution.n_stick},
               {"n_slip", step.solution.n_slip},
               {"n_open", step.solution.n_open},
               {"n_contact_iterations", step.solution.n_contact_iterations},
               {"n_slope_solves", step.solution.n_slope_solves},
               {"contact_result", step.solution.result}});
          summary["iterations"]       = steps;
          const auto &fe_stress       = analyses_results.fe_stress;
          summary["fe_stress_factor"] = {
            {"computed", fe_stress.computed},
            {"not_computed", fe_stress.not_computed},
            {"factor", number_or_null(fe_stress.factor)},
            {"F_R", fe_stress.resisting_force},
            {"F_tau", fe_stress.sliding_force},
            {"n_pairs_in_tension", fe_stress.n_pairs_in_tension}};
          summary["certificate"]           = certificate_json(sf.certificate);
          const auto &check                = sf.stiffness;
          summary["stiffness_sensitivity"] = {
            {"computed", check.computed},
            {"not_computed", check.not_computed},
            {"factor", check.factor},
            {"warning_above",
             model.get_parameters().safety_factor.stiffness_check_warning},
            {"wall_seconds", check.wall_seconds},
            {"K_stiffer", number_or_null(check.K_stiffer)},
            {"K_softer", number_or_null(check.K_softer)},
            {"relative_change",
             check.computed && std::isinf(check.relative_change) ?
               nlohmann::json("not certified") :
               number_or_null(check.relative_change)}};
        }
      summary["limit_equilibrium"] =
        analyses::to_json(analyses_results.limit_equilibrium);
      summary["rigid_motions"] = std::vector<double>(
        model.get_contact_outcome().solution.rigid_motions.begin(),
        model.get_contact_outcome().solution.rigid_motions.end());
      nlohmann::json iterations = nlohmann::json::array();
      for (const auto &record : model.get_contact_outcome().iterations)
        iterations.push_back(
          {{"n_stick", record.n_stick},
           {"n_slip", record.n_slip},
           {"n_open", record.n_open},
           {"n_at_cutoff", record.n_at_cutoff},
           {"n_changes", record.n_changes},
           {"reciprocal_condition", record.reciprocal_condition},
           {"factorized", record.factorized}});
      summary["contact"] = {
        {"result",
         contact::result_description(model.get_contact_outcome().result)},
        {"converged", model.get_contact_outcome().converged()},
        {"n_solves", model.get_contact_outcome().iterations.size()},
        {"n_cycles_broken", model.get_contact_outcome().n_cycles_broken},
        {"max_slip_angle_degrees", model.get_contact_outcome().max_slip_angle},
        {"reciprocal_condition",
         model.get_contact_outcome().iterations.empty() ?
           1.0 :
           model.get_contact_outcome().iterations.back().reciprocal_condition},
        {"n_factorizations",
         model.has_mixed_system() ?
           model.get_mixed_system().dense_solver().n_factorizations :
           0},
        {"n_reused_solves",
         model.has_mixed_system() ?
           model.get_mixed_system().dense_solver().n_reused_solves :
           0},
        {"mixed_system", model.get_parameters().solver.mixed_system},
        {"n_gmres_iterations",
         model.has_mixed_system() ?
           model.get_mixed_system().n_krylov_iterations :
           0},
        {"n_flexibility_products",
         model.has_mixed_system() ?
           model.get_mixed_system().n_flexibility_products :
           0},
        {"iterations", iterations}};
      summary["warnings"] = model.get_warnings();
      // For the log file and here, not the screen (postprocess/result_block.h).
      summary["conditioning"] = {{"notes", model.get_conditioning_notes()},
                                 {"max_digits_lost",
                                  model.get_max_digits_lost()}};
      summary["status"]       = status(model, safety_factor);
      return summary;
    }

    template nlohmann::json
    make_summary(const Model<2> &,
                 const analyses::AnalysisResults &,
                 const std::vector<std::vector<PairResult<2>>> &,
                 const nlohmann::json &,
                 const std::vector<double> &);
    template nlohmann::json
    make_summary(const Model<3> &,
                 const analyses::AnalysisResults &,
                 const std::vector<std::vector<PairResult<3>>> &,
                 const nlohmann::json &,
                 const std::vector<double> &);
  } // namespace postprocess
} // namespace fdem
