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
     * The name of the marker file that every folder fdem-slope makes for
     * results carries (it names the program, the host, the process and the
     * case). A folder without it is the user's: it is never moved or
     * removed.
     */
    inline constexpr char results_marker[] = ".fdem-slope-results";

    /**
     * Refuses, with one line naming Output/Directory, a results folder
     * @p target that a run of @p prm_file may not replace: the working
     * folder, the .prm's folder or a folder above either; a symbolic link;
     * a file; a folder without the marker (even an empty one: it is the
     * user's); and the same for `<target>.previous`. Read-only: every MPI
     * rank can call it.
     */
    void
    check_results_target(const std::string &target,
                         const std::string &prm_file);

    /**
     * The results folder of one run, so that a folder is always the output
     * of exactly one run and only folders the program made are replaced.
     * The run writes into a fresh folder beside the target,
     * `<target>.partial-<pid>`, which gets the marker first; commit() renames
     * it into place at the end, the previous results becoming
     * `<target>.previous` (an older `.previous` is removed). Both are
     * checked by check_results_target() when the run starts and again at the
     * swap, which happens under a lock on the folder that holds them, so
     * that two runs into one folder cannot interleave: the last to finish
     * wins, whole. A run that fails (an exception) or is stopped by SIGINT,
     * SIGTERM or SIGHUP removes its partial folder and leaves the target as
     * it was; the partial folders of runs on this host that were killed
     * (SIGKILL, a power cut) are removed by the next run into the target.
     * If the swap itself fails, the partial folder stays and the error names
     * it.
     *
     * Only the process that writes files (rank 0 under MPI) touches the
     * disk; on the others the object only checks and names the folder.
     */
    class ResultsFolder
    {
    public:
      ResultsFolder(const std::string &target,
                    const std::string &prm_file,
                    bool               writes_files);
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
      void
      remove_stale_partial_folders() const;

      void
      swap_into_place() const;

      std::string target;
      std::string prm_file;
      std::string staging_directory;
      bool        writes_files;
      bool        keep_staging = false;
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
