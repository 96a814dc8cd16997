// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/postprocess/results_folder.h>

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
#include <filesystem>

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



    ResultsFolder::ResultsFolder(const std::string &target_name,
                                 const bool         writes_files)
      : writes_files(writes_files)
    {
      // "out/" and "out" are one folder; the partial one goes beside it.
      fs::path path = fs::path(target_name).lexically_normal();
      if (path.filename().empty())
        path = path.parent_path();
      target            = path.string();
      staging_directory = target + ".partial-" + std::to_string(getpid());
      if (!writes_files)
        return;
      std::error_code error;
      fs::remove_all(staging_directory, error); // of a dead run with this pid
      fs::create_directories(staging_directory, error);
      AssertThrow(!error,
                  dealii::ExcMessage("Output/Directory: cannot create '" +
                                     staging_directory + "' beside '" + target +
                                     "': " + error.message() + "."));
      AssertThrow(staging_directory.size() < sizeof partial_folder,
                  dealii::ExcMessage(
                    "Output/Directory: the path is too long."));
      std::strcpy(partial_folder, staging_directory.c_str());
      for (const int s : signals)
        std::signal(s, remove_partial_folder_and_die);
    }



    ResultsFolder::~ResultsFolder()
    {
      if (!writes_files)
        return;
      for (const int s : signals)
        std::signal(s, SIG_DFL);
      partial_folder[0] = '\0';
      if (!committed)
        {
          std::error_code error;
          fs::remove_all(staging_directory, error);
        }
    }



    void
    ResultsFolder::commit()
    {
      if (!writes_files)
        return;
      // The lock file goes once the swap is done, without reopening the race
      // it closes: a run that waited on the lock of a file that has since
      // been removed holds a lock nobody else respects, so after locking it
      // checks that its file is still the one at that path, and otherwise
      // starts again with the new file. Only the holder removes the file,
      // while it holds the lock, so the file at the path and its lock holder
      // are always one.
      const std::string lock_file = target + ".lock";
      int               lock      = -1;
      for (;;)
        {
          lock = open(lock_file.c_str(), O_RDWR | O_CREAT, 0644);
          AssertThrow(lock >= 0,
                      dealii::ExcMessage("Output/Directory: cannot create '" +
                                         lock_file +
                                         "': " + std::strerror(errno) + "."));
          flock(lock, LOCK_EX);
          struct stat locked, named;
          if (fstat(lock, &locked) == 0 &&
              stat(lock_file.c_str(), &named) == 0 &&
              locked.st_dev == named.st_dev && locked.st_ino == named.st_ino)
            break;
          close(lock);
        }
      std::error_code   error;
      const std::string previous = target + ".previous";
      fs::remove_all(previous, error);
      if (fs::exists(target))
        fs::rename(target, previous, error);
      if (!error)
        fs::rename(staging_directory, target, error);
      unlink(lock_file.c_str());
      flock(lock, LOCK_UN);
      close(lock);
      AssertThrow(!error,
                  dealii::ExcMessage(
                    "Output/Directory: cannot move the results into '" +
                    target + "': " + error.message() + " (they are in '" +
                    staging_directory + "')."));
      committed         = true;
      partial_folder[0] = '\0';
    }
  } // namespace postprocess
} // namespace fdem
