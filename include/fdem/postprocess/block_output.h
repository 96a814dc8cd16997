// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/elastic_block.h>

#include <string>

namespace fdem
{
  namespace postprocess
  {
    /**
     * Writes one block's VTU file: displacement, stress (Cauchy, with
     * sigma_zz in plane strain as "stress_zz"), and the block index.
     * Returns the file name relative to @p directory. Collective on the
     * block's communicator (DataOut on a shared triangulation): every rank
     * calls it, rank 0 writes the whole block.
     */
    template <int dim>
    std::string
    write_block_vtu(const blocks::ElasticBlock<dim> &block,
                    const unsigned int               block_index,
                    const dealii::Vector<double> &   displacement,
                    const std::string &              directory,
                    const std::string &              suffix);
  } // namespace postprocess
} // namespace fdem
