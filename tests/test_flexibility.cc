// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The interface flexibility C_b = (K^{-1}) on the pair dofs: the inverse
// Schur complement of MUMPS_Schur, and the blocked solves of MUMPS and
// UMFPACK, against the blocked multi-RHS solves with KLU (the reference
// path), in 2D and 3D, for a floating block (held at its minimal support)
// and a fixed one, with constrained dofs in the list.
#include "test_helpers.h"

#include <deal.II/dofs/dof_tools.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace fdem;

namespace
{
  /**
   * Makes the first unconstrained dof on @p group follow (weight 0.5) an
   * unconstrained dof inside the block, so that a pair dof is constrained
   * with a master off the interface, as a roller or plate would do.
   */
  template <int dim>
  void
  constrain_one_interface_dof(blocks::ElasticBlock<dim>       &block,
                              const dealii::types::boundary_id group)
  {
    const dealii::IndexSet on_interface =
      dealii::DoFTools::extract_boundary_dofs(block.dof_handler,
                                              dealii::ComponentMask(),
                                              {group});
    const dealii::IndexSet on_boundary =
      dealii::DoFTools::extract_boundary_dofs(block.dof_handler);
    dealii::types::global_dof_index slave  = dealii::numbers::invalid_dof_index,
                                    master = dealii::numbers::invalid_dof_index;
    for (const auto dof : on_interface)
      if (!block.constraints.is_constrained(dof))
        {
          slave = dof;
          break;
        }
    for (dealii::types::global_dof_index dof = 0;
         dof < block.dof_handler.n_dofs();
         ++dof)
      if (!on_boundary.is_element(dof) &&
          !block.constraints.is_constrained(dof))
        {
          master = dof;
          break;
        }
    ASSERT_NE(slave, dealii::numbers::invalid_dof_index);
    ASSERT_NE(master, dealii::numbers::invalid_dof_index);
    dealii::AffineConstraints<double> constraints;
    for (const auto &line : block.constraints.get_lines())
      {
        constraints.add_line(line.index);
        constraints.add_entries(line.index, line.entries);
        constraints.set_inhomogeneity(line.index, line.inhomogeneity);
      }
    constraints.add_line(slave);
    constraints.add_entry(slave, master, 0.5);
    constraints.close();
    block.constraints.copy_from(constraints);
  }

  /** A model of @p parameters factorised with @p solver, up to its interfaces.
   */
  template <int dim>
  std::unique_ptr<Model<dim>>
  factorised_model(parameters::Parameters             parameters,
                   const parameters::DirectSolverType solver,
                   const bool                         extra_constraint)
  {
    parameters.solver.direct_solver = solver;
    static std::ostringstream log;
    auto model = std::make_unique<Model<dim>>(parameters, log);
    model->make_geometry();
    model->setup_blocks();
    if (extra_constraint)
      {
        const auto &groups = model->get_mesh().face_group_names;
        const dealii::types::boundary_id group =
          std::find(groups.begin(),
                    groups.end(),
                    parameters.interface_names.at(0)) -
          groups.begin();
        for (auto &block : model->get_blocks())
          constrain_one_interface_dof(*block, group);
      }
    model->assemble_and_factorize();
    model->build_interfaces();
    return model;
  }

  /** max |A - B| / max |B|. */
  double
  relative_difference(const dealii::FullMatrix<double> &A,
                      const dealii::FullMatrix<double> &B)
  {
    double difference = 0, size = 0;
    for (unsigned int i = 0; i < B.m(); ++i)
      for (unsigned int j = 0; j < B.n(); ++j)
        {
          difference = std::max(difference, std::abs(A(i, j) - B(i, j)));
          size       = std::max(size, std::abs(B(i, j)));
        }
    return difference / size;
  }

  /**
   * For every block: the pair dofs, the support dofs and some fixed dofs.
   * The Schur path must take them and agree with KLU's solves; a list
   * with an interior dof falls back to solves with the Schur factors.
   */
  template <int dim>
  void
  check_flexibility(const parameters::Parameters &parameters,
                    const bool                    extra_constraint)
  {
    const auto reference =
      factorised_model<dim>(parameters,
                            parameters::DirectSolverType::amesos_klu,
                            extra_constraint);
    const auto schur =
      factorised_model<dim>(parameters,
                            parameters::DirectSolverType::mumps_schur,
                            extra_constraint);
    const auto mumps =
      factorised_model<dim>(parameters,
                            parameters::DirectSolverType::mumps,
                            extra_constraint);
    const auto umfpack =
      factorised_model<dim>(parameters,
                            parameters::DirectSolverType::umfpack,
                            extra_constraint);
    const auto cholmod =
      factorised_model<dim>(parameters,
                            parameters::DirectSolverType::cholmod,
                            extra_constraint);
    ASSERT_EQ(reference->get_blocks().size(), schur->get_blocks().size());

    unsigned int n_floating = 0, n_constrained_pair_dofs = 0;
    for (unsigned int b = 0; b < reference->get_blocks().size(); ++b)
      {
        const auto &block = *reference->get_blocks()[b];
        n_floating += block.n_free_rigid_modes() > 0;
        std::vector<dealii::types::global_dof_index> dofs;
        for (const auto &interface : reference->get_interfaces())
          for (const auto &pair : interface.pairs)
            {
              if (interface.block_I == b)
                dofs.insert(dofs.end(), pair.dofs_I.begin(), pair.dofs_I.end());
              if (interface.block_J == b)
                dofs.insert(dofs.end(), pair.dofs_J.begin(), pair.dofs_J.end());
            }
        for (const auto dof : dofs)
          n_constrained_pair_dofs += block.constraints.is_constrained(dof);
        dofs.insert(dofs.end(),
                    block.support_dofs.begin(),
                    block.support_dofs.end());
        unsigned int n_fixed = 0;
        for (const auto &line : block.dirichlet_constraints.get_lines())
          if (line.entries.empty() && n_fixed++ < 5)
            dofs.push_back(line.index);

        const dealii::FullMatrix<double> C_reference = block.flexibility(dofs);
        dealii::FullMatrix<double>       C_schur(dofs.size(), dofs.size());
        ASSERT_TRUE(
          schur->get_blocks()[b]->flexibility_from_schur(dofs, C_schur))
          << block.name;
        // Two exact factorisations of the same K (condition ~1e6 here):
        // they agree to round-off times the condition, far below 1e-10.
        EXPECT_LT(relative_difference(C_schur, C_reference), 1e-10)
          << block.name;
        EXPECT_LT(relative_difference(mumps->get_blocks()[b]->flexibility(dofs),
                                      C_reference),
                  1e-10)
          << block.name;
        EXPECT_LT(relative_difference(
                    umfpack->get_blocks()[b]->flexibility(dofs), C_reference),
                  1e-10)
          << block.name;
        EXPECT_LT(relative_difference(
                    cholmod->get_blocks()[b]->flexibility(dofs), C_reference),
                  1e-10)
          << block.name;
        // Constrained dofs: a fixed or support dof has zero flexibility.
        for (unsigned int r = 0; r < dofs.size(); ++r)
          if (block.constraints.is_constrained(dofs[r]) &&
              block.constraints.get_constraint_entries(dofs[r])->empty())
            {
              for (unsigned int c = 0; c < dofs.size(); ++c)
                EXPECT_EQ(C_schur(r, c), 0.0);
            }

        // An interior dof is not in the Schur list (the last one: the
        // first may be the one an interface dof was made to follow): solves
        // with its factors.
        dealii::types::global_dof_index interior =
          block.dof_handler.n_dofs() - 1;
        const dealii::IndexSet on_boundary =
          dealii::DoFTools::extract_boundary_dofs(block.dof_handler);
        while (on_boundary.is_element(interior) ||
               block.constraints.is_constrained(interior))
          --interior;
        dofs.push_back(interior);
        dealii::FullMatrix<double> unused(dofs.size(), dofs.size());
        EXPECT_FALSE(
          schur->get_blocks()[b]->flexibility_from_schur(dofs, unused));
        EXPECT_LT(relative_difference(schur->get_blocks()[b]->flexibility(dofs),
                                      block.flexibility(dofs)),
                  1e-10)
          << block.name;

        // And a full solve through the Schur factors.
        const dealii::Vector<double> u_reference =
          block.solve(block.load_vector);
        dealii::Vector<double> u =
          schur->get_blocks()[b]->solve(block.load_vector);
        u -= u_reference;
        EXPECT_LT(u.linfty_norm(), 1e-10 * u_reference.linfty_norm())
          << block.name;
        u = cholmod->get_blocks()[b]->solve(block.load_vector);
        u -= u_reference;
        EXPECT_LT(u.linfty_norm(), 1e-10 * u_reference.linfty_norm())
          << block.name;
      }
    EXPECT_GT(n_floating, 0u);
    if (extra_constraint)
      {
        EXPECT_GT(n_constrained_pair_dofs, 0u);
      }
  }
} // namespace

TEST(Flexibility, SchurEqualsSolves2D)
{
  check_flexibility<2>(test_support::case_parameters("paper_slope.prm"), false);
}

TEST(Flexibility, SchurEqualsSolves2DConstrainedPairDof)
{
  check_flexibility<2>(test_support::case_parameters("inclined_block.prm"),
                       true);
}

TEST(Flexibility, SchurEqualsSolves3D)
{
  auto parameters = parameters::read_parameters(
    fdem::test_support::source_dir() + "/tests/three_d/block_on_plane_3d.prm");
  parameters.geometry.mesh_file =
    fdem::test_support::source_dir() + "/tests/data/block_on_plane_3d.geo";
  parameters.output.directory = test_support::test_directory("flexibility-3d");
  parameters.output.write_vtu = false;
  check_flexibility<3>(parameters, true);
}

TEST(Flexibility, PaperSlopeSafetyFactorUnchanged)
{
  // The same safety factor with the Schur complement as with KLU's solves:
  // the flexibilities agree to round-off, the iteration is the same.
  double K[2];
  for (const unsigned int s : {0u, 1u})
    {
      auto parameters = test_support::case_parameters("paper_slope.prm");
      parameters.solver.direct_solver =
        s == 0 ? parameters::DirectSolverType::amesos_klu :
                 parameters::DirectSolverType::mumps_schur;
      std::ostringstream log;
      CaseRun<2>         model(parameters, "", log);
      model.run();
      ASSERT_EQ(model.summary()["status"], "completed");
      K[s] = model.summary()["safety_factor"];
    }
  EXPECT_NEAR(K[1], K[0], 1e-10 * K[0]);
}

TEST(Flexibility, DirectSolverNamesAndCapabilities)
{
  // Every .prm string parses to its own type and back; only MUMPS_Schur
  // asks for the interface dofs' Schur complement.
  using parameters::DirectSolverType;
  for (const DirectSolverType type : {DirectSolverType::mumps_schur,
                                      DirectSolverType::mumps,
                                      DirectSolverType::cholmod,
                                      DirectSolverType::amesos_klu,
                                      DirectSolverType::amesos_mumps,
                                      DirectSolverType::umfpack})
    {
      const std::string name = parameters::direct_solver_name(type);
      EXPECT_TRUE(parameters::parse_direct_solver_type(name) == type) << name;
      EXPECT_EQ(
        blocks::make_block_factorization(type)->keeps_schur_complement(),
        type == DirectSolverType::mumps_schur)
        << name;
    }
  EXPECT_EQ(parameters::direct_solver_name(DirectSolverType::mumps_schur),
            "MUMPS_Schur");
  EXPECT_THROW(parameters::parse_direct_solver_type("Amesos_Lapack"),
               dealii::ExceptionBase);
}
