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
     * installs) can split them between the cores; the serial OpenBLAS and
     * the reference BLAS use one. The library is found at run time (the
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
     * One BLAS thread unless the environment sets OPENBLAS_NUM_THREADS (or
     * OMP_NUM_THREADS), which then rules. OpenBLAS's threads wait for each
     * other inside every LU by spinning: on a machine whose cores are busy
     * with other work (another run, a build) a run with two threads on two
     * cores took 1.75 times as long as with one, and 10 to 20 times with
     * both cores busy, while on idle cores it was 1.14-1.49 times faster
     * (doc/theory.md, "Threads"). So more threads are asked for by whoever
     * knows the cores are free. Under mpirun every rank makes the same
     * dense solves: one thread per rank is the setting that fits.
     */
    void
    choose_blas_threads();
  } // namespace linear_algebra
} // namespace fdem
