// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <string>

namespace fdem
{
  namespace test_support
  {
    /** The repository's folder (the tests' .prm, .geo and data files). */
    std::string
    source_dir();
  } // namespace test_support
} // namespace fdem
