// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/seismic_results.h>
#include <fdem/postprocess/json_number.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace fdem
{
  namespace analyses
  {
    namespace
    {
      std::string
      digits(const double x, const int significant)
      {
        std::ostringstream text;
        text << std::setprecision(significant) << x;
        return text.str();
      }

      double
      number(const nlohmann::json &object, const std::string &key)
      {
        if (!object.is_object() || !object.contains(key) ||
            !object[key].is_number())
          return std::numeric_limits<double>::quiet_NaN();
        return object[key].get<double>();
      }
    } // namespace

    nlohmann::json
    to_json(const SeismicResults &results)
    {
      nlohmann::json                 json = {{"kh", results.kh},
                                             {"kv", results.kv},
                                             {"kv_positive", "upwards"},
                                             {"direction", results.direction},
                                             {"direction_from", results.direction_from},
                                             {"on_pore_water", results.on_pore_water}};
      const YieldAccelerationResult &y    = results.yield;
      if (y.computed)
        {
          nlohmann::json curve = nlohmann::json::array();
          for (const auto &p : y.curve)
            curve.push_back(
              {{"kh", p.kh}, {"K", p.K}, {"certified", p.certified}});
          json["yield_acceleration"] = {
            {"k_y", postprocess::number_or_null(y.k_y)},
            {"found", y.not_found.empty()},
            {"not_found", y.not_found},
            {"bracket",
             {postprocess::number_or_null(y.bracket_low),
              postprocess::number_or_null(y.bracket_high)}},
            {"k_y_backward", postprocess::number_or_null(y.k_y_backward)},
            {"curve", curve},
            {"n_evaluations", y.curve.size()},
            {"csv", "yield_acceleration.csv"},
            {"wall_seconds", y.wall_seconds}};
        }
      const NewmarkResult &n = results.newmark;
      if (!n.record.empty())
        json["newmark"] = {{"computed", n.computed},
                           {"record", n.record},
                           {"unit", n.unit},
                           {"sliding", n.mode},
                           {"max_displacement_m", n.max_displacement},
                           {"time_of_max_s", n.time_of_max},
                           {"max_velocity_m_s", n.max_velocity},
                           {"n_samples", n.time.size()},
                           {"csv", n.computed ? "newmark.csv" : ""}};
      return json;
    }

    std::vector<std::pair<std::string, std::string>>
    seismic_result_lines(const nlohmann::json &summary)
    {
      std::vector<std::pair<std::string, std::string>> lines;
      if (!summary.contains("seismic") || !summary["seismic"].is_object())
        return lines;
      const nlohmann::json &s = summary["seismic"];
      lines.push_back({"Seismic load",
                       "kh = " + digits(number(s, "kh"), 6) + " (" +
                         s.value("direction_from", std::string()) + "), kv = " +
                         digits(number(s, "kv"), 6) + " (positive upwards)"});
      if (s.contains("yield_acceleration"))
        {
          const nlohmann::json &y = s["yield_acceleration"];
          lines.push_back({"Yield acceleration",
                           y.value("found", false) ?
                             "k_y = " + digits(number(y, "k_y"), 6) +
                               "  (K = 1; " +
                               std::to_string(y.value("n_evaluations", 0)) +
                               " K evaluations)" :
                             "none: " + y.value("not_found", std::string())});
        }
      if (s.contains("newmark") && s["newmark"].value("computed", false))
        lines.push_back(
          {"Newmark",
           "largest sliding displacement " +
             digits(number(s["newmark"], "max_displacement_m"), 4) + " m (" +
             s["newmark"].value("sliding", std::string()) + ")"});
      return lines;
    }
  } // namespace analyses
} // namespace fdem
