// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#ifndef fdem_linear_algebra_mpi_start_h
#define fdem_linear_algebra_mpi_start_h

#include <cstdlib>

namespace fdem
{
  namespace linear_algebra
  {
    /**
     * Call before MPI_Init. A process started without mpirun is an MPI
     * singleton, for which OpenMPI 4.1 starts a helper daemon (orted) that
     * costs about 0.2 s of every run (of each of the test suite's runs
     * too), and is needed only to spawn processes, which fdem-slope never
     * does. Such a process is therefore asked to run
     * isolated (OpenMPI's MCA parameter ess_singleton_isolated), unless the
     * environment already sets it. Under mpirun (OMPI_COMM_WORLD_SIZE set)
     * nothing changes.
     */
    inline void
    isolate_mpi_singleton()
    {
      if (std::getenv("OMPI_COMM_WORLD_SIZE") == nullptr)
        setenv("OMPI_MCA_ess_singleton_isolated", "1", /*overwrite=*/0);
    }
  } // namespace linear_algebra
} // namespace fdem

#endif
