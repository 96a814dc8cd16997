// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/analyses/probabilistic_parameters.h>
#include <fdem/parameters/numbers.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace fdem
{
  namespace analyses
  {
    using namespace dealii;

    namespace
    {
      const std::string variables_entry    = "Probabilistic/Variables";
      const std::string correlations_entry = "Probabilistic/Correlations";

      /** @p text as a finite number, or throws naming @p where. */
      double
      number(const std::string &text, const std::string &where)
      {
        double value = std::numeric_limits<double>::quiet_NaN();
        try
          {
            value = parameters::finite_number(Utilities::trim(text));
          }
        catch (...)
          {}
        AssertThrow(std::isfinite(value),
                    ExcMessage(where + ": '" + Utilities::trim(text) +
                               "' is not a number."));
        return value;
      }

      /**
       * One variable: "<Interfaces|Materials|Blocks>/<name>/<Cohesion|
       * Friction angle|tan(phi)>: <distribution>, mean m, sd s | cov v,
       * lower a, upper b".
       */
      RandomVariable
      parse_variable(const std::string &text, const unsigned int index)
      {
        const std::string where = variables_entry + ", variable " +
                                  std::to_string(index) + " ('" + text + "')";
        RandomVariable variable;
        const auto     colon = text.rfind(':');
        AssertThrow(
          colon != std::string::npos,
          ExcMessage(where +
                     ": expected '<target>: <distribution>, mean .., sd ..'."));
        variable.target           = Utilities::trim(text.substr(0, colon));
        const std::string &target = variable.target;
        const auto         first  = target.find('/');
        const auto         last   = target.rfind('/');
        if (target == "Loads/Unit weight factor")
          {
            variable.owner    = RandomVariable::Owner::loads;
            variable.quantity = RandomVariable::Quantity::unit_weight_factor;
          }
        else if (target == "Water/Piezometric line shift")
          {
            variable.owner    = RandomVariable::Owner::water;
            variable.quantity = RandomVariable::Quantity::water_level_shift;
          }
        else if (target == "Loads/Horizontal seismic coefficient")
          {
            variable.owner = RandomVariable::Owner::loads;
            variable.quantity =
              RandomVariable::Quantity::horizontal_seismic_coefficient;
          }
        else
          {
            AssertThrow(
              first != std::string::npos && last != first,
              ExcMessage(
                where + ": the target must be Interfaces/<name>/<quantity>, "
                        "Materials/<name>/<quantity>, Blocks/<name>/<quantity> "
                        "Loads/Unit weight factor, Loads/Horizontal "
                        "seismic coefficient or Water/Piezometric line "
                        "shift."));
            const std::string owner    = target.substr(0, first),
                              quantity = target.substr(last + 1);
            variable.name = target.substr(first + 1, last - first - 1);
            if (owner == "Interfaces")
              variable.owner = RandomVariable::Owner::interface;
            else if (owner == "Materials" || owner == "Blocks")
              variable.owner = RandomVariable::Owner::material;
            else
              AssertThrow(
                false,
                ExcMessage(
                  where + ": unknown owner '" + owner +
                  "'; expected Interfaces, Materials, Blocks or Loads."));
            if (quantity == "Cohesion")
              variable.quantity = RandomVariable::Quantity::cohesion;
            else if (quantity == "Friction angle")
              variable.quantity = RandomVariable::Quantity::friction_angle;
            else if (quantity == "tan(phi)")
              variable.quantity = RandomVariable::Quantity::tan_phi;
            else
              AssertThrow(
                false,
                ExcMessage(
                  where + ": unknown quantity '" + quantity +
                  "'; expected Cohesion, Friction angle or tan(phi)."));
          }

        const std::vector<std::string> fields =
          Utilities::split_string_list(text.substr(colon + 1), ',');
        AssertThrow(!fields.empty(),
                    ExcMessage(where + ": no distribution given."));
        using probability::Distribution;
        probability::Marginal &m = variable.marginal;
        if (fields[0] == "normal")
          m.distribution = Distribution::normal;
        else if (fields[0] == "lognormal")
          m.distribution = Distribution::lognormal;
        else if (fields[0] == "uniform")
          m.distribution = Distribution::uniform;
        else if (fields[0] == "truncated normal")
          m.distribution = Distribution::truncated_normal;
        else
          AssertThrow(false,
                      ExcMessage(
                        where + ": unknown distribution '" + fields[0] +
                        "'; expected normal, lognormal, uniform or truncated "
                        "normal."));
        std::map<std::string, double> values;
        for (unsigned int i = 1; i < fields.size(); ++i)
          {
            const auto        space = fields[i].find(' ');
            const std::string key   = fields[i].substr(0, space);
            AssertThrow(
              space != std::string::npos &&
                (key == "mean" || key == "sd" || key == "cov" ||
                 key == "lower" || key == "upper") &&
                values.count(key) == 0,
              ExcMessage(
                where + ": '" + fields[i] +
                "' is not one of mean, sd, cov, lower, upper with a value "
                "(each at most once)."));
            values[key] =
              number(fields[i].substr(space + 1), where + ", " + key);
          }
        const auto has = [&](const std::string &key) {
          return values.count(key) > 0;
        };
        AssertThrow(!(has("sd") && has("cov")),
                    ExcMessage(where + ": give sd or cov, not both."));
        if (has("lower"))
          m.lower = values["lower"];
        if (has("upper"))
          m.upper = values["upper"];
        AssertThrow(m.lower < m.upper,
                    ExcMessage(where + ": lower must be below upper."));
        if (m.distribution == Distribution::uniform && !has("mean"))
          {
            AssertThrow(std::isfinite(m.lower) && std::isfinite(m.upper) &&
                          !has("sd") && !has("cov"),
                        ExcMessage(
                          where +
                          ": a uniform distribution needs lower and upper, or "
                          "mean and sd (or cov)."));
            m.mean    = 0.5 * (m.lower + m.upper);
            m.std_dev = (m.upper - m.lower) / std::sqrt(12.0);
            return variable;
          }
        AssertThrow(has("mean"), ExcMessage(where + ": the mean is missing."));
        m.mean = values["mean"];
        AssertThrow(has("sd") || has("cov"),
                    ExcMessage(
                      where +
                      ": the standard deviation is missing (sd or cov)."));
        m.std_dev = has("sd") ? values["sd"] : values["cov"] * std::abs(m.mean);
        AssertThrow(
          m.std_dev > 0,
          ExcMessage(where +
                     ": the standard deviation must be > 0 (sd > 0, or cov > 0 "
                     "with a mean other than 0)."));
        if (m.distribution == Distribution::lognormal)
          AssertThrow(m.mean > 0,
                      ExcMessage(where + ": a lognormal needs a mean > 0."));
        if (m.distribution == Distribution::uniform)
          {
            AssertThrow(!has("lower") && !has("upper"),
                        ExcMessage(
                          where +
                          ": a uniform distribution takes lower and upper, or "
                          "mean and sd (or cov), not both."));
            m.lower = m.mean - std::sqrt(3.0) * m.std_dev;
            m.upper = m.mean + std::sqrt(3.0) * m.std_dev;
          }
        else if (m.distribution == Distribution::truncated_normal)
          {
            AssertThrow(
              has("lower") || has("upper"),
              ExcMessage(
                where +
                ": a truncated normal needs lower or upper (or both)."));
            const double mass =
              probability::normal_cdf((m.upper - m.mean) / m.std_dev) -
              probability::normal_cdf((m.lower - m.mean) / m.std_dev);
            AssertThrow(mass > 1e-9,
                        ExcMessage(
                          where +
                          ": [lower, upper] holds almost none of the normal's "
                          "probability."));
          }
        else
          AssertThrow(!has("lower") && !has("upper"),
                      ExcMessage(
                        where +
                        ": lower and upper belong to truncated normal and "
                        "uniform distributions only."));
        return variable;
      }
    } // namespace

    void
    ProbabilisticParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Probabilistic");
      prm.declare_entry(
        "Compute",
        "false",
        Patterns::Bool(),
        "After the safety factor, sample the random soil strengths of Variables "
        "and compute K of each sample on the model's one factorisation: mean and "
        "standard deviation of K, reliability index, probability of failure "
        "P(K < 1), samples.csv.");
      prm.declare_entry("Number of samples",
                        "1000",
                        Patterns::Anything(),
                        "Number of samples, an integer >= 1 (dimensionless).");
      prm.declare_entry(
        "Sampling",
        "Monte Carlo",
        Patterns::Selection("Monte Carlo|Latin hypercube"),
        "Monte Carlo: independent draws. Latin hypercube: each variable's "
        "probability cut into as many equal strata as samples, one point in each.");
      prm.declare_entry(
        "Seed",
        "1",
        Patterns::Integer(0),
        "Seed of the 64-bit Mersenne Twister (dimensionless): the same seed gives "
        "the same samples and results bit for bit, with any number of MPI ranks.");
      prm.declare_entry(
        "Variables",
        "",
        Patterns::Anything(),
        "Random soil strengths, separated by ';', each '<target>: <distribution>, mean m, sd s' "
        "(or 'cov v' for sd = v |m|), with 'lower a, upper b' for a truncated normal (the bounds, "
        "m and s those of the normal it is cut from) or a uniform (or mean and sd). Target: "
        "Interfaces/<name>/<quantity> (an interface with its own strength), or "
        "Materials/<name>/<quantity> or Blocks/<name>/<quantity> (a material's soil strength, "
        "used by interfaces with Strength = material); quantity: Cohesion (force/length^2), "
        "Friction angle (degrees) or tan(phi) (dimensionless). Distribution: normal, lognormal, "
        "uniform or truncated normal. Also Loads/Unit weight factor (dimensionless, > 0): a factor "
        "on the weight of every block and material (their unit weights, saturated ones below "
        "the water table, and densities), e.g. normal, mean 1, cov 0.05; and Loads/Horizontal "
        "seismic coefficient (dimensionless): the sample's pseudo-static kh in place of the "
        "case's, towards Loads/Seismic direction (or the free face), with the case's Vertical "
        "seismic coefficient and Seismic on pore water, without a new factorisation; and "
        "Water/Piezometric line shift (length, positive up, in the line's own coordinates): every point of Water/Piezometric "
        "line (or of Water/Piezometric surface file) and of the materials' own lines raised by the sample's value, with the pore "
        "pressures ('piezometric') and the saturated weights below them, a new right-hand side on the same factorisations "
        "(e.g. normal, mean 0, sd 1). Values not listed keep those of the case.");
      prm.declare_entry(
        "Correlations",
        "",
        Patterns::Anything(),
        "Correlation coefficients between variables, separated by ';', each "
        "'i, j, rho' with i and j the variables' positions in Variables (from "
        "1) and -1 <= rho <= 1 (dimensionless); pairs not listed are "
        "uncorrelated. The correlation is that of the variables' standard-normal "
        "images (exact for normal variables); the matrix must be positive "
        "definite.");
      prm.declare_entry(
        "Fragility variable",
        "0",
        Patterns::Integer(0),
        "Position (from 1) of the variable against which P(K < 1) is shown as a "
        "fragility curve, in bins of equal numbers of samples; 0: none.");
      prm.declare_entry(
        "Fragility bins",
        "10",
        Patterns::Integer(2, 1000),
        "Number of bins of the fragility curve (dimensionless).");
      prm.declare_entry(
        "FOSM",
        "true",
        Patterns::Bool(),
        "Also the first-order second-moment estimate of the mean and standard "
        "deviation of K (2n + 1 safety factors, central differences of one "
        "standard deviation).");
      prm.declare_entry(
        "Point estimate",
        "true",
        Patterns::Bool(),
        "Also Rosenblueth's point-estimate method (2^n safety factors at the "
        "means plus or minus one standard deviation; at most 10 variables).");
      prm.leave_subsection();
    }

    void
    ProbabilisticParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Probabilistic");
      compute = prm.get_bool("Compute");
      {
        const std::string text = Utilities::trim(prm.get("Number of samples"));
        const double value = number(text, "Probabilistic/Number of samples");
        AssertThrow(
          value >= 1 && value <= 1e8 && value == std::floor(value),
          ExcMessage(
            "Probabilistic/Number of samples: must be an integer from 1 to "
            "1e8, got " +
            text + "."));
        n_samples = static_cast<unsigned int>(value);
      }
      latin_hypercube = prm.get("Sampling") == "Latin hypercube";
      seed            = std::stoull(prm.get("Seed"));
      variables.clear();
      unsigned int index = 0;
      for (const std::string &text :
           Utilities::split_string_list(prm.get("Variables"), ';'))
        variables.push_back(parse_variable(text, ++index));
      const unsigned int n = variables.size();
      AssertThrow(!compute || n > 0,
                  ExcMessage(variables_entry +
                             ": Compute = true needs at least one variable."));
      correlation.assign(n * n, 0.0);
      for (unsigned int i = 0; i < n; ++i)
        correlation[i * n + i] = 1;
      for (const std::string &text :
           Utilities::split_string_list(prm.get("Correlations"), ';'))
        {
          const std::string where = correlations_entry + " ('" + text + "')";
          const std::vector<std::string> fields =
            Utilities::split_string_list(text, ',');
          AssertThrow(fields.size() == 3,
                      ExcMessage(where + ": expected 'i, j, rho'."));
          const double i   = number(fields[0], where),
                       j   = number(fields[1], where),
                       rho = number(fields[2], where);
          AssertThrow(i >= 1 && j >= 1 && i <= n && j <= n &&
                        i == std::floor(i) && j == std::floor(j) && i != j,
                      ExcMessage(where +
                                 ": i and j must be two different positions in "
                                 "Variables, from 1 to " +
                                 std::to_string(n) + "."));
          AssertThrow(rho >= -1 && rho <= 1,
                      ExcMessage(where +
                                 ": a correlation must lie in [-1, 1]."));
          const unsigned int a = i - 1, b = j - 1;
          AssertThrow(correlation[a * n + b] == 0,
                      ExcMessage(where + ": the pair is given twice."));
          correlation[a * n + b] = correlation[b * n + a] = rho;
        }
      probability::cholesky(correlation, n); // throws if not positive definite
      fragility_variable = prm.get_integer("Fragility variable");
      AssertThrow(fragility_variable <= n,
                  ExcMessage("Probabilistic/Fragility variable: " +
                             std::to_string(fragility_variable) +
                             " is not a position in "
                             "Variables (1 to " +
                             std::to_string(n) + ", or 0 for none)."));
      n_fragility_bins = prm.get_integer("Fragility bins");
      fosm             = prm.get_bool("FOSM");
      point_estimate   = prm.get_bool("Point estimate");
      AssertThrow(
        !(compute && point_estimate && n > 10),
        ExcMessage(
          "Probabilistic/Point estimate: 2^" + std::to_string(n) +
          " solves for " + std::to_string(n) +
          " variables; at most 10 variables, or Point estimate = false."));
      prm.leave_subsection();
    }

    void
    ProbabilisticParameters::check_targets(
      const std::map<std::string, bool> &interfaces_without_own_strength,
      const std::map<std::string, bool> &materials_with_strength) const
    {
      for (unsigned int v = 0; v < variables.size(); ++v)
        {
          const RandomVariable &variable = variables[v];
          const std::string     where    = variables_entry + ", variable " +
                                    std::to_string(v + 1) + " ('" +
                                    variable.target + "')";
          // c and phi (or tan(phi)) of one owner are two quantities; each
          // load is one.
          const auto same = [&](const RandomVariable &other) {
            if (other.owner != variable.owner || other.name != variable.name)
              return false;
            if (variable.owner == RandomVariable::Owner::loads ||
                variable.owner == RandomVariable::Owner::water)
              return other.quantity == variable.quantity;
            return (other.quantity == RandomVariable::Quantity::cohesion) ==
                   (variable.quantity == RandomVariable::Quantity::cohesion);
          };
          for (unsigned int w = 0; w < v; ++w)
            AssertThrow(!same(variables[w]),
                        ExcMessage(where + ": the same quantity as variable " +
                                   std::to_string(w + 1) + "."));
          if (variable.owner == RandomVariable::Owner::loads ||
              variable.owner == RandomVariable::Owner::water)
            continue;
          if (variable.owner == RandomVariable::Owner::interface)
            {
              const auto it =
                interfaces_without_own_strength.find(variable.name);
              AssertThrow(it != interfaces_without_own_strength.end(),
                          ExcMessage(where + ": no interface '" +
                                     variable.name + "' in Interfaces/Names."));
              AssertThrow(!it->second,
                          ExcMessage(
                            where +
                            ": the interface has no strength of its own "
                            "(Strength = material, or frictionless); make the "
                            "material's strength random instead."));
            }
          else
            {
              const auto it = materials_with_strength.find(variable.name);
              AssertThrow(it != materials_with_strength.end(),
                          ExcMessage(where + ": no block or material '" +
                                     variable.name + "'."));
              AssertThrow(it->second,
                          ExcMessage(where +
                                     ": the material has no soil strength "
                                     "(Friction angle)."));
            }
        }
    }
  } // namespace analyses
} // namespace fdem
