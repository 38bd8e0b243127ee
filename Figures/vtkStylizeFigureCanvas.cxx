#include "vtkStylizeFigureCanvas.h"

#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <potracelib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>

namespace vtkStylizeFigure
{
//------------------------------------------------------------------------------
bool ToImage(vtkImageData* data, Image& out)
{
  int dims[3];
  data->GetDimensions(dims);
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(data->GetPointData()->GetScalars());
  if (!scalars || dims[0] < 1 || dims[1] < 1 || scalars->GetNumberOfComponents() < 3)
  {
    return false;
  }
  const int c = scalars->GetNumberOfComponents();
  out.W = dims[0];
  out.H = dims[1];
  out.RGB.resize(static_cast<size_t>(out.W) * out.H * 3);
  const unsigned char* src = scalars->GetPointer(0);
  for (size_t i = 0, n = static_cast<size_t>(out.W) * out.H; i < n; ++i)
  {
    std::copy(src + c * i, src + c * i + 3, out.RGB.data() + 3 * i);
  }
  return true;
}

//------------------------------------------------------------------------------
std::vector<float> Channel(const Image& image, int c)
{
  std::vector<float> v(static_cast<size_t>(image.W) * image.H);
  for (size_t i = 0; i < v.size(); ++i)
  {
    v[i] = image.RGB[3 * i + c] / 255.0f;
  }
  return v;
}

//------------------------------------------------------------------------------
long long TraceInto(
  cairo_t* cr, const std::vector<float>& value, int W, int H, float threshold, int s)
{
  const long long sw = static_cast<long long>(W) * s, sh = static_cast<long long>(H) * s;
  const int bits = static_cast<int>(sizeof(potrace_word) * 8);
  const long long dy = (sw + bits - 1) / bits;
  std::vector<potrace_word> map(static_cast<size_t>(dy * sh), 0);
  bool any = false;
  auto v = [&](int x, int y)
  {
    x = std::min(std::max(x, 0), W - 1);
    y = std::min(std::max(y, 0), H - 1);
    return value[static_cast<size_t>(y) * W + x];
  };
  for (long long Y = 0; Y < sh; ++Y)
  {
    const double fy = (Y + 0.5) / s - 0.5;
    const int y0 = static_cast<int>(std::floor(fy));
    const double ty = fy - y0;
    for (long long X = 0; X < sw; ++X)
    {
      const double fx = (X + 0.5) / s - 0.5;
      const int x0 = static_cast<int>(std::floor(fx));
      const double tx = fx - x0;
      const float a = v(x0, y0), b = v(x0 + 1, y0), c = v(x0, y0 + 1), d = v(x0 + 1, y0 + 1);
      bool in;
      if (a < threshold && b < threshold && c < threshold && d < threshold)
      {
        in = true;
      }
      else if (!(a < threshold) && !(b < threshold) && !(c < threshold) && !(d < threshold))
      {
        in = false;
      }
      else
      {
        const double top = a + (b - a) * tx, bottom = c + (d - c) * tx;
        in = top + (bottom - top) * ty < threshold;
      }
      if (in)
      {
        map[static_cast<size_t>(Y * dy + X / bits)] |= static_cast<potrace_word>(1)
          << (bits - 1 - X % bits);
        any = true;
      }
    }
  }
  if (!any)
  {
    return 0;
  }
  potrace_bitmap_t bitmap;
  bitmap.w = static_cast<int>(sw);
  bitmap.h = static_cast<int>(sh);
  bitmap.dy = static_cast<int>(dy);
  bitmap.map = map.data();
  potrace_param_t* param = potrace_param_default();
  if (!param)
  {
    return 0;
  }
  potrace_state_t* state = potrace_trace(param, &bitmap);
  potrace_param_free(param);
  long long curves = 0;
  if (state && state->status == POTRACE_STATUS_OK)
  {
    const double scale = 1.0 / s;
    auto px = [&](const potrace_dpoint_t& p) { return p.x * scale; };
    auto py = [&](const potrace_dpoint_t& p) { return H - p.y * scale; };
    for (potrace_path_t* path = state->plist; path; path = path->next)
    {
      const potrace_curve_t& curve = path->curve;
      const int n = curve.n;
      if (n < 1)
      {
        continue;
      }
      cairo_move_to(cr, px(curve.c[n - 1][2]), py(curve.c[n - 1][2]));
      for (int i = 0; i < n; ++i)
      {
        if (curve.tag[i] == POTRACE_CORNER)
        {
          cairo_line_to(cr, px(curve.c[i][1]), py(curve.c[i][1]));
          cairo_line_to(cr, px(curve.c[i][2]), py(curve.c[i][2]));
        }
        else
        {
          cairo_curve_to(cr, px(curve.c[i][0]), py(curve.c[i][0]), px(curve.c[i][1]),
            py(curve.c[i][1]), px(curve.c[i][2]), py(curve.c[i][2]));
        }
      }
      cairo_close_path(cr);
      ++curves;
    }
  }
  if (state)
  {
    potrace_state_free(state);
  }
  return curves;
}

//------------------------------------------------------------------------------
void FillTraced(Canvas& c, const std::vector<float>& value, float threshold, double alpha)
{
  cairo_new_path(c.Cr);
  c.Paths += TraceInto(c.Cr, value, c.W, c.H, threshold, c.Supersampling);
  cairo_set_fill_rule(c.Cr, CAIRO_FILL_RULE_EVEN_ODD);
  cairo_set_source_rgba(c.Cr, 0, 0, 0, alpha);
  cairo_fill(c.Cr);
}

//------------------------------------------------------------------------------
void DrawImage(cairo_t* cr, const Image& image)
{
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, image.W, image.H);
  cairo_surface_flush(surface);
  unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for (int y = 0; y < image.H; ++y)
  {
    auto* row = reinterpret_cast<uint32_t*>(data + static_cast<size_t>(image.H - 1 - y) * stride);
    for (int x = 0; x < image.W; ++x)
    {
      row[x] = image.Key(x, y);
    }
  }
  cairo_surface_mark_dirty(surface);
  cairo_save(cr);
  cairo_set_source_surface(cr, surface, 0, 0);
  cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
  cairo_paint(cr);
  cairo_restore(cr);
  cairo_surface_destroy(surface);
}

//------------------------------------------------------------------------------
void SetColor(cairo_t* cr, unsigned key, double alpha)
{
  cairo_set_source_rgba(
    cr, ((key >> 16) & 255) / 255.0, ((key >> 8) & 255) / 255.0, (key & 255) / 255.0, alpha);
}

//------------------------------------------------------------------------------
bool DrawPaperRegions(Canvas& c, const Image& paper, int maximum)
{
  std::map<unsigned, long long> counts;
  for (int y = 0; y < paper.H; ++y)
  {
    for (int x = 0; x < paper.W; ++x)
    {
      ++counts[paper.Key(x, y)];
    }
  }
  const long long total = static_cast<long long>(paper.W) * paper.H;
  const long long minimum = std::max<long long>(4, total / 20000);
  std::vector<std::pair<long long, unsigned>> major;
  long long minor = 0;
  for (const auto& kv : counts)
  {
    if (kv.second >= minimum)
    {
      major.emplace_back(kv.second, kv.first);
    }
    else
    {
      minor += kv.second;
    }
  }
  std::sort(major.rbegin(), major.rend());
  if (major.empty() || static_cast<int>(major.size()) > maximum || minor > total / 50)
  {
    return false;
  }
  // every pixel to its nearest major colour
  std::map<unsigned, size_t> nearest;
  auto dist = [](unsigned a, unsigned b)
  {
    int d = 0;
    for (int s : { 16, 8, 0 })
    {
      const int q = static_cast<int>((a >> s) & 255) - static_cast<int>((b >> s) & 255);
      d += q * q;
    }
    return d;
  };
  for (const auto& kv : counts)
  {
    size_t best = 0;
    for (size_t i = 1; i < major.size(); ++i)
    {
      if (dist(kv.first, major[i].second) < dist(kv.first, major[best].second))
      {
        best = i;
      }
    }
    nearest[kv.first] = best;
  }
  std::vector<size_t> label(static_cast<size_t>(total));
  for (int y = 0; y < paper.H; ++y)
  {
    for (int x = 0; x < paper.W; ++x)
    {
      label[static_cast<size_t>(y) * paper.W + x] = nearest[paper.Key(x, y)];
    }
  }
  // the largest as the page, the others over it
  SetColor(c.Cr, major[0].second);
  cairo_rectangle(c.Cr, 0, 0, c.W, c.H);
  cairo_fill(c.Cr);
  ++c.Rectangles;
  std::vector<float> mask(label.size());
  for (size_t m = 1; m < major.size(); ++m)
  {
    for (size_t i = 0; i < label.size(); ++i)
    {
      mask[i] = label[i] == m ? 0.0f : 1.0f;
    }
    cairo_new_path(c.Cr);
    c.Paths += TraceInto(c.Cr, mask, c.W, c.H, 0.5f, 1);
    cairo_set_fill_rule(c.Cr, CAIRO_FILL_RULE_EVEN_ODD);
    SetColor(c.Cr, major[m].second);
    cairo_fill(c.Cr);
  }
  return true;
}

//------------------------------------------------------------------------------
void DrawPaper(Canvas& c, const Image& paper, int paperMode, int maximumPaperColors)
{
  if (paperMode == 0 && DrawPaperRegions(c, paper, maximumPaperColors))
  {
    return;
  }
  if (paperMode == 0)
  {
    c.Warning += "the paper has more than " + std::to_string(maximumPaperColors) +
      " colours: drawn as an image; ";
  }
  DrawImage(c.Cr, paper);
  ++c.Images;
}
}
