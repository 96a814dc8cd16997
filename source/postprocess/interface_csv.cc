// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// interfaces.csv: the pairs of each interface along the surface, so that a
// plot against the arc length needs no sorting.
#include <fdem/postprocess/interface_csv.h>
#include <fdem/postprocess/output_file.h>

#include <deal.II/base/symmetric_tensor.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <numeric>

namespace fdem
{
  namespace postprocess
  {
    using namespace dealii;

    namespace
    {
      /** 2D: chain from the higher end to the nearest pair not yet taken. */
      template <int dim>
      void
      chain_from_upper_end(const std::vector<PairResult<dim>> &results,
                           const Tensor<1, dim>               &up,
                           SurfaceOrder<dim>                  &surface)
      {
        const unsigned int n = results.size();
        // The ends: the pair farthest from pair 0, and the one farthest from
        // it.
        const unsigned int A = farthest_pair(results, results[0].position);
        const unsigned int B = farthest_pair(results, results[A].position);
        unsigned int       current =
          (results[B].position - results[A].position) * up > 0 ? B : A;
        std::vector<bool> taken(n, false);
        double            s = 0;
        for (unsigned int step = 0; step < n; ++step)
          {
            taken[current] = true;
            surface.order.push_back(current);
            surface.coordinate[current] = s;
            unsigned int next           = n;
            double       distance = std::numeric_limits<double>::infinity();
            for (unsigned int k = 0; k < n; ++k)
              if (!taken[k] && results[k].position.distance(
                                 results[current].position) < distance)
                {
                  distance =
                    results[k].position.distance(results[current].position);
                  next = k;
                }
            if (next == n)
              break;
            s += distance;
            current = next;
          }
      }

      /** 3D: by the distance down the dip of the mean plane. */
      template <int dim>
      void
      sort_down_dip(const std::vector<PairResult<dim>> &results,
                    const Tensor<1, dim>               &up,
                    SurfaceOrder<dim>                  &surface)
      {
        const unsigned int n = results.size();
        Tensor<1, dim>     centre;
        for (const auto &r : results)
          centre += r.position / static_cast<double>(n);
        SymmetricTensor<2, dim> spread;
        for (const auto &r : results)
          spread +=
            symmetrize(outer_product(r.position - centre, r.position - centre));
        // eigenvectors() sorts by decreasing eigenvalue: the last is the
        // normal.
        const auto     axes   = eigenvectors(spread);
        Tensor<1, dim> normal = axes[dim - 1].second;
        Tensor<1, dim> down   = -(up - (up * normal) * normal);
        // A horizontal plane has no dip: its longest axis instead.
        if (down.norm() <= 1e-9 * up.norm())
          down = axes[0].second;
        down /= down.norm();
        double lowest = std::numeric_limits<double>::infinity();
        for (unsigned int k = 0; k < n; ++k)
          {
            surface.coordinate[k] = (results[k].position - centre) * down;
            lowest                = std::min(lowest, surface.coordinate[k]);
          }
        for (double &s : surface.coordinate)
          s -= lowest;
        surface.order.resize(n);
        std::iota(surface.order.begin(), surface.order.end(), 0);
        std::stable_sort(surface.order.begin(),
                         surface.order.end(),
                         [&](auto a, auto b) {
                           return surface.coordinate[a] < surface.coordinate[b];
                         });
      }
    } // namespace

    template <int dim>
    SurfaceOrder<dim>
    surface_order(const std::vector<PairResult<dim>> &results,
                  const Tensor<1, dim>               &up)
    {
      SurfaceOrder<dim> surface;
      surface.coordinate.assign(results.size(), 0.0);
      if (results.empty())
        return surface;
      if constexpr (dim == 2)
        chain_from_upper_end(results, up, surface);
      else
        sort_down_dip(results, up, surface);
      return surface;
    }

    template <int dim>
    void
    write_interface_csv(
      const std::string                               &filename,
      const std::vector<contact::Interface<dim>>      &interfaces,
      const std::vector<std::vector<PairResult<dim>>> &results,
      const Tensor<1, dim>                            &up)
    {
      OutputFile out(filename);
      out
        << "interface,pair," << (dim == 2 ? "arc_length" : "down_dip_distance")
        << ",x,y" << (dim == 3 ? ",z" : "") << ",normal_force,"
        << (dim == 2 ? "tangential_force" :
                       "tangential_force_1,tangential_force_2")
        << ",normal_pressure,shear_stress,gap,slip,status,local_safety_factor,area,"
           "initial_gap,reference_normal_pressure,cohesion,friction_angle\n";
      out << std::setprecision(12);
      for (unsigned int i = 0; i < interfaces.size(); ++i)
        {
          const SurfaceOrder<dim> surface = surface_order(results[i], up);
          for (const unsigned int k : surface.order)
            {
              const PairResult<dim> &r = results[i][k];
              out << '"' << interfaces[i].name << "\"," << k << ','
                  << surface.coordinate[k];
              for (unsigned int d = 0; d < dim; ++d)
                out << ',' << r.position[d];
              out << ',' << r.normal_force;
              for (const double f : r.tangential_force)
                out << ',' << f;
              out << ',' << r.normal_pressure << ',' << r.shear_stress << ','
                  << r.gap << ',' << r.slip << ','
                  << contact::status_name(r.status) << ','
                  << r.local_safety_factor << ',' << r.area << ','
                  << r.initial_gap << ',';
              if (std::isfinite(r.reference_pressure))
                out << r.reference_pressure;
              out << ',' << r.cohesion << ',' << r.friction_angle << '\n';
            }
        }
      out.close();
    }

#define FDEM_INSTANTIATE(dim)                                      \
  template SurfaceOrder<dim> surface_order(                        \
    const std::vector<PairResult<dim>> &, const Tensor<1, dim> &); \
  template void write_interface_csv(                               \
    const std::string &,                                           \
    const std::vector<contact::Interface<dim>> &,                  \
    const std::vector<std::vector<PairResult<dim>>> &,             \
    const Tensor<1, dim> &);
    FDEM_INSTANTIATE(2)
    FDEM_INSTANTIATE(3)
#undef FDEM_INSTANTIATE
  } // namespace postprocess
} // namespace fdem
