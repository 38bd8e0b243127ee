#include "vtkStylizeFigureLineArt.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkLineArtPass.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vtkStylizeFigure
{
namespace
{
/** How far a simplified stroke may leave its line, page units (0.1 pt at one pixel per unit). */
constexpr double Tolerance = 0.1;
/** Consecutive points whose widths differ by less than this share stay in one path. */
constexpr double WidthStep = 0.1;
/** ... and whose ink (the share of it seen through translucent surfaces) by less than this. */
constexpr double InkStep = 0.05;

struct StrokePoint
{
  double X, Y, W;
  double I; // the ink's opacity: 1 but behind translucent surfaces (StrokeInk)
};

/** Douglas-Peucker on [first, last]: marks the points kept in `keep`. */
void Simplify(const std::vector<StrokePoint>& p, size_t first, size_t last, std::vector<char>& keep)
{
  if (last <= first + 1)
  {
    return;
  }
  const double dx = p[last].X - p[first].X, dy = p[last].Y - p[first].Y;
  const double len = std::hypot(dx, dy);
  double worst = -1.0;
  size_t at = first;
  for (size_t i = first + 1; i < last; ++i)
  {
    const double ex = p[i].X - p[first].X, ey = p[i].Y - p[first].Y;
    double d = len > 0.0 ? std::fabs(ex * dy - ey * dx) / len : std::hypot(ex, ey);
    // a change of width is kept as a change of shape would be
    const double t =
      len > 0.0 ? std::min(1.0, std::max(0.0, (ex * dx + ey * dy) / (len * len))) : 0.0;
    d = std::max(d, 0.5 * std::fabs(p[i].W - (p[first].W + t * (p[last].W - p[first].W))));
    // (and a change of ink: a tenth of the tolerance per InkStep)
    d = std::max(d,
      Tolerance / InkStep * 0.5 * std::fabs(p[i].I - (p[first].I + t * (p[last].I - p[first].I))));
    if (d > worst)
    {
      worst = d;
      at = i;
    }
  }
  if (worst > Tolerance)
  {
    keep[at] = 1;
    Simplify(p, first, at, keep);
    Simplify(p, at, last, keep);
  }
}

/**
 * Strokes one polyline: runs of nearly equal width and ink, each one path at its mean width in
 * `ink` at its mean opacity.
 */
void StrokeLine(Canvas& c, const std::vector<StrokePoint>& p, const double ink[3])
{
  size_t start = 0;
  while (start + 1 < p.size())
  {
    size_t end = start + 1;
    double lo = std::min(p[start].W, p[end].W), hi = std::max(p[start].W, p[end].W);
    double ilo = std::min(p[start].I, p[end].I), ihi = std::max(p[start].I, p[end].I);
    while (end + 1 < p.size())
    {
      const double w = p[end + 1].W, i = p[end + 1].I;
      const double nlo = std::min(lo, w), nhi = std::max(hi, w);
      const double nilo = std::min(ilo, i), nihi = std::max(ihi, i);
      if (nhi - nlo > WidthStep * nhi || nihi - nilo > InkStep)
      {
        break;
      }
      lo = nlo;
      hi = nhi;
      ilo = nilo;
      ihi = nihi;
      ++end;
    }
    const double alpha = 0.5 * (ilo + ihi);
    if (hi > 0.0 && alpha > 0.0)
    {
      if (alpha < 1.0)
      {
        cairo_set_source_rgba(c.Cr, ink[0], ink[1], ink[2], alpha);
      }
      else
      {
        cairo_set_source_rgb(c.Cr, ink[0], ink[1], ink[2]);
      }
      cairo_new_path(c.Cr);
      cairo_move_to(c.Cr, p[start].X, p[start].Y);
      for (size_t i = start + 1; i <= end; ++i)
      {
        cairo_line_to(c.Cr, p[i].X, p[i].Y);
      }
      cairo_set_line_width(c.Cr, 0.5 * (lo + hi));
      cairo_stroke(c.Cr);
      ++c.Paths;
      c.Segments += static_cast<long long>(end - start);
    }
    start = end;
  }
}
}

//------------------------------------------------------------------------------
void DrawStrokes(Canvas& c, vtkPolyData* strokes, const double ink[3])
{
  vtkPoints* points = strokes ? strokes->GetPoints() : nullptr;
  vtkDataArray* widths = points ? strokes->GetPointData()->GetArray("StrokeWidth") : nullptr;
  vtkDataArray* inks = points ? strokes->GetPointData()->GetArray("StrokeInk") : nullptr;
  if (!points || !widths)
  {
    return;
  }
  cairo_set_line_cap(c.Cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(c.Cr, CAIRO_LINE_JOIN_ROUND);
  vtkCellArray* cells = strokes->GetLines();
  vtkIdType n;
  const vtkIdType* ids;
  std::vector<StrokePoint> line, kept;
  std::vector<char> keep;
  for (cells->InitTraversal(); cells->GetNextCell(n, ids);)
  {
    line.clear();
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      points->GetPoint(ids[i], x);
      const double opacity = inks ? inks->GetTuple1(ids[i]) : 1.0;
      line.push_back({ x[0], c.H - x[1], widths->GetTuple1(ids[i]),
        std::isfinite(opacity) ? std::min(1.0, std::max(0.0, opacity)) : 1.0 }); // rows top down
    }
    if (line.size() < 2)
    {
      continue;
    }
    keep.assign(line.size(), 0);
    keep.front() = keep.back() = 1;
    Simplify(line, 0, line.size() - 1, keep);
    kept.clear();
    for (size_t i = 0; i < line.size(); ++i)
    {
      if (keep[i])
      {
        kept.push_back(line[i]);
      }
    }
    StrokeLine(c, kept, ink);
  }
}

//------------------------------------------------------------------------------
bool DrawLineArt(Canvas& c, vtkLineArtPass* lines, int paperMode, int maximumPaperColors)
{
  Image paper;
  if (!c.Capture(vtkLineArtPass::PAPER, nullptr, paper))
  {
    return false;
  }
  DrawPaper(c, paper, paperMode, maximumPaperColors);
  DrawStrokes(c, lines->ComputeFigureStrokes(c.W, c.H, c.Magnification), lines->GetInkColor());
  return true;
}
}
