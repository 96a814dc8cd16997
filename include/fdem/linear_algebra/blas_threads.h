// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

namespace fdem
{
  namespace linear_algebra
  {
    /**
     * Threads of the BLAS behind LAPACK, MUMPS and the dense mixed system.
     * The dense parts (the LU of the mixed system in every status
     * iteration, the Cholesky factor of a block's Schur complement, MUMPS's
     * fronts) run on the BLAS, and in 3D they are most of a run. Debian's
     * OpenBLAS with threads (libopenblas0-pthread, which bootstrap.sh
     * installs) uses every core unless OPENBLAS_NUM_THREADS (or
     * OMP_NUM_THREADS) says otherwise; the serial OpenBLAS and the
     * reference BLAS use one. The library is found at run time (the
     * openblas_* functions looked up by name), so the program runs on any
     * BLAS that Debian's alternatives put in place.
     *
     * @return the number of threads, or 0 if the BLAS does not say (not
     * OpenBLAS).
     */
    unsigned int
    n_blas_threads();

    /**
     * Sets the number of BLAS threads if the BLAS can be told (OpenBLAS);
     * returns whether it could.
     */
    bool
    set_n_blas_threads(unsigned int n_threads);

    /**
     * Under mpirun every rank makes the dense solves (doc/theory.md,
     * "Running with MPI"): with @p n_ranks > 1 each rank gets one BLAS
     * thread, so that the ranks do not share the cores between more threads
     * than there are, unless the environment sets OPENBLAS_NUM_THREADS or
     * OMP_NUM_THREADS, which then rules.
     */
    void
    choose_blas_threads(unsigned int n_ranks);
  } // namespace linear_algebra
} // namespace fdem
