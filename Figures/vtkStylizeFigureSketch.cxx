#include "vtkStylizeFigureSketch.h"

#include "vtkSketchPass.h"

#include <algorithm>
#include <vector>

namespace vtkStylizeFigure
{
//------------------------------------------------------------------------------
bool DrawSketch(Canvas& c, const Image& frame, vtkSketchPass* sketch, double outlineWidth)
{
  DrawImage(c.Cr, frame);
  ++c.Images;
  if (!(outlineWidth > 0))
  {
    return true;
  }
  // the background as a key colour: what differs from it is the scene
  const int W = frame.W, H = frame.H;
  const double key[3] = { 1.0, 0.0, 1.0 };
  Image keyed;
  if (!c.Capture(vtkSketchPass::SKETCH, key, keyed))
  {
    return false;
  }
  std::vector<float> background(static_cast<size_t>(W) * H);
  for (int y = 0; y < H; ++y)
  {
    for (int x = 0; x < W; ++x)
    {
      background[static_cast<size_t>(y) * W + x] = keyed.Key(x, y) == 0xff00ffu ? 1.0f : 0.0f;
    }
  }
  cairo_new_path(c.Cr);
  c.Paths += TraceInto(c.Cr, background, W, H, 0.5f, 1);
  double* pencil = sketch->GetPencilColor();
  const double points = H / std::max(1.0, sketch->GetReferenceHeight());
  cairo_set_source_rgb(c.Cr, pencil[0], pencil[1], pencil[2]);
  cairo_set_line_width(c.Cr, outlineWidth * points);
  cairo_set_line_join(c.Cr, CAIRO_LINE_JOIN_ROUND);
  cairo_stroke(c.Cr);
  return true;
}
}
