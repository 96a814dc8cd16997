// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/probabilistic.h>
#include <fdem/analyses/probabilistic_sampling.h>
#include <fdem/postprocess/json_number.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace fdem
{
  namespace analyses
  {
    std::string
    status_name(const SampleStatus status)
    {
      switch (status)
        {
          case SampleStatus::certified:
            return "certified";
          case SampleStatus::no_equilibrium:
            return "no equilibrium";
          case SampleStatus::not_certified:
            return "not certified";
          case SampleStatus::nonphysical:
            return "nonphysical";
        }
      return "";
    }

    namespace
    {
      /** Failure: no certified K, or K < 1. */
      bool
      fails(const double K, const SampleStatus status)
      {
        return status != SampleStatus::certified || K < 1;
      }
    } // namespace

    nlohmann::json
    sample_statistics(const std::vector<double>       &K,
                      const std::vector<SampleStatus> &status,
                      const std::vector<double>       &values,
                      const unsigned int               n_variables,
                      const int                        fragility_variable,
                      const unsigned int               n_bins)
    {
      nlohmann::json                       result;
      std::vector<double>                  certified;
      unsigned long                        n_evaluated = 0, n_failures = 0;
      std::map<std::string, unsigned long> counts;
      for (unsigned int s = 0; s < K.size(); ++s)
        {
          ++counts[status_name(status[s])];
          if (status[s] == SampleStatus::nonphysical)
            continue;
          ++n_evaluated;
          n_failures += fails(K[s], status[s]);
          if (status[s] == SampleStatus::certified)
            certified.push_back(K[s]);
        }
      for (const SampleStatus st : {SampleStatus::certified,
                                    SampleStatus::no_equilibrium,
                                    SampleStatus::not_certified,
                                    SampleStatus::nonphysical})
        {
          std::string key = "n_" + status_name(st);
          std::replace(key.begin(), key.end(), ' ', '_');
          result[key] = counts[status_name(st)];
        }
      result["n_samples"]   = K.size();
      result["n_evaluated"] = n_evaluated;
      result["n_failures"]  = n_failures;

      const double n = certified.size();
      // Two-pass sums in sample order: the same numbers on any number of ranks.
      const double mean =
        n > 0 ? std::accumulate(certified.begin(), certified.end(), 0.0) / n :
                std::numeric_limits<double>::quiet_NaN();
      double sum_squares = 0;
      for (const double k : certified)
        sum_squares += (k - mean) * (k - mean);
      const double std_dev = n > 1 ? std::sqrt(sum_squares / (n - 1)) :
                                     std::numeric_limits<double>::quiet_NaN();
      result["K_mean"]     = postprocess::number_or_null(mean);
      result["K_std"]      = postprocess::number_or_null(std_dev);
      result["K_mean_standard_error"] =
        postprocess::number_or_null(std_dev / std::sqrt(n));
      result["beta_normal"] = postprocess::number_or_null((mean - 1) / std_dev);
      const double V        = std_dev / mean;
      result["beta_lognormal"] = postprocess::number_or_null(
        std::log(mean / std::sqrt(1 + V * V)) / std::sqrt(std::log1p(V * V)));
      result["P_failure_normal"] = postprocess::number_or_null(
        probability::normal_cdf(-(mean - 1) / std_dev));

      const double                p = n_evaluated > 0 ?
                                        double(n_failures) / n_evaluated :
                                        std::numeric_limits<double>::quiet_NaN();
      const probability::Interval interval =
        probability::wilson_interval(n_failures, n_evaluated);
      result["P_failure"]          = postprocess::number_or_null(p);
      result["P_failure_interval"] = {{"lower", interval.lower},
                                      {"upper", interval.upper},
                                      {"confidence", 0.95},
                                      {"method", "Wilson score"}};

      std::sort(certified.begin(), certified.end());
      if (!certified.empty())
        {
          nlohmann::json quantiles;
          for (const double q :
               {0.01, 0.05, 0.1, 0.25, 0.5, 0.75, 0.9, 0.95, 0.99})
            {
              const std::size_t i =
                std::min(certified.size() - 1,
                         std::size_t(q * (certified.size() - 1) + 0.5));
              quantiles[std::to_string(int(std::round(100 * q)))] =
                certified[i];
            }
          result["K_percentiles"] = quantiles;
          const unsigned int n_histogram =
            std::clamp<unsigned int>(std::sqrt(n), 5, 40);
          const double low = certified.front(), high = certified.back();
          const double width = high > low ? (high - low) / n_histogram : 1;
          std::vector<unsigned long> histogram(n_histogram, 0);
          for (const double k : certified)
            ++histogram[std::min<unsigned int>(n_histogram - 1,
                                               (k - low) / width)];
          std::vector<double> edges;
          for (unsigned int b = 0; b <= n_histogram; ++b)
            edges.push_back(low + b * width);
          result["K_histogram"] = {{"edges", edges}, {"counts", histogram}};
        }

      if (fragility_variable >= 0)
        {
          // Bins of equal numbers of evaluated samples, by the variable's
          // value.
          std::vector<unsigned int> order;
          for (unsigned int s = 0; s < K.size(); ++s)
            if (status[s] != SampleStatus::nonphysical)
              order.push_back(s);
          const auto x = [&](const unsigned int s) {
            return values[s * n_variables + fragility_variable];
          };
          std::stable_sort(order.begin(),
                           order.end(),
                           [&](const unsigned int a, const unsigned int b) {
                             return x(a) < x(b);
                           });
          nlohmann::json     curve = nlohmann::json::array();
          const unsigned int bins = std::min<std::size_t>(n_bins, order.size());
          for (unsigned int b = 0; b < bins; ++b)
            {
              const std::size_t first = order.size() * b / bins,
                                last  = order.size() * (b + 1) / bins;
              unsigned long k         = 0;
              double        sum       = 0;
              for (std::size_t i = first; i < last; ++i)
                {
                  k += fails(K[order[i]], status[order[i]]);
                  sum += x(order[i]);
                }
              const probability::Interval ci =
                probability::wilson_interval(k, last - first);
              curve.push_back({{"x_low", x(order[first])},
                               {"x_high", x(order[last - 1])},
                               {"x_mean", sum / (last - first)},
                               {"n", last - first},
                               {"P_failure", double(k) / (last - first)},
                               {"lower", ci.lower},
                               {"upper", ci.upper}});
            }
          result["fragility"] = {{"variable", fragility_variable + 1},
                                 {"bins", curve}};
        }
      return result;
    }
  } // namespace analyses
} // namespace fdem
