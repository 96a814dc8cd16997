// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/linear_algebra/blas_threads.h>

#include <dlfcn.h>

#include <cstdlib>

namespace fdem
{
  namespace linear_algebra
  {
    namespace
    {
      // OpenBLAS's own functions, looked up among the libraries the process
      // has loaded (libblas.so.3 is OpenBLAS where Debian's alternatives
      // point to it): absent from other BLAS, and not declared in their
      // headers, so not linked by name.
      template <typename Function>
      Function *
      openblas_function(const char *name)
      {
        return reinterpret_cast<Function *>(dlsym(RTLD_DEFAULT, name));
      }
    } // namespace

    unsigned int
    n_blas_threads()
    {
      auto *get = openblas_function<int()>("openblas_get_num_threads");
      if (get == nullptr)
        return 0;
      const int n = get();
      return n > 0 ? static_cast<unsigned int>(n) : 0;
    }

    bool
    set_n_blas_threads(const unsigned int n_threads)
    {
      auto *set = openblas_function<void(int)>("openblas_set_num_threads");
      if (set == nullptr || n_threads == 0)
        return false;
      set(static_cast<int>(n_threads));
      return true;
    }

    void
    choose_blas_threads()
    {
      if (std::getenv("OPENBLAS_NUM_THREADS") == nullptr &&
          std::getenv("OMP_NUM_THREADS") == nullptr)
        set_n_blas_threads(1);
    }
  } // namespace linear_algebra
} // namespace fdem
