// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/postprocess/output_file.h>
#include <fdem/postprocess/results_folder.h>
#include <fdem/postprocess/run_log.h>

#include <deal.II/base/exceptions.h>

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace fdem
{
  namespace postprocess
  {
    namespace
    {
      namespace fs = std::filesystem;

      // The partial folder a signal must remove: a fixed buffer, since a
      // signal handler may not allocate.
      char partial_folder[4096] = "";

      /**
       * Removes the (flat) partial folder with system calls only, which a
       * signal handler may make, then dies of the signal as it would have.
       */
      extern "C" void
      remove_partial_folder_and_die(const int signal)
      {
        remove_partial_folder();
        std::signal(signal, SIG_DFL);
        raise(signal);
      }

      constexpr int signals[] = {SIGINT, SIGTERM, SIGHUP};

      std::string
      host_name()
      {
        char name[256] = "";
        if (gethostname(name, sizeof name - 1) != 0)
          return "unknown";
        return name;
      }

      /// The absolute, normalised form of @p path, without a trailing '/'.
      fs::path
      absolute_path(const std::string &path)
      {
        fs::path result = fs::absolute(fs::path(path)).lexically_normal();
        if (result.filename().empty() && result.has_parent_path() &&
            result != result.root_path())
          result = result.parent_path();
        return result;
      }

      /// Whether @p folder is @p path or one of the folders above it, once
      /// symbolic links are resolved.
      bool
      contains_or_is(const fs::path &folder, const fs::path &path)
      {
        std::error_code error;
        const fs::path  a = fs::weakly_canonical(folder, error);
        const fs::path  b = fs::weakly_canonical(path, error);
        if (error)
          return false;
        auto i = a.begin(), j = b.begin();
        for (; i != a.end() && j != b.end(); ++i, ++j)
          if (*i != *j)
            break;
        // An empty last component is the trailing '/' of "/".
        return i == a.end() || (std::next(i) == a.end() && i->empty());
      }

      /// The entries of the marker file of @p folder ("key: value" lines);
      /// empty if it has none.
      std::map<std::string, std::string>
      read_marker(const fs::path &folder)
      {
        std::map<std::string, std::string> entries;
        std::ifstream                      in(folder / results_marker);
        std::string                        line;
        while (std::getline(in, line))
          if (const auto colon = line.find(": "); colon != std::string::npos)
            entries[line.substr(0, colon)] = line.substr(colon + 2);
        return entries;
      }

      bool
      has_marker(const fs::path &folder)
      {
        std::error_code error;
        return fs::is_regular_file(
                 fs::symlink_status(folder / results_marker, error)) &&
               read_marker(folder).count("program") == 1;
      }

      /**
       * Refuses @p path, the results folder or its `.previous` (@p role says
       * which, for the message), unless it is absent or a folder with the
       * marker: a folder without it is the user's, even an empty one.
       */
      void
      check_replaceable(const fs::path &path, const std::string &role)
      {
        std::error_code       error;
        const fs::file_status status = fs::symlink_status(path, error);
        if (!fs::exists(status))
          return;
        const std::string name =
          "Output/Directory: " + role + "'" + path.string() + "'";
        AssertThrow(!fs::is_symlink(status),
                    dealii::ExcMessage(
                      name + " is a symbolic link; name the folder itself "
                             "(fdem-slope replaces a results folder by "
                             "renaming, which would move the link)."));
        AssertThrow(fs::is_directory(status),
                    dealii::ExcMessage(
                      name + " is a file, not a results folder of "
                             "fdem-slope; choose another Directory or move "
                             "the file."));
        AssertThrow(
          has_marker(path),
          dealii::ExcMessage(
            name + " is a folder that fdem-slope did not make (it has no " +
            results_marker +
            "); fdem-slope replaces only its own results folders: choose "
            "another Directory, or move or remove this folder yourself."));
      }

      /// Holds an exclusive lock on a folder (flock) while it lives.
      class FolderLock
      {
      public:
        explicit FolderLock(const fs::path &folder)
          : descriptor(open(folder.c_str(), O_RDONLY | O_DIRECTORY))
        {
          AssertThrow(descriptor >= 0 && flock(descriptor, LOCK_EX) == 0,
                      dealii::ExcMessage("Output/Directory: cannot lock '" +
                                         folder.string() +
                                         "': " + std::strerror(errno) + "."));
        }
        ~FolderLock()
        {
          flock(descriptor, LOCK_UN);
          close(descriptor);
        }
        FolderLock(const FolderLock &) = delete;
        FolderLock &
        operator=(const FolderLock &) = delete;

      private:
        int descriptor;
      };

      /// Whether no process of this host has the number @p pid.
      bool
      process_is_gone(const std::string &pid)
      {
        if (pid.empty() ||
            pid.find_first_not_of("0123456789") != std::string::npos ||
            pid.size() > 9)
          return false;
        return kill(std::stoi(pid), 0) != 0 && errno == ESRCH;
      }
    } // namespace



    void
    remove_partial_folder()
    {
      if (partial_folder[0] != '\0')
        {
          const int folder = open(partial_folder, O_RDONLY | O_DIRECTORY);
          if (folder >= 0)
            {
              char buffer[8192];
              long n;
              while (
                (n = syscall(SYS_getdents64, folder, buffer, sizeof buffer)) >
                0)
                for (long offset = 0; offset < n;)
                  {
                    struct Entry
                    {
                      ino64_t        d_ino;
                      off64_t        d_off;
                      unsigned short d_reclen;
                      unsigned char  d_type;
                      char           d_name[1];
                    };
                    const auto *entry =
                      reinterpret_cast<const Entry *>(buffer + offset);
                    if (std::strcmp(entry->d_name, ".") != 0 &&
                        std::strcmp(entry->d_name, "..") != 0)
                      unlinkat(folder, entry->d_name, 0);
                    offset += entry->d_reclen;
                  }
              close(folder);
            }
          rmdir(partial_folder);
        }
    }



    void
    exit_out_of_memory()
    {
      static const char message[] =
        "fdem-slope: error: out of memory: the model needs more memory than "
        "this machine (or ulimit -v) gives; use a coarser mesh (Geometry/"
        "Memory limit bounds the estimate made before meshing).\n";
      if (write(STDERR_FILENO, message, sizeof message - 1) < 0)
        {
          // Nothing else to tell.
        }
      remove_partial_folder();
      _exit(1);
    }



    void
    check_results_target(const std::string &target_name,
                         const std::string &prm_file)
    {
      const fs::path target = absolute_path(target_name);
      const fs::path prm_folder =
        absolute_path(prm_file.empty() ? "." : prm_file).parent_path();
      // A link first: its folder would be judged, not the link.
      check_replaceable(target.string() + ".previous", "the previous results ");
      std::error_code error;
      if (!fs::is_symlink(fs::symlink_status(target, error)))
        {
          AssertThrow(!contains_or_is(target, fs::current_path()),
                      dealii::ExcMessage(
                        "Output/Directory: '" + target_name +
                        "' is the working folder or a folder above it; give "
                        "the results a folder of their own (an empty "
                        "Directory means '<case name>-output')."));
          AssertThrow(!contains_or_is(target, prm_folder),
                      dealii::ExcMessage(
                        "Output/Directory: '" + target_name +
                        "' is the folder of " + prm_file +
                        " or a folder above it; give the results a folder "
                        "of their own (an empty Directory means '<case "
                        "name>-output')."));
        }
      check_replaceable(target, "");
    }



    ResultsFolder::ResultsFolder(const std::string &target_name,
                                 const std::string &prm_file,
                                 const bool         writes_files)
      : target(absolute_path(target_name).string())
      , prm_file(prm_file)
      , writes_files(writes_files)
    {
      check_results_target(target_name, prm_file);
      // The partial folder goes beside the target; errors name it as the
      // user wrote it.
      fs::path path = fs::path(target_name).lexically_normal();
      if (path.filename().empty())
        path = path.parent_path();
      staging_directory =
        path.string() + ".partial-" + std::to_string(getpid());
      if (!writes_files)
        return;
      AssertThrow(staging_directory.size() < sizeof partial_folder,
                  dealii::ExcMessage(
                    "Output/Directory: the path is too long."));
      remove_stale_partial_folders();
      std::error_code error;
      fs::create_directories(staging_directory, error);
      AssertThrow(!error && fs::is_empty(staging_directory, error),
                  dealii::ExcMessage(
                    "Output/Directory: cannot create '" + staging_directory +
                    "' beside '" + target_name + "': " +
                    (error ? error.message() : "it exists and is not empty") +
                    "."));
      std::strcpy(partial_folder, staging_directory.c_str());
      for (const int s : signals)
        std::signal(s, remove_partial_folder_and_die);
      const std::time_t now = std::time(nullptr);
      char              started[32];
      std::strftime(started,
                    sizeof started,
                    "%Y-%m-%dT%H:%M:%SZ",
                    std::gmtime(&now));
      write_text_file(staging_directory + "/" + results_marker,
                      "program: fdem-slope\nhost: " + host_name() + "\npid: " +
                        std::to_string(getpid()) + "\nstarted: " + started +
                        "\ncase: " + absolute_path(prm_file).string() +
                        "\nnote: fdem-slope replaces or removes only folders "
                        "that hold this file.\n");
    }



    ResultsFolder::~ResultsFolder()
    {
      if (!writes_files)
        return;
      for (const int s : signals)
        std::signal(s, SIG_DFL);
      partial_folder[0] = '\0';
      if (!keep_staging)
        {
          std::error_code error;
          if (has_marker(staging_directory))
            fs::remove_all(staging_directory, error);
        }
    }



    void
    ResultsFolder::remove_stale_partial_folders() const
    {
      const fs::path    path   = target;
      const fs::path    parent = path.parent_path();
      const std::string prefix = path.filename().string() + ".partial-";
      std::error_code   error;
      for (fs::directory_iterator entry(parent, error), end;
           !error && entry != end;
           entry.increment(error))
        {
          const std::string name = entry->path().filename().string();
          if (name.rfind(prefix, 0) != 0 ||
              !fs::is_directory(fs::symlink_status(entry->path(), error)))
            continue;
          // A folder with this process's number is a dead run's too: this
          // run has not made its own yet.
          const std::string pid = name.substr(prefix.size());
          const bool        gone =
            process_is_gone(pid) || pid == std::to_string(getpid());
          const auto marker = read_marker(entry->path());
          const bool made_here =
            marker.count("program") == 1 && marker.count("pid") == 1 &&
            marker.at("pid") == pid && marker.count("host") == 1 &&
            marker.at("host") == host_name();
          std::error_code ignored;
          if (gone && made_here)
            fs::remove_all(entry->path(), ignored);
        }
    }



    void
    ResultsFolder::swap_into_place() const
    {
      const fs::path path     = target;
      const fs::path previous = target + ".previous";
      // symlink_status() of a missing path is an error too: its own code.
      std::error_code missing, error;
      if (fs::exists(fs::symlink_status(previous, missing)))
        fs::remove_all(previous, error);
      if (!error && fs::exists(fs::symlink_status(path, missing)))
        {
          fs::rename(path, previous, error); // checked: it has the marker
        }
      if (!error)
        fs::rename(staging_directory, path, error);
      AssertThrow(!error,
                  dealii::ExcMessage(
                    "Output/Directory: cannot move the results into '" +
                    path.string() + "': " + error.message() + "."));
    }



    void
    ResultsFolder::commit()
    {
      if (!writes_files)
        return;
      // The swap happens under a lock on the folder that holds the target,
      // so that runs into one folder take turns; the checks are made again
      // under it, since the user may have put files there during the run.
      try
        {
          const FolderLock lock(fs::path(target).parent_path());
          check_results_target(target, prm_file);
          swap_into_place();
        }
      catch (const std::exception &error)
        {
          keep_staging      = true;
          partial_folder[0] = '\0';
          AssertThrow(false,
                      dealii::ExcMessage(one_line(error) +
                                         " This run's results are in '" +
                                         staging_directory + "'."));
        }
      keep_staging      = true;
      partial_folder[0] = '\0';
    }
  } // namespace postprocess
} // namespace fdem
