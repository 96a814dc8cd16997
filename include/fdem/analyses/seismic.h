// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <fdem/analyses/seismic_results.h>
#include <fdem/model.h>

#include <deal.II/base/tensor.h>

namespace fdem
{
  namespace analyses
  {
    /**
     * The pseudo-static seismic load (doc/theory.md, "Seismic load"): a body
     * force kh W in the horizontal direction h and kv W upwards, W the
     * weight, as a combination of the model's body-force load cases
     * (Model::body_force_cases()): no new factorisation.
     */
    template <int dim>
    struct SeismicLoad
    {
      double         kh = 0, kv = 0;
      Tensor<1, dim> direction;
      /** +1, or -1 where direction is the opposite of the reported one (the
       * backward search). */
      double direction_sign = 1;
      bool   on_pore_water  = false;
    };

    /**
     * The unit horizontal direction of a positive kh: Loads/Seismic
     * direction if given, else towards the free face: the horizontal part
     * (perpendicular to gravity) of sum_p A_p (g - (g.n_p) n_p) over the
     * pairs of the sliding surfaces, the downslope component of gravity
     * along them. Throws if it vanishes (a level surface). @p from says
     * which.
     */
    template <int dim>
    Tensor<1, dim>
    seismic_direction(const Model<dim> &model, std::string &from);

    /** Sets the model's load to gravity plus @p load
     * (Model::set_load_combination()). */
    template <int dim>
    void
    set_seismic_load(Model<dim> &model, const SeismicLoad<dim> &load);

    /**
     * The seismic analyses of a run, called once by CaseRun::run() after
     * compute_flexibility(): the yield acceleration (if asked) and the
     * Newmark displacement (if a record is given), then the load of
     * Loads/Horizontal and Vertical seismic coefficient set for the safety
     * factor that follows. Writes yield_acceleration.csv and newmark.csv.
     * Does nothing (and leaves the assembled load) if none is asked for.
     */
    template <int dim>
    SeismicResults
    seismic_analyses(Model<dim> &model);
  } // namespace analyses
} // namespace fdem
