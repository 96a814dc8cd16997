// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#ifndef fdem_parameters_numbers_h
#define fdem_parameters_numbers_h

#include <string>
#include <vector>

namespace fdem
{
  namespace parameters
  {
    /**
     * The one number reader of the input: @p text (blanks around it
     * allowed) read whole as a double that must be finite. Throws "'<text>'
     * is not a number." or "'<text>' is not a finite number." (nan, inf,
     * or out of a double's range such as 1e999), which the callers prefix
     * with the entry or file they read. Every entry, point list and table
     * value goes through it, so that no NaN reaches the model.
     */
    double
    finite_number(const std::string &text);

    /// finite_number() of each of @p texts.
    std::vector<double>
    finite_numbers(const std::vector<std::string> &texts);

    /// Whether @p text is a finite number; if so, @p value is it.
    bool
    read_finite_number(const std::string &text, double &value);

    /// What is wrong with @p text as a finite number: "'x' is not a
    /// number", "'nan' is not a finite number", or "" if nothing is.
    std::string
    number_problem(const std::string &text);
  } // namespace parameters
} // namespace fdem

#endif
