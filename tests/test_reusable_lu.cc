// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The mixed system's solver that reuses the LU factors of an earlier matrix
// when a few rows change (ReusableLU, doc/theory.md): the same solution and
// condition estimate as a fresh factorisation, and a fresh factorisation
// when many rows change or the system is singular.
#include <fdem/linear_algebra/reusable_lu.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using dealii::FullMatrix;
using dealii::Vector;
using fdem::linear_algebra::ReusableLU;

namespace
{
  constexpr unsigned int n_forces = 120, n_rigid = 6, n = n_forces + n_rigid;

  /**
   * A matrix of the form of the mixed system, [C -W; -W^T 0], with C
   * symmetric positive definite of the size of a flexibility (1e-6) and W
   * of order 1: the units of its blocks differ as they do in the model.
   */
  FullMatrix<double>
  mixed_matrix(std::mt19937 &random)
  {
    std::uniform_real_distribution<double> uniform(-1, 1);
    FullMatrix<double> G(n_forces, n_forces), C(n_forces, n_forces);
    for (unsigned int i = 0; i < n_forces; ++i)
      for (unsigned int j = 0; j < n_forces; ++j)
        G(i, j) = uniform(random);
    G.Tmmult(C, G);
    FullMatrix<double> matrix(n, n);
    for (unsigned int i = 0; i < n_forces; ++i)
      {
        for (unsigned int j = 0; j < n_forces; ++j)
          matrix(i, j) = 1e-6 * (C(i, j) + (i == j ? n_forces : 0.0));
        for (unsigned int r = 0; r < n_rigid; ++r)
          {
            const double w          = uniform(random);
            matrix(i, n_forces + r) = -w;
            matrix(n_forces + r, i) = -w;
          }
      }
    return matrix;
  }

  /** Pair p "opens": its rows become f = 0 (dim = 3 rows per pair). */
  void
  open_pair(FullMatrix<double> &matrix, const unsigned int p)
  {
    for (unsigned int i = 3 * p; i < 3 * p + 3; ++i)
      for (unsigned int j = 0; j < n; ++j)
        matrix(i, j) = i == j ? 1.0 : 0.0;
  }

  Vector<double>
  random_rhs(std::mt19937 &random)
  {
    std::uniform_real_distribution<double> uniform(-1, 1);
    Vector<double>                         rhs(n);
    for (unsigned int i = 0; i < n; ++i)
      rhs[i] = i < n_forces ? 1e-3 * uniform(random) : 1e3 * uniform(random);
    return rhs;
  }

  /** The solution and verdict of a fresh factorisation. */
  ReusableLU::Result
  fresh_solve(const FullMatrix<double> &matrix, Vector<double> &rhs)
  {
    ReusableLU::Control control;
    control.reuse = false;
    ReusableLU lu(control);
    return lu.solve(matrix, rhs);
  }

  /** max_i |x_i - y_i| / max_i |y_i|, each unknown group on its own. */
  double
  relative_difference(const Vector<double> &x,
                      const Vector<double> &y,
                      const unsigned int    begin,
                      const unsigned int    end)
  {
    double difference = 0, size = 0;
    for (unsigned int i = begin; i < end; ++i)
      {
        difference = std::max(difference, std::abs(x[i] - y[i]));
        size       = std::max(size, std::abs(y[i]));
      }
    return difference / size;
  }
} // namespace

TEST(ReusableLU, FewChangedRowsReuseTheFactorsWithTheFreshSolution)
{
  std::mt19937       random(42);
  FullMatrix<double> matrix = mixed_matrix(random);
  ReusableLU         lu;

  Vector<double>           x = random_rhs(random), x_fresh = x;
  const ReusableLU::Result first = lu.solve(matrix, x);
  const ReusableLU::Result fresh = fresh_solve(matrix, x_fresh);
  EXPECT_TRUE(first.factorized);
  EXPECT_TRUE(first.solved);
  EXPECT_EQ(first.reciprocal_condition, fresh.reciprocal_condition);
  for (unsigned int i = 0; i < n; ++i)
    EXPECT_EQ(x[i], x_fresh[i]); // the same operations

  // The same matrix again: the same factors, bit for bit.
  Vector<double> rhs = random_rhs(random);
  x = x_fresh                    = rhs;
  const ReusableLU::Result again = lu.solve(matrix, x);
  fresh_solve(matrix, x_fresh);
  EXPECT_FALSE(again.factorized);
  EXPECT_EQ(again.n_changed_rows, 0u);
  EXPECT_EQ(again.reciprocal_condition, first.reciprocal_condition);
  for (unsigned int i = 0; i < n; ++i)
    EXPECT_EQ(x[i], x_fresh[i]);

  // Two pairs open (6 rows), and one more on top: changes are counted
  // against the factorised matrix, so the second solve sees 9 rows (of
  // 126, below max_changed_fraction = 0.1).
  for (const unsigned int n_open : {2u, 3u})
    {
      for (unsigned int p = 0; p < n_open; ++p)
        open_pair(matrix, 7 * p + 2);
      rhs = random_rhs(random);
      x = x_fresh                     = rhs;
      const ReusableLU::Result reused = lu.solve(matrix, x);
      const ReusableLU::Result fresh  = fresh_solve(matrix, x_fresh);
      EXPECT_FALSE(reused.factorized);
      EXPECT_EQ(reused.n_changed_rows, 3 * n_open);
      EXPECT_TRUE(reused.solved);
      EXPECT_LE(reused.backward_error, 1e-14);
      // Both solutions are within about eps / rcond of the exact one (rcond
      // of the scaled system ~7e-7 here: 3e-10), so 1e-9 is a bound on their
      // difference (measured: 4e-14); a wrong update is off by O(1).
      EXPECT_LT(relative_difference(x, x_fresh, 0, n_forces), 1e-9);
      EXPECT_LT(relative_difference(x, x_fresh, n_forces, n), 1e-9);
      // Two estimates of the same 1-norm condition number: LAPACK's
      // estimator is exact or within a small factor (typically < 3) of it.
      EXPECT_GT(reused.reciprocal_condition, fresh.reciprocal_condition / 3);
      EXPECT_LT(reused.reciprocal_condition, fresh.reciprocal_condition * 3);
    }
  EXPECT_EQ(lu.n_factorizations, 1u);
  EXPECT_EQ(lu.n_reused_solves, 3u);
}

TEST(ReusableLU, ManyChangedRowsOrASingularSystemFactoriseAfresh)
{
  std::mt19937       random(7);
  FullMatrix<double> matrix = mixed_matrix(random);
  ReusableLU         lu;
  Vector<double>     x = random_rhs(random);
  lu.solve(matrix, x);

  // Half the pairs open: far beyond max_changed_fraction of the rows.
  for (unsigned int p = 0; p < n_forces / 6; ++p)
    open_pair(matrix, 2 * p);
  Vector<double> rhs = random_rhs(random), x_fresh = rhs;
  x                              = rhs;
  const ReusableLU::Result many  = lu.solve(matrix, x);
  const ReusableLU::Result fresh = fresh_solve(matrix, x_fresh);
  EXPECT_TRUE(many.factorized);
  EXPECT_EQ(many.n_changed_rows, n_forces / 2);
  EXPECT_EQ(many.reciprocal_condition, fresh.reciprocal_condition);
  for (unsigned int i = 0; i < n; ++i)
    EXPECT_EQ(x[i], x_fresh[i]);
  EXPECT_EQ(lu.n_factorizations, 2u);

  // One changed row makes the system singular (two equal equilibrium
  // rows): the verdict is a fresh factorisation's, as without reuse.
  FullMatrix<double> singular = matrix;
  for (unsigned int j = 0; j < n; ++j)
    singular(n_forces, j) = singular(n_forces + 1, j); // two equal rows
  x = x_fresh                            = rhs;
  const ReusableLU::Result verdict       = lu.solve(singular, x);
  const ReusableLU::Result fresh_verdict = fresh_solve(singular, x_fresh);
  EXPECT_EQ(verdict.n_changed_rows, 1u);
  EXPECT_TRUE(verdict.factorized);
  EXPECT_FALSE(verdict.solved);
  EXPECT_EQ(verdict.solved, fresh_verdict.solved);
  EXPECT_EQ(verdict.reciprocal_condition, fresh_verdict.reciprocal_condition);
  EXPECT_EQ(lu.n_factorizations, 3u);
}
