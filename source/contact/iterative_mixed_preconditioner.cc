// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The setup of the iterative solver's preconditioner (see
// iterative_mixed_solver.cc for the solver): the pairs' own blocks of P C P
// (P onto ker W^T), each pair's M_p = G_p D_p + F_p factorised per solve,
// the rigid unknowns' small system S, and a coarse space on groups of
// neighbouring pairs for the smooth force patterns, which the pairs' blocks
// precondition worst. All of it is done once per model, in the flexibility
// phase.
#include <fdem/contact/dirichlet_preconditioner.h>
#include <fdem/contact/iterative_mixed_solver.h>
#include <fdem/linear_algebra/dense_lu.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace fdem
{
  namespace contact
  {
    template <int dim>
    void
    IterativeMixedSolver<dim>::setup_preconditioner()
    {
      const FullMatrix<double> &rigid_coupling = system.rigid_coupling;
      const SystemScales       &scales         = system.scales;
      const unsigned int        n_pairs        = system.n_pairs();
      const unsigned int        n_forces       = dim * n_pairs;
      const unsigned int        n_rigid        = system.n_rigid_unknowns();

      // P C P = C - Pi C - C Pi + Pi C Pi with Pi = W (W^T W)^{-1} W^T, from
      // C W (one product per free mode). On a free block the diagonal of C
      // is several times that of P C P (6.6 times on the block on a plane
      // of prm/, 77 pairs), and its block-Jacobi preconditioner is the
      // worse for it (condition 108 against 25 on ker W^T, computed).
      projected_self_flexibility = system.self_flexibility;
      if (n_rigid > 0)
        {
          FullMatrix<double> WW(n_rigid, n_rigid);
          rigid_coupling.Tmmult(WW, rigid_coupling);
          const linear_algebra::DenseLU WW_lu(WW);
          // Whether W has full rank is judged on its columns over their
          // largest entries (translations and rotations differ in units).
          FullMatrix<double> WW_scaled(n_rigid, n_rigid);
          for (unsigned int r = 0; r < n_rigid; ++r)
            for (unsigned int c = 0; c < n_rigid; ++c)
              WW_scaled(r, c) = WW(r, c) / (scales.rigid[r] * scales.rigid[c]);
          if (linear_algebra::DenseLU(WW_scaled).reciprocal_condition_number() >
              1e-12)
            {
              std::vector<Vector<double>> W(n_rigid, Vector<double>(n_forces));
              for (unsigned int r = 0; r < n_rigid; ++r)
                for (unsigned int j = 0; j < n_forces; ++j)
                  W[r][j] = rigid_coupling(j, r);
              const std::vector<Vector<double>> CW =
                system.flexibility_products(W);
              // B = W (W^T W)^{-1} (n_forces x n_rigid), X = W^T C W.
              FullMatrix<double> B(n_forces, n_rigid), X(n_rigid, n_rigid);
              for (unsigned int j = 0; j < n_forces; ++j)
                {
                  Vector<double> row(n_rigid);
                  for (unsigned int r = 0; r < n_rigid; ++r)
                    row[r] = rigid_coupling(j, r);
                  WW_lu.solve(row); // (W^T W) symmetric: row of W (W^T W)^{-1}
                  for (unsigned int r = 0; r < n_rigid; ++r)
                    B(j, r) = row[r];
                }
              for (unsigned int r = 0; r < n_rigid; ++r)
                for (unsigned int c = 0; c < n_rigid; ++c)
                  X(r, c) = W[r] * CW[c];
              for (unsigned int p = 0; p < n_pairs; ++p)
                for (unsigned int i = 0; i < dim; ++i)
                  for (unsigned int k = 0; k < dim; ++k)
                    {
                      const unsigned int a = dim * p + i, b = dim * p + k;
                      double             value = 0;
                      for (unsigned int r = 0; r < n_rigid; ++r)
                        {
                          value -= B(a, r) * CW[r][b] + CW[r][a] * B(b, r);
                          for (unsigned int c = 0; c < n_rigid; ++c)
                            value += B(a, r) * X(r, c) * B(b, c);
                        }
                      projected_self_flexibility[p][i][k] += value;
                    }
              projector_coefficients = std::move(B);
            }
        }
      // The Dirichlet preconditioner is the inverse of C at every scale: the
      // smooth patterns, for which the groups were made, need no coarse space
      // beyond the rigid unknowns (FETI's own).
      if (system.krylov_control.preconditioner ==
          KrylovPreconditioner::dirichlet)
        dirichlet = std::make_unique<DirichletPreconditioner<dim>>(
          system,
          system.krylov_control.direct_solver,
          system.krylov_control.memory_limit_MiB);
      else
        setup_coarse_space();
    }

    template <int dim>
    void
    IterativeMixedSolver<dim>::setup_coarse_space()
    {
      const unsigned int n_pairs  = system.n_pairs();
      const unsigned int n_forces = dim * n_pairs;
      const unsigned int n_rigid  = system.n_rigid_unknowns();
      pair_group.assign(n_pairs, 0);
      n_groups = 0;
      if (n_pairs == 0)
        return;
      // Groups of neighbours by recursive halving of their positions, of at
      // most max(16, sqrt(n_pairs) / 2) pairs: about dim n_pairs / 12 coarse
      // vectors up to 1024 pairs, dim sqrt(n_pairs) 8/3 beyond, so that Z
      // and C Z grow as n_pairs^1.5, not as n_pairs^2. C Z costs one product
      // per coarse vector, in blocks of right-hand sides. (On the block on a
      // plane at 625 pairs, groups of 16 took the GMRES iterations of an
      // all-stick solve from 104 to 57, groups of 9 to 48.)
      const unsigned int max_size =
        std::max(16u,
                 static_cast<unsigned int>(
                   std::ceil(std::sqrt(static_cast<double>(n_pairs)) / 2)));
      std::vector<unsigned int> order(n_pairs);
      for (unsigned int p = 0; p < n_pairs; ++p)
        order[p] = p;
      const std::function<void(unsigned int, unsigned int)> bisect =
        [&](const unsigned int begin, const unsigned int end) {
          if (end - begin <= max_size)
            {
              for (unsigned int k = begin; k < end; ++k)
                pair_group[order[k]] = n_groups;
              ++n_groups;
              return;
            }
          // Halve along the longest extent of the group's positions.
          Point<dim> low = system.pair(order[begin]).position_I, high = low;
          for (unsigned int k = begin; k < end; ++k)
            for (unsigned int d = 0; d < dim; ++d)
              {
                low[d] = std::min(low[d], system.pair(order[k]).position_I[d]);
                high[d] =
                  std::max(high[d], system.pair(order[k]).position_I[d]);
              }
          unsigned int axis = 0;
          for (unsigned int d = 1; d < dim; ++d)
            if (high[d] - low[d] > high[axis] - low[axis])
              axis = d;
          const unsigned int middle = begin + (end - begin) / 2;
          std::nth_element(order.begin() + begin,
                           order.begin() + middle,
                           order.begin() + end,
                           [&](const unsigned int a, const unsigned int b) {
                             return system.pair(a).position_I[axis] <
                                    system.pair(b).position_I[axis];
                           });
          bisect(begin, middle);
          bisect(middle, end);
        };
      bisect(0, n_pairs);

      // Z: per group and local direction, 1 on the group's pairs; projected
      // onto ker W^T (z - W (W^T W)^{-1} W^T z), so that a coarse correction
      // leaves the resultants on the free blocks, which the rigid rows fix,
      // alone.
      const unsigned int          n_indicators = dim * n_groups;
      std::vector<Vector<double>> indicators(n_indicators,
                                             Vector<double>(n_forces));
      for (unsigned int p = 0; p < n_pairs; ++p)
        for (unsigned int i = 0; i < dim; ++i)
          indicators[dim * pair_group[p] + i][dim * p + i] = 1;
      if (!projector_coefficients.empty())
        for (Vector<double> &z : indicators)
          {
            Vector<double> resultant(n_rigid);
            system.rigid_coupling.Tvmult(resultant, z);
            Vector<double> correction(n_forces);
            projector_coefficients.vmult(correction, resultant);
            z -= correction;
          }
      // The projection makes some combinations vanish (on a plane, the
      // uniform shifts are rigid translations): an orthonormal basis of the
      // rest, from the eigenvectors of the Gram matrix with eigenvalues above
      // round-off.
      LAPACKFullMatrix<double> gram(n_indicators, n_indicators);
      for (unsigned int a = 0; a < n_indicators; ++a)
        for (unsigned int b = 0; b <= a; ++b)
          gram(a, b) = gram(b, a) = indicators[a] * indicators[b];
      double largest = 0;
      for (unsigned int a = 0; a < n_indicators; ++a)
        largest = std::max(largest, gram(a, a));
      Vector<double>     eigenvalues;
      FullMatrix<double> eigenvectors;
      gram.compute_eigenvalues_symmetric(
        1e-10 * largest, 2 * n_pairs, 0, eigenvalues, eigenvectors);
      const unsigned int          n_coarse = eigenvalues.size();
      std::vector<Vector<double>> Z(n_coarse, Vector<double>(n_forces));
      for (unsigned int c = 0; c < n_coarse; ++c)
        for (unsigned int a = 0; a < n_indicators; ++a)
          Z[c].add(eigenvectors(a, c) / std::sqrt(eigenvalues[c]),
                   indicators[a]);
      const std::vector<Vector<double>> CZ = system.flexibility_products(Z);
      coarse_basis.reinit(n_forces, n_coarse);
      coarse_flexibility.reinit(n_forces, n_coarse);
      for (unsigned int c = 0; c < n_coarse; ++c)
        for (unsigned int j = 0; j < n_forces; ++j)
          {
            coarse_basis(j, c)       = Z[c][j];
            coarse_flexibility(j, c) = CZ[c][j];
          }
    }

    template void
    IterativeMixedSolver<2>::setup_coarse_space();
    template void
    IterativeMixedSolver<3>::setup_coarse_space();
    template void
    IterativeMixedSolver<2>::setup_preconditioner();
    template void
    IterativeMixedSolver<3>::setup_preconditioner();
  } // namespace contact
} // namespace fdem
