/**
 * @file    vtkStylizeFigureSink.h
 * @brief   The output sink of vtkStylizeFigureWriter (private to the module): the cairo surface
 *          a figure is drawn on, its bytes, and their atomic write to a file.
 */

#ifndef vtkStylizeFigureSink_h
#define vtkStylizeFigureSink_h

#include <cairo.h>

#include <string> // for std::string
#include <vector> // for std::vector

namespace vtkStylizeFigure
{
/**
 * An SVG or PDF page of w x h units (SVG pixels, PDF points) whose bytes cairo writes into
 * memory. Draw on Context(), then Finish() and take GetBytes().
 */
class Sink
{
public:
  /** `svg`: an SVG document in pixels; otherwise a PDF document. */
  Sink(bool svg, int w, int h);
  ~Sink();
  Sink(const Sink&) = delete;
  Sink& operator=(const Sink&) = delete;

  /** The context to draw on, until Finish(). */
  cairo_t* Context() const { return this->Cr; }

  /** Ends the drawing and the document; returns cairo's status (CAIRO_STATUS_SUCCESS). */
  cairo_status_t Finish();

  /** The document's bytes (complete after a successful Finish()). */
  const std::vector<unsigned char>& GetBytes() const { return this->Bytes; }

  /**
   * Writes `bytes` to `name` whole: into a hidden temporary file beside it, renamed over it, so
   * that a failure leaves no partial file and the previous file as it was. Returns "" on
   * success, else "cannot write 'name': " and the reason.
   */
  static std::string WriteFile(const std::string& name, const std::vector<unsigned char>& bytes);

private:
  std::vector<unsigned char> Bytes;
  cairo_surface_t* Surface = nullptr;
  cairo_t* Cr = nullptr;
};
}

#endif
