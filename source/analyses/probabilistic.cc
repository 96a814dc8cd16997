// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/probabilistic.h>
#include <fdem/analyses/probabilistic_loads.h>
#include <fdem/analyses/probabilistic_sampling.h>
#include <fdem/analyses/probabilistic_strengths.h>
#include <fdem/analyses/safety_factor_iteration.h>
#include <fdem/analyses/sample_iteration.h>
#include <fdem/geometry/mesh_estimate.h>
#include <fdem/postprocess/json_number.h>
#include <fdem/postprocess/output_file.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace fdem
{
  namespace analyses
  {
    namespace
    {
      /** K of one set of strengths, and what it cost. */
      struct Evaluation
      {
        double       K       = std::numeric_limits<double>::quiet_NaN();
        SampleStatus status  = SampleStatus::nonphysical;
        unsigned int n_steps = 0, n_status_iterations = 0;
        /** The iteration from the predicted start was not certified. */
        bool fell_back = false;
      };

      /**
       * The safety factor of a sample: iterate() on the model's mixed
       * system with the sample's strengths, from the state and K at the
       * variables' means, without output.
       */
      template <int dim>
      class SampleSafetyFactor
      {
      public:
        SampleSafetyFactor(Model<dim>                        &model,
                           const std::vector<RandomVariable> &variables,
                           const SeismicResults              &seismic)
          : model(model)
          , strengths(model, variables)
          , loads(model, variables, seismic)
          , on_sliding_surface(model.pairs_on_sliding_surface())
          , quiet(nullptr)
        {
          control.max_iterations =
            model.get_parameters().contact.max_status_iterations;
          control.runaway_factor =
            model.get_parameters().contact.runaway_factor;
        }

        /**
         * K at @p values (the means) from the model's initial K and states,
         * as every later evaluation starts.
         */
        Result
        set_start(const std::vector<double> &values)
        {
          start_states.clear();
          parameters = model.get_parameters().safety_factor;
          Result result;
          evaluate(values, &result);
          // Each sample starts from the initial states (as the first solve
          // of the deterministic K did), not from the limit state at the
          // means: there every pair slips, and an all-slip state gives
          // K* = K at any K where it is static, a fixed point that is not
          // the sample's (measured: FOSM from the limit state gave half the
          // true dK/dc on the paper's slope).
          start_states.clear();
          return result;
        }


        /**
         * The statuses of the contact solve at @p values and @p K from the
         * initial states, kept as the first statuses of every later
         * iteration from a predicted start (empty, the initial states,
         * where that solve has no static solution or every pair slips).
         * The same on every rank and for every sample: a sample's result
         * still depends on the sample alone.
         */
        void
        set_warm_states(const std::vector<double> &values, const double K)
        {
          warm_states.clear();
          model.forget_mixed_factorization();
          loads.set(values, nullptr);
          const std::vector<contact::PairStrength> reduced =
            strengths(values, K);
          model.apply_strength_dependent_loads(K);
          const contact::ContactOutcome<dim> outcome = model.solve_contact_from(
            reduced,
            contact::initial_states(model.get_mixed_system(), reduced),
            control,
            quiet);
          const ReducedStrengthSolution solution = resisting_and_sliding_forces(
            model.get_mixed_system(), outcome, reduced, on_sliding_surface);
          if (outcome.converged() && !solution.degenerate)
            warm_states = outcome.states;
        }

        /**
         * K of @p values; with the water level random, its load case @p water
         * if given (SampleLoads::water_case()), else computed here
         * (collective).
         */
        Evaluation
        evaluate(
          const std::vector<double>                          &values,
          Result                                             *full  = nullptr,
          const typename contact::MixedSystem<dim>::LoadCase *water = nullptr,
          const double start = std::numeric_limits<double>::quiet_NaN())
        {
          Evaluation evaluation;
          if (!strengths.physical(values))
            return evaluation;
          // The same start for every sample: its state, K and a fresh
          // factorisation, whatever was solved before.
          model.forget_mixed_factorization();
          loads.set(values, water);
          // From a predicted start, the warm statuses (set_warm_states());
          // the reference from the initial states.
          std::vector<contact::PairState<dim>> states =
            std::isfinite(start) && !warm_states.empty() ? warm_states :
                                                           start_states;
          last_states.clear();
          const auto solve = [&](const double K) {
            const std::vector<contact::PairStrength> reduced =
              strengths(values, K);
            if (states.empty())
              states =
                contact::initial_states(model.get_mixed_system(), reduced);
            // The anchors' shear reduced by K (analyses/anchors.h), on top
            // of the sample's load.
            model.apply_strength_dependent_loads(K);
            const contact::ContactOutcome<dim> outcome =
              model.solve_contact_from(reduced, states, control, quiet);
            evaluation.n_status_iterations += outcome.iterations.size();
            const ReducedStrengthSolution solution =
              resisting_and_sliding_forces(model.get_mixed_system(),
                                           outcome,
                                           reduced,
                                           on_sliding_surface);
            // Not from a state with every pair slipping: it would carry
            // itself below the limit (SafetyFactorAnalysis::solve()).
            if (outcome.converged() && !solution.degenerate)
              states = last_states = outcome.states;
            return solution;
          };
          // Every sample starts with a fresh factorisation: given a
          // @p start, at its predicted K below its limit from the warm
          // statuses (set_warm_states()), that iteration taken only if
          // certified, else (and without a start) the reference decides
          // (iterate_from()): at Safety factor/Initial factor from the
          // initial states, as the deterministic K. Never from the limit
          // state at the means: where every pair slips, K* = K at any K
          // where that state is static (measured on the paper's slope: one
          // step, K certified below the sample's own, FOSM's dK/dc half the
          // true one).
          const auto reset = [&]() {
            model.forget_mixed_factorization();
            states = start_states;
            last_states.clear();
          };
          const SampleIteration sample =
            iterate_from(solve, reset, parameters, start, quiet);
          const Result &result = sample.result;
          evaluation.fell_back = sample.fell_back;
          evaluation.n_steps   = sample.n_discarded_steps + result.steps.size();
          evaluation.status    = result.converged ? SampleStatus::certified :
                                 result.no_equilibrium ?
                                                    SampleStatus::no_equilibrium :
                                                    SampleStatus::not_certified;
          if (result.converged)
            evaluation.K = result.safety_factor;
          if (full != nullptr)
            *full = result;
          return evaluation;
        }

        Model<dim>                          &model;
        SampleStrengths<dim>                 strengths;
        SampleLoads<dim>                     loads;
        const std::vector<bool>              on_sliding_surface;
        contact::StatusIterationControl      control;
        parameters::SafetyFactorParameters   parameters;
        std::vector<contact::PairState<dim>> start_states, last_states,
          warm_states;
        std::ostream quiet; // no output per sample
      };

      /**
       * FOSM: K at the means and at each mean plus and minus one standard
       * deviation; the variance g^T Sigma g with g by central differences.
       */
      template <int dim>
      nlohmann::json
      fosm(SampleSafetyFactor<dim>       &evaluator,
           const ProbabilisticParameters &p,
           const std::vector<double>     &means,
           const std::vector<double>     &std_devs,
           const double                   K_mean)
      {
        const unsigned int  n = means.size();
        std::vector<double> gradient(n);
        for (unsigned int v = 0; v < n; ++v)
          {
            std::vector<double> x = means;
            x[v]                  = means[v] + std_devs[v];
            const Evaluation up   = evaluator.evaluate(x);
            x[v]                  = means[v] - std_devs[v];
            const Evaluation down = evaluator.evaluate(x);
            if (up.status != SampleStatus::certified ||
                down.status != SampleStatus::certified)
              return {{"computed", false},
                      {"reason",
                       "no certified K at variable " + std::to_string(v + 1) +
                         " one standard deviation from its mean"}};
            gradient[v] = (up.K - down.K) / (2 * std_devs[v]);
          }
        double variance = 0;
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            variance += gradient[i] * gradient[j] * p.correlation[i * n + j] *
                        std_devs[i] * std_devs[j];
        const double std_dev = std::sqrt(variance);
        return {{"computed", true},
                {"K_mean", K_mean},
                {"K_std", std_dev},
                {"beta_normal",
                 postprocess::number_or_null((K_mean - 1) / std_dev)},
                {"P_failure_normal",
                 postprocess::number_or_null(
                   probability::normal_cdf(-(K_mean - 1) / std_dev))},
                {"gradient", gradient},
                {"n_safety_factors", 2 * n}};
      }

      /**
       * Rosenblueth (1975): the 2^n points mean +- one standard deviation,
       * weighted (1 + sum_{i<j} s_i s_j rho_ij) / 2^n.
       */
      template <int dim>
      nlohmann::json
      point_estimate(SampleSafetyFactor<dim>       &evaluator,
                     const ProbabilisticParameters &p,
                     const std::vector<double>     &means,
                     const std::vector<double>     &std_devs)
      {
        const unsigned int n  = means.size();
        double             m1 = 0, m2 = 0;
        for (unsigned int corner = 0; corner < (1u << n); ++corner)
          {
            std::vector<double> x = means;
            std::vector<int>    sign(n);
            double              weight = 1;
            for (unsigned int v = 0; v < n; ++v)
              {
                sign[v] = (corner >> v) & 1 ? 1 : -1;
                x[v] += sign[v] * std_devs[v];
                for (unsigned int w = 0; w < v; ++w)
                  weight += sign[v] * sign[w] * p.correlation[v * n + w];
              }
            weight /= double(1u << n);
            const Evaluation e = evaluator.evaluate(x);
            if (e.status != SampleStatus::certified)
              return {{"computed", false},
                      {"reason", "no certified K at a point estimate"}};
            m1 += weight * e.K;
            m2 += weight * e.K * e.K;
          }
        const double std_dev = std::sqrt(std::max(0.0, m2 - m1 * m1));
        return {{"computed", true},
                {"K_mean", m1},
                {"K_std", std_dev},
                {"beta_normal",
                 postprocess::number_or_null((m1 - 1) / std_dev)},
                {"n_safety_factors", 1u << n}};
      }
    } // namespace

    parameters::WorkEstimate
    sample_work_estimate(const ProbabilisticParameters &p,
                         const double                   seconds_per_sample,
                         const double                   bytes_per_water_case)
    {
      // Per sample: its standard normal values and its values (n_variables
      // each), K, status and three counts twice (local and gathered), and
      // the statistics' sorted copy of K.
      const double bytes_per_sample =
        2 * 8. * p.variables.size() + 2 * 5 * 8. + 8 + 4 + bytes_per_water_case;
      parameters::WorkEstimate work;
      work.entry      = "Probabilistic/Number of samples";
      work.what       = parameters::count_text(p.n_samples) + " samples";
      work.seconds    = p.n_samples * seconds_per_sample;
      work.memory_MiB = p.n_samples * bytes_per_sample / (1024. * 1024.);
      return work;
    }



    template <int dim>
    nlohmann::json
    probabilistic_safety_factor(Model<dim>           &model,
                                const double          deterministic_K,
                                const SeismicResults &seismic)
    {
      const ProbabilisticParameters &p = model.get_parameters().probabilistic;
      TimerOutput::Scope scope(model.phase_timer(), "probabilistic");
      Timer              timer;
      model.progress("probabilistic: " + std::to_string(p.n_samples) +
                     " samples");
      const unsigned int  n_variables = p.variables.size();
      std::vector<double> means, std_devs;
      for (const RandomVariable &v : p.variables)
        {
          means.push_back(v.marginal.distribution_mean());
          std_devs.push_back(v.marginal.distribution_std_dev());
        }

      nlohmann::json          result;
      SampleSafetyFactor<dim> evaluator(model, p.variables, seismic);
      const unsigned int      factorized_before =
        model.get_mixed_system().dense_solver().n_factorizations;
      const unsigned int reused_before =
        model.get_mixed_system().dense_solver().n_reused_solves;
      Timer        mean_timer;
      const Result at_means     = evaluator.set_start(means);
      const double mean_seconds = mean_timer.wall_time();
      result["K_at_means"]      = postprocess::number_or_null(
        at_means.converged ? at_means.safety_factor :
                             std::numeric_limits<double>::quiet_NaN());
      result["K_at_means_steps"]   = at_means.steps.size();
      result["K_at_means_seconds"] = mean_seconds;
      AssertThrow(
        at_means.converged,
        ExcMessage("Probabilistic/Variables: no certified safety factor at the "
                   "variables' means (" +
                   at_means.certificate.reason +
                   "); the samples start from that state."));

      // The samples' work, each at most the time of K at the means (that
      // one starts from the initial states, the samples from a prediction:
      // about 2.6 times fewer contact solves on the paper's slope), before
      // FOSM and the samples start.
      {
        const auto  &system = model.get_mixed_system();
        const double n_ranks =
          system.solver() == contact::MixedSystemSolver::dense ?
            Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) :
            1;
        const double water_bytes =
          evaluator.loads.varies_water() ?
            8. * (2 * dim * system.n_pairs() + system.n_rigid_unknowns()) :
            0;
        const auto &geometry = model.get_parameters().geometry;
        parameters::check_work_estimate(
          sample_work_estimate(p, mean_seconds / n_ranks, water_bytes),
          geometry::memory_limit_MiB(geometry),
          geometry.time_budget);
      }

      // FOSM (2n safety factors) before the samples.
      const nlohmann::json first_order =
        fosm(evaluator, p, means, std_devs, at_means.safety_factor);
      if (p.fosm)
        result["fosm"] = first_order;

      // Each sample's iteration starts at its first-order prediction from K
      // at the means and FOSM's gradient, lowered by 2 % (predicted_start();
      // rank 0's numbers on every rank, so that the start depends on the
      // sample alone), from the statuses of the means at their own such
      // start (set_warm_states(): computed once, the same for every sample
      // and rank), and falls back to the reference where that iteration is
      // not certified (iterate_from()). The reference, also with the
      // environment variable FDEM_PROBABILISTIC_START=reference: the
      // iteration as the deterministic K's, at Safety factor/Initial factor
      // from the initial states. Measured on the paper's slope
      // (doc/benchmarks.md): 2.6 times fewer contact solves than the
      // reference; 9 of 300 samples certified 3e-5 to 4.2e-5 above the
      // reference K (the statuses at the limit depend on the K solved
      // before: both answers are certified), the others within 1e-7.
      const char *start_choice = std::getenv("FDEM_PROBABILISTIC_START");
      const bool  predict      = first_order["computed"].get<bool>() &&
                           !(start_choice != nullptr &&
                             std::strcmp(start_choice, "reference") == 0);
      std::vector<double> gradient;
      double              K_prediction = at_means.safety_factor;
      if (predict)
        {
          gradient = first_order["gradient"].get<std::vector<double>>();
          gradient = Utilities::MPI::broadcast(MPI_COMM_WORLD, gradient, 0);
          K_prediction =
            Utilities::MPI::broadcast(MPI_COMM_WORLD, K_prediction, 0);
        }
      // The first-order prediction erred by -1.4 % to 0 on the paper's
      // slope (300 samples; K is convex in the strengths): 2 % below it
      // the first solve is below the sample's limit.
      const double start_margin = 0.02;
      // The statuses at the means 2 % below their K: a sample's first
      // solve from them took 1 to 2 status iterations on the paper's slope
      // instead of 5 to 7 from the initial states.
      if (predict)
        evaluator.set_warm_states(
          means,
          predicted_start(K_prediction, gradient, means, means, start_margin));

      // Every rank draws every sample from the seed; each evaluates its slice.
      const std::vector<double> L =
        probability::cholesky(p.correlation, n_variables);
      const std::vector<double> z = probability::standard_normal_samples(
        p.n_samples, n_variables, p.latin_hypercube, p.seed, L);
      std::vector<double> values(z.size());
      for (std::size_t i = 0; i < z.size(); ++i)
        values[i] =
          p.variables[i % n_variables].marginal.from_standard_normal(z[i]);

      // The iterative mixed solver's block solves are collective: there every
      // rank solves every sample.
      const bool split =
        model.get_mixed_system().solver() == contact::MixedSystemSolver::dense;
      const unsigned int n_ranks =
        split ? Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) : 1;
      const unsigned int rank =
        split ? Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) : 0;
      const unsigned int first = std::size_t(p.n_samples) * rank / n_ranks;
      const unsigned int last = std::size_t(p.n_samples) * (rank + 1) / n_ranks;
      const auto         sample = [&](const unsigned int s) {
        return std::vector<double>(values.begin() +
                                     std::size_t(s) * n_variables,
                                   values.begin() +
                                     std::size_t(s + 1) * n_variables);
      };
      // Per sample: K, status, steps, status iterations, fell back.
      constexpr unsigned int n_per_sample = 5;
      std::vector<double>    local;
      Timer                  sample_timer;
      // A random water level: the samples' water load cases first, on every
      // rank (the blocks' solves are collective), then each rank's slice.
      std::vector<typename contact::MixedSystem<dim>::LoadCase> water_cases;
      if (evaluator.loads.varies_water())
        for (unsigned int s = 0; s < p.n_samples; ++s)
          water_cases.push_back(evaluator.loads.water_case(sample(s)));
      const double water_seconds = sample_timer.wall_time();
      for (unsigned int s = first; s < last; ++s)
        {
          const std::vector<double> x = sample(s);
          const Evaluation          e = evaluator.evaluate(
            x,
            nullptr,
            water_cases.empty() ? nullptr : &water_cases[s],
            predict ?
                       predicted_start(K_prediction, gradient, means, x, start_margin) :
                       std::numeric_limits<double>::quiet_NaN());
          local.insert(local.end(),
                       {e.K,
                        double(e.status),
                        double(e.n_steps),
                        double(e.n_status_iterations),
                        double(e.fell_back)});
        }
      const double sample_seconds = sample_timer.wall_time();
      // The process's CPU time of the same span: what the samples cost
      // where other work shares the cores (the wall time then is not).
      const double        sample_cpu_seconds = sample_timer.cpu_time();
      std::vector<double> gathered;
      if (split)
        for (const auto &part :
             Utilities::MPI::all_gather(MPI_COMM_WORLD, local))
          gathered.insert(gathered.end(), part.begin(), part.end());
      else
        gathered = local;

      std::vector<double>       K(p.n_samples);
      std::vector<SampleStatus> status(p.n_samples);
      double n_steps = 0, n_status_iterations = 0, n_fell_back = 0;
      for (unsigned int s = 0; s < p.n_samples; ++s)
        {
          K[s]      = gathered[n_per_sample * s];
          status[s] = SampleStatus(int(gathered[n_per_sample * s + 1]));
          n_steps += gathered[n_per_sample * s + 2];
          n_status_iterations += gathered[n_per_sample * s + 3];
          n_fell_back += gathered[n_per_sample * s + 4];
        }
      result.update(sample_statistics(K,
                                      status,
                                      values,
                                      n_variables,
                                      int(p.fragility_variable) - 1,
                                      p.n_fragility_bins));
      result["seed"] = p.seed;
      result["sampling"] =
        p.latin_hypercube ? "Latin hypercube" : "Monte Carlo";
      result["deterministic_K"] = postprocess::number_or_null(deterministic_K);
      nlohmann::json variables  = nlohmann::json::array();
      for (unsigned int v = 0; v < n_variables; ++v)
        variables.push_back({{"target", p.variables[v].target},
                             {"distribution",
                              probability::distribution_name(
                                p.variables[v].marginal.distribution)},
                             {"mean", means[v]},
                             {"std", std_devs[v]}});
      result["variables"]   = variables;
      result["correlation"] = p.correlation;

      if (p.point_estimate)
        result["point_estimate"] =
          point_estimate(evaluator, p, means, std_devs);

      evaluator.loads.restore();
      // Cost: this rank's samples, the run's mean per sample.
      const unsigned int n_local = last - first;
      result["cost"]             = {
                    {"wall_seconds", timer.wall_time()},
                    {"samples_wall_seconds", sample_seconds},
                    {"samples_cpu_seconds", sample_cpu_seconds},
                    {"seconds_per_sample", n_local > 0 ? sample_seconds / n_local : 0.0},
                    {"water_load_seconds", water_seconds},
                    {"seconds_K_at_means", mean_seconds},
                    {"mean_steps_per_sample", n_steps / p.n_samples},
                    {"mean_contact_solves_per_sample", n_status_iterations / p.n_samples},
                    {"sample_start", predict ? "predicted" : "reference"},
                    {"n_fell_back", n_fell_back},
                    {"factorizations_rank0",
                     model.get_mixed_system().dense_solver().n_factorizations -
                       factorized_before},
                    {"reused_solves_rank0",
                     model.get_mixed_system().dense_solver().n_reused_solves -
                       reused_before},
                    {"n_ranks", n_ranks}};

      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        {
          postprocess::OutputFile out(
            model.get_parameters().output_directory() + "/samples.csv");
          out << "sample";
          for (const RandomVariable &v : p.variables)
            out << ",\"" << v.target << "\"";
          out << ",K,status,steps\n" << std::setprecision(17);
          for (unsigned int s = 0; s < p.n_samples; ++s)
            {
              out << s;
              for (unsigned int v = 0; v < n_variables; ++v)
                out << "," << values[std::size_t(s) * n_variables + v];
              out << ",";
              if (status[s] == SampleStatus::certified)
                out << K[s];
              out << "," << status_name(status[s]) << ","
                  << gathered[n_per_sample * s + 2] << "\n";
            }
          out.close();
        }
      model.log << "Probabilistic: " << p.n_samples << " samples, "
                << result["n_certified"]
                << " with a certified K, mean K = " << result["K_mean"]
                << ", P(K < 1) = " << result["P_failure"] << std::endl;
      if (result["n_nonphysical"].get<unsigned long>() > 0)
        model.warn(postprocess::warning_text(
          "nonphysical-samples",
          std::to_string(result["n_nonphysical"].get<unsigned long>()) +
            " samples had a strength outside its physical range (c < 0, phi outside [0, 90) "
            "degrees) and were left out of the statistics; a lognormal or truncated normal "
            "distribution keeps strengths physical"));
      return result;
    }

    template nlohmann::json
    probabilistic_safety_factor(Model<2> &,
                                const double,
                                const SeismicResults &);
    template nlohmann::json
    probabilistic_safety_factor(Model<3> &,
                                const double,
                                const SeismicResults &);
  } // namespace analyses
} // namespace fdem
