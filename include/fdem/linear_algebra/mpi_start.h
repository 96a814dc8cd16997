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
     * environment already sets it. Such a process also makes no session
     * directory (orte_create_session_dirs): every isolated singleton of a
     * user takes the same one, /tmp/ompi.<host>.<uid>/jf.0/1, and one that
     * ends removes it while another starts in it ("A call to mkdir was
     * unable to create the desired directory", once in a CI run of the
     * suite); a single process needs none (no shared memory with a peer,
     * no spawn). Under mpirun (OMPI_COMM_WORLD_SIZE set) nothing changes.
     */
    inline void
    isolate_mpi_singleton()
    {
      if (std::getenv("OMPI_COMM_WORLD_SIZE") == nullptr)
        {
          setenv("OMPI_MCA_ess_singleton_isolated", "1", /*overwrite=*/0);
          setenv("OMPI_MCA_orte_create_session_dirs", "0", /*overwrite=*/0);
        }
    }
  } // namespace linear_algebra
} // namespace fdem

#endif
