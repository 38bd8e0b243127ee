#include "vtkStylizeFigureWriter.h"

#include "vtkActor2D.h"
#include "vtkActor2DCollection.h"
#include "vtkCellArray.h"
#include "vtkComicPass.h"
#include "vtkContext2D.h"
#include "vtkContextActor.h"
#include "vtkContextScene.h"
#include "vtkCoordinate.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPixelArtPass.h"
#include "vtkPointData.h"
#include "vtkPropCollection.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkScalarBarActor.h"
#include "vtkScalarBarActorInternal.h"
#include "vtkSketchPass.h"
#include "vtkSmartPointer.h"
#include "vtkStylizeCairoContextDevice2D.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkUnsignedCharArray.h"
#include "vtkViewport.h"
#include "vtkWindow.h"
#include "vtkWindowToImageFilter.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>
#include <potracelib.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <map>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

vtkStandardNewMacro(vtkStylizeFigureWriter);
vtkCxxSetObjectMacro(vtkStylizeFigureWriter, RenderWindow, vtkRenderWindow);

namespace
{
constexpr double Pi = 3.14159265358979323846;

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

/** Bytes cairo writes, collected in memory. */
cairo_status_t Collect(void* closure, const unsigned char* data, unsigned int length)
{
  auto* bytes = static_cast<std::vector<unsigned char>*>(closure);
  bytes->insert(bytes->end(), data, data + length);
  return CAIRO_STATUS_SUCCESS;
}

/**
 * Traces where `value` (W x H, row 0 at the bottom) is below `threshold`, bilinearly
 * supersampled `s` times, with potrace, and appends the closed curves to cr's current path in
 * page coordinates (pixels, y down). Returns the number of curves.
 */
long long TraceInto(cairo_t* cr, const std::vector<float>& value, int W, int H, float threshold, int s)
{
  const long long sw = static_cast<long long>(W) * s, sh = static_cast<long long>(H) * s;
  const int bits = static_cast<int>(sizeof(potrace_word) * 8);
  const long long dy = (sw + bits - 1) / bits;
  std::vector<potrace_word> map(static_cast<size_t>(dy * sh), 0);
  bool any = false;
  auto v = [&](int x, int y) {
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
        map[static_cast<size_t>(Y * dy + X / bits)] |=
          static_cast<potrace_word>(1) << (bits - 1 - X % bits);
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

/** Embeds `image` at the page's origin, one image pixel per page unit. */
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

void SetColor(cairo_t* cr, unsigned key, double alpha = 1.0)
{
  cairo_set_source_rgba(cr, ((key >> 16) & 255) / 255.0, ((key >> 8) & 255) / 255.0,
    (key & 255) / 255.0, alpha);
}

/**
 * Accesses a scalar bar's laid-out swatches and labels (protected in VTK) through pointers to
 * the members, which apply to any vtkScalarBarActor (casting the bar to this class would not:
 * it is not one).
 */
class ScalarBarPeek : public vtkScalarBarActor
{
public:
  static vtkScalarBarActorInternal* Layout(vtkScalarBarActor* bar)
  {
    vtkScalarBarActorInternal* vtkScalarBarActor::*member = &ScalarBarPeek::P;
    return bar->*member;
  }
  static vtkTextActor* Title(vtkScalarBarActor* bar)
  {
    vtkTextActor* vtkScalarBarActor::*member = &ScalarBarPeek::TitleActor;
    return bar->*member;
  }
};
}

//------------------------------------------------------------------------------
struct vtkStylizeFigureWriter::Internals
{
  std::vector<unsigned char> Bytes;
  vtkNew<vtkUnsignedCharArray> Result;
  /** The 2D actors hidden while the layers render, with their visibility. */
  std::vector<std::pair<vtkProp*, int>> Hidden;
};

//------------------------------------------------------------------------------
vtkStylizeFigureWriter::vtkStylizeFigureWriter()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkStylizeFigureWriter::~vtkStylizeFigureWriter()
{
  this->SetRenderWindow(nullptr);
  this->SetFileName(nullptr);
  delete this->Internal;
}

//------------------------------------------------------------------------------
vtkUnsignedCharArray* vtkStylizeFigureWriter::GetResult()
{
  return this->Internal->Result;
}

//------------------------------------------------------------------------------
vtkStylizeStylePass* vtkStylizeFigureWriter::FindStylePass()
{
  if (!this->RenderWindow)
  {
    return nullptr;
  }
  vtkRendererCollection* renderers = this->RenderWindow->GetRenderers();
  renderers->InitTraversal();
  while (vtkRenderer* ren = renderers->GetNextItem())
  {
    if (auto* style = vtkStylizeStylePass::SafeDownCast(ren->GetPass()))
    {
      return style;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
bool vtkStylizeFigureWriter::CaptureLayer(int layer, const double* key, vtkImageData* out)
{
  vtkStylizeStylePass* style = this->FindStylePass();
  vtkRenderWindow* window = this->RenderWindow;
  if (!style || !window)
  {
    return false;
  }
  const int previous = SetStyleLayer(style, layer);
  struct Saved
  {
    vtkRenderer* Renderer;
    double Background[3];
    bool Gradient;
    bool Textured;
  };
  std::vector<Saved> saved;
  if (key)
  {
    vtkRendererCollection* renderers = window->GetRenderers();
    renderers->InitTraversal();
    while (vtkRenderer* ren = renderers->GetNextItem())
    {
      Saved s{ ren, { 0, 0, 0 }, ren->GetGradientBackground(), ren->GetTexturedBackground() };
      ren->GetBackground(s.Background);
      saved.push_back(s);
      ren->SetBackground(key[0], key[1], key[2]);
      ren->GradientBackgroundOff();
      ren->TexturedBackgroundOff();
    }
  }
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOn();
  grab->SetScale(this->Magnification);
  grab->Update();
  out->DeepCopy(grab->GetOutput());
  for (const Saved& s : saved)
  {
    s.Renderer->SetBackground(s.Background);
    s.Renderer->SetGradientBackground(s.Gradient);
    s.Renderer->SetTexturedBackground(s.Textured);
  }
  SetStyleLayer(style, previous);
  return out->GetNumberOfPoints() > 0;
}

//------------------------------------------------------------------------------
int vtkStylizeFigureWriter::SetStyleLayer(vtkStylizeStylePass* style, int layer)
{
  if (auto* comic = vtkComicPass::SafeDownCast(style))
  {
    const int previous = comic->GetLayer();
    comic->SetLayer(layer);
    return previous;
  }
  if (auto* pixelArt = vtkPixelArtPass::SafeDownCast(style))
  {
    const int previous = pixelArt->GetLayer();
    pixelArt->SetLayer(layer);
    return previous;
  }
  if (auto* sketch = vtkSketchPass::SafeDownCast(style))
  {
    const int previous = sketch->GetLayer();
    sketch->SetLayer(layer);
    return previous;
  }
  return -1;
}

//------------------------------------------------------------------------------
std::string vtkStylizeFigureWriter::EncodeAnimation(const char* pattern, int fps, const char* output)
{
  const std::string out = output ? output : "";
  std::string ext = out.size() >= 4 ? out.substr(out.size() - 4) : std::string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  if (!pattern || !*pattern || (ext != ".gif" && ext != ".mp4"))
  {
    return "cannot encode \"" + out + "\": the animation must end in .gif or .mp4";
  }
  const std::string what = "cannot write \"" + out + "\"";
  const size_t slash = out.find_last_of('/');
  const std::string temporary = (slash == std::string::npos ? std::string() : out.substr(0, slash + 1)) +
    "." + out.substr(slash == std::string::npos ? 0 : slash + 1) + ".encoding" + ext;
  std::vector<std::string> args = { "ffmpeg", "-nostdin", "-y", "-v", "error", "-framerate",
    std::to_string(std::min(120, std::max(1, fps))), "-i", pattern };
  if (ext == ".gif")
  {
    // one palette from all the frames' colours (comic: black, white and gray; pixel art: its
    // palette), no dithering of its own
    args.insert(args.end(),
      { "-vf", "split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse=dither=none",
        "-loop", "0" });
  }
  else
  {
    args.insert(args.end(), { "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264",
      "-pix_fmt", "yuv420p", "-crf", "18" });
  }
  args.push_back(temporary);
  std::vector<char*> argv;
  for (std::string& a : args)
  {
    argv.push_back(&a[0]);
  }
  argv.push_back(nullptr);
  pid_t pid = -1;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  const int spawned = posix_spawnp(&pid, "ffmpeg", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0)
  {
    return what + ": ffmpeg could not be run (" + std::strerror(spawned) +
      "; Debian: apt-get install ffmpeg); the frames are written";
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
  {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
  {
    ::unlink(temporary.c_str());
    return what + ": ffmpeg failed (exit status " +
      std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + "); the frames are written";
  }
  if (std::rename(temporary.c_str(), out.c_str()) != 0)
  {
    const int error = errno;
    ::unlink(temporary.c_str());
    return what + ": " + std::strerror(error);
  }
  return std::string();
}

//------------------------------------------------------------------------------
void vtkStylizeFigureWriter::RenderFrame()
{
  if (this->RenderWindow)
  {
    this->RenderWindow->Render();
  }
}

//------------------------------------------------------------------------------
std::string vtkStylizeFigureWriter::WriteFigure(vtkRenderWindow* window, const char* fileName)
{
  vtkNew<vtkStylizeFigureWriter> writer;
  writer->SetRenderWindow(window);
  writer->SetFileName(fileName);
  writer->Write();
  return writer->GetErrorMessage();
}

namespace
{
/** What one figure draws with: cairo's context, the page and the counts. */
struct Canvas
{
  cairo_t* Cr = nullptr;
  int W = 0, H = 0;
  int Supersampling = 4;
  long long Dots = 0, Segments = 0, Paths = 0, Rectangles = 0, Images = 0, Texts = 0;
};

std::vector<float> Channel(const Image& image, int c)
{
  std::vector<float> v(static_cast<size_t>(image.W) * image.H);
  for (size_t i = 0; i < v.size(); ++i)
  {
    v[i] = image.RGB[3 * i + c] / 255.0f;
  }
  return v;
}

/** Fills where `value` < threshold (traced) with black at `alpha`: multiplies by 1 - alpha. */
void FillTraced(Canvas& c, const std::vector<float>& value, float threshold, double alpha)
{
  cairo_new_path(c.Cr);
  c.Paths += TraceInto(c.Cr, value, c.W, c.H, threshold, c.Supersampling);
  cairo_set_fill_rule(c.Cr, CAIRO_FILL_RULE_EVEN_ODD);
  cairo_set_source_rgba(c.Cr, 0, 0, 0, alpha);
  cairo_fill(c.Cr);
}

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

/** Paper: one filled region per colour, or the image when it has too many colours. */
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
  auto dist = [](unsigned a, unsigned b) {
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

/** The comic pass's pattern in pixels of the figure, from its settings. */
struct ComicPattern
{
  double DotSpacing, DotAngle, HatchSpacing, HatchWidth, HatchAngle;
  int HatchSteps;
  bool Principal, Dots, Hatching, Cross;
  double Bright, Dark, CrossTone;

  /** The zone weight t of eq. 13-14: 1 dots, 0 hatching. */
  double Zone(double tone) const
  {
    if (this->Bright > this->Dark)
    {
      return std::min(1.0, std::max(0.0, (tone - this->Dark) / (this->Bright - this->Dark)));
    }
    return tone < this->Dark ? 0.0 : 1.0;
  }
  /** The hatch angle (radians) of a FIGURE_INPUTS direction step. */
  double Angle(int step) const
  {
    if (step == 255)
    {
      return this->HatchAngle;
    }
    const double stepAngle = Pi / std::max(1, this->HatchSteps);
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
      const double coverage = std::min(1.0, std::max(0.0, 1.0 - tone));
      if (t <= 0.0 || coverage <= 1e-4)
      {
        continue;
      }
      const double r = coverage <= 0.785398
        ? std::sqrt(coverage / Pi)
        : 0.5 + (0.7072 - 0.5) * (coverage - 0.785398) / 0.214602;
      cairo_save(c.Cr);
      cairo_translate(c.Cr, x, c.H - y);
      cairo_rotate(c.Cr, p.DotAngle);
      cairo_scale(c.Cr, ds, ds);
      cairo_new_path(c.Cr);
      if (r <= 0.5)
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
    auto flush = [&]() {
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
        [&](int x, int y, double& width, double& alpha) {
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
          width = p.HatchWidth > 0
            ? p.HatchWidth
            : (crossed ? 1.0 - std::sqrt(std::min(1.0, std::max(0.0, tone))) : 1.0 - tone);
          alpha = 1.0 - t;
          return width > 0;
        });
    }
  }
}

/** A text actor as vector text, fitted to the box VTK laid it out in. */
void DrawText(Canvas& c, vtkTextActor* text, vtkViewport* viewport, int magnification)
{
  const char* input = text->GetInput();
  vtkTextProperty* tp = text->GetTextProperty();
  if (!input || !*input || !tp)
  {
    return;
  }
  double box[4];
  text->GetBoundingBox(viewport, box); // relative to the actor's position
  if (!(box[1] > box[0]) || !(box[3] > box[2]))
  {
    return;
  }
  const int* origin = text->GetActualPositionCoordinate()->GetComputedViewportValue(viewport);
  box[0] += origin[0];
  box[1] += origin[0];
  box[2] += origin[1];
  box[3] += origin[1];
  // 2D text keeps its pixel size in a magnified image; its place scales with the image.
  const int hj = tp->GetJustification(), vj = tp->GetVerticalJustification();
  const double anchorX = hj == VTK_TEXT_LEFT ? box[0] : (hj == VTK_TEXT_RIGHT ? box[1] : 0.5 * (box[0] + box[1]));
  const double anchorY = vj == VTK_TEXT_BOTTOM ? box[2] : (vj == VTK_TEXT_TOP ? box[3] : 0.5 * (box[2] + box[3]));
  const double shiftX = anchorX * (magnification - 1), shiftY = anchorY * (magnification - 1);
  const double x0 = box[0] + shiftX, x1 = box[1] + shiftX, y0 = box[2] + shiftY, y1 = box[3] + shiftY;

  const std::string family = tp->GetFontFamily() == VTK_COURIER
    ? "Liberation Mono"
    : (tp->GetFontFamily() == VTK_TIMES ? "Liberation Serif" : "Liberation Sans");
  cairo_select_font_face(c.Cr, family.c_str(),
    tp->GetItalic() ? CAIRO_FONT_SLANT_ITALIC : CAIRO_FONT_SLANT_NORMAL,
    tp->GetBold() ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  std::vector<std::string> lines;
  std::string s = input;
  for (size_t start = 0;;)
  {
    const size_t end = s.find('\n', start);
    lines.push_back(s.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos)
    {
      break;
    }
    start = end + 1;
  }
  // VTK's size: the text property's font size in points at the window's DPI; the lines stacked
  // from the top of VTK's box, which spans the lines' ascent to descent
  vtkWindow* window = viewport->GetVTKWindow();
  const double dpi = window ? window->GetDPI() : 72.0;
  const double spacing = tp->GetLineSpacing() > 0 ? tp->GetLineSpacing() : 1.0;
  cairo_set_font_size(c.Cr, tp->GetFontSize() * dpi / 72.0);
  cairo_font_extents_t fe;
  cairo_font_extents(c.Cr, &fe);
  const double height = (fe.ascent + fe.descent) * (1.0 + (lines.size() - 1) * spacing);
  // centred vertically in VTK's box (whose padding differs slightly from cairo's extents)
  const double top = c.H - 0.5 * (y0 + y1) - 0.5 * height;
  double* rgb = tp->GetColor();
  cairo_set_source_rgba(c.Cr, rgb[0], rgb[1], rgb[2], tp->GetOpacity());
  double baseline = top + fe.ascent;
  for (const std::string& line : lines)
  {
    cairo_text_extents_t te;
    cairo_text_extents(c.Cr, line.c_str(), &te);
    double x = x0;
    if (hj == VTK_TEXT_CENTERED)
    {
      x = 0.5 * (x0 + x1 - te.x_advance);
    }
    else if (hj == VTK_TEXT_RIGHT)
    {
      x = x1 - te.x_advance;
    }
    cairo_move_to(c.Cr, x, baseline);
    cairo_show_text(c.Cr, line.c_str());
    baseline += (fe.ascent + fe.descent) * spacing;
  }
  cairo_new_path(c.Cr);
  ++c.Texts;
}

/** A scalar bar: its colour swatches as filled shapes, its title and labels as vector text. */
void DrawScalarBar(Canvas& c, vtkScalarBarActor* bar, vtkViewport* viewport, int magnification)
{
  vtkScalarBarActorInternal* layout = ScalarBarPeek::Layout(bar);
  if (layout && layout->SwatchPts && layout->Polys && layout->SwatchColors)
  {
    int* origin = bar->GetPositionCoordinate()->GetComputedViewportValue(viewport);
    const double ox = origin[0] * magnification, oy = origin[1] * magnification;
    vtkCellArray* polys = layout->Polys;
    vtkIdType npts;
    const vtkIdType* ids;
    vtkIdType cell = 0;
    for (polys->InitTraversal(); polys->GetNextCell(npts, ids); ++cell)
    {
      if (npts < 3 || cell >= layout->SwatchColors->GetNumberOfTuples())
      {
        continue;
      }
      cairo_new_path(c.Cr);
      for (vtkIdType k = 0; k < npts; ++k)
      {
        double q[3];
        layout->SwatchPts->GetPoint(ids[k], q);
        const double x = ox + q[0] * magnification, y = c.H - (oy + q[1] * magnification);
        k == 0 ? cairo_move_to(c.Cr, x, y) : cairo_line_to(c.Cr, x, y);
      }
      cairo_close_path(c.Cr);
      double color[4] = { 0, 0, 0, 255 };
      layout->SwatchColors->GetTuple(cell, color);
      const int n = layout->SwatchColors->GetNumberOfComponents();
      cairo_set_source_rgba(c.Cr, color[0] / 255.0, color[1] / 255.0, color[2] / 255.0,
        n > 3 ? color[3] / 255.0 : 1.0);
      // a hairline of the swatch's own colour closes the anti-aliased seams between swatches
      cairo_fill_preserve(c.Cr);
      cairo_set_line_width(c.Cr, 0.5);
      cairo_stroke(c.Cr);
      ++c.Rectangles;
    }
  }
  if (vtkTextActor* title = ScalarBarPeek::Title(bar))
  {
    if (title->GetVisibility())
    {
      DrawText(c, title, viewport, magnification);
    }
  }
  if (layout)
  {
    for (auto& label : layout->TextActors)
    {
      if (label && label->GetVisibility())
      {
        DrawText(c, label, viewport, magnification);
      }
    }
  }
}
}

//------------------------------------------------------------------------------
int vtkStylizeFigureWriter::Write()
{
  this->ErrorMessage.clear();
  this->Warning.clear();
  this->NumberOfDots = this->NumberOfHatchSegments = this->NumberOfTracedPaths = 0;
  this->NumberOfRectangles = this->NumberOfImages = this->NumberOfTexts = 0;
  this->Internal->Bytes.clear();
  this->Internal->Result->Initialize();
  auto fail = [this](const std::string& message) {
    this->ErrorMessage = message;
    vtkErrorMacro(<< message);
    return 0;
  };

  const std::string name = this->FileName ? this->FileName : "";
  int format = this->Format;
  if (format == AUTO)
  {
    auto endsWith = [&](const char* ext) {
      const size_t n = std::strlen(ext);
      if (name.size() < n)
      {
        return false;
      }
      std::string tail = name.substr(name.size() - n);
      std::transform(tail.begin(), tail.end(), tail.begin(), ::tolower);
      return tail == ext;
    };
    format = endsWith(".svg") ? SVG : (endsWith(".pdf") ? PDF : AUTO);
    if (format == AUTO)
    {
      return fail(name.empty() && this->WriteToMemory
          ? "no format: set Format (SVG or PDF) or a file name ending in .svg or .pdf"
          : "cannot write a figure to '" + name + "': the name must end in .svg or .pdf");
    }
  }
  if (!this->WriteToMemory && name.empty())
  {
    return fail("no file name: set FileName (ending in .svg or .pdf)");
  }
  vtkStylizeStylePass* style = this->FindStylePass();
  if (!style)
  {
    return fail("no VTK Stylize style to draw: the window's renderers render without a comic, "
                "pixel-art or sketch pass");
  }
  auto* comic = vtkComicPass::SafeDownCast(style);
  auto* pixelArt = vtkPixelArtPass::SafeDownCast(style);
  auto* sketch = vtkSketchPass::SafeDownCast(style);
  if (!comic && !pixelArt && !sketch)
  {
    return fail(std::string("cannot draw the style ") + style->GetClassName() + " as a figure");
  }

  // The 2D actors: hidden while the layers render, drawn as vectors afterwards.
  struct Overlay
  {
    vtkProp* Actor;
    vtkRenderer* Renderer;
  };
  std::vector<Overlay> overlays;
  std::vector<std::string> leftOut;
  if (this->RenderWindow)
  {
    // one render with the 2D actors in place, so that they lay themselves out
    this->RenderFrame();
    vtkRendererCollection* renderers = this->RenderWindow->GetRenderers();
    renderers->InitTraversal();
    while (vtkRenderer* ren = renderers->GetNextItem())
    {
      // the 2D actors of the visible props (a hidden widget's representation keeps its text
      // actor's own visibility on: ParaView's annotation)
      vtkNew<vtkPropCollection> actors;
      vtkPropCollection* props = ren->GetViewProps();
      props->InitTraversal();
      while (vtkProp* prop = props->GetNextProp())
      {
        if (prop->GetVisibility())
        {
          prop->GetActors2D(actors);
          // a vtkContextActor is a 2D overlay but not a vtkActor2D
          if (vtkContextActor::SafeDownCast(prop))
          {
            actors->AddItem(prop);
          }
        }
      }
      actors->InitTraversal();
      while (vtkProp* actor = actors->GetNextProp())
      {
        if (!(vtkActor2D::SafeDownCast(actor) || vtkContextActor::SafeDownCast(actor)) ||
          !actor->GetVisibility())
        {
          continue;
        }
        // drawn after the layers: as text, through vtkContext2D, or as a scalar bar; what none
        // of them draws is named in the warning
        overlays.push_back({ actor, ren });
        this->Internal->Hidden.emplace_back(actor, actor->GetVisibility());
        actor->VisibilityOff();
      }
    }
  }
  struct Restore
  {
    Internals* I;
    ~Restore()
    {
      for (auto& h : I->Hidden)
      {
        h.first->SetVisibility(h.second);
      }
      I->Hidden.clear();
    }
  } restore{ this->Internal };

  auto capture = [&](int layer, const double* key, Image& image) {
    vtkNew<vtkImageData> data;
    return this->CaptureLayer(layer, key, data) && ToImage(data, image);
  };

  // The frame as the PNG shows it (without the 2D actors).
  Image frame;
  const int frameLayer = comic ? static_cast<int>(vtkComicPass::COMIC)
                               : (pixelArt ? static_cast<int>(vtkPixelArtPass::PIXEL_ART)
                                           : static_cast<int>(vtkSketchPass::SKETCH));
  if (!capture(frameLayer, nullptr, frame))
  {
    return fail("rendering the figure's layers failed");
  }

  std::vector<unsigned char>& bytes = this->Internal->Bytes;
  const int W = frame.W, H = frame.H;
  cairo_surface_t* surface = format == SVG
    ? cairo_svg_surface_create_for_stream(Collect, &bytes, W, H)
    : cairo_pdf_surface_create_for_stream(Collect, &bytes, W, H);
  if (format == SVG)
  {
    cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PX);
  }
  else
  {
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "VTK Stylize");
  }
  Canvas c;
  c.Cr = cairo_create(surface);
  c.W = W;
  c.H = H;
  // keep the supersampled bitmap within 64 megapixels
  c.Supersampling = this->TraceSupersampling;
  while (c.Supersampling > 1 &&
    static_cast<double>(W) * H * c.Supersampling * c.Supersampling > 64.0e6)
  {
    --c.Supersampling;
  }
  bool ok = true;

  if (pixelArt)
  {
    // rows of runs of one colour, equal runs of consecutive rows merged into one rectangle
    struct Run
    {
      int X0, X1, Y0, Y1;
      unsigned Key;
    };
    std::vector<Run> done, open;
    for (int row = 0; row < H; ++row)
    {
      const int y = H - 1 - row; // page rows top down
      std::vector<Run> runs;
      for (int x = 0; x < W;)
      {
        const unsigned key = frame.Key(x, y);
        int x1 = x + 1;
        while (x1 < W && frame.Key(x1, y) == key)
        {
          ++x1;
        }
        runs.push_back({ x, x1, row, row + 1, key });
        x = x1;
      }
      std::vector<Run> next;
      size_t j = 0;
      for (Run& r : runs)
      {
        while (j < open.size() && open[j].X0 < r.X0)
        {
          done.push_back(open[j++]);
        }
        if (j < open.size() && open[j].X0 == r.X0 && open[j].X1 == r.X1 && open[j].Key == r.Key)
        {
          Run merged = open[j++];
          merged.Y1 = row + 1;
          next.push_back(merged);
        }
        else
        {
          next.push_back(r);
        }
      }
      while (j < open.size())
      {
        done.push_back(open[j++]);
      }
      open.swap(next);
    }
    done.insert(done.end(), open.begin(), open.end());
    std::map<unsigned, std::vector<const Run*>> byColor;
    for (const Run& r : done)
    {
      byColor[r.Key].push_back(&r);
    }
    for (const auto& kv : byColor)
    {
      cairo_new_path(c.Cr);
      for (const Run* r : kv.second)
      {
        cairo_rectangle(c.Cr, r->X0, r->Y0, r->X1 - r->X0, r->Y1 - r->Y0);
      }
      SetColor(c.Cr, kv.first);
      cairo_fill(c.Cr);
      c.Rectangles += static_cast<long long>(kv.second.size());
    }
  }
  else if (sketch)
  {
    DrawImage(c.Cr, frame);
    ++c.Images;
    if (this->SketchOutlineWidth > 0)
    {
      const double key[3] = { 1.0, 0.0, 1.0 };
      Image keyed;
      ok = capture(vtkSketchPass::SKETCH, key, keyed);
      if (ok)
      {
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
        cairo_set_line_width(c.Cr, this->SketchOutlineWidth * points);
        cairo_set_line_join(c.Cr, CAIRO_LINE_JOIN_ROUND);
        cairo_stroke(c.Cr);
      }
    }
  }
  else
  {
    Image paper, inputs, edges;
    ok = capture(vtkComicPass::PAPER, nullptr, paper) &&
      capture(vtkComicPass::FIGURE_INPUTS, nullptr, inputs);
    if (ok && (this->PaperMode == IMAGE || !DrawPaperRegions(c, paper, this->MaximumPaperColors)))
    {
      if (this->PaperMode == REGIONS)
      {
        this->Warning += "the paper has more than " + std::to_string(this->MaximumPaperColors) +
          " colours: drawn as an image; ";
      }
      DrawImage(c.Cr, paper);
      ++c.Images;
    }
    if (ok)
    {
      // the pattern, drawn as one group and painted through the surfaces' outline (one clip)
      std::vector<float> offSurface = Channel(inputs, 2);
      for (float& v : offSurface)
      {
        v = 1.0f - v;
      }
      cairo_push_group(c.Cr);
      const int tiles = this->Magnification;
      const double points = comic->GetPixelsPerPoint(H, tiles);
      ComicPattern p;
      p.DotSpacing = comic->GetDotSpacing() * points;
      p.DotAngle = comic->GetDotAngle() * Pi / 180.0;
      p.HatchSpacing = comic->GetHatchSpacing() * points;
      p.HatchWidth = comic->GetHatchWidth() > 0
        ? std::min(1.0, comic->GetHatchWidth() / comic->GetHatchSpacing())
        : 0.0;
      p.HatchAngle = comic->GetHatchAngle() * Pi / 180.0;
      p.Principal = comic->GetHatchOrientation() == vtkComicPass::PRINCIPAL;
      p.HatchSteps = p.Principal ? (comic->GetHatchDirections() > 0 ? comic->GetHatchDirections() : 8)
                                 : comic->GetHatchDirections();
      p.Dots = comic->GetDots();
      p.Hatching = comic->GetHatching();
      p.Cross = p.Hatching && comic->GetCrossHatching();
      p.Bright = comic->GetBrightThreshold();
      p.Dark = comic->GetDarkThreshold();
      p.CrossTone = comic->GetCrossThreshold();
      {
        if (comic->GetAnchor() == vtkComicPass::OBJECT || (!p.Dots && !p.Hatching) ||
          (p.Hatching && p.Principal))
        {
          // not a screen grid (or hatch directions that change from pixel to pixel along the
          // form, which lines of one direction per region would cut into dashes): the pattern
          // layer traced (ink below half)
          Image pattern;
          ok = capture(vtkComicPass::PATTERN, nullptr, pattern);
          if (ok)
          {
            std::vector<float> v = Channel(pattern, 0);
            FillTraced(c, v, 0.5f, 1.0);
          }
          this->Warning += "the pattern is not a screen grid (object anchor or principal hatching): "
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
      }
      cairo_pattern_t* group = cairo_pop_group(c.Cr);
      cairo_save(c.Cr);
      cairo_new_path(c.Cr);
      c.Paths += TraceInto(c.Cr, offSurface, W, H, 0.5f, 1);
      cairo_set_fill_rule(c.Cr, CAIRO_FILL_RULE_EVEN_ODD);
      cairo_set_source(c.Cr, group);
      cairo_fill(c.Cr);
      cairo_restore(c.Cr);
      cairo_pattern_destroy(group);
    }
    if (ok && comic->GetEdges())
    {
      ok = capture(vtkComicPass::EDGES, nullptr, edges);
      if (ok)
      {
        DrawEdges(c, edges);
      }
    }
  }

  vtkNew<vtkStylizeCairoContextDevice2D> device;
  for (const Overlay& o : overlays)
  {
    o.Actor->SetVisibility(1);
    if (auto* text = vtkTextActor::SafeDownCast(o.Actor))
    {
      DrawText(c, text, o.Renderer, this->Magnification);
    }
    else
    {
      // what paints itself through vtkContext2D (a vtkContextActor's scene, ParaView's scalar
      // bars), as vectors; 2D actors magnified with the page
      device->SetTarget(c.Cr, c.H, this->Magnification);
      device->Begin(o.Renderer);
      vtkNew<vtkContext2D> painter;
      painter->Begin(device);
      const bool painted = this->PaintContextOverlay(o.Actor, o.Renderer, painter);
      painter->End();
      device->End();
      c.Paths += device->GetNumberOfShapes();
      c.Texts += device->GetNumberOfTexts();
      c.Images += device->GetNumberOfImages();
      auto* bar = vtkScalarBarActor::SafeDownCast(o.Actor);
      if (!painted && bar)
      {
        DrawScalarBar(c, bar, o.Renderer, this->Magnification);
      }
      else if (!painted)
      {
        leftOut.emplace_back(o.Actor->GetClassName());
      }
    }
    o.Actor->SetVisibility(0);
  }
  if (!leftOut.empty())
  {
    this->Warning += "left out the 2D actors that are neither text, scalar bars nor painted "
                     "through vtkContext2D (";
    for (size_t i = 0; i < leftOut.size(); ++i)
    {
      this->Warning += (i ? ", " : "") + leftOut[i];
    }
    this->Warning += "); ";
  }
  if (!this->Warning.empty())
  {
    this->Warning.resize(this->Warning.size() - 2);
  }

  cairo_destroy(c.Cr);
  cairo_surface_finish(surface);
  const cairo_status_t status = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  this->NumberOfDots = c.Dots;
  this->NumberOfHatchSegments = c.Segments;
  this->NumberOfTracedPaths = c.Paths;
  this->NumberOfRectangles = c.Rectangles;
  this->NumberOfImages = c.Images;
  this->NumberOfTexts = c.Texts;
  if (!ok)
  {
    return fail("rendering the figure's layers failed");
  }
  if (status != CAIRO_STATUS_SUCCESS)
  {
    return fail(std::string("cairo could not draw the figure: ") + cairo_status_to_string(status));
  }

  if (this->WriteToMemory)
  {
    this->Internal->Result->SetNumberOfValues(static_cast<vtkIdType>(bytes.size()));
    std::copy(bytes.begin(), bytes.end(), this->Internal->Result->GetPointer(0));
    return 1;
  }
  // Written whole under a hidden name beside the file, then renamed over it.
  const size_t slash = name.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : name.substr(0, slash + 1);
  const std::string base = slash == std::string::npos ? name : name.substr(slash + 1);
  std::string temp = dir + (slash == std::string::npos ? "/." : ".") + base + ".XXXXXX";
  std::vector<char> templ(temp.begin(), temp.end());
  templ.push_back(0);
  const int fd = ::mkstemp(templ.data());
  const std::string what = "cannot write '" + name + "': ";
  if (fd < 0)
  {
    return fail(what + std::strerror(errno));
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
      return fail(what + std::strerror(error ? error : EIO));
    }
    written += static_cast<size_t>(n);
  }
  if (::close(fd) != 0 || std::rename(templ.data(), name.c_str()) != 0)
  {
    const int error = errno;
    ::unlink(templ.data());
    return fail(what + std::strerror(error));
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkStylizeFigureWriter::PaintContextOverlay(
  vtkProp* actor, vtkViewport* viewport, vtkContext2D* painter)
{
  auto* contextActor = vtkContextActor::SafeDownCast(actor);
  vtkContextScene* scene = contextActor ? contextActor->GetScene() : nullptr;
  if (!scene || !painter)
  {
    return false;
  }
  if (auto* renderer = vtkRenderer::SafeDownCast(viewport))
  {
    scene->SetRenderer(renderer);
  }
  scene->Paint(painter);
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizeFigureWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderWindow: " << this->RenderWindow << "\n";
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Format: " << this->Format << "\n";
  os << indent << "Magnification: " << this->Magnification << "\n";
  os << indent << "PaperMode: " << this->PaperMode << "\n";
  os << indent << "MaximumPaperColors: " << this->MaximumPaperColors << "\n";
  os << indent << "TraceSupersampling: " << this->TraceSupersampling << "\n";
  os << indent << "SketchOutlineWidth: " << this->SketchOutlineWidth << "\n";
  os << indent << "WriteToMemory: " << this->WriteToMemory << "\n";
}
