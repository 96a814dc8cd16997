// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/linear_algebra/blas_threads.h>
#include <fdem/linear_algebra/mpi_start.h>
#include <fdem/parameters/parameters.h>
#include <fdem/postprocess/result_block.h>
#include <fdem/postprocess/results_folder.h>
#include <fdem/postprocess/run_log.h>
#include <fdem/run/case_run.h>

#include <deal.II/base/mpi.h>

#include <iostream>
#include <new>
#include <string>

namespace
{
  const char *usage =
    "Usage: fdem-slope [--help] [--print-parameters] [--validate]\n"
    "                  [--quiet | --verbose] [--no-report] case.prm\n"
    "  Computes contact forces and the safety factor of a slope with a known\n"
    "  sliding surface by the mixed FEM-DEM method (Liu et al. 2012).\n"
    "  The screen shows the case, the model, one line per safety-factor step\n"
    "  and the result; the results folder's log.txt has the full log.\n"
    "  --verbose           the full log on the screen too (contact\n"
    "                      iterations, solver notes, time and memory)\n"
    "  --quiet             for scripts: on success only K (17 digits) on\n"
    "                      stdout, nothing when no K is computed; errors\n"
    "                      stay one line on stderr\n"
    "  --no-report         no report.html, whatever Output/Report says\n"
    "                      (the run's other files are the same)\n"
    "  --print-parameters  print every parameter (for case.prm, or the\n"
    "                      default case) with its default and help text\n"
    "  --validate          read and check case.prm and the model's layout\n"
    "                      (mesh, blocks, node pairs), then stop\n"
    "  --help              this text\n";
} // namespace

int
main(int argc, char *argv[])
{
  // Under mpirun only rank 0 prints (every rank runs the same case and
  // meets the same errors).
  bool host = true;
  std::set_new_handler(fdem::postprocess::exit_out_of_memory);
  try
    {
      fdem::linear_algebra::isolate_mpi_singleton();
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      host = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      fdem::linear_algebra::choose_blas_threads();
      dealii::deallog.depth_console(0);
      bool        print = false, validate = false, report = true;
      auto        verbosity = fdem::postprocess::Verbosity::normal;
      std::string prm_file;
      for (int i = 1; i < argc; ++i)
        {
          const std::string argument = argv[i];
          if (argument == "--help" || argument == "-h")
            {
              std::cout << usage;
              return 0;
            }
          if (argument == "--print-parameters")
            print = true;
          else if (argument == "--validate")
            validate = true;
          else if (argument == "--no-report")
            report = false;
          else if (argument == "--quiet" || argument == "--verbose")
            {
              const auto level = argument == "--quiet" ?
                                   fdem::postprocess::Verbosity::quiet :
                                   fdem::postprocess::Verbosity::verbose;
              if (verbosity != fdem::postprocess::Verbosity::normal &&
                  verbosity != level)
                {
                  std::cerr
                    << "fdem-slope: error: give --quiet or --verbose, not both; see --help.\n";
                  return 2;
                }
              verbosity = level;
            }
          else if (!argument.empty() && argument[0] == '-')
            {
              std::cerr << "fdem-slope: error: unknown option '" << argument
                        << "'; see --help.\n";
              return 2;
            }
          else if (prm_file.empty())
            prm_file = argument;
          else
            {
              std::cerr << "fdem-slope: error: give one parameter file, not '"
                        << prm_file << "' and '" << argument
                        << "'; see --help.\n";
              return 2;
            }
        }
      if (print)
        {
          std::ostream nowhere(nullptr);
          fdem::parameters::print_parameters(host ? std::cout : nowhere,
                                             prm_file);
          return 0;
        }
      if (prm_file.empty())
        {
          std::cerr << "fdem-slope: error: no parameter file given; see "
                       "--help.\n";
          return 2;
        }
      if (validate)
        {
          // The parameters, and the layout: mesh, blocks and node pairs
          // (doc/layout_checks.md), without any solve.
          std::ostream nowhere(nullptr);
          const auto   warnings = fdem::validate_case(prm_file, nowhere);
          if (host)
            {
              for (const std::string &warning : warnings)
                std::cout << "warning: " << warning << std::endl;
              std::cout << prm_file << ": valid." << std::endl;
            }
          return 0;
        }
      // One log in two levels (postprocess/run_log.h). Under --quiet
      // whatever else would reach stdout (the announcement of a long mesh)
      // goes to the log file instead.
      fdem::postprocess::RunLog log(verbosity, host);
      const bool      quiet = verbosity == fdem::postprocess::Verbosity::quiet;
      std::streambuf *stdout_buffer = std::cout.rdbuf();
      if (quiet)
        std::cout.rdbuf(log.detail().rdbuf());
      nlohmann::json summary;
      try
        {
          summary = fdem::run_case(prm_file, log, report);
        }
      catch (...)
        {
          std::cout.rdbuf(stdout_buffer);
          throw;
        }
      std::cout.rdbuf(stdout_buffer);
      const std::string status = summary["status"];
      if (status == "completed" && quiet && host)
        {
          const std::string line = fdem::postprocess::quiet_line(summary);
          if (!line.empty())
            std::cout << line << std::endl;
        }
      if (status != "completed")
        {
          // 3: no static equilibrium at all (every solve failed as a
          // mechanism); 4: no certified safety factor or an unsolved contact
          // problem (summary.json holds the steps, the bracket and the
          // certificate's numbers).
          if (host)
            std::cerr << "fdem-slope: " << status << " (see summary.json)."
                      << std::endl;
          return status.rfind("no static equilibrium", 0) == 0 ? 3 : 4;
        }
    }
  catch (const std::exception &error)
    {
      if (host)
        std::cerr << "fdem-slope: error: " << fdem::postprocess::one_line(error)
                  << std::endl;
      return 1;
    }
  catch (...)
    {
      if (host)
        std::cerr << "fdem-slope: error: unknown exception." << std::endl;
      return 1;
    }
  return 0;
}
