// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The yardstick of benchmarks/flexibility_solvers.py: one linear solve of
// the plain FE model of a case (every block's cells in one mesh, nodes
// shared, gravity loads) with the case's direct solver. Prints one JSON
// line: n_dofs, assembly, factorization, solve (wall seconds).
#include <fdem/linear_algebra/mpi_start.h>
#include <fdem/model.h>
#include <fdem/parameters/parameters.h>

#include <deal.II/base/mpi.h>

#include <chrono>
#include <iostream>

namespace
{
  template <int dim>
  void
  time_fe_solve(const fdem::parameters::Parameters &parameters)
  {
    using namespace fdem;
    std::ostringstream log;
    Model<dim>         model(parameters, log);
    model.make_geometry();

    std::vector<unsigned int>                              all_blocks;
    std::map<unsigned int, parameters::MaterialParameters> materials;
    for (unsigned int b = 0; b < model.get_mesh().block_names.size(); ++b)
      {
        all_blocks.push_back(b);
        materials[b] = parameters.materials.at(model.get_mesh().block_names[b]);
      }
    blocks::ElasticBlock<dim> merged(
      "merged", model.get_mesh(), all_blocks, materials, parameters.fe_degree);
    std::map<dealii::types::boundary_id, parameters::BoundaryParameters>
                conditions;
    const auto &groups = model.get_mesh().face_group_names;
    for (const std::string &name : parameters.boundary_names)
      conditions[std::find(groups.begin(), groups.end(), name) -
                 groups.begin()] = parameters.boundaries.at(name);
    merged.setup_constraints(conditions, {});
    merged.find_free_rigid_modes();
    merged.assemble_and_factorize(parameters.loads,
                                  parameters.solver.direct_solver);
    const auto                   start = std::chrono::steady_clock::now();
    const dealii::Vector<double> u     = merged.solve(merged.load_vector);
    const double                 solve =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    AssertThrow(std::isfinite(u.l2_norm()),
                dealii::ExcMessage("The solve failed."));
    std::cout << "{\"n_dofs\": " << merged.dof_handler.n_dofs()
              << ", \"free_rigid_modes\": " << merged.n_free_rigid_modes()
              << ", \"assembly\": " << merged.assembly_seconds
              << ", \"factorization\": " << merged.factorization_seconds
              << ", \"solve\": " << solve << "}" << std::endl;
  }
} // namespace

int
main(int argc, char *argv[])
{
  try
    {
      fdem::linear_algebra::isolate_mpi_singleton();
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      AssertThrow(argc == 2,
                  dealii::ExcMessage("usage: fdem-fe-solve-time case.prm"));
      const auto parameters = fdem::parameters::read_parameters(argv[1]);
      if (parameters.dimension == 2)
        time_fe_solve<2>(parameters);
      else
        time_fe_solve<3>(parameters);
    }
  catch (const std::exception &error)
    {
      std::cerr << "fdem-fe-solve-time: error: " << error.what() << std::endl;
      return 1;
    }
  return 0;
}
