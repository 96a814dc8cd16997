// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The result block that ends the screen (postprocess/result_block.h): the
// values it compares K with, the rule that keeps conditioning notes off the
// screen, --quiet's line and the warning ids.
#include <fdem/postprocess/result_block.h>
#include <fdem/postprocess/run_log.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace fdem::postprocess;

namespace
{
  /** A certified run's summary with @p n_notes conditioning notes. */
  nlohmann::json
  certified_summary(const unsigned int n_notes,
                    const int          max_digits_lost,
                    const double       stiffness_change)
  {
    nlohmann::json summary;
    summary["case"]             = "test";
    summary["status"]           = "completed";
    summary["safety_factor"]    = 1.3176009240752402;
    summary["warnings"]         = nlohmann::json::array();
    summary["contact"]          = {{"result", "converged"}};
    summary["certificate"]      = {{"kind", "fixed point"},
                                   {"holds", true},
                                   {"conservative", false},
                                   {"K", 1.3176009240752402},
                                   {"K_star", 1.3176009240752402},
                                   {"relative_difference", 4e-15},
                                   {"tolerance", 1e-6},
                                   {"reason", ""}};
    summary["fe_stress_factor"] = {{"computed", true}, {"factor", 1.2519376}};
    summary["stiffness_sensitivity"] = {{"computed", true},
                                        {"factor", 10.0},
                                        {"warning_above", 0.01},
                                        {"relative_change", stiffness_change}};
    nlohmann::json notes             = nlohmann::json::array();
    for (unsigned int i = 0; i < n_notes; ++i)
      notes.push_back(note_text("ill-conditioned", "... digits may be lost."));
    summary["conditioning"] = {{"notes", notes},
                               {"max_digits_lost", max_digits_lost}};
    return summary;
  }
} // namespace

TEST(ResultBlock,
     ComparisonValuesTakeTheFeStressFactorAndEveryLimitEquilibriumMethod)
{
  nlohmann::json summary = certified_summary(0, 0, 0.005);
  EXPECT_EQ(comparison_values(summary).size(), 1u);
  // The form a limit-equilibrium module may give: numbers or objects.
  summary["limit_equilibrium"] = {{"Bishop", 1.3136},
                                  {"Spencer", {{"K", 1.3125}}},
                                  {"Janbu", {{"safety_factor", 1.25}}},
                                  {"failed", {{"K", nullptr}}}};
  const auto values            = comparison_values(summary);
  ASSERT_EQ(values.size(), 4u);
  EXPECT_EQ(values[0].label, "FE-stress factor");
  EXPECT_EQ(values[1].label, "limit equilibrium, Bishop");
  // In the summary's key order (nlohmann::json sorts them).
  EXPECT_DOUBLE_EQ(values[2].factor, 1.25);
  EXPECT_DOUBLE_EQ(values[3].factor, 1.3125);
  const auto lines = comparison_lines(values, 1.3176009240752402);
  EXPECT_EQ(lines[0], "FE-stress factor 1.252 (-5.0 % of K)");
  EXPECT_EQ(lines[1], "limit equilibrium, Bishop 1.314 (-0.3 % of K)");
  // Every value reaches the block.
  std::string block;
  for (const auto &line : result_block(summary, "out", "log.txt"))
    block += line + "\n";
  EXPECT_NE(block.find("K = 1.318   (1.3176009)"), std::string::npos) << block;
  EXPECT_NE(block.find("limit equilibrium, Janbu 1.250"), std::string::npos)
    << block;
}

TEST(ResultBlock, ConditioningNotesReachTheScreenOnlyWhenTheyMayChangeK)
{
  // 5 digits left of the 6 the tolerance asks, but the stiffness check
  // agrees to the tolerance: off the screen (the rock wedge).
  EXPECT_FALSE(conditioning_changes_answer(certified_summary(6, 11, 5.6e-7)));
  // The same without the stiffness check's agreement: on the screen.
  EXPECT_TRUE(conditioning_changes_answer(certified_summary(6, 11, 2e-6)));
  nlohmann::json unchecked                       = certified_summary(6, 11, 0);
  unchecked["stiffness_sensitivity"]["computed"] = false;
  EXPECT_TRUE(conditioning_changes_answer(unchecked));
  // 7 digits left: enough for the tolerance.
  EXPECT_FALSE(conditioning_changes_answer(certified_summary(6, 9, 2e-6)));
  // No certified K: the notes may be why.
  nlohmann::json failed = certified_summary(1, 3, 0);
  failed["status"]      = "safety factor not certified: ...";
  EXPECT_TRUE(conditioning_changes_answer(failed));
  EXPECT_FALSE(conditioning_changes_answer(certified_summary(0, 0, 2e-6)));

  std::string block;
  for (const auto &line :
       result_block(certified_summary(6, 11, 5.6e-7), "out", "log.txt"))
    block += line + "\n";
  EXPECT_EQ(block.find("digits"), std::string::npos) << block;
  EXPECT_NE(block.find("6 conditioning notes in log.txt"), std::string::npos)
    << block;
}

TEST(ResultBlock, QuietLineIsTheDoubleExactly)
{
  const nlohmann::json summary = certified_summary(0, 0, 0.005);
  const std::string    line    = quiet_line(summary);
  EXPECT_EQ(std::stod(line), summary["safety_factor"].get<double>());
  nlohmann::json contact_only = summary;
  contact_only.erase("certificate");
  EXPECT_EQ(quiet_line(contact_only), "");
}

TEST(ResultBlock, WarningsCarryTheirIds)
{
  const std::string warning =
    warning_text("stiffness-dependent", "K changes by 34 % ...");
  EXPECT_EQ(message_id(warning), "stiffness-dependent");
  EXPECT_EQ(message_id("no id here"), "");
  EXPECT_TRUE(changes_answer(warning));
  nlohmann::json summary = certified_summary(0, 0, 0.34);
  summary["warnings"].push_back(warning);
  std::string block;
  for (const auto &line : result_block(summary, "out", "log.txt"))
    block += line + "\n";
  EXPECT_NE(block.find("NOT stable"), std::string::npos) << block;
  EXPECT_NE(block.find("1 (1 may change K)"), std::string::npos) << block;
  EXPECT_NE(block.find("warning [stiffness-dependent] K changes by 34 %"),
            std::string::npos)
    << block;
}
