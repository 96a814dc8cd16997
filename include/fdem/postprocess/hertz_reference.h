// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/model.h>
#include <fdem/postprocess/interface_output.h>

#include <nlohmann/json.hpp>

#include <vector>

namespace fdem
{
  namespace postprocess
  {
    /**
     * For the Hertz generator's model (2D, plane-strain cylinder on a
     * half-space) and the Hertz sphere generator's (3D,
     * hertz_sphere_reference()): the exact contact half-width or radius and
     * maximum pressure and the relative errors of the computed ones; the
     * exact pressure of each pair goes into @p results. Empty for any other
     * model, or without a static solution.
     */
    template <int dim>
    nlohmann::json
    hertz_reference(const Model<dim>                          &model,
                    std::vector<std::vector<PairResult<dim>>> &results);
  } // namespace postprocess
} // namespace fdem
