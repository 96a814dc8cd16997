// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// FETI's Dirichlet preconditioner of the interface flexibility (see the
// header): each block's Schur complement on its interface dofs, applied
// through one more sparse factorisation of the block, that of its stiffness
// with the interface dofs fixed.
#include <fdem/blocks/crs_rows.h>
#include <fdem/contact/dirichlet_preconditioner.h>

#include <deal.II/base/mpi.h>

#include <chrono>
#include <utility>

namespace fdem
{
  namespace contact
  {
    template <int dim>
    DirichletPreconditioner<dim>::DirichletPreconditioner(
      const MixedSystem<dim>            &system,
      const parameters::DirectSolverType solver_type,
      const double                       memory_limit_MiB)
      : system(system)
    {
      const auto start = std::chrono::steady_clock::now();
      const std::vector<typename MixedSystem<dim>::BlockTouch> &touches =
        system.block_touches();
      // The mean diagonal of K at each pair's node on sides I and J, over
      // its unconstrained dofs; -1 where the side holds every direction (a
      // fixed node: infinitely stiff).
      const unsigned int  n_pairs = system.n_pairs();
      std::vector<double> stiffness_I(n_pairs, -1), stiffness_J(n_pairs, -1);
      for (const auto &touch : touches)
        {
          const blocks::ElasticBlock<dim> &block = system.block(touch.block);
          AssertThrow(Utilities::MPI::n_mpi_processes(
                        block.stiffness().get_mpi_communicator()) == 1,
                      ExcMessage(
                        "Solver/Mixed preconditioner = Dirichlet needs one MPI "
                        "rank; with more, use pairs."));
          for (unsigned int k = 0; k < touch.pairs.size(); ++k)
            {
              double       sum = 0;
              unsigned int n   = 0;
              for (unsigned int i = 0; i < dim; ++i)
                {
                  const types::global_dof_index dof = touch.dofs[dim * k + i];
                  if (!block.constraints.is_constrained(dof))
                    {
                      sum += block.stiffness().diag_element(dof);
                      ++n;
                    }
                }
              (touch.signs[k] < 0 ? stiffness_I : stiffness_J)[touch.pairs[k]] =
                n > 0 ? sum / n : -1;
            }
        }

      parts.resize(touches.size());
      for (unsigned int t = 0; t < touches.size(); ++t)
        {
          const auto                      &touch  = touches[t];
          const blocks::ElasticBlock<dim> &block  = system.block(touch.block);
          const TrilinosWrappers::SparseMatrix &K = block.stiffness();
          BlockPart                            &part  = parts[t];
          std::vector<int>                     &index = part.dof_to_interface;
          index.assign(K.m(), -1);
          part.interface_index.assign(touch.dofs.size(), -1);
          for (unsigned int d = 0; d < touch.dofs.size(); ++d)
            {
              const types::global_dof_index dof = touch.dofs[d];
              if (block.constraints.is_constrained(dof))
                continue;
              if (index[dof] < 0)
                {
                  index[dof] = part.interface_dofs.size();
                  part.interface_dofs.push_back(dof);
                }
              part.interface_index[d] = index[dof];
            }
          // D_b = k_other / (k_b + k_other): with S_b = 1/c_b per pair, the
          // sum over both sides is the inverse of c_I + c_J exactly.
          part.weights.resize(touch.pairs.size());
          for (unsigned int k = 0; k < touch.pairs.size(); ++k)
            {
              const unsigned int p   = touch.pairs[k];
              const double       own = touch.signs[k] < 0 ? stiffness_I[p] :
                                                            stiffness_J[p],
                           other     = touch.signs[k] < 0 ? stiffness_J[p] :
                                                            stiffness_I[p];
              part.weights[k]        = own < 0   ? 0.0 :
                                       other < 0 ? 1.0 :
                                                   other / (own + other);
            }

          // K_RR: K with the interface dofs' rows and columns zero but for
          // their diagonal, so that a right-hand side zero on them gives a
          // solution zero on them and K_RR^{-1} elsewhere.
          part.fixed_stiffness.copy_from(K);
          const Epetra_CrsMatrix &crs = K.trilinos_matrix();
          for (const types::global_dof_index dof : part.interface_dofs)
            {
              std::vector<int> columns;
              blocks::for_each_entry_in_row(crs,
                                            crs.LRID(static_cast<int>(dof)),
                                            [&](const int column, double) {
                                              columns.push_back(column);
                                            });
              for (const int column : columns)
                if (column != static_cast<int>(dof))
                  {
                    part.fixed_stiffness.set(dof, column, 0.0);
                    part.fixed_stiffness.set(column, dof, 0.0);
                  }
            }
          part.fixed_stiffness.compress(VectorOperation::insert);
          part.fixed_factorization = blocks::make_block_factorization(
            solver_type == parameters::DirectSolverType::mumps_schur ?
              parameters::DirectSolverType::mumps :
              solver_type,
            /*block_low_rank_tolerance=*/0,
            memory_limit_MiB);
          part.fixed_factorization->factorize(part.fixed_stiffness, {});
        }
      factorization_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    }

    template <int dim>
    DirichletPreconditioner<dim>::~DirichletPreconditioner() = default;

    template <int dim>
    std::vector<Vector<double>>
    DirichletPreconditioner<dim>::schur_products(
      const unsigned int                 t,
      const std::vector<Vector<double>> &values) const
    {
      const BlockPart                      &part = parts[t];
      const TrilinosWrappers::SparseMatrix &K =
        system.block(system.block_touches()[t].block).stiffness();
      const Epetra_CrsMatrix &crs         = K.trilinos_matrix();
      const std::size_t       n           = K.m();
      const unsigned int      n_vectors   = values.size();
      const unsigned int      n_interface = part.interface_dofs.size();
      const std::vector<int> &index       = part.dof_to_interface;

      // K_GG v, and K_RG v as the right-hand side of K_RR (K symmetric: the
      // interface dofs' rows give both).
      std::vector<Vector<double>> products(n_vectors,
                                           Vector<double>(n_interface));
      std::vector<double>         interior(n * n_vectors, 0.0);
      for (unsigned int g = 0; g < n_interface; ++g)
        blocks::for_each_entry_in_row(
          crs,
          crs.LRID(static_cast<int>(part.interface_dofs[g])),
          [&](const int column, const double value) {
            for (unsigned int c = 0; c < n_vectors; ++c)
              if (index[column] >= 0)
                products[c][g] += value * values[c][index[column]];
              else
                interior[column + c * n] += value * values[c][g];
          });
      part.fixed_factorization->solve(interior, n_vectors);
      // S v = K_GG v - K_GR K_RR^{-1} K_RG v.
      for (unsigned int g = 0; g < n_interface; ++g)
        blocks::for_each_entry_in_row(
          crs,
          crs.LRID(static_cast<int>(part.interface_dofs[g])),
          [&](const int column, const double value) {
            if (index[column] < 0)
              for (unsigned int c = 0; c < n_vectors; ++c)
                products[c][g] -= value * interior[column + c * n];
          });
      return products;
    }

    template <int dim>
    std::vector<Vector<double>>
    DirichletPreconditioner<dim>::apply(
      const std::vector<Vector<double>> &displacements) const
    {
      const std::vector<typename MixedSystem<dim>::BlockTouch> &touches =
        system.block_touches();
      const unsigned int          n_vectors = displacements.size();
      std::vector<Vector<double>> forces(n_vectors,
                                         Vector<double>(dim *
                                                        system.n_pairs()));
      for (unsigned int t = 0; t < touches.size(); ++t)
        {
          const auto      &touch = touches[t];
          const BlockPart &part  = parts[t];
          // B_b^T D_b u: the weighted relative displacements as the block's
          // displacements at its interface dofs (sign s_b, global frame).
          std::vector<Vector<double>> values(
            n_vectors, Vector<double>(part.interface_dofs.size()));
          for (unsigned int c = 0; c < n_vectors; ++c)
            for (unsigned int k = 0; k < touch.pairs.size(); ++k)
              {
                const unsigned int p = touch.pairs[k];
                Tensor<1, dim>     u;
                for (unsigned int i = 0; i < dim; ++i)
                  u[i] = displacements[c][dim * p + i];
                const Tensor<1, dim> global =
                  touch.signs[k] * part.weights[k] *
                  (transpose(system.pair(p).frame) * u);
                for (unsigned int i = 0; i < dim; ++i)
                  if (part.interface_index[dim * k + i] >= 0)
                    values[c][part.interface_index[dim * k + i]] += global[i];
              }
          const std::vector<Vector<double>> products =
            schur_products(t, values);
          // D_b B_b S_b v: back to the pairs' frames.
          for (unsigned int c = 0; c < n_vectors; ++c)
            for (unsigned int k = 0; k < touch.pairs.size(); ++k)
              {
                const unsigned int p = touch.pairs[k];
                Tensor<1, dim>     s;
                for (unsigned int i = 0; i < dim; ++i)
                  if (part.interface_index[dim * k + i] >= 0)
                    s[i] = products[c][part.interface_index[dim * k + i]];
                const Tensor<1, dim> local =
                  touch.signs[k] * part.weights[k] * (system.pair(p).frame * s);
                for (unsigned int i = 0; i < dim; ++i)
                  forces[c][dim * p + i] += local[i];
              }
        }
      n_applications += n_vectors;
      return forces;
    }

    template class DirichletPreconditioner<2>;
    template class DirichletPreconditioner<3>;
  } // namespace contact
} // namespace fdem
