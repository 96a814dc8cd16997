// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/contact/pair_rows.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace fdem
{
  namespace contact
  {
    using namespace dealii;

    /**
     * The characteristic scales that make the mixed system dimensionless
     * (doc/theory.md, "Scale-free decisions"). Every decision taken on the
     * system (singularity, runaway, tolerances) compares dimensionless
     * numbers, so that it is the same in any consistent set of units and for
     * any common Young's modulus.
     *
     * - force: F_0, the largest total load of a block (the 1-norm of its
     *   nodal load vector), a force of the model that no modulus enters;
     * - flexibility: c_0, the mean diagonal entry of C, length over force;
     *   it carries 1/E;
     * - displacement: u_0 = c_0 F_0, the elastic relative displacement that
     *   F_0 causes, so that it scales with 1/E as C and g_bar do;
     * - rigid: w_m, the largest |W_jm| of each free mode m. Its relative
     *   motion W_m gamma_m is a length, so gamma_m ~ u_0 / w_m: translations
     *   have w_m of order 1, rotations a lever arm (the model's size).
     */
    struct SystemScales
    {
      double              force        = 1;
      double              flexibility  = 1;
      double              displacement = 1;
      std::vector<double> rigid;
    };

    /**
     * The magnitude rho_i of each of a pair's dim rows (PairRows): the
     * largest of |gap[i][k]| u_0 and |force[i][k]| F_0. A row divided by it
     * reads in dimensionless unknowns f / F_0 and W gamma / u_0 with
     * coefficients of at most 1. (1 for a row without any coefficient.)
     */
    template <int dim>
    Tensor<1, dim>
    row_magnitudes(const PairRows<dim> &rows, const SystemScales &scales);

    /**
     * Whether the free rigid modes can be in equilibrium under the pairs'
     * current states: the mechanical meaning of a singular mixed system
     * (doc/theory.md). Two matrices, both dimensionless (forces / F_0,
     * rigid motions W_m gamma_m / u_0, rows of PairRows divided by their
     * magnitudes):
     *
     * - equilibrium, E = [W_p^T N_p] over the pairs (n_rigid rows): N_p spans
     *   the forces that pair p can still take, those that its force rows do
     *   not fix (stick: all directions; slip: f_n with its limit shear
     *   -mu f_n d, and in 3D the force across the slip while its rows tie it
     *   to the slip; open: none). The fixed parts (c A d, sigma_t A) go to
     *   the right-hand side. If E has rank below n_rigid, the free modes have
     *   no equilibrium for almost every load, and none that fixes the forces;
     * - kinematics, K = [g_i^T W_p] over the rows with gap coefficients g_i:
     *   if K has rank below n_rigid, a rigid motion exists that none of the
     *   pairs' gap conditions resists, and its size is undetermined.
     *
     * Either rank deficiency makes the mixed system exactly singular (its
     * rigid rows or its rigid columns are dependent), whatever C is: the
     * blocks form a mechanism under these states. The ranks come from the
     * singular values (Householder QR, then SVD of the small triangle): a
     * smallest over largest below @p tolerance is a deficiency.
     */
    struct RigidModeTest
    {
      /** Number of free rigid modes (0: nothing to test). */
      unsigned int n_rigid = 0;
      /** sigma_min / sigma_max of E (0 with fewer force directions than modes).
       */
      double equilibrium_ratio = 1;
      /** sigma_min / sigma_max of K (0 with fewer gap rows than modes). */
      double kinematic_ratio = 1;
      /**
       * If E is deficient: the part of the rigid loads (net of the forces
       * fixed at their limits) outside the range of E, relative to their
       * size. Above the tolerance: no equilibrium at all; below: an
       * equilibrium with an undetermined rigid motion (a limit state).
       */
      double unbalanced_load = 0;
      /** Both ranks full: the free modes can be held. */
      bool holds = true;
    };

    /**
     * The test above for the rows @p rows of every pair, with W =
     * @p rigid_coupling (local frames, n_forces x n_rigid) and omega^T F =
     * @p rigid_loads.
     */
    template <int dim>
    RigidModeTest
    rigid_mode_test(const FullMatrix<double>         &rigid_coupling,
                    const Vector<double>             &rigid_loads,
                    const std::vector<PairRows<dim>> &rows,
                    const SystemScales               &scales,
                    const double                      tolerance);
  } // namespace contact
} // namespace fdem
