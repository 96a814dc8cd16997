// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/blocks/rigid_modes.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cmath>

namespace fdem
{
  namespace blocks
  {
    template <int dim>
    Tensor<1, dim>
    rigid_mode(const unsigned int mode,
               const Point<dim>  &x,
               const Point<dim>  &centre,
               const double       length)
    {
      Tensor<1, dim> u;
      if (mode < dim)
        {
          u[mode] = 1;
          return u;
        }
      const Tensor<1, dim> r = (x - centre) / length;
      if constexpr (dim == 2)
        {
          // Rotation about z: omega x r.
          u[0] = -r[1];
          u[1] = r[0];
        }
      else
        {
          Tensor<1, 3> axis;
          axis[mode - 3] = 1;
          u              = cross_product_3d(axis, r);
        }
      return u;
    }

    FullMatrix<double>
    free_rigid_modes(const AffineConstraints<double> &constraints,
                     const FullMatrix<double>        &modes_at_dofs)
    {
      const unsigned int n_modes = modes_at_dofs.n();
      // Gram matrix G = M^T M of the constraint rows M (one row per
      // constrained dof: u_i - sum_j a_ij u_j evaluated on each mode).
      LAPACKFullMatrix<double> gram(n_modes, n_modes);
      Vector<double>           row(n_modes);
      for (const auto &line : constraints.get_lines())
        {
          for (unsigned int m = 0; m < n_modes; ++m)
            row[m] = modes_at_dofs(line.index, m);
          for (const auto &[j, a] : line.entries)
            for (unsigned int m = 0; m < n_modes; ++m)
              row[m] -= a * modes_at_dofs(j, m);
          for (unsigned int m = 0; m < n_modes; ++m)
            for (unsigned int n = 0; n < n_modes; ++n)
              gram(m, n) += row[m] * row[n];
        }
      double scale = 1.0;
      for (unsigned int m = 0; m < n_modes; ++m)
        scale = std::max(scale, gram(m, m));

      std::vector<Vector<double>> eigenvectors;
      Vector<double>              eigenvalues;
      FullMatrix<double>          vectors(n_modes, n_modes);
      gram.compute_eigenvalues_symmetric(
        -1.0, 1e-10 * scale, 1e-14 * scale, eigenvalues, vectors);
      FullMatrix<double> basis(n_modes, eigenvalues.size());
      for (unsigned int k = 0; k < eigenvalues.size(); ++k)
        for (unsigned int m = 0; m < n_modes; ++m)
          basis(m, k) = vectors(m, k);
      return basis;
    }

    std::vector<types::global_dof_index>
    minimal_support_dofs(const FullMatrix<double> &free_modes,
                         const FullMatrix<double> &modes_at_dofs,
                         const std::vector<types::global_dof_index> &candidates)
    {
      const unsigned int n_free  = free_modes.n();
      const unsigned int n_modes = free_modes.m();
      // The motion of each candidate dof under each free mode (O(1): the
      // modes are scaled by the block's size).
      std::vector<Vector<double>> rows(candidates.size(),
                                       Vector<double>(n_free));
      for (unsigned int c = 0; c < candidates.size(); ++c)
        for (unsigned int k = 0; k < n_free; ++k)
          for (unsigned int m = 0; m < n_modes; ++m)
            rows[c][k] += modes_at_dofs(candidates[c], m) * free_modes(m, k);

      // Gram-Schmidt with pivoting: each time take the dof whose motion is
      // least explained by those already taken, for a well-conditioned
      // support. (Taking the first acceptable dof in order can leave the
      // last mode with no well independent dof on a coarse mesh.)
      std::vector<types::global_dof_index> support;
      std::vector<bool>                    taken(candidates.size(), false);
      while (support.size() < n_free)
        {
          unsigned int best      = candidates.size();
          double       best_norm = 1e-8;
          for (unsigned int c = 0; c < candidates.size(); ++c)
            if (!taken[c] && rows[c].l2_norm() > best_norm)
              {
                best      = c;
                best_norm = rows[c].l2_norm();
              }
          if (best == candidates.size())
            break; // the candidates cannot hold the block
          taken[best] = true;
          support.push_back(candidates[best]);
          const Vector<double> q = Vector<double>(rows[best]) /= best_norm;
          for (unsigned int c = 0; c < candidates.size(); ++c)
            if (!taken[c])
              rows[c].add(-(rows[c] * q), q);
        }
      return support;
    }

    template Tensor<1, 2>
    rigid_mode(const unsigned int,
               const Point<2> &,
               const Point<2> &,
               const double);
    template Tensor<1, 3>
    rigid_mode(const unsigned int,
               const Point<3> &,
               const Point<3> &,
               const double);
  } // namespace blocks
} // namespace fdem
