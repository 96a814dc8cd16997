// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/postprocess/interface_output.h>
#include <fdem/postprocess/output_files.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <numeric>

namespace fdem
{
  namespace postprocess
  {
    using namespace dealii;

    template <int dim>
    std::vector<PairResult<dim>>
    pair_results(const contact::Interface<dim>              &interface,
                 const unsigned int                          first_pair,
                 const contact::ContactSolution             &solution,
                 const std::vector<contact::PairState<dim>> &states,
                 const std::vector<contact::PairStrength>   &full_strengths)
    {
      std::vector<PairResult<dim>> results;
      for (unsigned int k = 0; k < interface.pairs.size(); ++k)
        {
          const contact::NodePair<dim> &pair = interface.pairs[k];
          const unsigned int            p    = first_pair + k;
          PairResult<dim>               r;
          r.position     = pair.position_J;
          r.normal_force = solution.forces[dim * p];
          for (unsigned int i = 0; i + 1 < dim; ++i)
            r.tangential_force[i] = solution.forces[dim * p + 1 + i];
          std::array<double, dim> g;
          for (unsigned int i = 0; i < dim; ++i)
            g[i] = solution.relative_displacements[dim * p + i];
          AssertThrow(
            std::isfinite(g[0]) && std::isfinite(g[1]) &&
              std::isfinite(g[dim - 1]),
            ExcMessage(
              "Interfaces/" + interface.name +
              ": the relative displacements exceed the range of a double "
              "(above 1e308): the Young's moduli are too small for the loads; "
              "give the moduli and the loads in one set of units."));
          // hypot, not the root of a sum of squares, which underflows or
          // overflows at the extremes of the Young's modulus.
          const double shear =
            dim == 2 ?
              std::abs(r.tangential_force[0]) :
              std::hypot(r.tangential_force[0], r.tangential_force[dim - 2]);
          r.normal_pressure = -r.normal_force / pair.area;
          r.shear_stress    = shear / pair.area;
          r.gap             = g[0];
          r.slip            = dim == 2 ? g[1] : std::hypot(g[1], g[dim - 1]);
          r.status          = states[p].status;
          if (r.status != contact::PairStatus::open)
            {
              const double strength =
                full_strengths[p].shear_capacity(r.normal_force);
              r.local_safety_factor =
                std::max(0.0,
                         shear * 1000 > strength ? strength / shear : 1000.0);
            }
          r.area           = pair.area;
          r.initial_gap    = pair.initial_gap;
          r.cohesion       = full_strengths[p].cohesion_force / pair.area;
          r.friction_angle = std::atan(full_strengths[p].friction_coefficient) *
                             180 / numbers::PI;
          results.push_back(r);
        }
      return results;
    }

    namespace
    {
      /**
       * Where q^2, fitted by c0 + c1 t + c2 t^2 over the points (t_i, q_i)
       * (t measured from the last closed pair towards the open one, which is
       * at t = gap), reaches zero: the root nearest t = 0 within
       * [-spacing, gap], where spacing is the distance to the previous closed
       * pair (the last closed pair may lie just beyond the true edge and
       * carry a small force); gap/2 if there is none.
       */
      double
      edge_of_pressure_profile(std::vector<double> t,
                               std::vector<double> q,
                               const double        gap)
      {
        const unsigned int n = t.size();
        // Order by t: the end pair (t = 0) last.
        std::vector<unsigned int> order(n);
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [&](auto a, auto b) {
          return t[a] < t[b];
        });
        const std::vector<double> t_in = t, q_in = q;
        for (unsigned int i = 0; i < n; ++i)
          {
            t[i] = t_in[order[i]];
            q[i] = q_in[order[i]];
          }
        if (n < 3)
          {
            if (n == 2 && q[0] > q[1])
              {
                // Linear extrapolation of q^2 from the last two pairs.
                const double q0 = q[1] * q[1], q1 = q[0] * q[0];
                const double root = -q0 * (t[0] - t[1]) / (q1 - q0);
                if (root >= t[0] && root <= gap)
                  return root;
              }
            return 0.5 * gap;
          }
        // Least squares by the normal equations (3 x 3), scaled by the gap.
        FullMatrix<double> normal(3, 3);
        Vector<double>     rhs(3), c(3);
        for (unsigned int i = 0; i < n; ++i)
          {
            const double x = t[i] / gap, y = q[i] * q[i];
            const double basis[3] = {1, x, x * x};
            for (unsigned int a = 0; a < 3; ++a)
              {
                rhs[a] += basis[a] * y;
                for (unsigned int b = 0; b < 3; ++b)
                  normal(a, b) += basis[a] * basis[b];
              }
          }
        normal.gauss_jordan();
        normal.vmult(c, rhs);
        // The smallest root in [0, 1] of c0 + c1 x + c2 x^2.
        std::vector<double> roots;
        if (std::abs(c[2]) < 1e-14 * (std::abs(c[0]) + std::abs(c[1])))
          roots.push_back(-c[0] / c[1]);
        else
          {
            const double discriminant = c[1] * c[1] - 4 * c[2] * c[0];
            if (discriminant >= 0)
              for (const double sign : {-1.0, 1.0})
                roots.push_back((-c[1] + sign * std::sqrt(discriminant)) /
                                (2 * c[2]));
          }
        const double lower = t[n - 2] / gap; // the previous pair, < 0
        double       best  = 0.5;
        bool         found = false;
        for (const double x : roots)
          if (std::isfinite(x) && x >= lower && x <= 1 &&
              (!found || std::abs(x) < std::abs(best)))
            {
              best  = x;
              found = true;
            }
        return best * gap;
      }
    } // namespace

    template <int dim>
    double
    contact_extent(const std::vector<PairResult<dim>> &results)
    {
      if constexpr (dim == 3)
        {
          double area = 0;
          for (const auto &r : results)
            area += (r.status != contact::PairStatus::open) ? r.area : 0;
          return area;
        }
      const unsigned int n = results.size();
      if (n == 0)
        return 0;
      // The chord: from the pair farthest from pair 0 to the one farthest from
      // it.
      const unsigned int A = farthest_pair(results, results[0].position);
      const unsigned int B = farthest_pair(results, results[A].position);
      Tensor<1, dim>     e = results[B].position - results[A].position;
      if (e.norm() > 0)
        e /= e.norm();
      std::vector<unsigned int> order(n);
      std::iota(order.begin(), order.end(), 0);
      std::vector<double> s(n);
      for (unsigned int k = 0; k < n; ++k)
        s[k] = (results[k].position - results[A].position) * e;
      std::sort(order.begin(), order.end(), [&](auto a, auto b) {
        return s[a] < s[b];
      });
      const auto closed = [&](const unsigned int i) {
        return results[order[i]].status != contact::PairStatus::open;
      };
      const auto pressure = [&](const unsigned int i) {
        return std::max(results[order[i]].normal_pressure, 0.0);
      };

      double extent = 0;
      for (unsigned int i = 0; i < n;)
        {
          if (!closed(i))
            {
              ++i;
              continue;
            }
          unsigned int j = i;
          while (j + 1 < n && closed(j + 1))
            ++j;
          const double s_first = s[order[i]], s_last = s[order[j]];
          const double half = 0.5 * (s_last - s_first);
          double       left = s_first, right = s_last;
          // Edge towards an open neighbour, from the outer half of the run.
          const auto edge =
            [&](const unsigned int end, const int step, const double s_open) {
              std::vector<double> t, q;
              for (unsigned int k = i; k <= j; ++k)
                {
                  const double distance = std::abs(s[order[k]] - s[order[end]]);
                  if (distance <= half + 1e-12 * (1 + half))
                    {
                      // t from the end pair towards the open one: <= 0 inside.
                      t.push_back(step * (s[order[k]] - s[order[end]]));
                      q.push_back(pressure(k));
                    }
                }
              return s[order[end]] +
                     step * edge_of_pressure_profile(
                              t, q, std::abs(s_open - s[order[end]]));
            };
          if (i > 0)
            left = edge(i, -1, s[order[i - 1]]);
          if (j + 1 < n)
            right = edge(j, +1, s[order[j + 1]]);
          extent += right - left;
          i = j + 1;
        }
      return extent;
    }

    template <int dim>
    unsigned int
    farthest_pair(const std::vector<PairResult<dim>> &results,
                  const Point<dim>                   &x)
    {
      unsigned int best = 0;
      for (unsigned int k = 1; k < results.size(); ++k)
        if (results[k].position.distance(x) >
            results[best].position.distance(x))
          best = k;
      return best;
    }

#define FDEM_INSTANTIATE(dim)                                                 \
  template double       contact_extent(const std::vector<PairResult<dim>> &); \
  template unsigned int farthest_pair(const std::vector<PairResult<dim>> &,   \
                                      const Point<dim> &);                    \
  template std::vector<PairResult<dim>> pair_results(                         \
    const contact::Interface<dim> &,                                          \
    const unsigned int,                                                       \
    const contact::ContactSolution &,                                         \
    const std::vector<contact::PairState<dim>> &,                             \
    const std::vector<contact::PairStrength> &);
    FDEM_INSTANTIATE(2)
    FDEM_INSTANTIATE(3)
#undef FDEM_INSTANTIATE
  } // namespace postprocess
} // namespace fdem
