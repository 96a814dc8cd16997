// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The mixed system in its all-stick form (doc/theory.md):
// free rigid modes, the flexibility C, the reactions of the minimal
// supports, and the oracle "everything sticks = one FE solve of the merged
// mesh".
#include "test_helpers.h"

#include <fdem/blocks/block_materials.h>
#include <fdem/blocks/surface_loads.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <gtest/gtest.h>

#include <iostream>
#include <map>

using namespace fdem;
using dealii::Point;
using dealii::Tensor;
using dealii::Vector;

namespace
{
  std::vector<unsigned int>
  free_modes_of(const std::string &prm)
  {
    std::ostringstream log;
    Model<2>           model(test_support::case_parameters(prm), log);
    model.make_geometry();
    model.setup_blocks();
    std::vector<unsigned int> modes;
    for (const auto &block : model.get_blocks())
      modes.push_back(block->n_free_rigid_modes());
    return modes;
  }

  /**
   * Compares the all-stick mixed solution with one FE solve of the merged
   * mesh: displacements at the interface nodes, and contact forces against
   * the nodal forces that block I's cells exert on block J's.
   */
  /** Interfaces so strong that every pair sticks (formulation Sec. 5). */
  parameters::Parameters
  unbreakable(parameters::Parameters parameters)
  {
    for (auto &[name, interface] : parameters.interfaces)
      {
        interface.cohesion               = 1e12;
        interface.tensile_strength       = 1e12;
        interface.strength_from_material = false;
      }
    return parameters;
  }

  void
  check_stick_equals_monolithic(const parameters::Parameters &input)
  {
    const parameters::Parameters parameters = unbreakable(input);
    std::ostringstream           log;
    const auto model = test_support::solved_model<2>(parameters, log);
    ASSERT_TRUE(model->get_contact_outcome().converged());
    for (const auto &state : model->get_contact_outcome().states)
      ASSERT_EQ(state.status, contact::PairStatus::stick);

    // The merged model: every block's cells in one mesh, nodes shared.
    // Its cells keep their material keys (block and material region).
    std::vector<unsigned int>                              all_blocks;
    std::map<unsigned int, parameters::MaterialParameters> materials;
    for (unsigned int b = 0; b < model->get_blocks().size(); ++b)
      {
        all_blocks.push_back(b);
        materials.merge(
          blocks::block_materials(model->get_mesh(), parameters, b));
      }
    blocks::ElasticBlock<2> merged(
      "merged", model->get_mesh(), all_blocks, materials, parameters.fe_degree);
    merged.water_table = model->get_blocks()[0]->water_table;
    std::map<dealii::types::boundary_id, parameters::BoundaryParameters>
      conditions;
    for (const std::string &name : parameters.boundary_names)
      {
        const auto &groups         = model->get_mesh().face_group_names;
        conditions[std::find(groups.begin(), groups.end(), name) -
                   groups.begin()] = parameters.boundaries.at(name);
      }
    merged.setup_constraints(conditions, {});
    std::map<dealii::types::boundary_id,
             std::shared_ptr<const dealii::Function<2>>>
      pressures, tractions;
    for (const auto &[id, condition] : conditions)
      {
        if (condition.pressure != "0")
          pressures[id] =
            blocks::make_pressure_function<2>(condition.pressure,
                                              parameters.water,
                                              parameters.geometry);
        if (condition.traction != "0")
          tractions[id] = blocks::make_traction_function<2>(condition.traction);
      }
    merged.set_surface_loads(pressures, tractions);
    merged.find_free_rigid_modes();
    ASSERT_EQ(merged.n_free_rigid_modes(), 0u);
    merged.assemble_and_factorize(parameters.loads,
                                  parameters.solver.direct_solver);
    const Vector<double> u = merged.solve(merged.load_vector);

    std::vector<Point<2>> points(merged.dof_handler.n_dofs());
    dealii::DoFTools::map_dofs_to_support_points(merged.mapping,
                                                 merged.dof_handler,
                                                 points);
    const auto merged_dofs_at = [&](const Point<2> &x) {
      std::array<dealii::types::global_dof_index, 2> dofs{};
      unsigned int                                   found = 0;
      for (unsigned int i = 0; i < points.size(); ++i)
        if (points[i].distance(x) < 1e-9 * (1 + x.norm()))
          dofs[found++ % 2] = i;
      EXPECT_EQ(found, 2u);
      // Dofs come in component order at one support point for FESystem.
      if (merged.fe.system_to_component_index(0).first != 0)
        std::swap(dofs[0], dofs[1]);
      return dofs;
    };

    const auto        &interface = model->get_interfaces().at(0);
    const unsigned int J         = interface.block_J;
    // Force of block I on block J at a node of J: K_J u - F_J over J's cells.
    // Summed over J's materials: the residual is additive over cells.
    Vector<double> force_on_J(merged.dof_handler.n_dofs());
    for (const auto &[key, material] : materials)
      if (model->get_mesh().block_of_key(key) == J)
        force_on_J += merged.nodal_residual(u, key);

    double max_u = u.linfty_norm(), max_f = 0, error_u = 0, error_f = 0;
    for (unsigned int k = 0; k < interface.pairs.size(); ++k)
      {
        const auto  &pair = interface.pairs[k];
        const auto   dofs = merged_dofs_at(pair.position_J);
        Tensor<1, 2> local;
        for (unsigned int d = 0; d < 2; ++d)
          local[d] = model->get_contact_outcome().solution.forces[2 * k + d];
        const Tensor<1, 2> f = transpose(pair.frame) * local;
        for (unsigned int d = 0; d < 2; ++d)
          {
            // Both sides of the pair move with the merged node.
            error_u = std::max(
              error_u,
              std::abs(
                model->get_displacements()[interface.block_I][pair.dofs_I[d]] -
                u[dofs[d]]));
            error_u =
              std::max(error_u,
                       std::abs(model->get_displacements()[J][pair.dofs_J[d]] -
                                u[dofs[d]]));
            error_f = std::max(error_f, std::abs(f[d] - force_on_J[dofs[d]]));
            max_f   = std::max(max_f, std::abs(force_on_J[dofs[d]]));
          }
      }
    std::cout << "  max |u| " << max_u << ", difference " << error_u
              << "; max |f| " << max_f << ", difference " << error_f
              << std::endl;
    // Direct solvers throughout: agreement to round-off, far below 1e-8.
    EXPECT_LT(error_u, 1e-8 * max_u) << "max |u| = " << max_u;
    EXPECT_LT(error_f, 1e-8 * max_f) << "max |f| = " << max_f;
    EXPECT_GT(max_f, 0);
  }
} // namespace

TEST(FreeRigidModes, FreeSlidingMassHasThree)
{
  EXPECT_EQ(free_modes_of("paper_slope.prm"),
            (std::vector<unsigned int>{3, 0}));
}

TEST(FreeRigidModes, HalfModelHertzCylinderHasOne)
{
  EXPECT_EQ(free_modes_of("hertz.prm"), (std::vector<unsigned int>{1, 0}));
}

TEST(FreeRigidModes, BlockOnInclinedPlaneHasThree)
{
  EXPECT_EQ(free_modes_of("inclined_block.prm"),
            (std::vector<unsigned int>{3, 0}));
}

TEST(StickEqualsMonolithic, BlockOnInclinedPlane)
{
  check_stick_equals_monolithic(
    test_support::case_parameters("inclined_block.prm"));
}

TEST(StickEqualsMonolithic, BlockOnInclinedPlaneQ2)
{
  auto parameters      = test_support::case_parameters("inclined_block.prm");
  parameters.fe_degree = 2;
  check_stick_equals_monolithic(parameters);
}

TEST(StickEqualsMonolithic, GravityLoadedSlope)
{
  auto parameters = test_support::case_parameters("paper_slope.prm");
  parameters.geometry.slope.mesh_size = 2.0;
  check_stick_equals_monolithic(parameters);
}

// Layers (Geometry/Slope/Layers) across both blocks, of three materials with
// different E, nu and weights, and a water table with saturated weights:
// the merged FE model has the same materials cell by cell.
TEST(StickEqualsMonolithic, LayeredSlopeWithWaterTable)
{
  auto parameters = test_support::case_parameters("layered_slope.prm");
  parameters.geometry.slope.mesh_size = 2.0;
  parameters.fe_degree                = 1;
  // Water in the interface pushes both sides apart, which the merged model
  // has no interface for: here only the weights see the water table.
  parameters.interfaces.at("sliding surface").pore_pressure = "0";
  check_stick_equals_monolithic(parameters);
  parameters.fe_degree = 2;
  check_stick_equals_monolithic(parameters);
}

TEST(Flexibility, IsSymmetricPositiveDefinite)
{
  std::ostringstream log;
  auto parameters = test_support::case_parameters("paper_slope.prm");
  parameters.geometry.slope.mesh_size = 2.0;
  const auto model =
    test_support::solved_model<2>(unbreakable(parameters), log);
  const auto &C         = model->get_mixed_system().flexibility;
  double      max_entry = 0, asymmetry = 0;
  for (unsigned int i = 0; i < C.m(); ++i)
    for (unsigned int j = 0; j < C.n(); ++j)
      {
        max_entry = std::max(max_entry, std::abs(C(i, j)));
        asymmetry = std::max(asymmetry, std::abs(C(i, j) - C(j, i)));
      }
  // K^{-1} of a symmetric K through an LU solver: symmetric to round-off.
  EXPECT_LT(asymmetry, 1e-10 * max_entry);
  dealii::LAPACKFullMatrix<double> symmetric(C.m(), C.n());
  for (unsigned int i = 0; i < C.m(); ++i)
    for (unsigned int j = 0; j < C.n(); ++j)
      symmetric(i, j) = 0.5 * (C(i, j) + C(j, i));
  Vector<double>             eigenvalues;
  dealii::FullMatrix<double> eigenvectors;
  symmetric.compute_eigenvalues_symmetric(
    -1e300, 1e300, 0, eigenvalues, eigenvectors);
  ASSERT_EQ(eigenvalues.size(), C.m());
  const double smallest =
    *std::min_element(eigenvalues.begin(), eigenvalues.end());
  const double largest =
    *std::max_element(eigenvalues.begin(), eigenvalues.end());
  // Positive definite, with a condition number a double can carry.
  EXPECT_GT(smallest, 1e-12 * largest)
    << "smallest " << smallest << ", largest " << largest;
}

TEST(MinimalSupport, ReactionsVanishAtEquilibrium)
{
  for (const std::string prm : {"inclined_block.prm", "paper_slope.prm"})
    {
      std::ostringstream log;
      auto               parameters       = test_support::case_parameters(prm);
      parameters.geometry.slope.mesh_size = 2.0;
      const auto model =
        test_support::solved_model<2>(unbreakable(parameters), log);
      for (unsigned int b = 0; b < model->get_blocks().size(); ++b)
        {
          const auto &block = *model->get_blocks()[b];
          if (block.n_free_rigid_modes() == 0)
            continue;
          EXPECT_EQ(block.support_dofs.size(), block.n_free_rigid_modes());
          const Vector<double> residual =
            block.nodal_residual(model->get_displacements()[b]);
          for (const auto dof : block.support_dofs)
            EXPECT_LT(std::abs(residual[dof]),
                      1e-9 * block.load_vector.l1_norm())
              << prm << ", block " << block.name;
        }
    }
}

TEST(StickEqualsMonolithic, BlockOnInclinedPlaneWithMumps)
{
  auto parameters = test_support::case_parameters("inclined_block.prm");
  parameters.solver.direct_solver = parameters::DirectSolverType::amesos_mumps;
  check_stick_equals_monolithic(parameters);
}
