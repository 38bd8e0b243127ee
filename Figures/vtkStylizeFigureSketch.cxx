#include "vtkStylizeFigureSketch.h"

#include "vtkSketchPass.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace vtkStylizeFigure
{
namespace
{
/** One candidate stroke per cell of this many points (and one crossing stroke). */
constexpr double SeedCell = 4.0;
/** Width of a stroke, points. */
constexpr double StrokeWidth = 1.2;
/** Darkness levels the strokes are grouped in, one path each. */
constexpr int Levels = 8;
/** A stroke ends on paper: where the tone is at least this. */
constexpr float PaperTone = 0.97f;
/** The feature lines are what the strokeless layer draws darker than this. */
constexpr float LineLevel = 0.8f;

/** A uniform value in [0, 1) for cell (i, j) and salt k: a hash, the same in every figure. */
double Hash(int i, int j, int k)
{
  uint32_t h = (static_cast<uint32_t>(i) * 0x8da6b343u) ^ (static_cast<uint32_t>(j) * 0xd8163841u) ^
    (static_cast<uint32_t>(k) * 0xcb1ab31fu);
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return (h >> 8) * (1.0 / 16777216.0);
}

/** The pencil's tone and stroke direction per pixel, in page order (row 0 at the top). */
struct PencilField
{
  int W = 0, H = 0;
  std::vector<float> Tone;     // the tone in [0, 1]; -1 off the surface
  std::vector<float> Cos, Sin; // the stroke direction on the page (y down)

  /** The pixel at page point (x, y), or -1 outside the page or off the surface. */
  long Index(double x, double y) const
  {
    if (!(x >= 0.0 && y >= 0.0 && x < this->W && y < this->H))
    {
      return -1;
    }
    const long i = static_cast<long>(y) * this->W + static_cast<long>(x);
    return this->Tone[i] < 0.0f ? -1 : i;
  }

  /** From the TONE and DIRECTIONS layers captured on the key colour (magenta). */
  void Read(const Image& tone, const Image& directions)
  {
    this->W = tone.W;
    this->H = tone.H;
    const size_t n = static_cast<size_t>(this->W) * this->H;
    this->Tone.assign(n, -1.0f);
    this->Cos.assign(n, 1.0f);
    this->Sin.assign(n, 0.0f);
    for (int y = 0; y < this->H; ++y)
    {
      for (int x = 0; x < this->W; ++x)
      {
        if (tone.Key(x, y) == 0xff00ffu || directions.Key(x, y) == 0xff00ffu)
        {
          continue;
        }
        const size_t i = static_cast<size_t>(this->H - 1 - y) * this->W + x;
        this->Tone[i] = tone.At(x, y)[0] / 255.0f;
        // the hue 0.5 + 0.5 cos(a - k 120 degrees), a = 2 theta (vtkSketchPass DIRECTIONS)
        const unsigned char* d = directions.At(x, y);
        const double a =
          std::atan2((d[1] - d[2]) / 255.0 / 0.8660254037844386, 2.0 * d[0] / 255.0 - 1.0);
        this->Cos[i] = static_cast<float>(std::cos(0.5 * a));
        this->Sin[i] = static_cast<float>(-std::sin(0.5 * a)); // image y up -> page y down
      }
    }
  }
};

using Polyline = std::vector<std::pair<double, double>>;

/**
 * A stroke through page point (x, y) along the field (turned 90 degrees when `across`),
 * `half` pixels each way in steps of `step`: it ends off the surface, on paper, and where the
 * field turns by more than 45 degrees in a step (a singular point).
 */
Polyline Trace(const PencilField& f, double x, double y, bool across, double half, double step)
{
  Polyline sides[2];
  for (int side = 0; side < 2; ++side)
  {
    double px = x, py = y, dx = 0.0, dy = 0.0;
    for (double run = 0.0; run <= half; run += step)
    {
      const long i = f.Index(px, py);
      if (i < 0 || f.Tone[i] >= PaperTone)
      {
        break;
      }
      double ux = across ? -f.Sin[i] : f.Cos[i];
      double uy = across ? f.Cos[i] : f.Sin[i];
      if (run == 0.0)
      {
        ux = side == 0 ? ux : -ux;
        uy = side == 0 ? uy : -uy;
      }
      else
      {
        const double dot = ux * dx + uy * dy;
        if (std::fabs(dot) < 0.7)
        {
          break;
        }
        ux = dot < 0.0 ? -ux : ux;
        uy = dot < 0.0 ? -uy : uy;
      }
      sides[side].emplace_back(px, py);
      dx = ux;
      dy = uy;
      px += ux * step;
      py += uy * step;
    }
  }
  Polyline line(sides[1].rbegin(), sides[1].rend());
  if (!line.empty() && !sides[0].empty())
  {
    line.pop_back(); // the start, again
  }
  line.insert(line.end(), sides[0].begin(), sides[0].end());
  return line;
}

/** Douglas-Peucker on [first, last] with `tolerance` (page units): marks the points kept. */
void Simplify(
  const Polyline& p, size_t first, size_t last, double tolerance, std::vector<char>& keep)
{
  if (last <= first + 1)
  {
    return;
  }
  const double dx = p[last].first - p[first].first, dy = p[last].second - p[first].second;
  const double len = std::hypot(dx, dy);
  double worst = -1.0;
  size_t at = first;
  for (size_t i = first + 1; i < last; ++i)
  {
    const double ex = p[i].first - p[first].first, ey = p[i].second - p[first].second;
    const double d = len > 0.0 ? std::fabs(ex * dy - ey * dx) / len : std::hypot(ex, ey);
    if (d > worst)
    {
      worst = d;
      at = i;
    }
  }
  if (worst > tolerance)
  {
    keep[at] = 1;
    Simplify(p, first, at, tolerance, keep);
    Simplify(p, at, last, tolerance, keep);
  }
}

/** Adds a polyline to the current path, simplified to within `tolerance` page units. */
void AddPolyline(cairo_t* cr, const Polyline& line, double tolerance)
{
  std::vector<char> keep(line.size(), 0);
  keep.front() = keep.back() = 1;
  Simplify(line, 0, line.size() - 1, tolerance, keep);
  cairo_move_to(cr, line.front().first, line.front().second);
  for (size_t k = 1; k < line.size(); ++k)
  {
    if (keep[k])
    {
      cairo_line_to(cr, line[k].first, line[k].second);
    }
  }
}

/**
 * The strokes: a candidate per cell of SeedCell points (and a crossing one below the cross
 * threshold) at a hashed place, kept with the probability that makes the strokes' expected
 * ink the darkness 1 - tone there, each as dark as that darkness (0.35 to 1).
 */
void DrawStrokes(Canvas& c, const PencilField& f, vtkSketchPass* sketch, double pixelsPerPoint)
{
  if (!(pixelsPerPoint > 0.0) || !std::isfinite(pixelsPerPoint))
  {
    pixelsPerPoint = 1.0;
  }
  const double cell = std::max(1.0, SeedCell * pixelsPerPoint);
  const double width = StrokeWidth * pixelsPerPoint;
  const double length = 2.0 * sketch->GetSteps() * sketch->GetStepLength() * pixelsPerPoint;
  const double step = std::max(1.0, 0.5 * pixelsPerPoint);
  const double crossAt = sketch->GetCrossThreshold();
  const bool crossing = sketch->GetCrossHatching();
  std::vector<std::vector<Polyline>> levels(Levels);
  const int ci = static_cast<int>(std::ceil(f.W / cell)),
            cj = static_cast<int>(std::ceil(f.H / cell));
  for (int j = 0; j < cj; ++j)
  {
    for (int i = 0; i < ci; ++i)
    {
      for (int across = 0; across < (crossing ? 2 : 1); ++across)
      {
        const double x = (i + Hash(i, j, 3 * across)) * cell;
        const double y = (j + Hash(i, j, 3 * across + 1)) * cell;
        const long at = f.Index(x, y);
        if (at < 0)
        {
          continue;
        }
        const double tone = f.Tone[at], dark = 1.0 - tone;
        double amount = 1.0;
        if (across)
        {
          const double t = std::min(1.0, std::max(0.0, (crossAt - tone) / 0.2));
          amount = t * t * (3.0 - 2.0 * t);
        }
        // Strokes fall where they will (a Poisson process): covering a share c of the page
        // takes -ln(1 - c) strokes' area per area; c = darkness / alpha gives the tone.
        const double alpha = 0.35 + 0.65 * dark;
        const double cover = std::min(0.95, dark * amount / alpha);
        const double p = -std::log(1.0 - cover) * cell * cell / (width * length);
        if (!(dark > 0.0) || Hash(i, j, 3 * across + 2) >= p)
        {
          continue;
        }
        Polyline line = Trace(f, x, y, across == 1, 0.5 * length, step);
        if (line.size() >= 2)
        {
          const int level = std::min(Levels - 1, static_cast<int>(alpha * Levels));
          levels[level].push_back(std::move(line));
        }
      }
    }
  }
  const double* pencil = sketch->GetPencilColor();
  cairo_set_line_width(c.Cr, width);
  cairo_set_line_cap(c.Cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(c.Cr, CAIRO_LINE_JOIN_ROUND);
  for (int level = 0; level < Levels; ++level)
  {
    if (levels[level].empty())
    {
      continue;
    }
    cairo_new_path(c.Cr);
    for (const Polyline& line : levels[level])
    {
      AddPolyline(c.Cr, line, 0.25 * pixelsPerPoint);
    }
    cairo_set_source_rgba(c.Cr, pencil[0], pencil[1], pencil[2], (level + 0.5) / Levels);
    cairo_stroke(c.Cr);
    c.Segments += static_cast<long long>(levels[level].size());
  }
}
}

//------------------------------------------------------------------------------
bool DrawVectorSketch(Canvas& c, vtkSketchPass* sketch, int paperMode, int maximumPaperColors)
{
  // The layers: the paper (every tone lifted to paper, flat strokes where a tone of 0 stays
  // dark, no lines), the feature lines alone on the key colour, the tone and the directions;
  // the settings are restored after.
  const double key[3] = { 1.0, 0.0, 1.0 };
  const bool lines = sketch->GetFeatureLines();
  const bool crossing = sketch->GetCrossHatching();
  const double contrast = sketch->GetStrokeContrast();
  double bright[2];
  sketch->GetBrightThresholds(bright);
  Image paper, ink, tone, directions;
  sketch->SetFeatureLines(false);
  sketch->SetCrossHatching(false);
  sketch->SetStrokeContrast(0.0);
  sketch->SetBrightThresholds(0.0, 1.0e-4);
  bool ok = c.Capture(vtkSketchPass::SKETCH, nullptr, paper);
  if (ok && lines)
  {
    sketch->SetFeatureLines(true);
    ok = c.Capture(vtkSketchPass::SKETCH, key, ink);
    sketch->SetFeatureLines(false);
  }
  sketch->SetBrightThresholds(bright[0], bright[1]);
  sketch->SetStrokeContrast(contrast);
  sketch->SetCrossHatching(crossing);
  ok = ok && c.Capture(vtkSketchPass::TONE, key, tone) &&
    c.Capture(vtkSketchPass::DIRECTIONS, key, directions);
  sketch->SetFeatureLines(lines);
  if (!ok || tone.W != paper.W || tone.H != paper.H || directions.W != tone.W ||
    directions.H != tone.H)
  {
    return false;
  }
  DrawPaper(c, paper, paperMode, maximumPaperColors);
  PencilField field;
  field.Read(tone, directions);
  DrawStrokes(c, field, sketch, sketch->GetPixelsPerPoint(c.H, c.Magnification));
  if (lines && ink.W == tone.W && ink.H == tone.H)
  {
    std::vector<float> value(static_cast<size_t>(ink.W) * ink.H, 1.0f);
    for (int y = 0; y < ink.H; ++y)
    {
      for (int x = 0; x < ink.W; ++x)
      {
        if (ink.Key(x, y) != 0xff00ffu)
        {
          const unsigned char* p = ink.At(x, y);
          value[static_cast<size_t>(y) * ink.W + x] =
            (0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]) / 255.0f;
        }
      }
    }
    cairo_new_path(c.Cr);
    c.Paths += TraceInto(c.Cr, value, ink.W, ink.H, LineLevel, c.Supersampling);
    const double* pencil = sketch->GetPencilColor();
    cairo_set_source_rgb(c.Cr, pencil[0], pencil[1], pencil[2]);
    cairo_set_fill_rule(c.Cr, CAIRO_FILL_RULE_WINDING);
    cairo_fill(c.Cr);
  }
  return true;
}

namespace
{
/** The mask's maximum (Dilated) or minimum (Eroded) over each pixel's 3 x 3 neighbourhood. */
std::vector<float> Filtered3x3(const std::vector<float>& m, int W, int H, bool maximum)
{
  std::vector<float> out(m.size());
  for (int y = 0; y < H; ++y)
  {
    for (int x = 0; x < W; ++x)
    {
      float v = m[static_cast<size_t>(y) * W + x];
      for (int j = std::max(0, y - 1); j <= std::min(H - 1, y + 1); ++j)
      {
        for (int i = std::max(0, x - 1); i <= std::min(W - 1, x + 1); ++i)
        {
          const float q = m[static_cast<size_t>(j) * W + i];
          v = maximum ? std::max(v, q) : std::min(v, q);
        }
      }
      out[static_cast<size_t>(y) * W + x] = v;
    }
  }
  return out;
}

std::vector<float> Dilated(const std::vector<float>& m, int W, int H)
{
  return Filtered3x3(m, W, H, true);
}

std::vector<float> Eroded(const std::vector<float>& m, int W, int H)
{
  return Filtered3x3(m, W, H, false);
}
}

//------------------------------------------------------------------------------
bool DrawSketch(Canvas& c, const Image& frame, vtkSketchPass* sketch, double outlineWidth,
  int paperMode, int maximumPaperColors)
{
  if (sketch->GetVectorFigureStrokes())
  {
    return DrawVectorSketch(c, sketch, paperMode, maximumPaperColors);
  }
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
  // the surfaces' outline: lines and points (an axes grid, a wireframe) drawn one or two pixels
  // wide are opened away (the background dilated, then eroded, by a 3 x 3 square) so that the
  // pencil does not outline them as shapes
  background = Eroded(Dilated(background, W, H), W, H);
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
