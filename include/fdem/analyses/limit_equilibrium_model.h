// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/limit_equilibrium.h>
#include <fdem/analyses/limit_equilibrium_parameters.h>
#include <fdem/parameters/parameters.h>

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace fdem
{
  namespace analyses
  {
    /**
     * Limit equilibrium on the model's own section and sliding surface (the
     * slope generator's ground, layers, weights, water, tension crack and
     * circle or polyline): each method of "Limit equilibrium/Methods" with
     * the number of slices asked for and with twice as many, the change
     * between the two being the convergence check.
     */
    struct LimitEquilibriumResults
    {
      /** One method: with n slices and with 2n. */
      struct Entry
      {
        limit_equilibrium::Method       method;
        limit_equilibrium::MethodResult result, doubled;
        /** Why this method has no answer (empty if it has). */
        std::string not_computed;
      };

      bool computed = false;
      /** Why nothing was computed: a sentence (empty if computed). */
      std::string not_computed;
      /** What of the FE model the section does not represent. */
      std::vector<std::string> notes;
      std::vector<Entry>       methods;
    };

    /**
     * The section and sliding surface of the model of @p parameters, or an
     * empty @p why_not saying why there is none; @p notes receives what of
     * the FE model it leaves out. Throws (naming the entry) if the surface
     * leaves the model, unless @p check_surface is false (the surface
     * search, whose circles are checked one by one).
     */
    bool
    model_section(const parameters::Parameters &parameters,
                  limit_equilibrium::Section   &section,
                  limit_equilibrium::Surface   &surface,
                  std::string                  &why_not,
                  std::vector<std::string>     &notes,
                  const bool                    check_surface = true);

    /**
     * Throws "Geometry/Slope: the sliding surface leaves the model ..." if
     * @p surface does not cut the ground of @p section, or has an end
     * beyond the ground's x range or a point below @p base_elevation.
     */
    void
    check_surface_in_model(const limit_equilibrium::Section &section,
                           const limit_equilibrium::Surface &surface,
                           const double                      base_elevation);

    /** Every method of @p settings on one section and surface. */
    LimitEquilibriumResults
    evaluate_limit_equilibrium(const limit_equilibrium::Section &section,
                               const limit_equilibrium::Surface &surface,
                               const LimitEquilibriumParameters &settings);

    /** Limit equilibrium on the model of @p parameters (see the class). */
    LimitEquilibriumResults
    model_limit_equilibrium(const parameters::Parameters &parameters);

    /** summary.json's "limit_equilibrium". */
    nlohmann::json
    to_json(const LimitEquilibriumResults &results);

    /** One line per method for the run's final screen block. */
    void
    print_limit_equilibrium(const LimitEquilibriumResults &results,
                            std::ostream                  &out);
  } // namespace analyses
} // namespace fdem
