// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#pragma once

#include <exception>
#include <fstream>
#include <memory>
#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

namespace fdem
{
  namespace postprocess
  {
    /**
     * How much of the run's log reaches the screen (doc/troubleshooting.md,
     * "What the program prints"): `--quiet` (nothing but one line with K),
     * the default (the case, the model, one line per safety-factor step and
     * the result block) or `--verbose` (everything, as the log file).
     */
    enum class Verbosity
    {
      quiet,
      normal,
      verbose
    };

    /**
     * A stream buffer that writes everything it is given to each of its
     * targets (none: the text is dropped).
     */
    class TeeBuffer : public std::streambuf
    {
    public:
      /** Adds @p target; it must outlive this buffer. */
      void
      add(std::streambuf *target);

      /** Whether every write to @p target so far took all it was given. */
      bool
      wrote_all_to(const std::streambuf *target) const;

    protected:
      int_type
      overflow(int_type c) override;
      std::streamsize
      xsputn(const char *text, std::streamsize n) override;
      int
      sync() override;

    private:
      std::vector<std::streambuf *>       targets;
      std::vector<const std::streambuf *> failed_targets;
    };

    /**
     * The run's log in two levels, one verbosity mechanism for the whole
     * program: brief() takes the lines of the default screen, detail() the
     * rest (contact iterations, solver notes, time and memory stamps). Both
     * go to the log file once open_file() has opened it; the screen gets
     * brief() unless quiet, and detail() only when verbose. Only the process
     * that prints (rank 0 under MPI) has a screen or a file.
     */
    class RunLog
    {
    public:
      RunLog(Verbosity verbosity, bool prints);
      RunLog(const RunLog &) = delete;
      RunLog &
      operator=(const RunLog &) = delete;

      /** From now on both levels also go to the file @p path (truncated). */
      void
      open_file(const std::string &path);

      /**
       * Flushes the log file and throws, naming it, if any write to it
       * failed (a full disk): a run whose log was cut does not end as
       * completed. The file stays open.
       */
      void
      check_file();

      /** The lines an engineer reads: the default screen. */
      std::ostream &
      brief()
      {
        return brief_stream;
      }

      /** Everything else: on the screen with --verbose, always in the file. */
      std::ostream &
      detail()
      {
        return detail_stream;
      }

      /** The verbosity of the screen. */
      Verbosity
      verbosity() const
      {
        return screen_verbosity;
      }

    private:
      Verbosity     screen_verbosity;
      bool          prints;
      std::ofstream file;
      std::string   file_name;
      TeeBuffer     brief_buffer, detail_buffer;
      std::ostream  brief_stream, detail_stream;
    };

    /**
     * A warning of the run, "[id] text": @p id is short, fixed and listed
     * in doc/troubleshooting.md with what it means and what to do (a test
     * checks that every id used in the sources is listed there).
     */
    std::string
    warning_text(const std::string &id, const std::string &text);

    /**
     * A note of the run, "[id] text", for the log file and summary.json
     * only (see conditioning_changes_answer() for when one reaches the
     * screen); its id is listed in doc/troubleshooting.md as a warning's is.
     */
    std::string
    note_text(const std::string &id, const std::string &text);

    /** The id of a warning or note made by warning_text() or note_text(), or
     * "". */
    std::string
    message_id(const std::string &message);

    /**
     * The reason of an error on one line: deal.II's exception text has the
     * file, line and condition of the check around the message; a user
     * needs only the message (the `fdem-slope: error:` line, a candidate's
     * status in search.csv).
     */
    std::string
    one_line(const std::exception &error);
  } // namespace postprocess
} // namespace fdem
