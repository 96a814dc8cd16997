// SPDX-License-Identifier: LGPL-2.1-or-later
// Copyright (C) 2026 the fdem-slope authors
#include <fdem/postprocess/output_file.h>

#include <deal.II/base/exceptions.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

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
    } // namespace



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
