// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#ifndef fdem_postprocess_results_folder_h
#define fdem_postprocess_results_folder_h

#include <string>

namespace fdem
{
  namespace postprocess
  {
    /**
     * The results folder of one run, so that a folder is always the output
     * of exactly one run: the run writes into a fresh folder beside the
     * target, `<target>.partial-<pid>`, and commit() renames it into place
     * at the end, the previous results becoming `<target>.previous` (an
     * older `.previous` is removed). The swap happens under a lock on
     * `<target>.lock`, so that two runs into one folder cannot interleave:
     * the last to finish wins, whole. The lock file is removed by its
     * holder before it unlocks; a run that got the lock of a removed file
     * sees that the path names another file (or none) and locks again, so
     * removing it reopens no race. A run that fails (an exception) or is
     * stopped by SIGINT, SIGTERM or SIGHUP removes its partial folder and
     * leaves the target as it was.
     *
     * Only the process that writes files (rank 0 under MPI) touches the
     * disk; on the others the object only names the folder.
     */
    class ResultsFolder
    {
    public:
      ResultsFolder(const std::string &target, bool writes_files);
      ~ResultsFolder();
      ResultsFolder(const ResultsFolder &) = delete;
      ResultsFolder &
      operator=(const ResultsFolder &) = delete;

      /// Where the run writes its files until commit().
      const std::string &
      staging() const
      {
        return staging_directory;
      }

      /// Moves the finished folder into place (see the class description).
      void
      commit();

    private:
      std::string target;
      std::string staging_directory;
      bool        writes_files;
      bool        committed = false;
    };

    /**
     * Removes the partial folder of the running ResultsFolder, if any, with
     * system calls only: safe in a signal handler that ends the process.
     */
    void
    remove_partial_folder();

    /**
     * The new-handler of the program (std::set_new_handler): an allocation
     * that fails ends the run with one error line, the partial folder
     * removed. A std::bad_alloc thrown instead would end it in
     * std::terminate with a stack trace wherever it cannot be caught, as
     * inside Gmsh's OpenMP loops (found by the fuzz test: Mesh size = 1e-9
     * under a raised Geometry/Memory limit).
     */
    [[noreturn]] void
    exit_out_of_memory();
  } // namespace postprocess
} // namespace fdem

#endif
