// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The safety-factor iteration, eqs. (10)-(13), on synthetic steps (K* given
// as a function of K, test_support::synthetic_step): planar limits, brackets
// and their certificates, K-dependent factors, folds of all-slipping states
// (the 3D sliding mass) and the estimate after a failed first K.
#include "synthetic_step.h"

#include <fdem/analyses/safety_factor_iteration.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

using namespace fdem;

namespace
{
  using test_support::synthetic_step;

  /**
   * A step of a fold of all-slipping states (a 3D sliding mass):
   * synthetic_step() with every one of @p n_slip pairs slipping wherever a
   * static solution exists (below @p K_end).
   */
  analyses::ReducedStrengthSolution
  all_slipping_step(const double       K,
                    const double       K_star,
                    const double       K_end,
                    const unsigned int n_slip)
  {
    analyses::ReducedStrengthSolution s = synthetic_step(K, K_star, K_end);
    s.all_slipping                      = s.converged;
    s.n_slip                            = n_slip;
    return s;
  }

  /** The certificate's numbers hold: a step at its K with its K*, within the
   * tolerance. */
  void
  expect_certificate_holds(const analyses::Result &result,
                           const double            tolerance)
  {
    const auto &c = result.certificate;
    ASSERT_TRUE(c.holds) << c.reason;
    EXPECT_LE(std::abs(c.K_star - c.K), tolerance * c.K);
    EXPECT_TRUE(std::any_of(result.steps.begin(),
                            result.steps.end(),
                            [&](const auto &step) {
                              return step.K == c.K && step.K_star == c.K_star;
                            }));
  }
} // namespace

TEST(SafetyFactorIteration,
     PlanarLimitFromTwoAgreeingFactorsCertifiedJustBelowIt)
{
  // A planar surface: K* does not depend on K, and the limit itself has no
  // static solution (singular system). K = 1, fail at 1.5, K = 1.25: K* is
  // independent of K, so one solve just below it, at 1.5 (1 - tol/4),
  // certifies it as a fixed point: four solves.
  parameters::SafetyFactorParameters control;
  std::ostringstream                 log;
  const auto                         result = analyses::iterate(
    [](const double K) { return synthetic_step(K, 1.5, 1.5); }, control, log);
  ASSERT_TRUE(result.converged) << log.str();
  EXPECT_EQ(result.safety_factor, 1.5);
  EXPECT_EQ(result.certificate.kind, analyses::Certificate::Kind::fixed_point);
  expect_certificate_holds(result, control.tolerance);
  EXPECT_EQ(result.steps.size(), 4u) << log.str();
}

TEST(SafetyFactorIteration, AgreeingFactorsAboveAFailedSolveAreNotCertified)
{
  // K* = 1.5 from every K, but solves already fail from 1.2: the bracket
  // below 1.2 is no limit, since K* at its solved end points far beyond it
  // (what an undeclared contact looks like). The run says so.
  parameters::SafetyFactorParameters control;
  std::ostringstream                 log;
  const auto                         result = analyses::iterate(
    [](const double K) { return synthetic_step(K, 1.5, 1.2); }, control, log);
  EXPECT_FALSE(result.converged) << log.str();
  EXPECT_TRUE(std::isnan(result.safety_factor));
  EXPECT_EQ(result.certificate.kind, analyses::Certificate::Kind::bracket);
  EXPECT_FALSE(result.certificate.holds);
  EXPECT_NEAR(result.certificate.K, 1.2, 2 * control.tolerance * 1.2);
  EXPECT_EQ(result.certificate.K_star, 1.5);
  EXPECT_NE(result.certificate.reason.find("did not close"), std::string::npos)
    << result.certificate.reason;
  // Static states below the failures have K* far beyond them: each failure
  // K may be solved again, but at most twice in the run.
  std::size_t n_retries = 0;
  for (std::size_t p = log.str().find("solving there again");
       p != std::string::npos;
       p = log.str().find("solving there again", p + 1))
    ++n_retries;
  EXPECT_GE(n_retries, 1u) << log.str();
  EXPECT_LE(n_retries, 2u) << log.str();
}

TEST(SafetyFactorIteration, BracketAtTheLimitWithAMechanismAboveIsCertified)
{
  // K* = 1.2 + (1.2 - K)^2 below 1.2, a mechanism from 1.2 up: K* reaches K
  // only at the limit, where the solve fails. The bracket is certified.
  parameters::SafetyFactorParameters control;
  std::ostringstream                 log;
  const auto                         result = analyses::iterate(
    [](const double K) {
      return synthetic_step(K, 1.2 + std::pow(1.2 - K, 2) / 1.2, 1.2);
    },
    control,
    log);
  ASSERT_TRUE(result.converged) << log.str() << result.certificate.reason;
  expect_certificate_holds(result, control.tolerance);
  EXPECT_NEAR(result.safety_factor, 1.2, control.tolerance * 1.2);
}

TEST(SafetyFactorIteration, FailureBelowStrengthToSpareIsSolvedAgainOnce)
{
  // K* = 1.3 + 0.1 (K - 1), fixed point 4/3, a mechanism from 1.4 up; but
  // the first solve at or above 1.2 fails as a mechanism (as a solve that
  // started from a state further down, with pairs open, did on a sphere
  // with a soft mass). A static state solved below that failure has K*
  // beyond it by more than Bracket agreement, so the iteration solves the
  // failure's K again from that state, once, and goes on to the fixed
  // point.
  parameters::SafetyFactorParameters control;
  std::ostringstream                 log;
  bool                               failed_once = false;
  const auto                         result      = analyses::iterate(
    [&](const double K) {
      const bool fail = !failed_once && K >= 1.2;
      failed_once     = failed_once || fail;
      return synthetic_step(K, 1.3 + 0.1 * (K - 1), fail ? K : 1.4);
    },
    control,
    log);
  ASSERT_TRUE(result.converged) << log.str() << result.certificate.reason;
  expect_certificate_holds(result, control.tolerance);
  EXPECT_NEAR(result.safety_factor, 4.0 / 3, control.tolerance * 4 / 3);
  EXPECT_NE(log.str().find("solving there again"), std::string::npos)
    << log.str();
}

TEST(SafetyFactorCertificate, BracketNeedsAMechanismAbove)
{
  // A bracket as the iteration leaves it: a solved K_lo whose K* agrees
  // with it, its fixed point not yet shown (distance left larger than the
  // tolerance), and a failed K_hi within the tolerance above. Certified only
  // if the failure above is a mechanism, not a numerical breakdown.
  const double     tolerance = 1e-6;
  analyses::Result result;
  analyses::Step   solved;
  solved.K                    = 1.2 * (1 - 0.5 * tolerance);
  solved.K_star               = solved.K * (1 + 0.1 * tolerance);
  solved.K_next               = 1.2;
  solved.distance_left        = 10 * tolerance;
  solved.solution             = synthetic_step(solved.K, solved.K_star, 1.2);
  const analyses::Step failed = {1.2,
                                 std::nan(""),
                                 solved.K,
                                 std::nan(""),
                                 synthetic_step(1.2, 0, 1.2, true)};
  result.steps                = {solved, failed};
  result.bracket_low          = solved.K;
  result.bracket_high         = failed.K;
  const analyses::Certificate breakdown = analyses::certify(result, tolerance);
  EXPECT_EQ(breakdown.kind, analyses::Certificate::Kind::bracket);
  EXPECT_FALSE(breakdown.holds);
  EXPECT_NE(breakdown.reason.find("failed numerically"), std::string::npos)
    << breakdown.reason;

  result.steps[1].solution              = synthetic_step(1.2, 0, 1.2, false);
  const analyses::Certificate mechanism = analyses::certify(result, tolerance);
  EXPECT_TRUE(mechanism.holds) << mechanism.reason;
  EXPECT_EQ(mechanism.K, solved.K);
  EXPECT_EQ(mechanism.K_failed, 1.2);

  // The last step solved but its fixed point not shown, and no bracket: none
  // holds.
  result.steps.pop_back();
  result.bracket_high                = std::numeric_limits<double>::infinity();
  const analyses::Certificate moving = analyses::certify(result, tolerance);
  EXPECT_EQ(moving.kind, analyses::Certificate::Kind::fixed_point);
  EXPECT_FALSE(moving.holds);
  EXPECT_NE(moving.reason.find("still moving"), std::string::npos)
    << moving.reason;
}

TEST(SafetyFactorIteration, NoEquilibriumOnlyWhenEveryFailureIsAMechanism)
{
  parameters::SafetyFactorParameters control;
  std::ostringstream                 log;
  const auto                         mechanism =
    analyses::iterate([](const double K) { return synthetic_step(K, 1, 0); },
                      control,
                      log);
  EXPECT_FALSE(mechanism.converged);
  EXPECT_TRUE(mechanism.no_equilibrium);
  const auto breakdown = analyses::iterate(
    [](const double K) { return synthetic_step(K, 1, 0, true); }, control, log);
  EXPECT_FALSE(breakdown.converged);
  EXPECT_FALSE(breakdown.no_equilibrium);
}

TEST(SafetyFactorIteration, FactorThatDependsOnKConvergesToItsFixedPoint)
{
  // K* = K + (2 - K)/2: a fixed point at 2 that is solvable, K* changes
  // with K, so only eq. (13) itself can stop the iteration.
  parameters::SafetyFactorParameters control;
  std::ostringstream                 log;
  const auto                         result = analyses::iterate(
    [](const double K) { return synthetic_step(K, K + 0.5 * (2 - K), 10); },
    control,
    log);
  ASSERT_TRUE(result.converged) << log.str();
  expect_certificate_holds(result, control.tolerance);
  EXPECT_NEAR(result.safety_factor, 2.0, control.tolerance * 2.0);
}

TEST(SafetyFactorIteration,
     SlowlyCreepingFactorStopsWithinTheToleranceOfItsFixedPoint)
{
  // h = K* - K = (K_lim - K)^1.75, roughly as on a 3D wedge (there with
  // every pair slipping, FoldOfAllSlippingStates... below), the limit a
  // mechanism: the reported K must be within the tolerance of K_lim (the
  // stop used to fire 2e-6 short on such a sequence).
  parameters::SafetyFactorParameters control;
  std::ostringstream                 log;
  const double                       K_lim  = 0.7266;
  const auto                         result = analyses::iterate(
    [&](const double K) {
      return synthetic_step(K,
                            K + std::pow(std::max(K_lim - K, 0.0), 1.75),
                            K_lim);
    },
    control,
    log);
  ASSERT_TRUE(result.converged) << log.str();
  expect_certificate_holds(result, control.tolerance);
  EXPECT_LE(std::abs(result.safety_factor - K_lim), control.tolerance * K_lim)
    << log.str();
}

TEST(SafetyFactorIteration, FoldOfAllSlippingStatesIsReachedInFewSteps)
{
  // A 3D sliding mass with every pair slipping: h = K* - K = a d^2 /
  // (1 + c d), d = L - K, the local exponent 1.8 at d = 5e-3 and 2 at the
  // limit, as measured on prm/rock_wedge.prm (a = 6, L = 0.7266); the
  // solves end 1.3e-6 (relative) below L, as there. The answer must be a
  // static K within the tolerance below where the solves end, certified;
  // the secant on h alone took 26 steps on the wedge. From K = 1, halved to
  // 0.5 (no estimate): measured 11 steps (13 before the known fold went for
  // the end of the solves).
  parameters::SafetyFactorParameters control;
  std::ostringstream                 log;
  const double                       L = 0.7266, end = L * (1 - 1.3e-6);
  const auto                         result = analyses::iterate(
    [&](const double K) {
      const double d = L - K;
      return all_slipping_step(K, K + 6 * d * d / (1 + 44 * d), end, 10);
    },
    control,
    log);
  ASSERT_TRUE(result.converged) << log.str();
  expect_certificate_holds(result, control.tolerance);
  EXPECT_LT(result.safety_factor, end);
  EXPECT_GE(result.safety_factor, end * (1 - control.tolerance)) << log.str();
  EXPECT_LE(result.steps.size(), 11u) << log.str();
}

namespace
{
  /**
   * The fold of FoldOfAllSlippingStatesIsReachedInFewSteps: every pair
   * slipping, h = a d^2 / (1 + c d), the solves ending 1.3e-6 (relative)
   * below L = 0.7266, as on prm/rock_wedge.prm.
   */
  analyses::ReducedStrengthSolution
  wedge_like_fold(const double K)
  {
    const double L = 0.7266, end = L * (1 - 1.3e-6), d = L - K;
    return all_slipping_step(K, K + 6 * d * d / (1 + 44 * d), end, 10);
  }
} // namespace

TEST(SafetyFactorIteration, FailedFirstFactorGoesToTheEstimateThenToTheFold)
{
  // The wedge-like fold from K = 1, which fails: the next K is the
  // estimate (the FE-stress factor, 4.4 % below L on the wedge), asked for
  // once, not 0.5; from there the fold is reached and the end of the
  // solves bracketed. Measured: 10 steps (13 from 0.5, the old start).
  parameters::SafetyFactorParameters control;
  std::ostringstream                 log;
  const double                       L = 0.7266, end = L * (1 - 1.3e-6);
  unsigned int                       n_estimates = 0;
  const auto result = analyses::iterate(wedge_like_fold, control, log, [&]() {
    ++n_estimates;
    return 0.956 * L;
  });
  ASSERT_TRUE(result.converged) << log.str();
  expect_certificate_holds(result, control.tolerance);
  EXPECT_EQ(n_estimates, 1u);
  ASSERT_GE(result.steps.size(), 2u);
  EXPECT_FALSE(result.steps[0].solution.converged);
  EXPECT_EQ(result.steps[1].K, 0.956 * L);
  EXPECT_LT(result.safety_factor, end);
  EXPECT_GE(result.safety_factor, end * (1 - control.tolerance)) << log.str();
  EXPECT_LE(result.steps.size(), 10u) << log.str();
}

TEST(SafetyFactorIteration, EstimateAboveTheFailedFirstFactorIsNotTried)
{
  // An estimate at or above the K that failed cannot be closer to the
  // limit: K is halved as without one, and the answer is the same.
  parameters::SafetyFactorParameters control;
  std::ostringstream                 log;
  const auto                         with =
    analyses::iterate(wedge_like_fold, control, log, []() { return 1.2; });
  const auto without = analyses::iterate(wedge_like_fold, control, log);
  ASSERT_TRUE(with.converged) << log.str();
  ASSERT_GE(with.steps.size(), 2u);
  EXPECT_EQ(with.steps[1].K, 0.5);
  EXPECT_EQ(with.safety_factor, without.safety_factor);
  EXPECT_EQ(with.steps.size(), without.steps.size());
}

TEST(SafetyFactorIteration, AllSlipStatesBoundFromAboveAndNeverCertify)
{
  // Below K_s = 0.9 a state with a sticking pair, K* = K + (0.9 - K)/2;
  // from 0.9 up a static state with every pair slipping, so K* = K at any
  // K (what the paper's slope under kh = 0.15 gave at K = 1, after a rigid
  // slide of 540 m). The first step, at K = 1, is such a state: it must
  // not certify K = 1; the answer is the limit of the informative steps.
  parameters::SafetyFactorParameters control;
  std::ostringstream                 log;
  const double                       K_s    = 0.9;
  const auto                         result = analyses::iterate(
    [&](const double K) {
      if (K < K_s)
        return synthetic_step(K, K + 0.5 * (K_s - K), 10);
      analyses::ReducedStrengthSolution s = synthetic_step(K, K, 10);
      s.n_slip                            = 10;
      s.degenerate                        = true;
      return s;
    },
    control,
    log);
  ASSERT_TRUE(result.converged) << log.str() << result.certificate.reason;
  EXPECT_TRUE(result.steps.front().solution.degenerate);
  EXPECT_LE(std::abs(result.safety_factor - K_s), control.tolerance * K_s)
    << log.str();
  // What the certificate rests on is an informative step.
  for (const auto &step : result.steps)
    {
      if (step.K == result.certificate.K &&
          step.K_star == result.certificate.K_star)
        {
          EXPECT_FALSE(step.solution.degenerate) << log.str();
        }
    }

  // An all-slip step alone, its K* = K to the last digit, certifies nothing.
  analyses::Result alone;
  alone.steps                   = {result.steps.front()};
  alone.steps[0].distance_left  = 0;
  const analyses::Certificate c = analyses::certify(alone, control.tolerance);
  EXPECT_FALSE(c.holds);
  EXPECT_NE(c.reason.find("every pair in contact slips"), std::string::npos)
    << c.reason;
}

namespace
{
  /**
   * K* - K of prm/rock_wedge.prm (Mesh size 4 m) as measured, one solve at
   * each K: every pair slips (92, one open) from 4.5 % below the limit
   * equilibrium L = 0.726602024686 (tests/scripts/wedge_reference.py) up to
   * 2e-6 below it, and the solve 1e-6 below it found no static solution.
   * sqrt(K* - K) = rho (L - K): rho (here against r = (L - K)/L) climbs from
   * 1.49 far away to 1.607 near L, flat below r = 1e-5 to 2e-4 of itself,
   * so the fold of sqrt(K* - K) is L to about 1e-10. Between the measured
   * r, rho is interpolated linearly in ln r; the solves end at r = 1.5e-6.
   */
  double
  measured_wedge_h(const double K)
  {
    static const std::array<double, 18> rs   = {{4.5e-2,
                                                 3e-2,
                                                 2e-2,
                                                 1e-2,
                                                 5e-3,
                                                 3e-3,
                                                 2e-3,
                                                 1e-3,
                                                 5e-4,
                                                 3e-4,
                                                 2e-4,
                                                 1e-4,
                                                 5e-5,
                                                 2e-5,
                                                 1e-5,
                                                 5e-6,
                                                 3e-6,
                                                 2e-6}};
    static const std::array<double, 18> rhos = {{1.48782,
                                                 1.49780,
                                                 1.47591,
                                                 1.49067,
                                                 1.52710,
                                                 1.55184,
                                                 1.56742,
                                                 1.58570,
                                                 1.59604,
                                                 1.60042,
                                                 1.60267,
                                                 1.60496,
                                                 1.60612,
                                                 1.60682,
                                                 1.60706,
                                                 1.60719,
                                                 1.60725,
                                                 1.60728}};
    const double                        L = 0.726602024686, r = (L - K) / L;
    double rho = r >= rs.front() ? rhos.front() : rhos.back();
    for (unsigned int i = 0; i + 1 < rs.size(); ++i)
      if (r <= rs[i] && r >= rs[i + 1])
        {
          const double t = std::log(rs[i] / r) / std::log(rs[i] / rs[i + 1]);
          rho            = (1 - t) * rhos[i] + t * rhos[i + 1];
        }
    const double g = rho * (L - K);
    return g * g;
  }

  /** measured_wedge_h() as steps, the solves ending at r = 1.5e-6. */
  analyses::ReducedStrengthSolution
  measured_wedge_fold(const double K)
  {
    const double L = 0.726602024686;
    return all_slipping_step(K, K + measured_wedge_h(K), L * (1 - 1.5e-6), 92);
  }

  /**
   * A step of the fold h(K) = K* - K ending at @p K_end, with the slope of
   * K* as SafetyFactorAnalysis computes it for a step with every pair
   * slipping: the central difference over a hundredth of sqrt(h) either
   * side (of h itself here: the program's two solves are linear solves,
   * which do not end where the status iteration's do).
   */
  template <typename H>
  analyses::ReducedStrengthSolution
  step_with_slope(const H           &h,
                  const double       K,
                  const double       K_end,
                  const unsigned int n_slip)
  {
    analyses::ReducedStrengthSolution s =
      all_slipping_step(K, K + h(K), K_end, n_slip);
    if (s.converged)
      {
        const double dK  = std::max(1e-2 * std::sqrt(h(K)), 1e-9 * K);
        s.K_star_slope   = 1 + (h(K + dK) - h(K - dK)) / (2 * dK);
        s.n_slope_solves = 2;
      }
    return s;
  }
} // namespace

TEST(SafetyFactorIteration, MeasuredWedgeFoldIsReachedInFewSteps)
{
  // The rock wedge's measured K* - K (measured_wedge_fold) from K = 1,
  // which fails, then the measured FE-stress factor 0.69450393: the answer
  // a static K within the tolerance below where the solves end, certified.
  parameters::SafetyFactorParameters control;
  std::ostringstream                 log;
  const double                       L = 0.726602024686, end = L * (1 - 1.5e-6);
  const auto                         result =
    analyses::iterate(measured_wedge_fold, control, log, []() {
      return 0.6945039317319832;
    });
  ASSERT_TRUE(result.converged) << log.str();
  expect_certificate_holds(result, control.tolerance);
  EXPECT_LT(result.safety_factor, end);
  EXPECT_GE(result.safety_factor, end * (1 - control.tolerance)) << log.str();
  // Measured 12, as the program itself took on the wedge without the
  // slopes of K* (the same sequence of K to three digits): the path of
  // steps without slopes (doc/theory.md, "The fold's slope").
  EXPECT_LE(result.steps.size(), 12u) << log.str();
}

TEST(SafetyFactorIteration, MeasuredWedgeFoldWithSlopesTakesSixSteps)
{
  // The same measured fold, now with the slope of K* at each step (as the
  // program computes it for every step with all pairs slipping): Newton's
  // steps on sqrt(K* - K) from the FE-stress factor, 95 % of the way, then
  // the end of the solves once the roots' error is within 2 tolerances.
  // Measured: 6 steps (K = 1, 0.6945, 0.7252, 0.726519 with the limit
  // known, 0.7266008 static, 0.7266015 a mechanism), 12 without the
  // slopes; the program on the wedge itself took 6 too.
  parameters::SafetyFactorParameters control;
  std::ostringstream                 log;
  const double                       L = 0.726602024686, end = L * (1 - 1.5e-6);
  const auto                         result = analyses::iterate(
    [&](const double K) {
      return step_with_slope(measured_wedge_h, K, end, 92);
    },
    control,
    log,
    []() { return 0.6945039317319832; });
  ASSERT_TRUE(result.converged) << log.str();
  expect_certificate_holds(result, control.tolerance);
  EXPECT_LT(result.safety_factor, end);
  EXPECT_GE(result.safety_factor, end * (1 - control.tolerance)) << log.str();
  EXPECT_LE(result.steps.size(), 6u) << log.str();
}

TEST(SafetyFactorIteration, SteepFoldWithSlopesIsReachedAsWithout)
{
  // The synthetic fold h = 6 d^2 / (1 + 44 d) of wedge_like_fold, whose
  // sqrt(h) bends far more than the wedge's (its Newton root overshoots
  // by 29 % of the distance 4.4 % below L): with the slopes the fold must
  // be reached, certified, and in no more steps than without them (10).
  // Measured 9: the first Newton step overshoots and fails, the bracket
  // is bisected, and from there the fitted exponent leads in.
  parameters::SafetyFactorParameters control;
  std::ostringstream                 log;
  const double                       L = 0.7266, end = L * (1 - 1.3e-6);
  const auto                         h = [&](const double K) {
    const double d = L - K;
    return 6 * d * d / (1 + 44 * d);
  };
  const auto result = analyses::iterate(
    [&](const double K) { return step_with_slope(h, K, end, 10); },
    control,
    log,
    [&]() { return 0.956 * L; });
  ASSERT_TRUE(result.converged) << log.str();
  expect_certificate_holds(result, control.tolerance);
  EXPECT_LT(result.safety_factor, end);
  EXPECT_GE(result.safety_factor, end * (1 - control.tolerance)) << log.str();
  EXPECT_LE(result.steps.size(), 10u) << log.str();
}
