// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/safety_factor_iteration.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>

namespace fdem
{
  namespace analyses
  {
    namespace
    {
      /** The force of passive bar @p p (a link of the mixed system) in
       * global coordinates. */
      template <int dim>
      dealii::Tensor<1, dim>
      bar_force(const contact::MixedSystem<dim>    &system,
                const contact::ContactOutcome<dim> &outcome,
                const unsigned int                  p)
      {
        dealii::Tensor<1, dim> local;
        for (unsigned int i = 0; i < dim; ++i)
          local[i] = outcome.solution.forces[dim * p + i];
        return dealii::transpose(system.bar(p).link.frame) * local;
      }

      /** @p direction less its part along @p normal, of unit length (zero
       * if nothing is left). */
      template <int dim>
      dealii::Tensor<1, dim>
      along_plane(const dealii::Tensor<1, dim> &direction,
                  const dealii::Tensor<1, dim> &normal)
      {
        dealii::Tensor<1, dim> t = direction - (direction * normal) * normal;
        const double           length = t.norm();
        return length > 0 ? t / length : dealii::Tensor<1, dim>();
      }

      /**
       * The pairs' relative rigid motion: the relative displacements g of
       * the contact pairs projected, by least squares weighted by the pairs'
       * areas, on the motions that the free rigid modes make at the pairs
       * (the range of W); the projection W gamma' at every pair and passive
       * bar, in the pairs' frames. Empty when no block moves rigidly or
       * nothing moves relative to the blocks' neighbours (every pair sticks:
       * the projection is round-off).
       *
       * Why not W gamma, the solve's own rigid unknowns: gamma is the rigid
       * part of a block's displacement under its support convention (the
       * elastic part is zero at a few dofs chosen by pivoting,
       * blocks/supports.cc), so W gamma carries the elastic displacement of
       * those dofs, and which dofs are chosen depends on the frame and the
       * numbering. The undrained sphere turned by 30 degrees had K* = 1.0306
       * instead of 1.0198 at K = 1 with the same forces and statuses. The
       * projection of g depends only on the relative displacements and on
       * range(W), neither of which depends on the gauge.
       */
      template <int dim>
      dealii::Vector<double>
      relative_rigid_motion(const contact::MixedSystem<dim>    &system,
                            const contact::ContactOutcome<dim> &outcome)
      {
        const dealii::FullMatrix<double> &W = system.rigid_coupling;
        const dealii::Vector<double>     &g =
          outcome.solution.relative_displacements;
        const unsigned int n_rigid = W.n();
        if (n_rigid == 0 || g.size() != W.m())
          return {};
        dealii::LAPACKFullMatrix<double> normal(n_rigid, n_rigid);
        dealii::Vector<double>           rhs(n_rigid);
        std::vector<unsigned int>        columns;
        for (unsigned int p = 0; p < system.n_contact_pairs(); ++p)
          {
            const double area = system.pair(p).area;
            for (unsigned int i = 0; i < dim; ++i)
              {
                const unsigned int row = dim * p + i;
                // A row moves with the modes of the pair's two blocks only.
                columns.clear();
                for (unsigned int a = 0; a < n_rigid; ++a)
                  if (W(row, a) != 0)
                    columns.push_back(a);
                for (const unsigned int a : columns)
                  {
                    rhs[a] += area * W(row, a) * g[row];
                    for (const unsigned int b : columns)
                      normal(a, b) += area * W(row, a) * W(row, b);
                  }
              }
          }
        // Singular values of W^T A W below 1e-12 of the largest are null
        // directions of W on the pairs (modes that move no pair).
        normal.compute_inverse_svd(1e-12);
        dealii::Vector<double> gamma(n_rigid), motion(W.m());
        normal.vmult(gamma, rhs);
        W.vmult(motion, gamma);
        // Every pair sticking leaves g at the solve's round-off of the
        // displacements that cancel in it (g_bar, C f, W gamma); a motion
        // that small is no motion (nor is none, g = 0).
        const double scale =
          std::max({outcome.solution.elastic_displacements.linfty_norm(),
                    outcome.solution.relative_displacements.linfty_norm(),
                    system.external_gap.linfty_norm()});
        if (!(motion.linfty_norm() > 1e-9 * scale))
          return {};
        return motion;
      }

      /**
       * The direction of the tangential part of each pair's relative rigid
       * motion (relative_rigid_motion()), in global coordinates and of unit
       * length; zero for a pair that moves (to 1e-12 of the largest) along
       * its normal only or not at all, and empty when there is no relative
       * rigid motion.
       */
      template <int dim>
      std::vector<dealii::Tensor<1, dim>>
      rigid_sliding_directions(const contact::MixedSystem<dim>    &system,
                               const contact::ContactOutcome<dim> &outcome)
      {
        dealii::Vector<double> motion = relative_rigid_motion(system, outcome);
        if (motion.size() == 0)
          return {};
        // Only directions are wanted: the motion scaled to a largest entry
        // of 1 first, so that the norms below neither underflow (a Young's
        // modulus of 1e200, motions of 1e-200 m) nor overflow (1e-300).
        motion /= motion.linfty_norm();
        std::vector<dealii::Tensor<1, dim>> directions(system.n_pairs());
        double                              largest = 0;
        for (unsigned int p = 0; p < system.n_pairs(); ++p)
          {
            const dealii::Tensor<2, dim> &frame = system.is_bar(p) ?
                                                    system.bar(p).link.frame :
                                                    system.pair(p).frame;
            dealii::Tensor<1, dim>        global;
            for (unsigned int i = 0; i < dim; ++i)
              global += motion[dim * p + i] * frame[i];
            const dealii::Tensor<1, dim> n =
              system.is_bar(p) ? system.bar(p).surface_frame[0] : frame[0];
            directions[p] = global - (global * n) * n;
            largest       = std::max(largest, directions[p].norm());
          }
        if (!(largest > 0))
          return {};
        for (auto &d : directions)
          d = d.norm() > 1e-12 * largest ? d / d.norm() :
                                           dealii::Tensor<1, dim>();
        return directions;
      }

      /**
       * The 3D sliding force: each pair's (and passive bar's) shear summed
       * along a sliding direction on its tangent plane, the larger of two
       * sums: along the shear resultant @p resultant projected on the
       * plane, and along the pair's relative rigid motion (the free rigid
       * modes' motion, rigid_sliding_directions()).
       *
       * In plane strain either is the 2D sum along the surface's tangents;
       * where every shear is along the resultant (a block on a plane, a
       * wedge at its limit), the magnitude of the resultant. The magnitude
       * alone is shorter than the shears along a curved surface (the
       * paper's section extruded: 4 m x 678.82 against 4 m x 710.84 at
       * K = 1), while F_R adds the pairs' capacities: K* > K at every K,
       * and no K was certified. A mass that turns (a sphere, a spheroid
       * about its axis) slips along circles about the axis, which no one
       * direction projected on the planes follows: along the resultant,
       * K* stayed 0.7 % above K where the solves ended (the undrained
       * sphere, doc/verification.md), and along the rigid motion K* = K
       * there. The larger sum keeps a block on a plane exact (its rigid
       * motion also tilts it, so the rigid directions leave the resultant
       * by the tilt: K* was 1.6e-7 off the planar value).
       */
      template <int dim>
      double
      shears_along_sliding_direction(
        const contact::MixedSystem<dim>    &system,
        const contact::ContactOutcome<dim> &outcome,
        const std::vector<bool>            &on_sliding_surface,
        const dealii::Tensor<1, dim>       &resultant)
      {
        if (!outcome.converged())
          return 0;
        const std::vector<dealii::Tensor<1, dim>> rigid =
          rigid_sliding_directions(system, outcome);
        // The shears summed along the resultant's direction and along the
        // rigid motion's (where a pair has none, the resultant's).
        double     along_resultant = 0, along_rigid = 0;
        const auto add = [&](const unsigned int            p,
                             const dealii::Tensor<1, dim> &shear,
                             const dealii::Tensor<1, dim> &n) {
          const double s = shear * along_plane(resultant, n);
          along_resultant += s;
          along_rigid +=
            (!rigid.empty() && rigid[p].norm() > 0) ? shear * rigid[p] : s;
        };
        for (unsigned int p = 0; p < on_sliding_surface.size(); ++p)
          if (on_sliding_surface[p] &&
              outcome.states[p].status != contact::PairStatus::open)
            {
              const auto            &frame = system.pair(p).frame;
              dealii::Tensor<1, dim> shear;
              for (unsigned int i = 1; i < dim; ++i)
                shear += outcome.solution.forces[dim * p + i] * frame[i];
              add(p, shear, frame[0]);
            }
        for (unsigned int p = system.n_contact_pairs(); p < system.n_pairs();
             ++p)
          {
            const dealii::Tensor<1, dim> force = bar_force(system, outcome, p);
            const dealii::Tensor<1, dim> n     = system.bar(p).surface_frame[0];
            add(p, force - (force * n) * n, n);
          }
        return std::max(std::abs(along_resultant), std::abs(along_rigid));
      }
    } // namespace

    template <int dim>
    ReducedStrengthSolution
    resisting_and_sliding_forces(
      const contact::MixedSystem<dim>          &system,
      const contact::ContactOutcome<dim>       &outcome,
      const std::vector<contact::PairStrength> &reduced_strengths,
      const std::vector<bool>                  &on_sliding_surface)
    {
      ReducedStrengthSolution s;
      s.converged            = outcome.converged();
      s.mechanism            = outcome.is_mechanism();
      s.result               = contact::result_description(outcome.result);
      s.n_contact_iterations = outcome.iterations.size();
      double                 sum_f_t = 0;
      dealii::Tensor<1, dim> sum_tangential;
      for (unsigned int p = 0; p < on_sliding_surface.size(); ++p)
        {
          if (!on_sliding_surface[p])
            continue;
          const contact::PairStatus status = outcome.states[p].status;
          s.n_stick += status == contact::PairStatus::stick;
          s.n_slip += status == contact::PairStatus::slip;
          s.n_open += status == contact::PairStatus::open;
          if (!s.converged || status == contact::PairStatus::open)
            continue;
          sum_f_t += outcome.solution.forces[dim * p + 1];
          for (unsigned int i = 1; i < dim; ++i)
            sum_tangential +=
              outcome.solution.forces[dim * p + i] * system.pair(p).frame[i];
          s.resisting_force += reduced_strengths[p].shear_capacity(
            outcome.solution.forces[dim * p]);
        }
      // A passive bar resists along the surface where it crosses it: its
      // force's part along the surface is in F_tau with the pairs', and the
      // same part of the force at which it yields (its capacity as the
      // solve had it, reduced by K or not) in F_R. While the bar is
      // elastic, F_R > F_tau and K* > K; at the fixed point it has yielded
      // (doc/theory.md, "Passive bars").
      bool an_elastic_bar = false;
      if (s.converged)
        for (unsigned int p = system.n_contact_pairs(); p < system.n_pairs();
             ++p)
          {
            an_elastic_bar |=
              outcome.states[p].status == contact::PairStatus::stick;
            const contact::BarLink<dim> &bar   = system.bar(p);
            const dealii::Tensor<1, dim> force = bar_force(system, outcome, p);
            const dealii::Tensor<1, dim> n     = bar.surface_frame[0];
            sum_f_t += bar.surface_frame[1] * force;
            sum_tangential += force - (force * n) * n;
            for (unsigned int i = 0; i < dim; ++i)
              {
                const dealii::Tensor<1, dim> axis = bar.link.frame[i];
                const double                 capacity =
                  i == 0 ? reduced_strengths[p].bar_axial_capacity :
                                           (bar.shear_stiffness > 0 ?
                                              reduced_strengths[p].bar_shear_capacity :
                                              0.0);
                s.resisting_force += capacity * (axis - (axis * n) * n).norm();
              }
          }
      s.sliding_force = dim == 2 ?
                          std::abs(sum_f_t) :
                          shears_along_sliding_direction(system,
                                                         outcome,
                                                         on_sliding_surface,
                                                         sum_tangential);
      // The slip rows fix each |f_t| at its reduced strength exactly, so
      // F_tau = F_R holds to round-off of the solve (1e-13 measured);
      // 1e-10 leaves room and is far below any Safety factor/Tolerance.
      // A bar still elastic has strength left (F_R - F_tau is its unused
      // capacity, computed to round-off of its force): not degenerate,
      // however close to yield.
      //
      // In 3D the shears of slipping pairs add up only where they are
      // parallel, and F_R - F_tau falls off as the square of their angles:
      // a wedge a relative 3e-6 below its limit has F_tau = (1 - 7.5e-11)
      // F_R, so 1e-10 would take it for the limit and bound K 5.5e-6 too
      // low (measured on prm/rock_wedge.prm). There only round-off counts:
      // 1e-12, ten times the solve's.
      s.all_slipping =
        s.converged && s.n_stick == 0 && s.n_slip > 0 && !an_elastic_bar;
      s.degenerate =
        s.all_slipping &&
        s.sliding_force >= (1 - (dim == 2 ? 1e-10 : 1e-12)) * s.resisting_force;
      return s;
    }

    template ReducedStrengthSolution
    resisting_and_sliding_forces(const contact::MixedSystem<2> &,
                                 const contact::ContactOutcome<2> &,
                                 const std::vector<contact::PairStrength> &,
                                 const std::vector<bool> &);
    template ReducedStrengthSolution
    resisting_and_sliding_forces(const contact::MixedSystem<3> &,
                                 const contact::ContactOutcome<3> &,
                                 const std::vector<contact::PairStrength> &,
                                 const std::vector<bool> &);
  } // namespace analyses
} // namespace fdem
