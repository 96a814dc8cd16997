// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#ifndef fdem_postprocess_json_number_h
#define fdem_postprocess_json_number_h

#include <nlohmann/json.hpp>

#include <cmath>

namespace fdem
{
  namespace postprocess
  {
    /**
     * @p x as a JSON number, or null where it is not finite (JSON has no
     * infinity or NaN): the summary's one form of a value that may be
     * missing, such as a limit-equilibrium factor with no driving force.
     */
    inline nlohmann::json
    number_or_null(const double x)
    {
      return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
    }
  } // namespace postprocess
} // namespace fdem

#endif
