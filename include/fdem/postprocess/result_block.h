// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace fdem
{
  namespace postprocess
  {
    /** A factor to set beside K: what it is, and its value. */
    struct ComparisonValue
    {
      std::string label;
      double      factor;
    };

    /**
     * The factors of @p summary to compare K with, in this order: the
     * FE-stress factor ("fe_stress_factor", where computed), then every
     * method of a "limit_equilibrium" object (in its key order, alphabetical),
     * if the summary has one: each entry method -> a number, or an object with
     * a number "K", "safety_factor" or "factor" (entries without a finite
     * number are left out).
     */
    std::vector<ComparisonValue>
    comparison_values(const nlohmann::json &summary);

    /**
     * One line per value of @p values: its label, the factor to 3 decimals
     * and its difference from @p K in per cent (none where K is not finite).
     */
    std::vector<std::string>
    comparison_lines(const std::vector<ComparisonValue> &values, double K);

    /**
     * Whether the warning @p warning (made by warning_text()) may change the
     * answer, by its id: every warning of today's program does (a wrong
     * model, a K that depends on the stiffness, a conservative bound);
     * doc/troubleshooting.md says so for each.
     */
    bool
    changes_answer(const std::string &warning);

    /**
     * Whether the conditioning notes of @p summary belong on the screen
     * (doc/troubleshooting.md, `ill-conditioned`): when the run has no
     * certified K, or when the digits they leave (16 minus the most lost)
     * are fewer than the safety factor's tolerance asks for and no stiffness
     * check confirmed K to the tolerance. The stiffness check solves the
     * limit twice more with the moving blocks' stiffness changed tenfold
     * (other matrices, other rounding): K agreeing to the tolerance in all
     * three shows that the digits the bound says may be lost were not lost
     * where K is concerned.
     */
    bool
    conditioning_changes_answer(const nlohmann::json &summary);

    /**
     * Two lines on summary.json's "probabilistic", if it has one: mean and
     * standard deviation of K with the sample counts; P(K < 1) with its
     * 95 % Wilson interval and the reliability indices.
     */
    std::vector<std::string>
    probabilistic_lines(const nlohmann::json &summary);

    /**
     * The critical surface of summary.json's "surface_search" in two lines
     * (empty without a search): the circle and how it was chosen.
     */
    std::vector<std::string>
    surface_search_lines(const nlohmann::json &summary);

    /**
     * The block an engineer reads first, ending the default screen and the
     * log file: K to 3 decimals (and once in full), its certificate in
     * words, the comparison values, the stiffness check, the warnings that
     * may change the answer (and how many there are), and where the results
     * are. @p results_folder is the run's folder, @p log_file the name of
     * its log file in it.
     */
    std::vector<std::string>
    result_block(const nlohmann::json &summary,
                 const std::string    &results_folder,
                 const std::string    &log_file);

    /**
     * The one line of `--quiet` on success: K with 17 significant digits
     * (the double, exactly), or "" when the run computed no safety factor.
     */
    std::string
    quiet_line(const nlohmann::json &summary);
  } // namespace postprocess
} // namespace fdem
