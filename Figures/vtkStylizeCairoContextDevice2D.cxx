#include "vtkStylizeCairoContextDevice2D.h"

#include "vtkBrush.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMarkerUtilities.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPath.h"
#include "vtkPen.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRect.h"
#include "vtkStdString.h"
#include "vtkTextProperty.h"
#include "vtkTextRenderer.h"
#include "vtkViewport.h"
#include "vtkWindow.h"

#if VTK_MAJOR_VERSION == 9 && VTK_MINOR_VERSION < 2
#include "vtkUnicodeString.h"
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

vtkStandardNewMacro(vtkStylizeCairoContextDevice2D);

vtkStylizeCairoContextDevice2D::vtkStylizeCairoContextDevice2D() = default;
vtkStylizeCairoContextDevice2D::~vtkStylizeCairoContextDevice2D() = default;

//------------------------------------------------------------------------------
void vtkStylizeCairoContextDevice2D::SetTarget(cairo_t* cr, double height, double scale)
{
  this->Cr = cr;
  this->PageHeight = height;
  this->Scale = scale > 0 ? scale : 1.0;
  this->Shapes = this->Texts = this->Images = 0;
}

//------------------------------------------------------------------------------
void vtkStylizeCairoContextDevice2D::Begin(vtkViewport* viewport)
{
  this->Current = { 1, 0, 0, 0, 1, 0 };
  this->Stack.clear();
  this->Clipping = false;
  this->Origin[0] = this->Origin[1] = 0;
  this->DotsPerInch =
    viewport && viewport->GetVTKWindow() ? viewport->GetVTKWindow()->GetDPI() : 72;
  if (viewport)
  {
    // device coordinates are the viewport's pixels: the viewport's origin in the window
    const int* size = viewport->GetSize();
    const int* origin = viewport->GetOrigin();
    this->Geometry[0] = size[0];
    this->Geometry[1] = size[1];
    this->Origin[0] = origin[0];
    this->Origin[1] = origin[1];
  }
}

int vtkStylizeCairoContextDevice2D::Dpi() const
{
  return this->DotsPerInch > 0 ? this->DotsPerInch : 72;
}

//------------------------------------------------------------------------------
void vtkStylizeCairoContextDevice2D::ToPage(double x, double y, double& px, double& py) const
{
  const Matrix& m = this->Current;
  const double wx = this->Origin[0] + m[0] * x + m[1] * y + m[2];
  const double wy = this->Origin[1] + m[3] * x + m[4] * y + m[5];
  px = wx * this->Scale;
  py = this->PageHeight - wy * this->Scale;
}

void vtkStylizeCairoContextDevice2D::Open()
{
  cairo_save(this->Cr);
  cairo_new_path(this->Cr);
  if (this->Clipping)
  {
    // the clipping rectangle is in the viewport's pixels (x, y, width, height), not transformed
    const double x0 = this->Origin[0] + this->ClipRect[0];
    const double y1 = this->Origin[1] + this->ClipRect[1] + this->ClipRect[3];
    cairo_rectangle(this->Cr, x0 * this->Scale, this->PageHeight - y1 * this->Scale,
      this->ClipRect[2] * this->Scale, this->ClipRect[3] * this->Scale);
    cairo_clip(this->Cr);
  }
}

void vtkStylizeCairoContextDevice2D::Close()
{
  cairo_new_path(this->Cr);
  cairo_restore(this->Cr);
}

void vtkStylizeCairoContextDevice2D::PathThrough(const float* points, int n, bool closed, bool line)
{
  // Where the OpenGL device's lines fall (it projects (0.5, 0.5) .. (w - 0.5, h - 0.5) onto the
  // viewport): a line of an odd width on whole coordinates is centred on the pixel centres half a
  // pixel down and left, one of an even width covers as many pixels either side of the whole
  // coordinate; the edges of a fill fall on pixel boundaries (so the figure matches the
  // screenshot: docs/figures.md).
  double shift = 0.0;
  if (line)
  {
    const double width = std::max(1.0f, this->Pen->GetWidth());
    const bool even = std::fabs(width - std::round(width)) < 1e-3 &&
      static_cast<long long>(std::round(width)) % 2 == 0;
    shift = (even ? 0.0 : 0.5) * this->Scale;
  }
  for (int i = 0; i < n; ++i)
  {
    double x, y;
    this->ToPage(points[2 * i], points[2 * i + 1], x, y);
    x -= shift;
    y += shift;
    i == 0 ? cairo_move_to(this->Cr, x, y) : cairo_line_to(this->Cr, x, y);
  }
  if (closed && n > 2)
  {
    cairo_close_path(this->Cr);
  }
}

void vtkStylizeCairoContextDevice2D::StrokePen(const unsigned char* rgba)
{
  vtkPen* pen = this->Pen;
  if (pen->GetLineType() == vtkPen::NO_PEN)
  {
    return;
  }
  const unsigned char* c = rgba ? rgba : pen->GetColor();
  const double alpha = c[3] / 255.0;
  if (alpha <= 0)
  {
    return;
  }
  cairo_set_source_rgba(this->Cr, c[0] / 255.0, c[1] / 255.0, c[2] / 255.0, alpha);
  // a width of 0 is OpenGL's thinnest line: one pixel
  const double width = std::max(1.0f, pen->GetWidth()) * this->Scale;
  cairo_set_line_width(this->Cr, width);
  cairo_set_line_cap(this->Cr, CAIRO_LINE_CAP_BUTT);
  cairo_set_line_join(this->Cr, CAIRO_LINE_JOIN_MITER);
  // the OpenGL device's 16-pixel stipple patterns, as dash lengths in pixels
  std::vector<double> dashes;
  switch (pen->GetLineType())
  {
    case vtkPen::DASH_LINE:
      dashes = { 8, 8 };
      break;
    case vtkPen::DOT_LINE:
      dashes = { 1, 7 };
      break;
    case vtkPen::DASH_DOT_LINE:
      dashes = { 4, 6, 2, 4 };
      break;
    case vtkPen::DASH_DOT_DOT_LINE:
      dashes = { 3, 3, 1, 3, 1, 5 };
      break;
    case vtkPen::DENSE_DOT_LINE:
      dashes = { 1, 3 };
      break;
    default:
      break;
  }
  for (double& d : dashes)
  {
    d *= this->Scale;
  }
  cairo_set_dash(
    this->Cr, dashes.empty() ? nullptr : dashes.data(), static_cast<int>(dashes.size()), 0);
  cairo_stroke_preserve(this->Cr);
  ++this->Shapes;
}

void vtkStylizeCairoContextDevice2D::FillBrush()
{
  const unsigned char* c = this->Brush->GetColor();
  if (c[3] == 0)
  {
    return;
  }
  cairo_set_source_rgba(this->Cr, c[0] / 255.0, c[1] / 255.0, c[2] / 255.0, c[3] / 255.0);
  cairo_fill_preserve(this->Cr);
  ++this->Shapes;
}

//------------------------------------------------------------------------------
void vtkStylizeCairoContextDevice2D::DrawPoly(float* points, int n, unsigned char* colors, int nc)
{
  if (!this->Cr || !points || n < 2)
  {
    return;
  }
  this->Open();
  if (colors && nc >= 3)
  {
    // per-vertex colours: each segment in its first vertex's colour
    for (int i = 0; i + 1 < n; ++i)
    {
      unsigned char rgba[4] = { colors[nc * i], colors[nc * i + 1], colors[nc * i + 2],
        static_cast<unsigned char>(nc > 3 ? colors[nc * i + 3] : 255) };
      cairo_new_path(this->Cr);
      this->PathThrough(points + 2 * i, 2, false, true);
      this->StrokePen(rgba);
    }
  }
  else
  {
    this->PathThrough(points, n, false, true);
    this->StrokePen();
  }
  this->Close();
}

void vtkStylizeCairoContextDevice2D::DrawLines(float* f, int n, unsigned char* colors, int nc)
{
  if (!this->Cr || !f)
  {
    return;
  }
  for (int i = 0; i + 1 < n; i += 2)
  {
    this->DrawPoly(f + 2 * i, 2, colors ? colors + nc * i : nullptr, nc);
  }
}

void vtkStylizeCairoContextDevice2D::DrawPoints(float* points, int n, unsigned char* colors, int nc)
{
  // square points of PointSize pixels, as OpenGL draws them
  this->DrawMarkers(VTK_MARKER_SQUARE, false, points, n, colors, nc);
}

void vtkStylizeCairoContextDevice2D::DrawPointSprites(
  vtkImageData*, float* points, int n, unsigned char* colors, int nc)
{
  this->DrawPoints(points, n, colors, nc);
}

void vtkStylizeCairoContextDevice2D::DrawMarkers(
  int shape, bool highlight, float* points, int n, unsigned char* colors, int nc)
{
  if (!this->Cr || !points)
  {
    return;
  }
  // the marker's shape in vector form, PointSize pixels across, in the pen's colour
  const double r = 0.5 * std::max(1.0f, this->PointSize) * (highlight ? 1.5 : 1.0) * this->Scale;
  this->Open();
  for (int i = 0; i < n; ++i)
  {
    const unsigned char* c = this->Pen->GetColor();
    unsigned char rgba[4] = { c[0], c[1], c[2], c[3] };
    if (colors && nc >= 3)
    {
      rgba[0] = colors[nc * i];
      rgba[1] = colors[nc * i + 1];
      rgba[2] = colors[nc * i + 2];
      rgba[3] = nc > 3 ? colors[nc * i + 3] : 255;
    }
    double x, y;
    this->ToPage(points[2 * i], points[2 * i + 1], x, y);
    cairo_new_path(this->Cr);
    cairo_set_source_rgba(
      this->Cr, rgba[0] / 255.0, rgba[1] / 255.0, rgba[2] / 255.0, rgba[3] / 255.0);
    cairo_set_dash(this->Cr, nullptr, 0, 0);
    cairo_set_line_width(this->Cr, std::max(1.0, 0.25 * r));
    switch (shape)
    {
      case VTK_MARKER_CROSS:
        cairo_move_to(this->Cr, x - r, y - r);
        cairo_line_to(this->Cr, x + r, y + r);
        cairo_move_to(this->Cr, x - r, y + r);
        cairo_line_to(this->Cr, x + r, y - r);
        cairo_stroke(this->Cr);
        break;
      case VTK_MARKER_PLUS:
        cairo_move_to(this->Cr, x - r, y);
        cairo_line_to(this->Cr, x + r, y);
        cairo_move_to(this->Cr, x, y - r);
        cairo_line_to(this->Cr, x, y + r);
        cairo_stroke(this->Cr);
        break;
      case VTK_MARKER_SQUARE:
        cairo_rectangle(this->Cr, x - r, y - r, 2 * r, 2 * r);
        cairo_fill(this->Cr);
        break;
      case VTK_MARKER_DIAMOND:
        cairo_move_to(this->Cr, x, y - r);
        cairo_line_to(this->Cr, x + r, y);
        cairo_line_to(this->Cr, x, y + r);
        cairo_line_to(this->Cr, x - r, y);
        cairo_close_path(this->Cr);
        cairo_fill(this->Cr);
        break;
      default: // VTK_MARKER_CIRCLE and others
        cairo_arc(this->Cr, x, y, r, 0, 2 * vtkMath::Pi());
        cairo_fill(this->Cr);
        break;
    }
    ++this->Shapes;
  }
  this->Close();
}

void vtkStylizeCairoContextDevice2D::DrawQuad(float* points, int n)
{
  // n points, every four a quad, filled with the brush
  for (int i = 0; i + 3 < n; i += 4)
  {
    this->DrawPolygon(points + 2 * i, 4);
  }
}

void vtkStylizeCairoContextDevice2D::DrawQuadStrip(float* points, int n)
{
  for (int i = 0; i + 3 < n; i += 2)
  {
    const float* p = points + 2 * i;
    float quad[8] = { p[0], p[1], p[2], p[3], p[6], p[7], p[4], p[5] };
    this->DrawPolygon(quad, 4);
  }
}

void vtkStylizeCairoContextDevice2D::DrawPolygon(float* points, int n)
{
  this->DrawColoredPolygon(points, n, nullptr, 0);
}

void vtkStylizeCairoContextDevice2D::DrawColoredPolygon(
  float* points, int n, unsigned char* colors, int nc)
{
  if (!this->Cr || !points || n < 3)
  {
    return;
  }
  this->Open();
  this->PathThrough(points, n, true);
  if (colors && nc >= 3)
  {
    // per-vertex colours: the mean (a vector fill has one colour)
    double sum[4] = { 0, 0, 0, 0 };
    for (int i = 0; i < n; ++i)
    {
      for (int k = 0; k < 4; ++k)
      {
        sum[k] += k < nc ? colors[nc * i + k] : 255;
      }
    }
    cairo_set_source_rgba(this->Cr, sum[0] / (255.0 * n), sum[1] / (255.0 * n),
      sum[2] / (255.0 * n), sum[3] / (255.0 * n));
    cairo_fill_preserve(this->Cr);
    ++this->Shapes;
  }
  else
  {
    this->FillBrush();
  }
  this->Close();
}

namespace
{
/**
 * Appends the points of an elliptic arc about (x, y), radii (rx, ry), from angle a0 to a1
 * (degrees), in 1-degree steps (exact to well under a pixel at any radius of a legend); reversed
 * runs from a1 to a0.
 */
void AppendArc(std::vector<float>& p, double x, double y, double rx, double ry, double a0,
  double a1, bool reversed = false)
{
  const int steps = std::max(2, static_cast<int>(std::ceil(std::fabs(a1 - a0))));
  for (int k = 0; k <= steps; ++k)
  {
    const int i = reversed ? steps - k : k;
    const double a = vtkMath::RadiansFromDegrees(a0 + (a1 - a0) * i / steps);
    p.push_back(static_cast<float>(x + rx * std::cos(a)));
    p.push_back(static_cast<float>(y + ry * std::sin(a)));
  }
}
}

void vtkStylizeCairoContextDevice2D::DrawEllipseWedge(float x, float y, float outRx, float outRy,
  float inRx, float inRy, float startAngle, float stopAngle)
{
  if (!this->Cr || !(outRx > 0) || !(outRy > 0))
  {
    return;
  }
  // the outer arc, then the inner one back: a polygon the brush fills
  std::vector<float> p;
  AppendArc(p, x, y, outRx, outRy, startAngle, stopAngle);
  AppendArc(p, x, y, inRx, inRy, startAngle, stopAngle, true);
  this->DrawPolygon(p.data(), static_cast<int>(p.size() / 2));
}

void vtkStylizeCairoContextDevice2D::DrawEllipticArc(
  float x, float y, float rX, float rY, float startAngle, float stopAngle)
{
  if (!this->Cr || !(rX > 0) || !(rY > 0))
  {
    return;
  }
  std::vector<float> p;
  AppendArc(p, x, y, rX, rY, startAngle, stopAngle);
  // the brush fills it, the pen outlines it (as vtkOpenGLContextDevice2D)
  this->Open();
  this->PathThrough(p.data(), static_cast<int>(p.size() / 2), true);
  this->FillBrush();
  this->StrokePen();
  this->Close();
}

//------------------------------------------------------------------------------
void vtkStylizeCairoContextDevice2D::ComputeStringBounds(
  const vtkStdString& string, float bounds[4])
{
  this->ComputeJustifiedStringBounds(string.c_str(), bounds);
  bounds[0] = bounds[1] = 0.f;
}

void vtkStylizeCairoContextDevice2D::ComputeJustifiedStringBounds(
  const char* string, float bounds[4])
{
  // what vtkOpenGLContextDevice2D measures: the text renderer's box at the window's DPI
  std::fill(bounds, bounds + 4, 0.f);
  vtkTextRenderer* renderer = vtkTextRenderer::GetInstance();
  int box[4];
  if (!renderer || !string || !*string ||
    !renderer->GetBoundingBox(this->TextProp, vtkStdString(string), box, this->Dpi()) ||
    box[0] > box[1] || box[2] > box[3])
  {
    return;
  }
  bounds[0] = static_cast<float>(box[0]);
  bounds[1] = static_cast<float>(box[2]);
  bounds[2] = static_cast<float>(box[1] - box[0] + 1);
  bounds[3] = static_cast<float>(box[3] - box[2] + 1);
}

void vtkStylizeCairoContextDevice2D::DrawString(float* point, const vtkStdString& string)
{
  vtkTextRenderer* renderer = vtkTextRenderer::GetInstance();
  if (!this->Cr || !point || string.empty() || !renderer)
  {
    return;
  }
  vtkTextProperty* tp = this->TextProp;
  // The glyph outlines VTK's text renderer lays out for the property (font, size at the DPI,
  // justification and rotation about the anchor); the anchor on whole pixels, as the OpenGL
  // device puts it.
  vtkNew<vtkPath> path;
  if (!renderer->StringToPath(tp, string, path, this->Dpi()) || path->GetNumberOfPoints() == 0)
  {
    return;
  }
  // The outlines lie one pixel below the bitmap the OpenGL device draws for the same string (its
  // quad is the text renderer's box, one pixel taller than the box's extent): drawn one pixel up
  // they fall on the screenshot's glyphs (ParaView's legend: docs/figures.md).
  const double ax = std::floor(point[0]), ay = std::floor(point[1]);
  this->Open();
  if (tp->GetBackgroundOpacity() > 0)
  {
    int box[4];
    if (renderer->GetBoundingBox(tp, string, box, this->Dpi()))
    {
      const float corners[8] = { static_cast<float>(ax + box[0]), static_cast<float>(ay + box[2]),
        static_cast<float>(ax + box[1] + 1), static_cast<float>(ay + box[2]),
        static_cast<float>(ax + box[1] + 1), static_cast<float>(ay + box[3] + 1),
        static_cast<float>(ax + box[0]), static_cast<float>(ay + box[3] + 1) };
      this->PathThrough(corners, 4, true);
      const double* bg = tp->GetBackgroundColor();
      cairo_set_source_rgba(this->Cr, bg[0], bg[1], bg[2], tp->GetBackgroundOpacity());
      cairo_fill(this->Cr);
    }
  }
  vtkPoints* points = path->GetPoints();
  vtkDataArray* codes = path->GetCodes();
  const vtkIdType n = points->GetNumberOfPoints();
  auto at = [&](vtkIdType i, double& x, double& y)
  {
    double q[3];
    points->GetPoint(i, q);
    this->ToPage(ax + q[0], ay + q[1] + 1.0, x, y);
  };
  cairo_new_path(this->Cr);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const int code = static_cast<int>(codes->GetTuple1(i));
    double x, y;
    if (code == vtkPath::MOVE_TO)
    {
      at(i, x, y);
      cairo_move_to(this->Cr, x, y);
    }
    else if (code == vtkPath::LINE_TO)
    {
      at(i, x, y);
      cairo_line_to(this->Cr, x, y);
    }
    else if (code == vtkPath::CONIC_CURVE && i + 1 < n)
    {
      // quadratic: control point, end point; as the cubic with the same curve
      double cx, cy, ex, ey, sx, sy;
      cairo_get_current_point(this->Cr, &sx, &sy);
      at(i, cx, cy);
      at(i + 1, ex, ey);
      cairo_curve_to(this->Cr, sx + 2.0 / 3.0 * (cx - sx), sy + 2.0 / 3.0 * (cy - sy),
        ex + 2.0 / 3.0 * (cx - ex), ey + 2.0 / 3.0 * (cy - ey), ex, ey);
      ++i;
    }
    else if (code == vtkPath::CUBIC_CURVE && i + 2 < n)
    {
      double x1, y1, x2, y2, x3, y3;
      at(i, x1, y1);
      at(i + 1, x2, y2);
      at(i + 2, x3, y3);
      cairo_curve_to(this->Cr, x1, y1, x2, y2, x3, y3);
      i += 2;
    }
  }
  const double* rgb = tp->GetColor();
  cairo_set_fill_rule(this->Cr, CAIRO_FILL_RULE_WINDING);
  cairo_set_source_rgba(this->Cr, rgb[0], rgb[1], rgb[2], tp->GetOpacity());
  cairo_fill(this->Cr);
  this->Close();
  ++this->Texts;
}

void vtkStylizeCairoContextDevice2D::DrawMathTextString(float* point, const vtkStdString& string)
{
  // VTK's text renderer handles MathText itself where it is built with it
  this->DrawString(point, string);
}

#if VTK_MAJOR_VERSION == 9 && VTK_MINOR_VERSION < 2
void vtkStylizeCairoContextDevice2D::DrawString(float* point, const vtkUnicodeString& string)
{
  this->DrawString(point, vtkStdString(string.utf8_str()));
}

void vtkStylizeCairoContextDevice2D::ComputeStringBounds(
  const vtkUnicodeString& string, float bounds[4])
{
  this->ComputeStringBounds(vtkStdString(string.utf8_str()), bounds);
}
#endif

//------------------------------------------------------------------------------
void vtkStylizeCairoContextDevice2D::PaintImage(
  vtkImageData* image, double x, double y, double w, double h)
{
  if (!this->Cr || !image || !(w > 0) || !(h > 0))
  {
    return;
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  int dims[3];
  image->GetDimensions(dims);
  const int nc = scalars ? scalars->GetNumberOfComponents() : 0;
  if (!scalars || dims[0] < 1 || dims[1] < 1 || nc < 1 || nc > 4 ||
    static_cast<long long>(dims[0]) * dims[1] > scalars->GetNumberOfTuples())
  {
    return;
  }
  auto rgba = [&](vtkIdType i, double c[4])
  {
    double t[4] = { 0, 0, 0, 255 };
    scalars->GetTuple(i, t);
    if (nc < 3)
    {
      c[0] = c[1] = c[2] = t[0] / 255.0;
      c[3] = nc == 2 ? t[1] / 255.0 : 1.0;
    }
    else
    {
      c[0] = t[0] / 255.0;
      c[1] = t[1] / 255.0;
      c[2] = t[2] / 255.0;
      c[3] = nc == 4 ? t[3] / 255.0 : 1.0;
    }
    for (int k = 0; k < 4; ++k)
    {
      c[k] = std::min(1.0, std::max(0.0, c[k]));
    }
  };
  double x0, y0, x1, y1;
  this->ToPage(x, y, x0, y0);
  this->ToPage(x + w, y + h, x1, y1);
  this->Open();
  cairo_rectangle(
    this->Cr, std::min(x0, x1), std::min(y0, y1), std::fabs(x1 - x0), std::fabs(y1 - y0));
  if (dims[0] == 1 || dims[1] == 1)
  {
    // a colour strip (a scalar bar's): a linear gradient through the pixels' centres, as the
    // texture's linear filtering draws it
    const int n = std::max(dims[0], dims[1]);
    cairo_pattern_t* gradient = dims[1] == 1 ? cairo_pattern_create_linear(x0, y0, x1, y0)
                                             : cairo_pattern_create_linear(x0, y0, x0, y1);
    for (int i = 0; i < n; ++i)
    {
      double c[4];
      rgba(i, c);
      cairo_pattern_add_color_stop_rgba(gradient, (i + 0.5) / n, c[0], c[1], c[2], c[3]);
    }
    cairo_pattern_set_extend(gradient, CAIRO_EXTEND_PAD);
    cairo_set_source(this->Cr, gradient);
    cairo_fill(this->Cr);
    cairo_pattern_destroy(gradient);
  }
  else
  {
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, dims[0], dims[1]);
    unsigned char* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    for (int j = 0; j < dims[1]; ++j)
    {
      // VTK's rows go up, cairo's down
      auto* row = reinterpret_cast<uint32_t*>(data + static_cast<size_t>(dims[1] - 1 - j) * stride);
      for (int i = 0; i < dims[0]; ++i)
      {
        double c[4];
        rgba(static_cast<vtkIdType>(j) * dims[0] + i, c);
        const auto a = static_cast<uint32_t>(std::lround(255 * c[3]));
        auto pre = [&](double v) { return static_cast<uint32_t>(std::lround(255 * v * c[3])); };
        row[i] = (a << 24) | (pre(c[0]) << 16) | (pre(c[1]) << 8) | pre(c[2]);
      }
    }
    cairo_surface_mark_dirty(surface);
    cairo_translate(this->Cr, std::min(x0, x1), std::min(y0, y1));
    cairo_scale(this->Cr, std::fabs(x1 - x0) / dims[0], std::fabs(y1 - y0) / dims[1]);
    cairo_set_source_surface(this->Cr, surface, 0, 0);
    cairo_fill(this->Cr);
    cairo_surface_destroy(surface);
  }
  this->Close();
  ++this->Images;
}

void vtkStylizeCairoContextDevice2D::DrawImage(float p[2], float scale, vtkImageData* image)
{
  if (!image || !p)
  {
    return;
  }
  int* extent = image->GetExtent();
  // the OpenGL device's quad: scale * extent + 1 pixels
  this->PaintImage(image, p[0], p[1], scale * extent[1] + 1.0, scale * extent[3] + 1.0);
}

void vtkStylizeCairoContextDevice2D::DrawImage(const vtkRectf& pos, vtkImageData* image)
{
  this->PaintImage(image, pos.GetX(), pos.GetY(), pos.GetWidth(), pos.GetHeight());
}

//------------------------------------------------------------------------------
void vtkStylizeCairoContextDevice2D::SetColor4(unsigned char color[4])
{
  this->Pen->SetColor(color);
}

void vtkStylizeCairoContextDevice2D::SetTexture(vtkImageData*, int)
{
  // brushes fill with their colour (a textured brush is drawn in its colour)
}

void vtkStylizeCairoContextDevice2D::SetPointSize(float size)
{
  this->PointSize = size;
}

void vtkStylizeCairoContextDevice2D::SetLineWidth(float width)
{
  this->Pen->SetWidth(width);
}

void vtkStylizeCairoContextDevice2D::SetLineType(int type)
{
  this->Pen->SetLineType(type);
}

//------------------------------------------------------------------------------
void vtkStylizeCairoContextDevice2D::SetMatrix(vtkMatrix3x3* m)
{
  const double* e = m->GetData();
  this->Current = { e[0], e[1], e[2], e[3], e[4], e[5] };
}

void vtkStylizeCairoContextDevice2D::GetMatrix(vtkMatrix3x3* m)
{
  double* e = m->GetData();
  e[0] = this->Current[0];
  e[1] = this->Current[1];
  e[2] = this->Current[2];
  e[3] = this->Current[3];
  e[4] = this->Current[4];
  e[5] = this->Current[5];
  e[6] = 0;
  e[7] = 0;
  e[8] = 1;
  m->Modified();
}

void vtkStylizeCairoContextDevice2D::MultiplyMatrix(vtkMatrix3x3* m)
{
  const double* e = m->GetData();
  const Matrix a = this->Current;
  this->Current = { a[0] * e[0] + a[1] * e[3], a[0] * e[1] + a[1] * e[4],
    a[0] * e[2] + a[1] * e[5] + a[2], a[3] * e[0] + a[4] * e[3], a[3] * e[1] + a[4] * e[4],
    a[3] * e[2] + a[4] * e[5] + a[5] };
}

void vtkStylizeCairoContextDevice2D::PushMatrix()
{
  this->Stack.push_back(this->Current);
}

void vtkStylizeCairoContextDevice2D::PopMatrix()
{
  if (!this->Stack.empty())
  {
    this->Current = this->Stack.back();
    this->Stack.pop_back();
  }
}

void vtkStylizeCairoContextDevice2D::SetClipping(int* x)
{
  if (x)
  {
    std::copy(x, x + 4, this->ClipRect);
  }
}

void vtkStylizeCairoContextDevice2D::EnableClipping(bool enable)
{
  this->Clipping = enable;
}
