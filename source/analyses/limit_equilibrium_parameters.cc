// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/limit_equilibrium_parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <map>

namespace fdem
{
  namespace analyses
  {
    using namespace dealii;

    namespace
    {
      const std::map<std::string, limit_equilibrium::Method> &
      method_names()
      {
        using M                                     = limit_equilibrium::Method;
        static const std::map<std::string, M> names = {
          {"ordinary", M::ordinary},
          {"Bishop", M::bishop},
          {"Janbu", M::janbu},
          {"Janbu corrected", M::janbu_corrected},
          {"Spencer", M::spencer},
          {"Morgenstern-Price constant", M::morgenstern_price_constant},
          {"Morgenstern-Price half-sine", M::morgenstern_price_half_sine}};
        return names;
      }
    } // namespace

    std::string
    method_name_selection()
    {
      std::string all;
      for (const auto &name : method_names())
        all += (all.empty() ? "" : "|") + name.first;
      return all;
    }

    limit_equilibrium::Method
    method_from_name(const std::string &name)
    {
      return method_names().at(name);
    }

    void
    LimitEquilibriumParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Limit equilibrium");
      prm.declare_entry(
        "Enabled",
        "true",
        Patterns::Bool(),
        "Compute the limit-equilibrium factors of safety of the "
        "model's own sliding surface beside K (slope generator "
        "only: Geometry/Source = slope; other geometries say in "
        "summary.json why not). They use the same ground, "
        "layers, unit weights, piezometric line, pore pressure "
        "and tension crack as the FE model.");
      const std::string all = method_name_selection();
      prm.declare_entry(
        "Methods",
        "ordinary, Bishop, Janbu, Janbu corrected, Spencer, "
        "Morgenstern-Price constant, Morgenstern-Price half-sine",
        Patterns::MultipleSelection(all),
        "Methods of slices, in this order: ordinary (Fellenius); "
        "Bishop (simplified, circles only); Janbu (simplified, "
        "force equilibrium without interslice shear, no "
        "correction); Janbu corrected (times Janbu's f0); "
        "Spencer; Morgenstern-Price with a constant or a "
        "half-sine interslice function.");
      prm.declare_entry("Number of slices",
                        "400",
                        Patterns::Integer(1, 1000000),
                        "Slices of about equal width, at least 10 "
                        "(dimensionless); more where a line has a vertex or "
                        "two lines cross. Each method is also run with twice "
                        "as many, and the change is reported.");
      prm.declare_entry("Tolerance",
                        "1e-14",
                        Patterns::Double(1e-16, 1e-3),
                        "Absolute tolerance of the roots in the factor of "
                        "safety (dimensionless); the interslice scale lambda "
                        "is found to ten times it.");
      prm.leave_subsection();
    }

    void
    LimitEquilibriumParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Limit equilibrium");
      enabled  = prm.get_bool("Enabled");
      n_slices = prm.get_integer("Number of slices");
      AssertThrow(n_slices >= min_n_slices,
                  ExcMessage("Limit equilibrium/Number of slices: at least " +
                             std::to_string(min_n_slices) +
                             " are needed, not " + std::to_string(n_slices) +
                             "."));
      tolerance = prm.get_double("Tolerance");
      methods.clear();
      for (const std::string &name :
           Utilities::split_string_list(prm.get("Methods")))
        methods.push_back(method_names().at(name));
      prm.leave_subsection();
    }
  } // namespace analyses
} // namespace fdem
