// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/contact/contact_law.h>

namespace fdem
{
  namespace contact
  {
    std::string
    status_name(const PairStatus status)
    {
      switch (status)
        {
          case PairStatus::stick:
            return "stick";
          case PairStatus::slip:
            return "slip";
          default:
            return "open";
        }
    }
  } // namespace contact
} // namespace fdem
