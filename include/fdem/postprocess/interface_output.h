// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/blocks/elastic_block.h>
#include <fdem/contact/interface_pairs.h>
#include <fdem/contact/mixed_system.h>

#include <array>
#include <string>
#include <vector>

namespace fdem
{
  namespace postprocess
  {
    /** What the output says about one node pair. */
    template <int dim>
    struct PairResult
    {
      dealii::Point<dim> position;
      /** f_n: force of block I on block J along n (> 0 tension). */
      double normal_force = 0;
      /** f_t (2D), f_t1 and f_t2 (3D). */
      std::array<double, dim - 1> tangential_force{};
      /** -f_n / A (> 0 in compression). */
      double normal_pressure = 0;
      /** |f_t| / A. */
      double shear_stress = 0;
      /** g_n: normal relative displacement plus initial gap (> 0 open). */
      double gap = 0;
      /** Tangential relative displacement (2D: along t; 3D: magnitude). */
      double slip = 0;
      contact::PairStatus status = contact::PairStatus::stick;
      double area = 0, initial_gap = 0;
    };

    /** Per-pair results of @p interface, whose first pair is @p first_pair overall. */
    template <int dim>
    std::vector<PairResult<dim>>
    pair_results(const contact::Interface<dim> &         interface,
                 const unsigned int                      first_pair,
                 const contact::ContactSolution &            solution,
                 const std::vector<contact::PairState<dim>> &states);

    /** Writes all interfaces' pairs into one CSV table. */
    template <int dim>
    void
    write_interface_csv(const std::string &                              filename,
                        const std::vector<contact::Interface<dim>> &      interfaces,
                        const std::vector<std::vector<PairResult<dim>>> &results);

    /**
     * Writes the interface as a surface (a line in 2D) on block J's faces,
     * with the pair results as nodal fields. Returns the file name.
     */
    template <int dim>
    std::string
    write_interface_vtu(const blocks::ElasticBlock<dim> &    block_J,
                        const contact::Interface<dim> &      interface,
                        const std::vector<PairResult<dim>> &results,
                        const std::string &                  directory,
                        const std::string &                  suffix);
  } // namespace postprocess
} // namespace fdem
