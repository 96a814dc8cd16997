// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// Preloaded into the tests of the sanitizer build only (tests/CMakeLists.txt):
// dlclose() that keeps the library loaded. OpenMPI 4.1 loads its components
// (mca_*.so) with dlopen and unloads them in MPI_Finalize, before
// LeakSanitizer looks at the heap; their allocations then have no module
// name and cannot be told apart from ours. Kept loaded, they can be
// suppressed by name (tests/sanitizers/lsan.supp). Unloading code at exit
// has no effect a test could observe.
extern "C" int
dlclose(void *)
{
  return 0;
}
