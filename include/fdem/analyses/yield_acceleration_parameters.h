// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace fdem
{
  namespace analyses
  {
    /**
     * The yield acceleration k_y and the Newmark displacement: subsection
     * "Yield acceleration" (yield_acceleration.h, newmark.h).
     */
    struct YieldAccelerationParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /** Reads the subsection (a relative record file is taken from the .prm
       * file's folder). */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /** Find k_y (the kh at which K = 1). */
      bool compute = false;
      /** Absolute tolerance of k_y (the root search stops when its bracket is
       * narrower). */
      double tolerance = 1e-6;
      /** The largest kh searched: no K = 1 below it, no k_y. */
      double max_coefficient = 1;
      /** Largest number of K evaluations of the search. */
      unsigned int max_evaluations = 40;
      /** The acceleration record (CSV of time and acceleration); empty: none.
       */
      std::string acceleration_record;
      /** "g" or "m/s^2". */
      std::string acceleration_unit = "g";
      /** Whether the mass may also slide backwards (two-directional Newmark).
       */
      bool two_directional = false;
    };
  } // namespace analyses
} // namespace fdem
