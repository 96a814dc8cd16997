// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/limit_equilibrium.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace fdem
{
  namespace analyses
  {
    /**
     * Limit equilibrium by the method of slices on the model's own sliding
     * surface, beside K: subsection "Limit equilibrium"
     * (limit_equilibrium_model.h).
     */
    struct LimitEquilibriumParameters
    {
      /** The fewest slices accepted: fewer cannot follow a circle. */
      static constexpr unsigned int min_n_slices = 10;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /** Compute the limit-equilibrium factors (slope generator only). */
      bool enabled = true;
      /** The methods, in the order given. */
      std::vector<limit_equilibrium::Method> methods;
      /** Number of slices asked for (each line straight inside a slice). */
      unsigned int n_slices = 400;
      /** Absolute tolerance of the roots in K (lambda: ten times it). */
      double tolerance = 1e-14;
    };

    /** The methods' names in .prm files joined by '|' (a Patterns::Selection).
     */
    std::string
    method_name_selection();

    /** The method called @p name in .prm files ("Bishop", "Spencer", ...). */
    limit_equilibrium::Method
    method_from_name(const std::string &name);
  } // namespace analyses
} // namespace fdem
