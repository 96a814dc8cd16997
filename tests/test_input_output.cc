// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
//
// The input's one number reader refuses what is not a finite number, the
// table reader takes a spreadsheet's byte order mark and names a folder,
// an output file whose write fails or that would hold a nan says so, and
// work the input makes too large is refused before it starts, and files
// name other files relative to themselves (issue: never lose a user's file,
// never accept a number that is not one).
#include <fdem/analyses/newmark.h>
#include <fdem/analyses/probabilistic.h>
#include <fdem/analyses/surface_search.h>
#include <fdem/parameters/numbers.h>
#include <fdem/parameters/parameter_file.h>
#include <fdem/parameters/parameters.h>
#include <fdem/parameters/work_estimate.h>
#include <fdem/postprocess/output_file.h>
#include <fdem/postprocess/output_files.h>
#include <fdem/postprocess/run_log.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

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

TEST(OutputFiles, ValueThatIsNotFiniteIsAnError)
{
  // A nan or inf among the results is a bug: the file says where it is
  // rather than passing it on (a CSV cell "nan", a null in JSON that reads
  // as a missing value).
  const std::string folder =
    std::filesystem::temp_directory_path() /
    ("fdem-output-files-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  const std::string csv     = folder + "/table.csv";
  const std::string message = io_error_message([&] {
    fdem::postprocess::OutputFile out(csv);
    out << "x,K\n" << 1.0 << ',' << 1.25 << '\n';
    out << 2.0 << ',' << std::numeric_limits<double>::quiet_NaN() << '\n';
    out << 3.0 << ',' << std::numeric_limits<double>::infinity() << '\n';
    out.close();
  });
  EXPECT_NE(message.find("the output file '" + csv +
                         "' would hold the value nan on line 3"),
            std::string::npos)
    << message;
  EXPECT_EQ(io_error_message([&] {
              fdem::postprocess::OutputFile out(csv);
              out << 1.0 << ',' << -1e308 << ',' << 0.0 << '\n';
              out.close();
            }),
            "");

  nlohmann::json summary;
  summary["status"]          = "completed";
  summary["methods"]         = nlohmann::json::array();
  summary["methods"][0]["K"] = 1.5;
  summary["methods"][1]["K"] = -std::numeric_limits<double>::infinity();
  summary["safety_factor"]   = nullptr;
  const std::string json     = folder + "/summary.json";
  const std::string json_message =
    io_error_message([&] { fdem::postprocess::write_json(json, summary); });
  EXPECT_NE(json_message.find("would hold a value that is not finite at "
                              "/methods/1/K"),
            std::string::npos)
    << json_message;
  EXPECT_FALSE(std::filesystem::exists(json));
  summary["methods"][1]["K"] = nullptr;
  EXPECT_EQ(io_error_message(
              [&] { fdem::postprocess::write_json(json, summary); }),
            "");
  EXPECT_TRUE(std::filesystem::exists(json));
  std::filesystem::remove_all(folder);
}

TEST(WorkEstimates, RefusedWithTheEntryTheEstimateAndTheOverride)
{
  // A search of 1000 x 1000 centres and 1000 tangent elevations: 1e9
  // circles of 50 slices, far beyond a day and any memory.
  fdem::analyses::SurfaceSearchParameters search;
  search.n_x = search.n_y = 1000;
  search.tangent_elevations.assign(1000, 1.0);
  const fdem::parameters::WorkEstimate circles =
    fdem::analyses::search_work_estimate(search);
  EXPECT_EQ(circles.what, "1e+09 circles");
  EXPECT_GT(circles.seconds, 86400);
  EXPECT_GT(circles.memory_MiB, 1e5);
  const std::string memory = io_error_message(
    [&] { fdem::parameters::check_work_estimate(circles, 24576, 86400); });
  EXPECT_EQ(memory.rfind("Surface search/Centre grid counts: 1e+09 circles "
                         "would need about ",
                         0),
            0u)
    << memory;
  EXPECT_NE(memory.find("more than the 24 GiB allowed (Geometry/Memory limit"),
            std::string::npos)
    << memory;
  // With memory enough, the time: the override is named.
  const std::string time = io_error_message(
    [&] { fdem::parameters::check_work_estimate(circles, 1e12, 86400); });
  EXPECT_NE(time.find("would take about "), std::string::npos) << time;
  EXPECT_NE(time.find("days, longer than Geometry/Time budget (24 h): ask for "
                      "fewer, or raise Geometry/Time budget (0: no limit)"),
            std::string::npos)
    << time;
  EXPECT_EQ(io_error_message(
              [&] { fdem::parameters::check_work_estimate(circles, 1e12, 0); }),
            "");
  // The default grid, 10 x 10 centres and three elevations, passes.
  search.n_x = search.n_y = 10;
  search.tangent_elevations.assign(3, 1.0);
  EXPECT_EQ(io_error_message([&] {
              fdem::parameters::check_work_estimate(
                fdem::analyses::search_work_estimate(search), 1024, 600);
            }),
            "");

  // 1e8 samples of four variables at 0.5 s each: years, and gigabytes.
  fdem::analyses::ProbabilisticParameters samples;
  samples.n_samples = 100000000;
  samples.variables.resize(4);
  const fdem::parameters::WorkEstimate work =
    fdem::analyses::sample_work_estimate(samples, 0.5, 0);
  EXPECT_EQ(work.what, "1e+08 samples");
  EXPECT_DOUBLE_EQ(work.seconds, 5e7);
  // 2 x 8 x 4 + 2 x 5 x 8 + 12 bytes per sample.
  EXPECT_NEAR(work.memory_MiB, 1e8 * 156 / 1048576., 1e-6);
  EXPECT_NE(io_error_message(
              [&] { fdem::parameters::check_work_estimate(work, 4096, 86400); })
              .find("Probabilistic/Number of samples: 1e+08 samples would "
                    "need about 14.5 GiB of memory"),
            std::string::npos);
  EXPECT_EQ(fdem::parameters::duration_text(40), "40 s");
  EXPECT_EQ(fdem::parameters::duration_text(720), "12 min");
  EXPECT_EQ(fdem::parameters::duration_text(5 * 3600), "5 h");
  EXPECT_EQ(fdem::parameters::duration_text(5e7), "579 days");
}

namespace
{
  /// A folder of its own under the temporary folder, removed at the end.
  struct TemporaryTree
  {
    std::filesystem::path root = std::filesystem::temp_directory_path() /
                                 ("fdem-paths-" + std::to_string(getpid()));

    TemporaryTree()
    {
      std::filesystem::create_directories(root / "case" / "shared");
    }
    ~TemporaryTree()
    {
      std::filesystem::remove_all(root);
    }
    void
    write(const std::string &name, const std::string &text) const
    {
      std::ofstream(root / name) << text;
    }
  };

  /// The four file entries in their subsections, as the program has them.
  void
  declare_file_entries(dealii::ParameterHandler &prm)
  {
    for (const std::string &entry : fdem::parameters::input_file_entries())
      {
        const auto parts = dealii::Utilities::split_string_list(entry, '/');
        for (unsigned int i = 0; i + 1 < parts.size(); ++i)
          prm.enter_subsection(parts[i]);
        prm.declare_entry(parts.back(), "", dealii::Patterns::FileName());
        for (unsigned int i = 0; i + 1 < parts.size(); ++i)
          prm.leave_subsection();
      }
  }

  std::string
  entry(dealii::ParameterHandler &prm, const std::string &path)
  {
    const auto parts = dealii::Utilities::split_string_list(path, '/');
    for (unsigned int i = 0; i + 1 < parts.size(); ++i)
      prm.enter_subsection(parts[i]);
    const std::string value = prm.get(parts.back());
    for (unsigned int i = 0; i + 1 < parts.size(); ++i)
      prm.leave_subsection();
    return value;
  }

  /// An entry's name as ParameterHandler's JSON output mangles it ("_20"
  /// for a blank) read back.
  std::string
  demangled(const std::string &key)
  {
    std::string name;
    for (std::size_t i = 0; i < key.size(); ++i)
      if (key[i] == '_' && i + 2 < key.size())
        {
          name += char(std::stoi(key.substr(i + 1, 2), nullptr, 16));
          i += 2;
        }
      else
        name += key[i];
    return name;
  }

  /// A handler of the file entries with @p file read into it, from the
  /// working directory @p folder.
  std::unique_ptr<fdem::parameters::FileRelativeParameterHandler>
  parsed(const std::string &file, const std::filesystem::path &folder);

  /// Runs @p action with the working directory @p folder.
  void
  in_folder(const std::filesystem::path &folder,
            const std::function<void()> &action)
  {
    const std::filesystem::path before = std::filesystem::current_path();
    std::filesystem::current_path(folder);
    try
      {
        action();
      }
    catch (...)
      {
        std::filesystem::current_path(before);
        throw;
      }
    std::filesystem::current_path(before);
  }

  std::unique_ptr<fdem::parameters::FileRelativeParameterHandler>
  parsed(const std::string &file, const std::filesystem::path &folder)
  {
    auto prm = std::make_unique<fdem::parameters::FileRelativeParameterHandler>(
      fdem::parameters::input_file_entries());
    declare_file_entries(*prm);
    in_folder(folder, [&] {
      fdem::parameters::parse_parameter_file(*prm, file, false);
    });
    return prm;
  }
} // namespace

TEST(ParameterFiles, PathsRelativeToTheFileThatNamesThem)
{
  const TemporaryTree tree;
  // An include and a file entry over two lines in the top file; in the
  // included file, one in another folder, two entries of its own.
  tree.write("case/main.prm",
             "include shared/base.prm\n"
             "subsection Geometry\n"
             "  set Mesh file = \\\n"
             "      meshes/a.msh\n"
             "end\n");
  tree.write("case/shared/base.prm",
             "subsection Water\n"
             "  set Piezometric surface file = water.csv\n"
             "end\n"
             "subsection Yield acceleration\n"
             "  set Acceleration record = records/quake.csv # a comment\n"
             "end\n"
             "subsection Geometry\n"
             "  subsection Slope 3D\n"
             "    set Terrain file = /data/terrain.csv\n"
             "  end\n"
             "end\n");
  // From a working directory that is neither file's folder.
  const std::filesystem::path root = tree.root;
  const auto prm = parsed((root / "case/main.prm").string(), "/");
  EXPECT_EQ(entry(*prm, "Geometry/Mesh file"),
            (root / "case/meshes/a.msh").string());
  EXPECT_EQ(entry(*prm, "Water/Piezometric surface file"),
            (root / "case/shared/water.csv").string());
  EXPECT_EQ(entry(*prm, "Yield acceleration/Acceleration record"),
            (root / "case/shared/records/quake.csv").string());
  EXPECT_EQ(entry(*prm, "Geometry/Slope 3D/Terrain file"), "/data/terrain.csv");

  // The top file named relative to the working directory: the names stay
  // relative to it.
  const auto relative = parsed("case/main.prm", root);
  EXPECT_EQ(entry(*relative, "Geometry/Mesh file"), "case/meshes/a.msh");
  EXPECT_EQ(entry(*relative, "Water/Piezometric surface file"),
            "case/shared/water.csv");

  // deal.II's line numbers are the file's own after the two-line entry.
  tree.write("case/typo.prm",
             "subsection Geometry\n"
             "  set Mesh file = \\\n"
             "      a.msh\n"
             "end\n"
             "set No such entry = 1\n");
  const std::string message =
    io_error_message([&] { parsed((root / "case/typo.prm").string(), root); });
  EXPECT_NE(message.find("Line <5>"), std::string::npos) << message;

  // A missing include is named as the program looked for it.
  tree.write("case/shared/missing.prm", "include neighbour.prm\n");
  const std::string missing = io_error_message(
    [&] { parsed((root / "case/shared/missing.prm").string(), "/"); });
  EXPECT_NE(missing.find("the included file '" +
                         (root / "case/shared/neighbour.prm").string() +
                         "': no such file."),
            std::string::npos)
    << missing;
}

TEST(ParameterFiles, FileEntriesOfAJsonFile)
{
  const TemporaryTree tree;
  tree.write("case/main.json",
             R"({"Geometry": {"Mesh file": "meshes/a.msh"}})");
  const auto prm = parsed((tree.root / "case/main.json").string(), "/");
  EXPECT_EQ(entry(*prm, "Geometry/Mesh file"),
            (tree.root / "case/meshes/a.msh").string());
}

TEST(ParameterFiles, EveryFileEntryIsResolved)
{
  // Every entry whose pattern is a file name is in the list the handler
  // resolves, and every listed entry is one: a new file entry cannot be
  // read relative to the working directory by mistake.
  dealii::ParameterHandler prm;
  fdem::parameters::Parameters::declare_parameters(
    prm, {"block"}, {"boundary"}, {"interface"}, {"material"});
  std::ostringstream json;
  prm.print_parameters(json, dealii::ParameterHandler::JSON);
  std::vector<std::string>                                               found;
  const std::function<void(const nlohmann::json &, const std::string &)> visit =
    [&](const nlohmann::json &node, const std::string &path) {
      for (const auto &[key, value] : node.items())
        {
          if (!value.is_object())
            continue;
          const std::string name = path + demangled(key);
          if (value.contains("pattern_description"))
            {
              if (value["pattern_description"].get<std::string>().find(
                    "FileName") != std::string::npos)
                found.push_back(name);
            }
          else
            visit(value, name + "/");
        }
    };
  visit(nlohmann::json::parse(json.str()), "");
  std::vector<std::string> listed = fdem::parameters::input_file_entries();
  std::sort(found.begin(), found.end());
  std::sort(listed.begin(), listed.end());
  EXPECT_EQ(found, listed);
}
