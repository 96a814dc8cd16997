// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The input's one number reader refuses what is not a finite number, the
// table reader takes a spreadsheet's byte order mark and names a folder,
// and an output file whose write fails says so (issue: never lose a
// user's file, never accept a number that is not one).
#include <fdem/analyses/newmark.h>
#include <fdem/parameters/numbers.h>
#include <fdem/postprocess/output_file.h>
#include <fdem/postprocess/run_log.h>

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

namespace
{
  using fdem::parameters::finite_number;
  using fdem::parameters::number_problem;

  std::string
  io_error_message(const std::function<void()> &action)
  {
    try
      {
        action();
      }
    catch (const std::exception &error)
      {
        return fdem::postprocess::one_line(error);
      }
    return "";
  }
} // namespace

TEST(InputNumbers, FiniteNumbersOnly)
{
  EXPECT_EQ(finite_number(" 2.5 "), 2.5);
  EXPECT_EQ(finite_number("-1e300"), -1e300);
  // An underflow is a number close to zero, not an error.
  EXPECT_GE(finite_number("1e-320"), 0.0);
  EXPECT_LT(finite_number("1e-320"), 1e-300);
  for (const char *text : {"nan", "NaN", "inf", "-inf", "1e999", "-1e400"})
    EXPECT_EQ(number_problem(text),
              "'" + std::string(text) + "' is not a finite number")
      << text;
  for (const char *text : {"", "abc", "1,2", "2.5x", "0x"})
    EXPECT_EQ(number_problem(text).find("is not a number") != std::string::npos,
              true)
      << text;
  EXPECT_NE(io_error_message([] {
              finite_number("nan");
            }).find("'nan' is not a finite number."),
            std::string::npos);
}

TEST(InputNumbers, TableWithByteOrderMarkAndFolder)
{
  const std::string file = std::filesystem::temp_directory_path() /
                           ("fdem-bom-" + std::to_string(getpid()) + ".csv");
  {
    std::ofstream out(file);
    out << "\xEF\xBB\xBFtime,acceleration\n0,0\n0.01,0.1\n0.02,0\n";
  }
  const auto record = fdem::analyses::read_acceleration_record(file, "g");
  std::remove(file.c_str());
  ASSERT_EQ(record.time.size(), 3u);
  EXPECT_DOUBLE_EQ(record.acceleration[1],
                   0.1 * fdem::analyses::standard_gravity);
  const std::string folder  = std::filesystem::temp_directory_path();
  const std::string message = io_error_message(
    [&] { fdem::analyses::read_acceleration_record(folder, "g"); });
  EXPECT_NE(message.find("is a folder, not a file."), std::string::npos)
    << message;
}

TEST(OutputFiles, FailedWriteIsAnError)
{
  // /dev/full: every write fails with ENOSPC, as on a full disk.
  const std::string text(1 << 16, 'x');
  const std::string message = io_error_message([&] {
    fdem::postprocess::OutputFile out("/dev/full");
    out << text;
    out.close();
  });
  EXPECT_NE(message.find("cannot write the output file '/dev/full': No space "
                         "left on device."),
            std::string::npos)
    << message;
  EXPECT_NE(io_error_message([] {
              fdem::postprocess::write_text_file("/nonexistent-folder/a.txt",
                                                 "a");
            }).find("cannot create the output file"),
            std::string::npos);
}
