// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The report of a run (report.html) is made by a Python script, since the
// plots need a plotting library the program does not link; the program
// only finds and runs it, and records what came of it.
#include <fdem/postprocess/output_files.h>
#include <fdem/postprocess/report.h>
#include <fdem/postprocess/run_log.h>

#include <pthread.h>
#include <sys/wait.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iomanip>

// The Python found when the program was configured (CMakeLists.txt).
#ifndef FDEM_PYTHON
#  define FDEM_PYTHON "python3"
#endif

namespace fdem
{
  namespace postprocess
  {
    namespace
    {
      namespace fs = std::filesystem;

      /** @p text quoted for /bin/sh. */
      std::string
      quoted(const std::string &text)
      {
        std::string out = "'";
        for (const char c : text)
          out += c == '\'' ? std::string("'\\''") : std::string(1, c);
        return out + "'";
      }

      /** The last non-empty line of @p text, trimmed. */
      std::string
      last_line(const std::string &text)
      {
        std::string line, last;
        for (const char c : text + "\n")
          if (c == '\n')
            {
              const auto first = line.find_first_not_of(" \t\r");
              if (first != std::string::npos)
                last = line.substr(first,
                                   line.find_last_not_of(" \t\r") + 1 - first);
              line.clear();
            }
          else
            line += c;
        return last;
      }
    } // namespace

    std::string
    report_script()
    {
      std::error_code error;
      const fs::path  exe = fs::read_symlink("/proc/self/exe", error);
      if (error)
        return "";
      for (const fs::path &candidate :
           {exe.parent_path() / "share" / "fdem-slope" / "fdem_report.py",
            exe.parent_path().parent_path() / "share" / "fdem-slope" /
              "fdem_report.py"})
        if (fs::is_regular_file(candidate, error))
          return candidate.string();
      return "";
    }

    void
    make_report(const std::string &folder,
                nlohmann::json    &summary,
                std::ostream      &log)
    {
      const auto start  = std::chrono::steady_clock::now();
      const auto script = report_script();
      // FDEM_PYTHON in the environment names another Python (one with
      // matplotlib where the configured one has none).
      const char       *chosen = std::getenv("FDEM_PYTHON");
      const std::string python =
        chosen != nullptr && *chosen != '\0' ? chosen : FDEM_PYTHON;
      std::string reason;
      if (script.empty())
        reason =
          "fdem_report.py is not installed beside the program (share/fdem-slope/)";
      else
        {
          // Exit codes: 0 made; 3 a Python module is missing (the script
          // says which); 127 no Python (from the shell).
          const std::string command = quoted(python) + " " + quoted(script) +
                                      " " + quoted(folder) + " 2>&1";
          // SIGINT, SIGTERM and SIGHUP wait until the script is done: their
          // handler removes the partial folder, which the script would
          // otherwise go on writing into (the folder must end whole or
          // absent). The script inherits the mask; it takes about a second.
          sigset_t stopping, previous;
          sigemptyset(&stopping);
          for (const int s : {SIGINT, SIGTERM, SIGHUP})
            sigaddset(&stopping, s);
          pthread_sigmask(SIG_BLOCK, &stopping, &previous);
          std::string output;
          if (FILE *pipe = popen(command.c_str(), "r"))
            {
              char        buffer[4096];
              std::size_t n;
              while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0)
                output.append(buffer, n);
              const int status = pclose(pipe);
              const int code   = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
              if (code == 127)
                reason = "no Python at " + python;
              else if (code != 0)
                reason = last_line(output).empty() ?
                           "fdem_report.py failed (exit code " +
                             std::to_string(code) + ")" :
                           last_line(output);
            }
          else
            reason = "cannot start " + python;
          pthread_sigmask(SIG_SETMASK, &previous, nullptr);
        }
      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
      if (reason.empty())
        {
          summary["report"] = {{"made", true},
                               {"file", "report.html"},
                               {"wall_seconds", seconds}};
          log << "Report: report.html (" << std::fixed << std::setprecision(2)
              << seconds << " s, not part of the run's timings)"
              << std::defaultfloat << std::endl;
        }
      else
        {
          summary["report"] = {{"made", false},
                               {"reason", reason},
                               {"wall_seconds", seconds}};
          // The caller shows the warning: it belongs on the screen.
          summary["warnings"].push_back(warning_text("no-report", reason));
        }
      write_json(folder + "/summary.json", summary);
    }
  } // namespace postprocess
} // namespace fdem
