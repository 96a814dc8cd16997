// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/postprocess/run_log.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <iostream>
#include <regex>

namespace fdem
{
  namespace postprocess
  {
    void
    TeeBuffer::add(std::streambuf *target)
    {
      targets.push_back(target);
    }

    TeeBuffer::int_type
    TeeBuffer::overflow(const int_type c)
    {
      if (traits_type::eq_int_type(c, traits_type::eof()))
        return traits_type::not_eof(c);
      for (std::streambuf *target : targets)
        if (traits_type::eq_int_type(
              target->sputc(traits_type::to_char_type(c)), traits_type::eof()))
          failed_targets.push_back(target);
      return c;
    }

    std::streamsize
    TeeBuffer::xsputn(const char *text, const std::streamsize n)
    {
      for (std::streambuf *target : targets)
        if (target->sputn(text, n) != n)
          failed_targets.push_back(target);
      return n;
    }

    bool
    TeeBuffer::wrote_all_to(const std::streambuf *target) const
    {
      return std::find(failed_targets.begin(), failed_targets.end(), target) ==
             failed_targets.end();
    }

    int
    TeeBuffer::sync()
    {
      int result = 0;
      for (std::streambuf *target : targets)
        if (target->pubsync() != 0)
          result = -1;
      return result;
    }

    RunLog::RunLog(const Verbosity verbosity, const bool prints)
      : screen_verbosity(verbosity)
      , prints(prints)
      , brief_stream(&brief_buffer)
      , detail_stream(&detail_buffer)
    {
      if (!prints)
        return;
      if (verbosity != Verbosity::quiet)
        brief_buffer.add(std::cout.rdbuf());
      if (verbosity == Verbosity::verbose)
        detail_buffer.add(std::cout.rdbuf());
    }

    void
    RunLog::open_file(const std::string &path)
    {
      if (!prints)
        return;
      file.open(path);
      AssertThrow(file,
                  dealii::ExcMessage(
                    "Output/Directory: cannot write the log file " + path +
                    "."));
      brief_buffer.add(file.rdbuf());
      detail_buffer.add(file.rdbuf());
      file_name = path;
    }

    void
    RunLog::check_file()
    {
      if (!prints || !file.is_open())
        return;
      brief_stream.flush();
      detail_stream.flush();
      errno              = 0;
      const bool flushed = file.rdbuf()->pubsync() == 0;
      AssertThrow(flushed && brief_buffer.wrote_all_to(file.rdbuf()) &&
                    detail_buffer.wrote_all_to(file.rdbuf()),
                  dealii::ExcMessage(
                    "cannot write the output file '" + file_name + "': " +
                    (errno != 0 ? std::strerror(errno) : "the write failed") +
                    "."));
    }

    std::string
    warning_text(const std::string &id, const std::string &text)
    {
      return "[" + id + "] " + text;
    }

    std::string
    note_text(const std::string &id, const std::string &text)
    {
      return "[" + id + "] " + text;
    }

    std::string
    message_id(const std::string &message)
    {
      const auto end = message.find("] ");
      if (message.empty() || message[0] != '[' || end == std::string::npos)
        return "";
      return message.substr(1, end - 1);
    }

    std::string
    one_line(const std::exception &error)
    {
      std::string       text   = error.what();
      const std::string marker = "Additional information:";
      const auto        start  = text.find(marker);
      if (start != std::string::npos)
        text = text.substr(start + marker.size());
      text = text.substr(0, text.find("Stacktrace:"));
      text = std::regex_replace(text, std::regex("-{10,}"), " ");
      text = std::regex_replace(text, std::regex("\\s+"), " ");
      return std::regex_replace(text, std::regex("^ | $"), "");
    }
  } // namespace postprocess
} // namespace fdem
