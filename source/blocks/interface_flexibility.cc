// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The interface flexibility of an ElasticBlock: C = P K^{-1} P^T on the
// pair dofs, from the inverse Schur complement of MUMPS_Schur, from
// MUMPS's selected entries of K^{-1}, or from blocked solves
// (doc/theory.md, "What each block contributes").
#include <fdem/blocks/elastic_block.h>

#include <deal.II/dofs/dof_tools.h>

#include <algorithm>
#include <map>
#include <set>

namespace fdem
{
  namespace blocks
  {
    template <int dim>
    std::vector<types::global_dof_index>
    ElasticBlock<dim>::interface_schur_dofs() const
    {
      if (interface_ids.empty())
        return {};
      const std::set<types::boundary_id> interfaces(interface_ids.begin(),
                                                    interface_ids.end());
      const IndexSet                     on_interface =
        DoFTools::extract_boundary_dofs(dof_handler,
                                        ComponentMask(),
                                        interfaces);
      std::set<types::global_dof_index> schur;
      for (const types::global_dof_index dof : on_interface)
        if (!constraints.is_constrained(dof))
          schur.insert(dof);
        else
          for (const auto &[master, weight] :
               *constraints.get_constraint_entries(dof))
            schur.insert(master);
      return {schur.begin(), schur.end()};
    }

    template <int dim>
    bool
    ElasticBlock<dim>::flexibility_from_schur(
      const std::vector<types::global_dof_index> &dofs,
      FullMatrix<double>                         &C) const
    {
      const std::vector<types::global_dof_index> &schur =
        factorization->schur_dofs();
      if (schur.empty())
        return false;
      // Row r of the constraint map P (u = P u_free): the unconstrained
      // dofs dof r follows, as positions in the Schur list, with weights.
      std::vector<std::vector<std::pair<unsigned int, double>>> rows(
        dofs.size());
      for (unsigned int r = 0; r < dofs.size(); ++r)
        {
          const auto entry = [&](const types::global_dof_index dof,
                                 const double                  w) {
            const auto it = std::lower_bound(schur.begin(), schur.end(), dof);
            if (it == schur.end() || *it != dof)
              return false;
            rows[r].emplace_back(it - schur.begin(), w);
            return true;
          };
          if (!constraints.is_constrained(dofs[r]))
            {
              if (!entry(dofs[r], 1.0))
                return false;
            }
          else
            for (const auto &[master, weight] :
                 *constraints.get_constraint_entries(dofs[r]))
              if (!entry(master, weight))
                return false;
        }
      // C = P (K^{-1})_SS P^T; a fixed dof has an empty row, so zero.
      const std::vector<double> inverse =
        factorization->inverse_on_schur_dofs();
      const std::size_t n_s = schur.size();
      for (unsigned int r = 0; r < dofs.size(); ++r)
        for (unsigned int c = 0; c < dofs.size(); ++c)
          {
            double value = 0;
            for (const auto &[i, wi] : rows[r])
              for (const auto &[j, wj] : rows[c])
                value += wi * wj * inverse[i + j * n_s];
            C(r, c) = value;
          }
      return true;
    }

    template <int dim>
    FullMatrix<double>
    ElasticBlock<dim>::flexibility(
      const std::vector<types::global_dof_index> &dofs) const
    {
      const unsigned int n = dofs.size();
      FullMatrix<double> C(n, n);
      if (flexibility_from_schur(dofs, C))
        return C;
      // Unit loads on the dofs, column c of C the displacements of load c.
      solve_blocked(
        n,
        [&](const unsigned int c, Vector<double> &f) { f[dofs[c]] = 1; },
        [&](const unsigned int c, const Vector<double> &u) {
          for (unsigned int r = 0; r < n; ++r)
            C(r, c) = u[dofs[r]];
        });
      return C;
    }

    template <int dim>
    std::vector<FullMatrix<double>>
    ElasticBlock<dim>::flexibility_diagonal_blocks(
      const std::vector<std::array<types::global_dof_index, dim>> &nodes) const
    {
      std::vector<FullMatrix<double>> blocks(nodes.size(),
                                             FullMatrix<double>(dim, dim));
      // Without MUMPS's entries of K^{-1}: the columns of the nodes' dofs
      // are solved in blocks of right-hand sides, whole nodes per pass (63
      // columns in 3D), and only their own blocks kept.
      if (!factorization->computes_inverse_entries())
        {
          solve_blocked(
            dim * nodes.size(),
            [&](const unsigned int c, Vector<double> &f) {
              f[nodes[c / dim][c % dim]] = 1;
            },
            [&](const unsigned int c, const Vector<double> &u) {
              for (unsigned int i = 0; i < dim; ++i)
                blocks[c / dim](i, c % dim) = u[nodes[c / dim][i]];
            },
            dim * (max_rhs_per_solve / dim));
          return blocks;
        }
      // C = P K^{-1} P^T with P the constraints (u = P u_free, a fixed dof
      // has an empty row): the entries of K^{-1} between the dofs that a
      // node's dofs follow, each asked for once.
      using Weights = std::vector<std::pair<types::global_dof_index, double>>;
      const auto follows = [&](const types::global_dof_index dof) {
        if (!constraints.is_constrained(dof))
          return Weights{{dof, 1.0}};
        return Weights(constraints.get_constraint_entries(dof)->begin(),
                       constraints.get_constraint_entries(dof)->end());
      };
      std::map<std::pair<types::global_dof_index, types::global_dof_index>,
               std::size_t>
        entry_index;
      std::vector<std::pair<types::global_dof_index, types::global_dof_index>>
                                            entries;
      std::vector<std::array<Weights, dim>> weights(nodes.size());
      for (unsigned int k = 0; k < nodes.size(); ++k)
        for (unsigned int i = 0; i < dim; ++i)
          weights[k][i] = follows(nodes[k][i]);
      for (unsigned int k = 0; k < nodes.size(); ++k)
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            for (const auto &[a, wa] : weights[k][i])
              for (const auto &[b, wb] : weights[k][j])
                if (entry_index.emplace(std::make_pair(a, b), entries.size())
                      .second)
                  entries.emplace_back(a, b);
      const std::vector<double> values =
        factorization->inverse_entries(entries);
      for (unsigned int k = 0; k < nodes.size(); ++k)
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            for (const auto &[a, wa] : weights[k][i])
              for (const auto &[b, wb] : weights[k][j])
                blocks[k](i, j) += wa * wb * values[entry_index.at({a, b})];
      return blocks;
    }

    template FullMatrix<double>
    ElasticBlock<2>::flexibility(
      const std::vector<types::global_dof_index> &) const;
    template std::vector<FullMatrix<double>>
    ElasticBlock<2>::flexibility_diagonal_blocks(
      const std::vector<std::array<types::global_dof_index, 2>> &) const;
    template bool
    ElasticBlock<2>::flexibility_from_schur(
      const std::vector<types::global_dof_index> &,
      FullMatrix<double> &) const;
    template std::vector<types::global_dof_index>
    ElasticBlock<2>::interface_schur_dofs() const;
    template FullMatrix<double>
    ElasticBlock<3>::flexibility(
      const std::vector<types::global_dof_index> &) const;
    template std::vector<FullMatrix<double>>
    ElasticBlock<3>::flexibility_diagonal_blocks(
      const std::vector<std::array<types::global_dof_index, 3>> &) const;
    template bool
    ElasticBlock<3>::flexibility_from_schur(
      const std::vector<types::global_dof_index> &,
      FullMatrix<double> &) const;
    template std::vector<types::global_dof_index>
    ElasticBlock<3>::interface_schur_dofs() const;
  } // namespace blocks
} // namespace fdem
