// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

namespace fdem
{
  namespace postprocess
  {
    /**
     * The report post-processor installed with the program,
     * fdem_report.py: beside the executable in share/fdem-slope/ (the build
     * tree) or in ../share/fdem-slope/ (an installed program). Empty if
     * neither holds it.
     */
    std::string
    report_script();

    /**
     * Makes report.html and its PNGs in @p folder (a run's finished
     * folder, holding summary.json) with fdem_report.py under the Python
     * found when the program was configured, and records in @p summary and
     * in @p folder/summary.json whether it was made ("report": made, file
     * or reason, wall_seconds). Without Python, matplotlib or the script,
     * or if the script fails, the run goes on: the reason in
     * summary.json's "report" and, as the warning [no-report], as the last of
     * its "warnings" (the caller shows it). The
     * report's wall time goes to @p log; it is not part of the run's
     * "timings".
     */
    void
    make_report(const std::string &folder,
                nlohmann::json    &summary,
                std::ostream      &log);
  } // namespace postprocess
} // namespace fdem
