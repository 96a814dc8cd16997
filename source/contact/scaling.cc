// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/contact/scaling.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace fdem
{
  namespace contact
  {
    namespace
    {
      /**
       * The singular values (largest first) of the tall m x n matrix @p a
       * (by columns; m >= n): Householder QR, then the SVD of the n x n
       * triangle R, whose singular values are those of a. With @p vt, also
       * V^T of R = U S V^T (a^T = V S U^T Q^T: its range is spanned by V).
       */
      std::vector<double>
      tall_singular_values(std::vector<double> a,
                           const unsigned int  m,
                           const unsigned int  n,
                           FullMatrix<double> *vt = nullptr)
      {
        Assert(m >= n && a.size() == std::size_t(m) * n, ExcInternalError());
        std::vector<double> sigma(n, 0.0);
        if (n == 0)
          return sigma;
        // LAPACK through deal.II's wrappers (lapack_templates.h), which
        // know the BLAS integer type of the library deal.II was built with.
        const types::blas_int rows = m, columns = n;
        types::blas_int       info = 0, lwork = -1;
        std::vector<double>   tau(n);
        double                size = 0;
        geqrf(
          &rows, &columns, a.data(), &rows, tau.data(), &size, &lwork, &info);
        lwork =
          std::max<types::blas_int>(1, static_cast<types::blas_int>(size));
        std::vector<double> work(lwork);
        geqrf(&rows,
              &columns,
              a.data(),
              &rows,
              tau.data(),
              work.data(),
              &lwork,
              &info);
        AssertThrow(info == 0, ExcInternalError());
        LAPACKFullMatrix<double> R(n, n);
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i <= j; ++i)
            R(i, j) = a[std::size_t(j) * m + i];
        R.compute_svd();
        for (unsigned int i = 0; i < n; ++i)
          sigma[i] = R.singular_value(i);
        if (vt != nullptr)
          {
            const LAPACKFullMatrix<double> &V_T = R.get_svd_vt();
            vt->reinit(n, n);
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                (*vt)(i, j) = V_T(i, j);
          }
        return sigma;
      }

      /** sigma_min / sigma_max, 0 for a zero matrix. */
      double
      ratio(const std::vector<double> &sigma)
      {
        if (sigma.empty())
          return 1;
        return sigma.front() > 0 ? sigma.back() / sigma.front() : 0.0;
      }

      /**
       * The forces a pair can still take under its pure force rows
       * @p h f = @p v (dimensionless, at most dim of them): an orthonormal
       * basis of their null space, and the least-norm solution f_0.
       */
      template <int dim>
      void
      admissible_forces(const std::vector<Tensor<1, dim>> &h,
                        const std::vector<double>         &v,
                        std::vector<Tensor<1, dim>>       &basis,
                        Tensor<1, dim>                    &f_0)
      {
        // Gram-Schmidt on the rows, keeping the combination that maps v:
        // q_k = (h_k - sum_{l<k} (h_k . q_l) q_l) / |.|, and w_k the value of
        // q_k . f_0, so that f_0 = sum_k w_k q_k.
        // At most dim of each (no allocation: called for every pair of
        // every solve).
        std::array<Tensor<1, dim>, dim> q;
        std::array<double, dim>         w;
        unsigned int                    n_q = 0;
        for (unsigned int k = 0; k < h.size(); ++k)
          {
            Tensor<1, dim> r     = h[k];
            double         value = v[k];
            for (unsigned int l = 0; l < n_q; ++l)
              {
                const double c = r * q[l];
                r -= c * q[l];
                value -= c * w[l];
              }
            const double norm = r.norm();
            // Rows are scaled to a largest coefficient of 1: a remainder
            // this small is a row that repeats the others.
            if (norm > 1e-10 * h[k].norm())
              {
                q[n_q] = r / norm;
                w[n_q] = value / norm;
                ++n_q;
              }
          }
        f_0 = Tensor<1, dim>();
        for (unsigned int l = 0; l < n_q; ++l)
          f_0 += w[l] * q[l];
        // The complement: the unit vectors with the largest remainders.
        basis.clear();
        while (n_q < dim)
          {
            Tensor<1, dim> best;
            double         best_norm = 0;
            for (unsigned int i = 0; i < dim; ++i)
              {
                Tensor<1, dim> r;
                r[i] = 1;
                for (unsigned int l = 0; l < n_q; ++l)
                  r -= (r * q[l]) * q[l];
                if (r.norm() > best_norm)
                  {
                    best      = r;
                    best_norm = r.norm();
                  }
              }
            q[n_q] = best / best_norm;
            basis.push_back(q[n_q]);
            ++n_q;
          }
      }
    } // namespace

    template <int dim>
    Tensor<1, dim>
    row_magnitudes(const PairRows<dim> &rows, const SystemScales &scales)
    {
      Tensor<1, dim> rho;
      for (unsigned int i = 0; i < dim; ++i)
        {
          double largest = 0;
          for (unsigned int k = 0; k < dim; ++k)
            largest = std::max({largest,
                                std::abs(rows.gap[i][k]) * scales.displacement,
                                std::abs(rows.force[i][k]) * scales.force});
          rho[i] = largest > 0 ? largest : 1.0;
        }
      return rho;
    }

    template <int dim>
    RigidModeTest
    rigid_mode_test(const FullMatrix<double>         &rigid_coupling,
                    const Vector<double>             &rigid_loads,
                    const std::vector<PairRows<dim>> &rows,
                    const SystemScales               &scales,
                    const double                      tolerance)
    {
      RigidModeTest      test;
      const unsigned int n_rigid = rigid_loads.size();
      test.n_rigid               = n_rigid;
      if (n_rigid == 0)
        return test;
      AssertDimension(scales.rigid.size(), n_rigid);

      // Dimensionless: W~ = W / w_m by columns; the load of mode m over
      // w_m F_0; rows over their magnitudes.
      const auto W = [&](const unsigned int j, const unsigned int m) {
        return rigid_coupling(j, m) / scales.rigid[m];
      };
      Vector<double> load(n_rigid);
      for (unsigned int m = 0; m < n_rigid; ++m)
        load[m] = rigid_loads[m] / (scales.rigid[m] * scales.force);

      // Columns of E (stored as rows of E^T) and rows of K, n_rigid numbers
      // each, one after the other (one array each: a solve makes this test,
      // and an allocation per row was a measurable part of it).
      std::vector<double>         E_columns, K_rows;
      Vector<double>              fixed(n_rigid); // W~^T f_0 of all pairs
      std::vector<Tensor<1, dim>> h, basis;
      std::vector<double>         v;
      E_columns.reserve(std::size_t(dim) * rows.size() * n_rigid);
      K_rows.reserve(std::size_t(dim) * rows.size() * n_rigid);
      for (unsigned int p = 0; p < rows.size(); ++p)
        {
          const Tensor<1, dim> rho = row_magnitudes(rows[p], scales);
          h.clear();
          v.clear();
          for (unsigned int i = 0; i < dim; ++i)
            {
              Tensor<1, dim> g, f;
              for (unsigned int k = 0; k < dim; ++k)
                {
                  g[k] = rows[p].gap[i][k] * scales.displacement / rho[i];
                  f[k] = rows[p].force[i][k] * scales.force / rho[i];
                }
              if (!rows[p].is_gap_row(i))
                {
                  // A force row: it fixes a combination of the pair's forces.
                  h.push_back(f);
                  v.push_back(rows[p].value[i] / rho[i]);
                }
              else
                {
                  // A row on the gap: it resists the rigid motion g . W gamma.
                  for (unsigned int m = 0; m < n_rigid; ++m)
                    {
                      double entry = 0.0;
                      for (unsigned int k = 0; k < dim; ++k)
                        entry += g[k] * W(dim * p + k, m);
                      K_rows.push_back(entry);
                    }
                }
            }
          Tensor<1, dim> f_0;
          admissible_forces<dim>(h, v, basis, f_0);
          for (unsigned int m = 0; m < n_rigid; ++m)
            for (unsigned int k = 0; k < dim; ++k)
              fixed[m] += W(dim * p + k, m) * f_0[k];
          for (const Tensor<1, dim> &direction : basis)
            {
              for (unsigned int m = 0; m < n_rigid; ++m)
                {
                  double entry = 0.0;
                  for (unsigned int k = 0; k < dim; ++k)
                    entry += W(dim * p + k, m) * direction[k];
                  E_columns.push_back(entry);
                }
            }
        }

      // A tall matrix by columns from a list of its rows, padded with zero
      // rows up to n_rigid (that changes neither rank nor range).
      const auto by_columns = [n_rigid](const std::vector<double> &list,
                                        unsigned int              &m) {
        const unsigned int n_rows = list.size() / n_rigid;
        m                         = std::max<unsigned int>(n_rows, n_rigid);
        std::vector<double> a(std::size_t(m) * n_rigid, 0.0);
        for (unsigned int i = 0; i < n_rows; ++i)
          for (unsigned int j = 0; j < n_rigid; ++j)
            a[std::size_t(j) * m + i] = list[std::size_t(i) * n_rigid + j];
        return a;
      };
      unsigned int              m_E = 0, m_K = 0;
      FullMatrix<double>        V_T;
      std::vector<double>       E_T = by_columns(E_columns, m_E);
      std::vector<double>       K   = by_columns(K_rows, m_K);
      const std::vector<double> sigma_E =
        tall_singular_values(std::move(E_T), m_E, n_rigid, &V_T);
      const std::vector<double> sigma_K =
        tall_singular_values(std::move(K), m_K, n_rigid);
      test.equilibrium_ratio = ratio(sigma_E);
      test.kinematic_ratio   = ratio(sigma_K);
      test.holds =
        test.equilibrium_ratio > tolerance && test.kinematic_ratio > tolerance;

      if (test.equilibrium_ratio <= tolerance)
        {
          // The load the free directions must carry, b = load - W~^T f_0,
          // less its part in the range of E (spanned by the rows of V^T
          // with singular values above the tolerance).
          Vector<double> b = load;
          b -= fixed;
          Vector<double> outside = b;
          for (unsigned int i = 0; i < n_rigid; ++i)
            if (sigma_E[i] > tolerance * sigma_E.front())
              {
                double c = 0;
                for (unsigned int j = 0; j < n_rigid; ++j)
                  c += V_T(i, j) * b[j];
                for (unsigned int j = 0; j < n_rigid; ++j)
                  outside[j] -= c * V_T(i, j);
              }
          const double size    = std::max(load.l2_norm(), fixed.l2_norm());
          test.unbalanced_load = size > 0 ? outside.l2_norm() / size : 0.0;
        }
      return test;
    }

    template Tensor<1, 2>
    row_magnitudes(const PairRows<2> &, const SystemScales &);
    template Tensor<1, 3>
    row_magnitudes(const PairRows<3> &, const SystemScales &);
    template RigidModeTest
    rigid_mode_test(const FullMatrix<double> &,
                    const Vector<double> &,
                    const std::vector<PairRows<2>> &,
                    const SystemScales &,
                    const double);
    template RigidModeTest
    rigid_mode_test(const FullMatrix<double> &,
                    const Vector<double> &,
                    const std::vector<PairRows<3>> &,
                    const SystemScales &,
                    const double);
  } // namespace contact
} // namespace fdem
