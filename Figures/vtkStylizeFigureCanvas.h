/**
 * @file    vtkStylizeFigureCanvas.h
 * @brief   What vtkStylizeFigureWriter's drawers share (private to the module): the captured
 *          layers as images, the drawing context of one figure, and the tracing and painting
 *          helpers.
 *
 * The writer captures the style's layers, opens a Canvas on its output sink's cairo context and
 * hands it to the drawer of its style (vtkStylizeFigureComic.h, vtkStylizeFigurePixelArt.h,
 * vtkStylizeFigureSketch.h), then to the overlay drawer (vtkStylizeFigureOverlays.h). The page's
 * unit is the image pixel, y down; images keep VTK's rows, row 0 at the bottom.
 */

#ifndef vtkStylizeFigureCanvas_h
#define vtkStylizeFigureCanvas_h

#include <cairo.h>

#include <functional> // for std::function
#include <string>     // for std::string
#include <vector>     // for std::vector

class vtkImageData;

namespace vtkStylizeFigure
{
/** An RGB image, row 0 at the bottom (VTK's order). */
struct Image
{
  int W = 0, H = 0;
  std::vector<unsigned char> RGB;
  const unsigned char* At(int x, int y) const
  {
    return RGB.data() + 3 * (static_cast<size_t>(y) * W + x);
  }
  unsigned Key(int x, int y) const
  {
    const unsigned char* p = this->At(x, y);
    return (unsigned(p[0]) << 16) | (unsigned(p[1]) << 8) | p[2];
  }
};

/**
 * Renders the style's layer `layer` (with the flat background `key` when not null) into
 * `image`; false when nothing could be read.
 */
using CaptureFunction = std::function<bool(int layer, const double* key, Image& image)>;

/** What one figure draws with: cairo's context, the page, the layers and the counts. */
struct Canvas
{
  cairo_t* Cr = nullptr;
  int W = 0, H = 0;
  /** Supersampling of the outlines' tracing (the writer's TraceSupersampling, bounded). */
  int Supersampling = 4;
  /** The writer's Magnification: the tiles the layers render in, and the 2D actors' scale. */
  int Magnification = 1;
  CaptureFunction Capture;
  long long Dots = 0, Segments = 0, Paths = 0, Rectangles = 0, Images = 0, Texts = 0;
  /** What the figure left out or drew otherwise: clauses, each ending in "; ". */
  std::string Warning;
};

/** Copies the RGB of an image with at least three unsigned char components; false otherwise. */
bool ToImage(vtkImageData* data, Image& out);

/** Channel `c` of `image` in [0, 1]. */
std::vector<float> Channel(const Image& image, int c);

/**
 * Traces where `value` (W x H, row 0 at the bottom) is below `threshold`, bilinearly
 * supersampled `s` times, with potrace, and appends the closed curves to cr's current path in
 * page coordinates (pixels, y down). Returns the number of curves.
 */
long long TraceInto(
  cairo_t* cr, const std::vector<float>& value, int W, int H, float threshold, int s);

/** Fills where `value` < threshold (traced) with black at `alpha`: multiplies by 1 - alpha. */
void FillTraced(Canvas& c, const std::vector<float>& value, float threshold, double alpha);

/**
 * The paper as one filled region per colour (traced); false, drawing nothing, when it has more
 * than `maximum` colours.
 */
bool DrawPaperRegions(Canvas& c, const Image& paper, int maximum);

/**
 * The paper of a style (its captured layer `paper`) as the writer's PaperMode says (0, REGIONS:
 * regions of one colour each, an image beyond `maximumPaperColors` with a warning; 1, IMAGE:
 * one image).
 */
void DrawPaper(Canvas& c, const Image& paper, int paperMode, int maximumPaperColors);

/** Embeds `image` at the page's origin, one image pixel per page unit. */
void DrawImage(cairo_t* cr, const Image& image);

/** Sets the source to the colour of an Image::Key. */
void SetColor(cairo_t* cr, unsigned key, double alpha = 1.0);
}

#endif
