// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/parameters/numbers.h>

#include <deal.II/base/exceptions.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace fdem
{
  namespace parameters
  {
    namespace
    {
      std::string
      trimmed(const std::string &text)
      {
        const auto first = text.find_first_not_of(" \t\r\n");
        if (first == std::string::npos)
          return "";
        return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
      }

      /// 0: a finite number, 1: no number, 2: not finite.
      int
      parse(const std::string &text, double &value)
      {
        const std::string number = trimmed(text);
        if (number.empty())
          return 1;
        char *end = nullptr;
        errno     = 0;
        value     = std::strtod(number.c_str(), &end);
        if (end == number.c_str() || *end != '\0')
          return 1;
        // ERANGE with a tiny result is an underflow to (almost) zero, which
        // is a number; with a huge one, the text is beyond a double.
        if (!std::isfinite(value) || (errno == ERANGE && std::abs(value) > 1))
          return 2;
        return 0;
      }

      double
      parse_or_zero(const std::string &text)
      {
        double value = 0;
        parse(text, value);
        return value;
      }
    } // namespace



    std::string
    number_problem(const std::string &text)
    {
      double    value  = 0;
      const int result = parse(text, value);
      return result == 0 ? "" :
                           "'" + trimmed(text) +
                             (result == 1 ? "' is not a number" :
                                            "' is not a finite number");
    }



    double
    finite_number(const std::string &text)
    {
      const std::string problem = number_problem(text);
      AssertThrow(problem.empty(), dealii::ExcMessage(problem + "."));
      return parse_or_zero(text);
    }



    std::vector<double>
    finite_numbers(const std::vector<std::string> &texts)
    {
      std::vector<double> values;
      values.reserve(texts.size());
      for (const std::string &text : texts)
        values.push_back(finite_number(text));
      return values;
    }



    bool
    read_finite_number(const std::string &text, double &value)
    {
      return parse(text, value) == 0;
    }
  } // namespace parameters
} // namespace fdem
