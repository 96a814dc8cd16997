// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/blocks/amesos_solver.h>
#include <fdem/blocks/block_factorization.h>
#include <fdem/blocks/cholmod_solver.h>
#include <fdem/blocks/mumps_schur_solver.h>
#include <fdem/blocks/umfpack_solver.h>

#include <deal.II/base/exceptions.h>

namespace fdem
{
  namespace blocks
  {
    Vector<double>
    BlockFactorization::solve(const Vector<double> &b) const
    {
      std::vector<double> x(b.begin(), b.end());
      solve(x, 1);
      return Vector<double>(x.begin(), x.end());
    }

    const std::vector<types::global_dof_index> &
    BlockFactorization::schur_dofs() const
    {
      static const std::vector<types::global_dof_index> none;
      return none;
    }

    std::vector<double>
    BlockFactorization::inverse_on_schur_dofs() const
    {
      Assert(false,
             ExcMessage("This factorisation keeps no Schur complement."));
      return {};
    }

    std::vector<double>
    BlockFactorization::inverse_entries(
      const std::vector<
        std::pair<types::global_dof_index, types::global_dof_index>> &) const
    {
      Assert(false,
             ExcMessage(
               "This factorisation computes no entries of the inverse."));
      return {};
    }

    std::unique_ptr<BlockFactorization>
    make_block_factorization(const parameters::DirectSolverType type,
                             const double block_low_rank_tolerance,
                             const double memory_limit_MiB)
    {
      using parameters::DirectSolverType;
      Assert(block_low_rank_tolerance == 0 ||
               type == DirectSolverType::mumps_schur ||
               type == DirectSolverType::mumps,
             ExcMessage("Only MUMPS has a block low-rank factorisation."));
      switch (type)
        {
          case DirectSolverType::mumps_schur:
            return std::make_unique<MumpsSchurSolver>(
              /*keep_schur_complement=*/true,
              block_low_rank_tolerance,
              memory_limit_MiB);
          case DirectSolverType::mumps:
            return std::make_unique<MumpsSchurSolver>(
              /*keep_schur_complement=*/false,
              block_low_rank_tolerance,
              memory_limit_MiB);
          case DirectSolverType::cholmod:
            return std::make_unique<CholmodSolver>();
          case DirectSolverType::amesos_klu:
          case DirectSolverType::amesos_mumps:
            return std::make_unique<AmesosSolver>(
              parameters::direct_solver_name(type));
          case DirectSolverType::umfpack:
            return std::make_unique<UmfpackSolver>();
        }
      Assert(false, ExcInternalError());
      return nullptr;
    }

    void
    assert_one_rank(const TrilinosWrappers::SparseMatrix &matrix,
                    const parameters::DirectSolverType    type)
    {
      AssertThrow(
        Utilities::MPI::n_mpi_processes(matrix.get_mpi_communicator()) == 1,
        ExcMessage(
          "Solver/Direct solver: " + parameters::direct_solver_name(type) +
          " runs on one MPI rank only; with mpirun use "
          "MUMPS_Schur, MUMPS, Amesos_Mumps or Amesos_Klu."));
    }
  } // namespace blocks
} // namespace fdem
