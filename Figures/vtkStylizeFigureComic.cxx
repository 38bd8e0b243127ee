#include "vtkStylizeFigureComic.h"
#include "vtkStylizeFigureLineArt.h"

#include "vtkComicPass.h"
#include "vtkComicPatterns.h"
#include "vtkStylizeFigureWriter.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace vtkStylizeFigure
{
namespace
{
using vtkComicPatterns::Pi;

/**
 * The edge factor's levels as black fills: e < 0.75 at half ink (the normal edges of the default
 * weights), e < 0.25 at full ink.
 */
void DrawEdges(Canvas& c, const Image& edges)
{
  const std::vector<float> e = Channel(edges, 0);
  FillTraced(c, e, 0.75f, 0.5);
  FillTraced(c, e, 0.25f, 1.0);
}

/** The comic pass's pattern in pixels of the figure, from its settings. */
struct ComicPattern
{
  double DotSpacing, DotAngle, HatchSpacing, HatchWidth, HatchAngle;
  int HatchSteps;
  bool Principal, Dots, Hatching, Cross;
  double Bright, Dark, CrossTone;

  /** The zone weight t of eq. 13-14: 1 dots, 0 hatching. */
  double Zone(double tone) const { return vtkComicPatterns::Zone(tone, this->Bright, this->Dark); }
  /** The hatch angle (radians) of a FIGURE_INPUTS direction step. */
  double Angle(int step) const
  {
    if (step == vtkComicPatterns::FixedAngleStep)
    {
      return this->HatchAngle;
    }
    const double stepAngle = vtkComicPatterns::HatchAngleStep(this->HatchSteps);
    return this->Principal ? stepAngle * step : this->HatchAngle + stepAngle * step;
  }
};

/** Halftone dots: one circle (or disc clipped to its cell) per grid cell with ink. */
void DrawDots(Canvas& c, const Image& inputs, const ComicPattern& p)
{
  const double ds = p.DotSpacing, cs = std::cos(p.DotAngle), sn = std::sin(p.DotAngle);
  // uv = R(angle) plane / ds; plane = ds R(-angle) uv (GL pixel coordinates, y up)
  double umin = 1e300, umax = -1e300, vmin = 1e300, vmax = -1e300;
  for (double x : { 0.0, double(c.W) })
  {
    for (double y : { 0.0, double(c.H) })
    {
      const double u = (cs * x - sn * y) / ds, v = (sn * x + cs * y) / ds;
      umin = std::min(umin, u);
      umax = std::max(umax, u);
      vmin = std::min(vmin, v);
      vmax = std::max(vmax, v);
    }
  }
  for (long long j = static_cast<long long>(std::floor(vmin)) - 1; j <= std::ceil(vmax); ++j)
  {
    for (long long i = static_cast<long long>(std::floor(umin)) - 1; i <= std::ceil(umax); ++i)
    {
      const double u = i + 0.5, v = j + 0.5;
      const double x = ds * (cs * u + sn * v), y = ds * (-sn * u + cs * v);
      if (x < -ds || y < -ds || x > c.W + ds || y > c.H + ds)
      {
        continue;
      }
      const int px = std::min(std::max(static_cast<int>(std::floor(x)), 0), c.W - 1);
      const int py = std::min(std::max(static_cast<int>(std::floor(y)), 0), c.H - 1);
      const unsigned char* in = inputs.At(px, py);
      if (in[2] < 128)
      {
        continue;
      }
      const double tone = in[0] / 255.0;
      const double t = p.Hatching ? p.Zone(tone) : 1.0;
      const double coverage = vtkComicPatterns::DotCoverage(tone);
      if (t <= 0.0 || coverage <= 1e-4)
      {
        continue;
      }
      const double r = vtkComicPatterns::DotRadius(coverage);
      cairo_save(c.Cr);
      cairo_translate(c.Cr, x, c.H - y);
      cairo_rotate(c.Cr, p.DotAngle);
      cairo_scale(c.Cr, ds, ds);
      cairo_new_path(c.Cr);
      if (r <= vtkComicPatterns::DotInscribedRadius)
      {
        cairo_arc(c.Cr, 0, 0, r, 0, 2 * Pi);
      }
      else if (r >= std::sqrt(0.5))
      {
        cairo_rectangle(c.Cr, -0.5, -0.5, 1, 1);
      }
      else
      {
        // the disc clipped to its cell: the sides inside the circle, the arcs at the corners
        const double h = std::sqrt(r * r - 0.25);
        cairo_move_to(c.Cr, 0.5, -h);
        cairo_line_to(c.Cr, 0.5, h);
        cairo_arc(c.Cr, 0, 0, r, std::atan2(h, 0.5), std::atan2(0.5, h));
        cairo_line_to(c.Cr, -h, 0.5);
        cairo_arc(c.Cr, 0, 0, r, std::atan2(0.5, -h), std::atan2(h, -0.5));
        cairo_line_to(c.Cr, -0.5, -h);
        cairo_arc(c.Cr, 0, 0, r, std::atan2(-h, -0.5), std::atan2(-0.5, -h));
        cairo_line_to(c.Cr, h, -0.5);
        cairo_arc(c.Cr, 0, 0, r, std::atan2(-0.5, h), std::atan2(-h, 0.5));
        cairo_close_path(c.Cr);
      }
      cairo_restore(c.Cr);
      cairo_set_source_rgba(c.Cr, 0, 0, 0, t);
      cairo_fill(c.Cr);
      ++c.Dots;
    }
  }
}

/**
 * Hatch lines at `angle` (radians, GL pixel coordinates) over the pixels `take` accepts: the
 * lines u = m (u across them in spacing units), walked in half-pixel steps, one segment per run
 * of equal width and ink. take(x, y, width, alpha) returns false where this direction draws
 * nothing.
 */
template <typename Take>
void DrawLines(Canvas& c, double angle, double spacing, Take take)
{
  const double dx = std::cos(angle), dy = std::sin(angle);
  const double ax = -dy, ay = dx; // across
  double mmin = 1e300, mmax = -1e300, smin = 1e300, smax = -1e300;
  for (double x : { 0.0, double(c.W) })
  {
    for (double y : { 0.0, double(c.H) })
    {
      mmin = std::min(mmin, (ax * x + ay * y) / spacing);
      mmax = std::max(mmax, (ax * x + ay * y) / spacing);
      smin = std::min(smin, dx * x + dy * y);
      smax = std::max(smax, dx * x + dy * y);
    }
  }
  const double step = 0.5;
  cairo_set_line_cap(c.Cr, CAIRO_LINE_CAP_BUTT);
  for (long long m = static_cast<long long>(std::floor(mmin)); m <= std::ceil(mmax); ++m)
  {
    const double bx = m * spacing * ax, by = m * spacing * ay;
    int runW = -1, runA = -1;
    double runStart = 0, runEnd = 0;
    auto flush = [&]()
    {
      if (runW > 0 && runA > 0)
      {
        const double x0 = bx + runStart * dx, y0 = by + runStart * dy;
        const double x1 = bx + runEnd * dx, y1 = by + runEnd * dy;
        cairo_new_path(c.Cr);
        cairo_move_to(c.Cr, x0, c.H - y0);
        cairo_line_to(c.Cr, x1, c.H - y1);
        cairo_set_line_width(c.Cr, std::min(64, runW) / 64.0 * spacing);
        cairo_set_source_rgba(c.Cr, 0, 0, 0, runA / 32.0);
        cairo_stroke(c.Cr);
        ++c.Segments;
      }
      runW = -1;
      runA = -1;
    };
    for (double s = smin + 0.5 * step; s < smax; s += step)
    {
      const double x = bx + s * dx, y = by + s * dy;
      double width = 0, alpha = 0;
      int qw = -1, qa = -1;
      if (x >= 0 && y >= 0 && x < c.W && y < c.H &&
        take(static_cast<int>(x), static_cast<int>(y), width, alpha))
      {
        qw = static_cast<int>(std::lround(std::min(1.0, width) * 64));
        qa = static_cast<int>(std::lround(alpha * 32));
      }
      if (qw != runW || qa != runA)
      {
        flush();
        runW = qw;
        runA = qa;
        runStart = s - 0.5 * step;
      }
      runEnd = s + 0.5 * step;
    }
    flush();
  }
}

void DrawHatching(Canvas& c, const Image& inputs, const ComicPattern& p)
{
  std::vector<bool> present(256, false);
  for (int y = 0; y < inputs.H; ++y)
  {
    for (int x = 0; x < inputs.W; ++x)
    {
      const unsigned char* in = inputs.At(x, y);
      if (in[2] >= 128)
      {
        present[in[1]] = true;
      }
    }
  }
  for (int k = 0; k < 256; ++k)
  {
    if (!present[k])
    {
      continue;
    }
    for (int second = 0; second < (p.Cross ? 2 : 1); ++second)
    {
      DrawLines(c, p.Angle(k) + (second ? 0.5 * Pi : 0.0), p.HatchSpacing,
        [&](int x, int y, double& width, double& alpha)
        {
          const unsigned char* in = inputs.At(x, y);
          if (in[2] < 128 || in[1] != k)
          {
            return false;
          }
          const double tone = in[0] / 255.0;
          const double t = p.Dots ? p.Zone(tone) : 0.0;
          const bool crossed = p.Cross && tone < p.CrossTone;
          if (t >= 1.0 || (second && !crossed))
          {
            return false;
          }
          width = vtkComicPatterns::HatchLineWidth(tone, p.HatchWidth, crossed);
          alpha = 1.0 - t;
          return width > 0;
        });
    }
  }
}

/** The pattern's settings of `comic` in pixels of a figure `height` pixels tall. */
ComicPattern PatternOf(vtkComicPass* comic, int height, int tiles)
{
  const double points = comic->GetPixelsPerPoint(height, tiles);
  ComicPattern p;
  p.DotSpacing = comic->GetDotSpacing() * points;
  p.DotAngle = comic->GetDotAngle() * Pi / 180.0;
  p.HatchSpacing = comic->GetHatchSpacing() * points;
  p.HatchWidth =
    vtkComicPatterns::HatchWidthFraction(comic->GetHatchWidth(), comic->GetHatchSpacing());
  p.HatchAngle = comic->GetHatchAngle() * Pi / 180.0;
  p.Principal = comic->GetHatchOrientation() == vtkComicPass::PRINCIPAL;
  p.HatchSteps = p.Principal ? vtkComicPatterns::PrincipalSteps(comic->GetHatchDirections())
                             : comic->GetHatchDirections();
  p.Dots = comic->GetDots();
  p.Hatching = comic->GetHatching();
  p.Cross = p.Hatching && comic->GetCrossHatching();
  p.Bright = comic->GetBrightThreshold();
  p.Dark = comic->GetDarkThreshold();
  p.CrossTone = comic->GetCrossThreshold();
  return p;
}

/**
 * The dots and hatch lines, drawn as one group and painted through the surfaces' outline (one
 * clip). A pattern that is not a screen grid is traced from its layer instead. Returns false
 * when a layer could not be captured.
 */
bool DrawPattern(Canvas& c, vtkComicPass* comic, const Image& inputs)
{
  std::vector<float> offSurface = Channel(inputs, 2);
  for (float& v : offSurface)
  {
    v = 1.0f - v;
  }
  bool ok = true;
  cairo_push_group(c.Cr);
  const ComicPattern p = PatternOf(comic, c.H, c.Magnification);
  if (comic->GetAnchor() == vtkComicPass::OBJECT || (!p.Dots && !p.Hatching) ||
    (p.Hatching && p.Principal))
  {
    // not a screen grid (or hatch directions that change from pixel to pixel along the form,
    // which lines of one direction per region would cut into dashes): the pattern layer traced
    // (ink below half)
    Image pattern;
    ok = c.Capture(vtkComicPass::PATTERN, nullptr, pattern);
    if (ok)
    {
      std::vector<float> v = Channel(pattern, 0);
      FillTraced(c, v, 0.5f, 1.0);
    }
    c.Warning += "the pattern is not a screen grid (object anchor or principal hatching): "
                 "traced from its layer; ";
  }
  else
  {
    if (p.Hatching)
    {
      DrawHatching(c, inputs, p);
    }
    if (p.Dots)
    {
      DrawDots(c, inputs, p);
    }
  }
  cairo_pattern_t* group = cairo_pop_group(c.Cr);
  cairo_save(c.Cr);
  cairo_new_path(c.Cr);
  c.Paths += TraceInto(c.Cr, offSurface, c.W, c.H, 0.5f, 1);
  cairo_set_fill_rule(c.Cr, CAIRO_FILL_RULE_EVEN_ODD);
  cairo_set_source(c.Cr, group);
  cairo_fill(c.Cr);
  cairo_restore(c.Cr);
  cairo_pattern_destroy(group);
  return ok;
}
}

//------------------------------------------------------------------------------
bool DrawComic(Canvas& c, vtkComicPass* comic, int paperMode, int maximumPaperColors)
{
  Image paper, inputs;
  bool ok = c.Capture(vtkComicPass::PAPER, nullptr, paper) &&
    c.Capture(vtkComicPass::FIGURE_INPUTS, nullptr, inputs);
  if (ok)
  {
    DrawPaper(c, paper, paperMode, maximumPaperColors);
  }
  if (ok)
  {
    ok = DrawPattern(c, comic, inputs);
  }
  if (ok && comic->GetEdges())
  {
    Image edges;
    ok = c.Capture(vtkComicPass::EDGES, nullptr, edges);
    if (ok)
    {
      DrawEdges(c, edges);
    }
  }
  if (ok)
  {
    // the feature lines and iso-lines, exact: paths from the geometry (the EDGES layer leaves
    // them out)
    const double black[3] = { 0.0, 0.0, 0.0 };
    DrawStrokes(c, comic->ComputeFigureStrokes(c.W, c.H, c.Magnification), black);
  }
  return ok;
}
}
