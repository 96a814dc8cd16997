// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#ifndef fdem_postprocess_output_file_h
#define fdem_postprocess_output_file_h

#include <fstream>
#include <string>

namespace fdem
{
  namespace postprocess
  {
    /**
     * An output file whose every write counts: opening it, writing to it
     * and closing it throw, with one line naming the file and the reason
     * (a full disk, a folder that went away), where a plain std::ofstream
     * would leave a cut file behind a run that says it completed. Every
     * writer of the program writes through it and ends with close(); a file
     * destroyed without close() (an exception on the way) is removed, so
     * that no cut file looks like a result.
     *
     * A number that is not finite (nan, inf) is never a result: every
     * floating-point value written with operator<< passes a number facet
     * that counts them, and close() refuses the file with the first one's
     * line, since such a value is a bug of the program, not the user's.
     */
    class OutputFile : public std::ostream
    {
    public:
      explicit OutputFile(const std::string      &filename,
                          std::ios_base::openmode mode = std::ios_base::out);
      ~OutputFile() override;
      OutputFile(const OutputFile &) = delete;
      OutputFile &
      operator=(const OutputFile &) = delete;

      /// Flushes and closes the file; throws if any write or the close
      /// failed.
      void
      close();

      const std::string &
      name() const
      {
        return filename;
      }

    private:
      /// The first value that was not finite, and where in the file it
      /// went (-1: none).
      struct NonFinite
      {
        long long   offset = -1;
        std::string text;
      };

      /// The stream's number formatting, with a count of the values that
      /// are not finite.
      class FiniteNumberPut;

      /// A file buffer that keeps the errno of its first failed write (the
      /// stream's state says only that one failed).
      class Buffer : public std::filebuf
      {
      public:
        int first_error = 0;

      protected:
        int_type
        overflow(int_type c) override;
        std::streamsize
        xsputn(const char *text, std::streamsize n) override;
        int
        sync() override;

      private:
        void
        keep_error();
      };

      std::string filename;
      Buffer      buffer;
      NonFinite   non_finite;
      bool        closed = false;
    };

    /**
     * The error of an output file that would hold a number that is not
     * finite, @p what saying which and where ("the value nan on line 3"):
     * a bug of the program, said so in one line.
     */
    std::string
    non_finite_output_error(const std::string &filename,
                            const std::string &what);

    /// Writes @p text to @p filename through an OutputFile.
    void
    write_text_file(const std::string &filename, const std::string &text);
  } // namespace postprocess
} // namespace fdem

#endif
