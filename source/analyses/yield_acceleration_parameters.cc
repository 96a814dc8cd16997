// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/yield_acceleration_parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

namespace fdem
{
  namespace analyses
  {
    using namespace dealii;

    void
    YieldAccelerationParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Yield acceleration");
      prm.declare_entry(
        "Compute",
        "false",
        Patterns::Bool(),
        "Find the yield acceleration k_y: the horizontal seismic "
        "coefficient kh (in Loads/Seismic direction, with "
        "Loads/Vertical seismic coefficient) at which K = 1, by a "
        "bracketing root search with Brent's method on K(kh) - 1; "
        "each K is the safety-factor iteration on the same "
        "factorisations (contact solves only). Reports k_y and the "
        "K(kh) curve (summary.json, yield_acceleration.csv).");
      prm.declare_entry(
        "Tolerance",
        "1e-6",
        Patterns::Double(1e-14, 0.1),
        "Absolute tolerance of k_y (dimensionless): the search "
        "stops when the bracket of the root is this narrow. K is "
        "known to Safety factor/Tolerance, so a tolerance far "
        "below it buys nothing.");
      prm.declare_entry(
        "Maximum coefficient",
        "1",
        Patterns::Double(0.001, 1),
        "The largest kh searched (dimensionless): if K stays above "
        "1 up to it, there is no k_y below it (reported so).");
      prm.declare_entry("Maximum evaluations",
                        "40",
                        Patterns::Integer(3, 1000),
                        "Largest number of K evaluations of the search.");
      prm.declare_entry(
        "Acceleration record",
        "",
        Patterns::FileName(),
        "A CSV file of the ground motion for the Newmark sliding "
        "displacement (needs Compute = true): two columns, time "
        "(s, strictly increasing) and acceleration, comma or "
        "blank separated, '#' comments, an optional header line; "
        "linear between samples. A positive acceleration drives "
        "the mass in the direction of a positive kh. Relative to "
        "the folder of the file that sets it. Empty: no Newmark analysis.");
      prm.declare_entry(
        "Acceleration unit",
        "g",
        Patterns::Selection("g|m/s^2"),
        "Unit of the record's accelerations: g (standard gravity, "
        "9.80665 m/s^2) or m/s^2. The displacement is in m, the "
        "velocity in m/s, whatever the model's units.");
      prm.declare_entry(
        "Sliding",
        "one-directional",
        Patterns::Selection("one-directional|two-directional"),
        "one-directional: the mass slides only towards the free "
        "face, when the acceleration exceeds k_y g; "
        "two-directional: also backwards, when it is below -k_y' "
        "g, k_y' the yield coefficient of the opposite direction "
        "(searched the same way; none up to the Maximum "
        "coefficient: no backward sliding).");
      prm.leave_subsection();
    }

    void
    YieldAccelerationParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Yield acceleration");
      compute             = prm.get_bool("Compute");
      tolerance           = prm.get_double("Tolerance");
      max_coefficient     = prm.get_double("Maximum coefficient");
      max_evaluations     = prm.get_integer("Maximum evaluations");
      acceleration_record = Utilities::trim(prm.get("Acceleration record"));
      acceleration_unit   = prm.get("Acceleration unit");
      two_directional     = prm.get("Sliding") == "two-directional";
      AssertThrow(
        acceleration_record.empty() || compute,
        ExcMessage(
          "Yield acceleration/Acceleration record: the Newmark "
          "displacement needs k_y; set Yield acceleration/Compute = true."));
      prm.leave_subsection();
    }
  } // namespace analyses
} // namespace fdem
