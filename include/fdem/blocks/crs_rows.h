// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <Epetra_CrsMatrix.h>

namespace fdem
{
  namespace blocks
  {
    /**
     * Calls @p f(column, value) for every stored entry of row @p row of a
     * serial Epetra matrix (global column numbers).
     */
    template <typename Function>
    void
    for_each_entry_in_row(const Epetra_CrsMatrix &matrix,
                          const int               row,
                          const Function         &f)
    {
      int     n_entries;
      double *values;
      int    *indices;
      matrix.ExtractMyRowView(row, n_entries, values, indices);
      for (int e = 0; e < n_entries; ++e)
        f(matrix.GCID(indices[e]), values[e]);
    }
  } // namespace blocks
} // namespace fdem
