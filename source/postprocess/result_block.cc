// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The result block of the screen and the log file, made from summary.json
// alone: what the screen says is what the results folder holds.
#include <fdem/analyses/anchor_results.h>
#include <fdem/analyses/seismic_results.h>
#include <fdem/postprocess/result_block.h>
#include <fdem/postprocess/run_log.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace fdem
{
  namespace postprocess
  {
    namespace
    {
      constexpr double nan = std::numeric_limits<double>::quiet_NaN();

      /** The number at @p key of @p object, or NaN (absent, null, not a
       * number). */
      double
      number(const nlohmann::json &object, const std::string &key)
      {
        if (!object.is_object() || !object.contains(key) ||
            !object[key].is_number())
          return nan;
        return object[key].get<double>();
      }

      /// @p x with @p decimals decimals; from a million on in exponent form
      /// (a cohesion of 1e200 gives K near 4e198: 199 digits otherwise).
      std::string
      fixed(const double x, const int decimals)
      {
        std::ostringstream text;
        if (std::abs(x) >= 1e6)
          text << std::setprecision(decimals + 2) << x;
        else
          text << std::fixed << std::setprecision(decimals) << x;
        return text.str();
      }

      std::string
      digits(const double x, const int significant)
      {
        std::ostringstream text;
        text << std::setprecision(significant) << x;
        return text.str();
      }

      /** The certificate of K in words, e.g. "certified: ...". */
      std::string
      certificate_words(const nlohmann::json &summary)
      {
        const nlohmann::json &c = summary["certificate"];
        const std::string     tolerance =
          " (tolerance " + digits(number(c, "tolerance"), 3) + ")";
        if (!c.value("holds", false))
          return "NOT certified: " +
                 c.value("reason", std::string("no reason given"));
        if (c.value("kind", std::string()) == "fixed point")
          {
            // A difference of a few hundred units in the last place is
            // round-off: its digits change with the compiler and the order
            // of sums, so the screen names it, not its value (summary.json
            // keeps the value).
            const double difference = number(c, "relative_difference");
            return "certified: the state solved at K = " +
                   digits(number(c, "K"), 8) + " gives K* = K " +
                   (difference < 1e-13 ?
                      std::string("to round-off (below 1e-13)") :
                      "within " + digits(difference, 2) + " relative") +
                   tolerance;
          }
        // Above the bracket: a solve without a static solution, or a state
        // with every pair slipping (K* = K at any K, a limit state).
        const bool all_slipping =
          c.value("failure", std::string()).rfind("every pair", 0) == 0;
        const std::string bracket =
          "static at K = " + digits(number(c, "K"), 8) +
          (all_slipping ? ", every pair slipping at K = " :
                          ", a mechanism (no static solution) at K = ") +
          digits(number(c, "K_failed"), 8);
        if (c.value("conservative", false))
          return "certified as a conservative value: " + bracket +
                 ", further apart than the tolerance: K may be a little low";
        const double width =
          (number(c, "K_failed") - number(c, "K")) / number(c, "K");
        return "certified: " + bracket + ", " + digits(width, 2) + " apart" +
               tolerance;
      }

      /** Stable or not: the stiffness check in words. */
      std::string
      stiffness_words(const nlohmann::json &summary,
                      const bool            stiffness_warned)
      {
        const nlohmann::json &s = summary["stiffness_sensitivity"];
        if (!s.value("computed", false))
          return "not checked (" + s.value("not_computed", std::string()) + ")";
        const std::string blocks = " with the moving blocks " +
                                   digits(number(s, "factor"), 3) +
                                   " times stiffer or softer";
        const double change = number(s, "relative_change");
        if (std::isnan(change))
          return "NOT stable: no certified K" + blocks;
        const std::string changes =
          "K changes by " + digits(100 * change, 3) + " %" + blocks +
          " (warning above " + digits(100 * number(s, "warning_above"), 3) +
          " %)";
        return stiffness_warned ? "NOT stable: " + changes :
                                  "stable: " + changes;
      }
    } // namespace

    std::vector<ComparisonValue>
    comparison_values(const nlohmann::json &summary)
    {
      std::vector<ComparisonValue> values;
      if (summary.contains("fe_stress_factor") &&
          summary["fe_stress_factor"].value("computed", false))
        {
          const double factor = number(summary["fe_stress_factor"], "factor");
          if (std::isfinite(factor))
            values.push_back({"FE-stress factor", factor});
        }
      // limit_equilibrium: {"methods": {method: {"K": ...}}, ...}, or a
      // plain map method -> K.
      const nlohmann::json &le = summary.contains("limit_equilibrium") ?
                                   summary["limit_equilibrium"] :
                                   nlohmann::json();
      const nlohmann::json &methods =
        le.is_object() && le.contains("methods") ? le["methods"] : le;
      if (methods.is_object())
        for (const auto &[method, value] : methods.items())
          {
            double factor = value.is_number() ? value.get<double>() : nan;
            for (const char *key : {"K", "safety_factor", "factor"})
              if (std::isnan(factor))
                factor = number(value, key);
            // The names engineers know; an unknown key is shown as it is.
            static const std::map<std::string, std::string> names = {
              {"bishop_simplified", "Bishop simplified"},
              {"janbu_corrected", "Janbu corrected"},
              {"janbu_simplified", "Janbu simplified"},
              {"morgenstern_price_constant", "Morgenstern-Price, constant"},
              {"morgenstern_price_half_sine", "Morgenstern-Price, half-sine"},
              {"ordinary", "ordinary (Fellenius)"},
              {"spencer", "Spencer"}};
            const auto name = names.find(method);
            if (std::isfinite(factor))
              values.push_back({"limit equilibrium, " +
                                  (name == names.end() ? method : name->second),
                                factor});
          }
      return values;
    }

    std::vector<std::string>
    comparison_lines(const std::vector<ComparisonValue> &values, const double K)
    {
      std::vector<std::string> lines;
      for (const auto &value : values)
        {
          std::string line = value.label + " " + fixed(value.factor, 3);
          if (std::isfinite(K) && K != 0)
            {
              std::ostringstream change;
              change << std::showpos << std::fixed << std::setprecision(1)
                     << 100 * (value.factor - K) / K;
              line += " (" + change.str() + " % of K)";
            }
          lines.push_back(line);
        }
      return lines;
    }

    bool
    changes_answer(const std::string &warning)
    {
      // Ids of warnings that leave K as it is. A new warning is taken to
      // change the answer until it is listed here.
      static const std::set<std::string> harmless = {"no-report"};
      return harmless.count(message_id(warning)) == 0;
    }

    bool
    conditioning_changes_answer(const nlohmann::json &summary)
    {
      if (!summary.contains("conditioning") ||
          summary["conditioning"]["notes"].empty())
        return false;
      if (summary.value("status", std::string()) != "completed")
        return true;
      if (!summary.contains("certificate"))
        return false; // no safety factor: the contact problem was solved
      const double lost = number(summary["conditioning"], "max_digits_lost");
      const double tolerance = number(summary["certificate"], "tolerance");
      if (!(16 - lost < -std::log10(tolerance)))
        return false;
      const nlohmann::json &s = summary["stiffness_sensitivity"];
      return !(s.value("computed", false) &&
               number(s, "relative_change") <= tolerance);
    }

    std::vector<std::string>
    probabilistic_lines(const nlohmann::json &summary)
    {
      if (!summary.contains("probabilistic"))
        return {};
      const nlohmann::json &p    = summary["probabilistic"];
      const auto            text = [&](const char *key, const unsigned int n) {
        return p.contains(key) && p[key].is_number() ?
                            fixed(p[key].get<double>(), n) :
                            "none";
      };
      std::vector<std::string> lines;
      lines.push_back(
        "mean K = " + text("K_mean", 3) + ", std " + text("K_std", 3) + " (" +
        std::to_string(p["n_samples"].get<unsigned long>()) + " samples, " +
        std::to_string(p["n_certified"].get<unsigned long>()) + " certified)");
      const auto &interval = p["P_failure_interval"];
      lines.push_back("P(K < 1) = " + text("P_failure", 4) + " [" +
                      fixed(interval["lower"].get<double>(), 4) + ", " +
                      fixed(interval["upper"].get<double>(), 4) +
                      "] (95 % Wilson), beta = " + text("beta_normal", 2) +
                      " (normal), " + text("beta_lognormal", 2) +
                      " (lognormal)");
      return lines;
    }

    std::vector<std::string>
    surface_search_lines(const nlohmann::json &summary)
    {
      if (!summary.contains("surface_search"))
        return {};
      const nlohmann::json &s = summary["surface_search"];
      const nlohmann::json &c = s["critical"];
      const nlohmann::json &n = s["counts"];
      std::string           surface;
      if (c.value("shape", std::string("circular")) == "polyline")
        {
          const nlohmann::json &p = c["polyline"];
          surface                 = "polyline of " + std::to_string(p.size()) +
                    " vertices from (" + digits(p.front()[0].get<double>(), 6) +
                    ", " + digits(p.front()[1].get<double>(), 6) + ") to (" +
                    digits(p.back()[0].get<double>(), 6) + ", " +
                    digits(p.back()[1].get<double>(), 6) + ")";
        }
      else
        surface = "circle centre (" + digits(c["centre"][0].get<double>(), 6) +
                  ", " + digits(c["centre"][1].get<double>(), 6) +
                  "), radius " + digits(c["radius"].get<double>(), 6);
      std::string polylines;
      if (s.contains("non_circular"))
        polylines =
          ", " +
          std::to_string(
            s["non_circular"]["counts"]["screened"].get<unsigned int>()) +
          " polylines";
      return {surface + " (critical_surface.prm)",
              "chosen by the " + c.value("chosen_by", std::string()) +
                " from " +
                std::to_string(n["grid"].get<unsigned int>() +
                               n["refinement"].get<unsigned int>()) +
                " circles" + polylines + " screened and " +
                std::to_string(n["contact_evaluations"].get<unsigned int>()) +
                " contact evaluations (search.csv)"};
    }

    std::vector<std::string>
    result_block(const nlohmann::json &summary,
                 const std::string    &results_folder,
                 const std::string    &log_file)
    {
      std::vector<std::string> lines;
      const auto               add = [&lines](const std::string &label,
                                const std::string &text) {
        lines.push_back(
          "  " + label +
          std::string(label.size() < 18 ? 18 - label.size() : 1, ' ') + text);
      };
      lines.push_back("");
      lines.push_back("Result of " +
                      summary.value("case", std::string("the case")) + ":");
      const bool   has_factor = summary.contains("certificate");
      const double K = has_factor ? number(summary, "safety_factor") : nan;
      if (has_factor)
        {
          add("Safety factor",
              std::isfinite(K) ?
                "K = " + fixed(K, 3) + "   (" + digits(K, 8) + ")" :
                "none");
          add("Certificate", certificate_words(summary));
          const auto compared = comparison_lines(comparison_values(summary), K);
          for (unsigned int i = 0; i < compared.size(); ++i)
            add(i == 0 ? "Compared with" : "", compared[i]);
        }
      else
        add("Contact problem",
            summary["contact"].value("result", std::string()));
      const auto critical = surface_search_lines(summary);
      for (unsigned int i = 0; i < critical.size(); ++i)
        add(i == 0 ? "Critical surface" : "", critical[i]);

      std::vector<std::string> listed;
      for (const auto &w : summary["warnings"])
        listed.push_back(w.get<std::string>());
      if (has_factor)
        {
          bool stiffness_warned = false;
          for (const std::string &w : listed)
            stiffness_warned |= message_id(w) == "stiffness-dependent";
          add("Stiffness check", stiffness_words(summary, stiffness_warned));
        }
      for (const auto &[label, text] : analyses::seismic_result_lines(summary))
        add(label, text);
      for (const auto &[label, text] :
           analyses::reinforcement_result_lines(summary))
        add(label, text);
      const auto probabilistic = probabilistic_lines(summary);
      for (unsigned int i = 0; i < probabilistic.size(); ++i)
        add(i == 0 ? "Probabilistic" : "", probabilistic[i]);

      unsigned int n_changing = 0;
      for (const std::string &w : listed)
        n_changing += changes_answer(w);
      const unsigned int n_notes = summary.contains("conditioning") ?
                                     summary["conditioning"]["notes"].size() :
                                     0;
      std::string        count   = listed.empty() ?
                                     "none" :
                                     std::to_string(listed.size()) + " (" +
                              std::to_string(n_changing) + " may change K)";
      if (n_notes > 0 && !conditioning_changes_answer(summary))
        count += "; " + std::to_string(n_notes) + " conditioning notes in " +
                 log_file + ", not changing K";
      add("Warnings", count);
      for (const std::string &w : listed)
        if (changes_answer(w))
          add("", "warning " + w);
      if (n_notes > 0 && conditioning_changes_answer(summary))
        add(
          "",
          "note [ill-conditioned] " + std::to_string(n_notes) +
            " contact solves were ill-conditioned: up to " +
            digits(number(summary["conditioning"], "max_digits_lost"), 3) +
            " of the 16 significant digits of the contact forces may be lost (each in " +
            log_file + ")");
      add("Results",
          results_folder + "/  (full log: " + results_folder + "/" + log_file +
            ")");
      return lines;
    }

    std::string
    quiet_line(const nlohmann::json &summary)
    {
      const double K = number(summary, "safety_factor");
      if (!summary.contains("certificate") || !std::isfinite(K))
        return "";
      return digits(K, 17);
    }
  } // namespace postprocess
} // namespace fdem
