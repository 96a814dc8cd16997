// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include "source_dir.h"

#include <fdem/model.h>
#include <fdem/run/case_run.h>

#include <unistd.h>

#include <filesystem>
#include <memory>
#include <sstream>
#include <string>

namespace fdem
{
  namespace test_support
  {
    /**
     * A folder of the temporary directory for output named @p name, unique
     * to this process: ctest runs each test in its own process, several at
     * once, and two tests writing one summary.json collide.
     */
    inline std::string
    test_directory(const std::string &name)
    {
      const auto directory =
        std::filesystem::temp_directory_path() /
        ("fdem-test-" + name + "-" + std::to_string(getpid()));
      std::filesystem::create_directories(directory);
      return directory.string();
    }

    /** Parameters of prm/<name>, writing into a fresh folder of the test's. */
    inline parameters::Parameters
    case_parameters(const std::string &name)
    {
      parameters::Parameters parameters = parameters::read_parameters(
        fdem::test_support::source_dir() + "/prm/" + name);
      parameters.output.directory = test_directory(name);
      parameters.output.write_vtu = false;
      return parameters;
    }

    /** A model up to its mixed system (blocks factorised, C computed), not
     * solved. */
    template <int dim>
    std::unique_ptr<Model<dim>>
    factorised_model(const parameters::Parameters &parameters,
                     std::ostream                 &log)
    {
      auto model = std::make_unique<Model<dim>>(parameters, log);
      model->make_geometry();
      model->setup_blocks();
      model->assemble_and_factorize();
      model->build_interfaces();
      model->compute_flexibility();
      return model;
    }

    /** A model taken through every step of run() up to the contact solve. */
    template <int dim>
    std::unique_ptr<Model<dim>>
    solved_model(const parameters::Parameters &parameters, std::ostream &log)
    {
      auto model = factorised_model<dim>(parameters, log);
      model->solve_contact();
      model->recover_block_displacements();
      return model;
    }
  } // namespace test_support
} // namespace fdem
