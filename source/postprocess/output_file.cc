// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/postprocess/output_file.h>

#include <deal.II/base/exceptions.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <locale>

namespace fdem
{
  namespace postprocess
  {
    namespace
    {
      std::string
      reason(const int error = errno)
      {
        return error != 0 ? std::strerror(error) : "the write failed";
      }



      /// The line of @p filename that holds byte @p offset.
      unsigned long
      line_at(const std::string &filename, const long long offset)
      {
        std::ifstream file(filename, std::ios_base::binary);
        unsigned long line = 1;
        char          c;
        for (long long i = 0; i < offset && file.get(c); ++i)
          line += c == '\n' ? 1 : 0;
        return line;
      }
    } // namespace



    /**
     * The classic number formatting, which notes the first value that is
     * not finite (and its line) before writing it as usual.
     */
    class OutputFile::FiniteNumberPut : public std::num_put<char>
    {
    public:
      FiniteNumberPut(NonFinite &record, Buffer &buffer)
        : std::num_put<char>(0)
        , record(record)
        , buffer(buffer)
      {}

    protected:
      iter_type
      do_put(iter_type      out,
             std::ios_base &format,
             char           fill,
             const double   x) const override
      {
        note(std::isfinite(x), x);
        return std::num_put<char>::do_put(out, format, fill, x);
      }

      iter_type
      do_put(iter_type         out,
             std::ios_base    &format,
             char              fill,
             const long double x) const override
      {
        note(std::isfinite(x), static_cast<double>(x));
        return std::num_put<char>::do_put(out, format, fill, x);
      }

    private:
      void
      note(const bool finite, const double x) const
      {
        if (!finite && record.offset < 0)
          {
            record.offset = static_cast<long long>(
              buffer.pubseekoff(0, std::ios_base::cur, std::ios_base::out));
            record.text = std::isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf");
          }
      }

      NonFinite &record;
      Buffer    &buffer;
    };



    void
    OutputFile::Buffer::keep_error()
    {
      if (first_error == 0)
        first_error = errno != 0 ? errno : EIO;
    }



    OutputFile::Buffer::int_type
    OutputFile::Buffer::overflow(const int_type c)
    {
      errno                 = 0;
      const int_type result = std::filebuf::overflow(c);
      if (traits_type::eq_int_type(result, traits_type::eof()))
        keep_error();
      return result;
    }



    std::streamsize
    OutputFile::Buffer::xsputn(const char *text, const std::streamsize n)
    {
      errno                         = 0;
      const std::streamsize written = std::filebuf::xsputn(text, n);
      if (written != n)
        keep_error();
      return written;
    }



    int
    OutputFile::Buffer::sync()
    {
      errno            = 0;
      const int result = std::filebuf::sync();
      if (result != 0)
        keep_error();
      return result;
    }



    OutputFile::OutputFile(const std::string            &filename,
                           const std::ios_base::openmode mode)
      : std::ostream(nullptr)
      , filename(filename)
    {
      rdbuf(&buffer);
      imbue(std::locale(std::locale::classic(),
                        new FiniteNumberPut(non_finite, buffer)));
      errno = 0;
      AssertThrow(buffer.open(filename, mode | std::ios_base::out) != nullptr,
                  dealii::ExcMessage("cannot create the output file '" +
                                     filename + "': " + reason() + "."));
    }



    OutputFile::~OutputFile()
    {
      if (!closed)
        {
          buffer.close();
          std::remove(filename.c_str());
        }
    }



    void
    OutputFile::close()
    {
      flush();
      const bool written = good();
      errno              = 0;
      const bool shut    = buffer.close() != nullptr;
      if (!shut)
        buffer.first_error = buffer.first_error != 0 ? buffer.first_error :
                             errno != 0              ? errno :
                                                       EIO;
      closed = true;
      AssertThrow(written && shut,
                  dealii::ExcMessage("cannot write the output file '" +
                                     filename +
                                     "': " + reason(buffer.first_error) + "."));
      AssertThrow(non_finite.offset < 0,
                  dealii::ExcMessage(non_finite_output_error(
                    filename,
                    "the value " + non_finite.text + " on line " +
                      std::to_string(line_at(filename, non_finite.offset)))));
    }



    std::string
    non_finite_output_error(const std::string &filename,
                            const std::string &what)
    {
      return "the output file '" + filename + "' would hold " + what +
             ", which is not a result: this is a bug of fdem-slope; please "
             "report it with the parameter file.";
    }



    void
    write_text_file(const std::string &filename, const std::string &text)
    {
      OutputFile out(filename);
      out << text;
      out.close();
    }
  } // namespace postprocess
} // namespace fdem
