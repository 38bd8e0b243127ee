#include "vtkStylizeFigureSink.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>

namespace vtkStylizeFigure
{
namespace
{
/** Bytes cairo writes, collected in memory. */
cairo_status_t Collect(void* closure, const unsigned char* data, unsigned int length)
{
  auto* bytes = static_cast<std::vector<unsigned char>*>(closure);
  bytes->insert(bytes->end(), data, data + length);
  return CAIRO_STATUS_SUCCESS;
}
}

//------------------------------------------------------------------------------
Sink::Sink(bool svg, int w, int h)
{
  this->Surface = svg ? cairo_svg_surface_create_for_stream(Collect, &this->Bytes, w, h)
                      : cairo_pdf_surface_create_for_stream(Collect, &this->Bytes, w, h);
  if (svg)
  {
    cairo_svg_surface_set_document_unit(this->Surface, CAIRO_SVG_UNIT_PX);
  }
  else
  {
    cairo_pdf_surface_set_metadata(this->Surface, CAIRO_PDF_METADATA_CREATOR, "VTK Stylize");
  }
  this->Cr = cairo_create(this->Surface);
}

//------------------------------------------------------------------------------
Sink::~Sink()
{
  if (this->Cr)
  {
    cairo_destroy(this->Cr);
  }
  if (this->Surface)
  {
    cairo_surface_destroy(this->Surface);
  }
}

//------------------------------------------------------------------------------
cairo_status_t Sink::Finish()
{
  cairo_destroy(this->Cr);
  this->Cr = nullptr;
  cairo_surface_finish(this->Surface);
  const cairo_status_t status = cairo_surface_status(this->Surface);
  cairo_surface_destroy(this->Surface);
  this->Surface = nullptr;
  return status;
}

//------------------------------------------------------------------------------
std::string Sink::WriteFile(const std::string& name, const std::vector<unsigned char>& bytes)
{
  // Written whole under a hidden name beside the file, then renamed over it.
  const size_t slash = name.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : name.substr(0, slash + 1);
  const std::string base = slash == std::string::npos ? name : name.substr(slash + 1);
  std::string temp = dir + (slash == std::string::npos ? "/." : ".") + base + ".XXXXXX";
  std::vector<char> templ(temp.begin(), temp.end());
  templ.push_back(0);
  const int fd = ::mkstemp(templ.data());
  const int opened = errno;
  const std::string what = "cannot write '" + name + "': ";
  if (fd < 0)
  {
    return what + std::strerror(opened);
  }
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  size_t written = 0;
  while (written < bytes.size())
  {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0)
    {
      const int error = errno;
      ::close(fd);
      ::unlink(templ.data());
      return what + std::strerror(error ? error : EIO);
    }
    written += static_cast<size_t>(n);
  }
  if (::close(fd) != 0 || std::rename(templ.data(), name.c_str()) != 0)
  {
    const int error = errno;
    ::unlink(templ.data());
    return what + std::strerror(error);
  }
  return std::string();
}
}
