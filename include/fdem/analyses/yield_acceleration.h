// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/seismic.h>
#include <fdem/analyses/seismic_results.h>
#include <fdem/analyses/yield_acceleration_parameters.h>
#include <fdem/model.h>

namespace fdem
{
  namespace analyses
  {
    /**
     * The yield acceleration k_y of a factorised Model (doc/theory.md, "The
     * yield acceleration"): the horizontal seismic coefficient in @p load's
     * direction (with its kv) at which K = 1. K(kh) is evaluated by the
     * safety-factor iteration (iterate(), eqs. 10-13, each K certified) on
     * the model's factorisations with the seismic load superposed
     * (set_seismic_load()); the root of K(kh) - 1 is bracketed from kh = 0
     * upwards with secant steps and refined by Brent's method. With @p
     * parameters' two_directional also the coefficient of the opposite
     * direction. Leaves the model's load and contact state to the caller.
     */
    template <int dim>
    YieldAccelerationResult
    yield_acceleration(Model<dim>                        &model,
                       const SeismicLoad<dim>            &load,
                       const YieldAccelerationParameters &parameters);
  } // namespace analyses
} // namespace fdem
