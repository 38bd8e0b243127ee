#include "vtkStylizeFigureSink.h"

#include "vtkStylizeAtomicFile.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <cstring>

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
  const int error = vtkStylizeAtomicFile::Write(name.c_str(), bytes.data(), bytes.size());
  return error ? "cannot write '" + name + "': " + std::strerror(error) : std::string();
}
}
