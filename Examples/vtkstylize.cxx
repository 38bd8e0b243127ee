/**
 * vtkstylize: renders a data file (or the built-in scene) offscreen through the VTK Stylize
 * render passes and writes a PNG image.
 *
 *   vtkstylize [options] [INPUT]
 *
 * Error contract: on any failure the program writes exactly one line starting with
 * "vtkstylize: " to stderr, exits with 2 (usage error) or 1 (input, render or output error) and
 * leaves no output file behind. VTK's own messages are captured by an output window and only the
 * first error is folded into that line; anything else that libraries write directly to stderr is
 * discarded (set VTKSTYLIZE_VERBOSE=1 to see it all).
 *
 * Sections of this file:
 *   1. error output and crash handling
 *   2. options: the option table, parsing, --help
 *   3. scene: actors, colouring, annotations, lights, camera
 *   4. rendering and writing the PNG
 *   5. main
 * The input stage (readers, checks, surfaces) is in vtkstylizeInput.cxx, the structural checks
 * of PLY, OBJ, STL and legacy files in vtkstylizeFileChecks.cxx, and the error type and the
 * capture of VTK's messages in vtkstylizeCommon.cxx.
 */

#include "vtkComicPass.h"
#include "vtkPixelArtPass.h"
#include "vtkSketchPass.h"
#include "vtkStylizeDemoScene.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkstylizeCommon.h"
#include "vtkstylizeInput.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkCoordinate.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLogger.h"
#include "vtkMath.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScalarBarActor.h"
#include "vtkSmartPointer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVersion.h"
#include "vtkWindowToImageFilter.h"

#ifdef VTKSTYLIZE_HAVE_X11
#include <X11/Xlib.h>
#endif

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <map>
#include <new>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#ifndef VTKSTYLIZE_VERSION
#define VTKSTYLIZE_VERSION "unknown"
#endif

namespace
{
using namespace vtkstylize;

//==============================================================================
// 1. Error output and crash handling
//==============================================================================

// Descriptor of the real stderr (fd 2 itself is redirected to /dev/null while VTK works).
int ErrorDescriptor = 2;

// Temporary PNG being written, removed by the crash handler. Fixed buffer: signal-safe.
char TemporaryPath[4096] = { 0 };

void WriteError(const std::string& message)
{
  const std::string line = "vtkstylize: " + OneLine(message, 1000) + "\n";
  ssize_t ignored = ::write(ErrorDescriptor, line.data(), line.size());
  (void)ignored;
}

/**
 * Handler of fatal and terminating signals: removes the temporary PNG, prints one line, then
 * dies of the same signal (so that a crash stays a crash for the caller).
 */
extern "C" void CrashHandler(int sig)
{
  if (TemporaryPath[0])
  {
    ::unlink(TemporaryPath);
  }
  const char* text = "vtkstylize: internal error: terminated by a signal\n";
  switch (sig)
  {
    case SIGSEGV:
      text = "vtkstylize: internal error: segmentation fault\n";
      break;
    case SIGBUS:
      text = "vtkstylize: internal error: bus error\n";
      break;
    case SIGFPE:
      text = "vtkstylize: internal error: floating point exception\n";
      break;
    case SIGABRT:
      text = "vtkstylize: internal error: aborted\n";
      break;
    case SIGINT:
    case SIGTERM:
    case SIGHUP:
      text = "vtkstylize: interrupted\n";
      break;
    default:
      break;
  }
  ssize_t ignored = ::write(ErrorDescriptor, text, std::strlen(text));
  (void)ignored;
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

/** Removes the temporary file on scope exit unless released. */
class TemporaryFileGuard
{
public:
  TemporaryFileGuard() = default;
  ~TemporaryFileGuard() { this->Remove(); }
  TemporaryFileGuard(const TemporaryFileGuard&) = delete;
  TemporaryFileGuard& operator=(const TemporaryFileGuard&) = delete;

  void Set(const std::string& path)
  {
    this->Path = path;
    std::snprintf(TemporaryPath, sizeof(TemporaryPath), "%s", path.c_str());
  }
  void Release()
  {
    this->Path.clear();
    TemporaryPath[0] = 0;
  }
  void Remove()
  {
    if (!this->Path.empty())
    {
      ::unlink(this->Path.c_str());
    }
    this->Release();
  }
  const std::string& Get() const { return this->Path; }

private:
  std::string Path;
};

//==============================================================================
// 2. Options
//==============================================================================

constexpr int MaxImageSize = 16384;
constexpr int MaxLights = 10000;
constexpr int MaxMultiSamples = 16;
constexpr int MaxMagnify = 8;
constexpr double MaxAngle = 360.0;
constexpr double MinZoom = 0.01;
constexpr double MaxZoom = 100.0;

// Camera defaults for the built-in scene (files use 0 / 0: looking down -z).
constexpr double SceneAzimuth = 30.0;
constexpr double SceneElevation = 20.0;

/** Settings of the lighting pass, with the defaults of a default-constructed pass. */
struct LightingSettings
{
  int Model = vtkStylizeLightingPass::STANDARD;
  double SubjectFactor = 0;
  double GrayLevelsNear = 0;
  double GrayLevelsFar = 0;
  double SpecularGain = 0;
  double Scattering = 0;
  double SpecularOcclusion = 0;

  static LightingSettings FromDefaultPass()
  {
    vtkNew<vtkStylizeLightingPass> pass;
    LightingSettings s;
    s.Model = pass->GetModel();
    s.SubjectFactor = pass->GetSubjectFactor();
    s.GrayLevelsNear = pass->GetGrayLevelsNear();
    s.GrayLevelsFar = pass->GetGrayLevelsFar();
    s.SpecularGain = pass->GetSpecularGain();
    s.Scattering = pass->GetScattering();
    s.SpecularOcclusion = pass->GetSpecularOcclusion();
    return s;
  }

  void ApplyTo(vtkStylizeLightingPass* pass) const
  {
    pass->SetModel(this->Model);
    pass->SetSubjectFactor(this->SubjectFactor);
    pass->SetGrayLevelsNear(this->GrayLevelsNear);
    pass->SetGrayLevelsFar(this->GrayLevelsFar);
    pass->SetSpecularGain(this->SpecularGain);
    pass->SetScattering(this->Scattering);
    pass->SetSpecularOcclusion(this->SpecularOcclusion);
  }
};

/** Copies every lighting setting from one lighting pass to another. */
void CopyLighting(vtkStylizeLightingPass* from, vtkStylizeLightingPass* to)
{
  to->SetModel(from->GetModel());
  to->SetSubjectFactor(from->GetSubjectFactor());
  to->SetGrayLevelsNear(from->GetGrayLevelsNear());
  to->SetGrayLevelsFar(from->GetGrayLevelsFar());
  to->SetSpecularGain(from->GetSpecularGain());
  to->SetScattering(from->GetScattering());
  to->SetSpecularOcclusion(from->GetSpecularOcclusion());
}

/** Settings of the style passes, applied in command-line order to the pass that is built. */
struct StyleSettings
{
  std::vector<std::function<void(vtkComicPass*)>> Comic;
  std::vector<std::function<void(vtkPixelArtPass*)>> Pixel;
  std::vector<std::function<void(vtkSketchPass*)>> Sketch;
  // --reference-height 0 for the sketch pass: one point is one window pixel (the pass itself
  // needs a height of at least 1, so it gets WindowHeight, set before the pass is built).
  bool SketchWindowPoints = false;
  int WindowHeight = 0;
};

/**
 * A style: its name for --style, a one-line description for --help, the lighting model it uses
 * unless --lighting says otherwise (-1: the lighting pass's default), and the function that
 * builds the renderer's pass from the lighting pass (and the G-buffer pass when --gbuffer is
 * given). New styles are added to Styles() below.
 */
struct StyleSpec
{
  const char* Name;
  const char* Description;
  int DefaultModel;
  std::function<vtkSmartPointer<vtkRenderPass>(
    vtkStylizeLightingPass*, vtkStylizeGBufferPass*, const StyleSettings&)>
    MakePass;
};

const std::vector<StyleSpec>& Styles()
{
  static const std::vector<StyleSpec> styles = {
    { "none", "no style pass: the lighting model only", -1,
      [](vtkStylizeLightingPass* lighting, vtkStylizeGBufferPass* gbuffer,
        const StyleSettings&) -> vtkSmartPointer<vtkRenderPass> {
        if (gbuffer)
        {
          return gbuffer;
        }
        return lighting;
      } },
    { "comic", "black-and-white comic: edges, halftone dots, hatching (vtkComicPass)",
      vtkStylizeLightingPass::COMIC,
      [](vtkStylizeLightingPass* lighting, vtkStylizeGBufferPass*,
        const StyleSettings& settings) -> vtkSmartPointer<vtkRenderPass> {
        auto comic = vtkSmartPointer<vtkComicPass>::New();
        CopyLighting(lighting, comic->GetLightingPass());
        for (const auto& apply : settings.Comic)
        {
          apply(comic);
        }
        return comic;
      } },
    { "pixel", "pixel art: pixelation, Canny outlines, 8x8 ordered dither to a palette "
               "(vtkPixelArtPass)",
      vtkStylizeLightingPass::PIXEL_ART,
      [](vtkStylizeLightingPass* lighting, vtkStylizeGBufferPass*,
        const StyleSettings& settings) -> vtkSmartPointer<vtkRenderPass> {
        auto pixel = vtkSmartPointer<vtkPixelArtPass>::New();
        CopyLighting(lighting, pixel->GetLightingPass());
        for (const auto& apply : settings.Pixel)
        {
          apply(pixel);
        }
        return pixel;
      } },
    { "sketch",
      "pencil sketch: principal-direction strokes (line integral convolution of solid noise), "
      "pencil tone (vtkSketchPass)",
      vtkStylizeLightingPass::STANDARD,
      [](vtkStylizeLightingPass* lighting, vtkStylizeGBufferPass*,
        const StyleSettings& settings) -> vtkSmartPointer<vtkRenderPass> {
        auto sketch = vtkSmartPointer<vtkSketchPass>::New();
        CopyLighting(lighting, sketch->GetLightingPass());
        for (const auto& apply : settings.Sketch)
        {
          apply(sketch);
        }
        if (settings.SketchWindowPoints && settings.WindowHeight > 0)
        {
          sketch->SetReferenceHeight(settings.WindowHeight);
        }
        return sketch;
      } },
  };
  return styles;
}

const StyleSpec* FindStyle(const std::string& name)
{
  for (const StyleSpec& s : Styles())
  {
    if (name == s.Name)
    {
      return &s;
    }
  }
  return nullptr;
}

std::string StyleNames(const char* separator)
{
  std::string names;
  for (const StyleSpec& s : Styles())
  {
    names += (names.empty() ? "" : separator) + std::string(s.Name);
  }
  return names;
}

struct Options
{
  std::string Style = "none";
  std::string Output = "stylized.png";
  int Width = 1280;
  int Height = 720;
  int Lights = 1;
  std::optional<double> Azimuth;
  std::optional<double> Elevation;
  double Zoom = 1.0;
  bool Parallel = false;
  double Background[3] = { 1.0, 1.0, 1.0 };
  LightingSettings Lighting;
  bool LightingModelGiven = false;
  StyleSettings StyleOptions;
  bool ModelDirections = false; // --direction-source model: compute the principal directions
  int Magnify = 1;
  bool GBuffer = false;
  std::optional<double> IsoValue;
  std::string ColorBy;
  bool NoScalars = false;
  bool NoAnnotations = false;
  int MultiSamples = 0;
  bool Quiet = false;
  bool Help = false;
  bool Version = false;
  std::string Input; // empty: the built-in scene
};

/** Parses a finite double that takes the whole string. */
bool ParseDouble(const std::string& text, double& value)
{
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])))
  {
    return false;
  }
  errno = 0;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && errno != ERANGE && std::isfinite(value);
}

/** Parses a decimal integer that takes the whole string. */
bool ParseInt(const std::string& text, long& value)
{
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])))
  {
    return false;
  }
  errno = 0;
  char* end = nullptr;
  value = std::strtol(text.c_str(), &end, 10);
  return end == text.c_str() + text.size() && errno != ERANGE;
}

double DoubleInRange(const std::string& option, const std::string& text, double lo, double hi)
{
  double v = 0;
  if (!ParseDouble(text, v))
  {
    UsageError("invalid value " + Quote(text) + " for " + option + ": expected a number");
  }
  if (v < lo || v > hi)
  {
    UsageError(option + " " + text + " is out of range [" + FormatNumber(lo) + ", " +
      FormatNumber(hi) + "]");
  }
  return v;
}

int IntInRange(const std::string& option, const std::string& text, long lo, long hi)
{
  long v = 0;
  if (!ParseInt(text, v))
  {
    UsageError("invalid value " + Quote(text) + " for " + option + ": expected an integer");
  }
  if (v < lo || v > hi)
  {
    UsageError(option + " " + text + " is out of range [" + std::to_string(lo) + ", " +
      std::to_string(hi) + "]");
  }
  return static_cast<int>(v);
}

std::vector<std::string> Split(const std::string& text, char separator)
{
  std::vector<std::string> parts;
  std::string::size_type start = 0;
  while (true)
  {
    const auto pos = text.find(separator, start);
    parts.push_back(text.substr(start, pos - start));
    if (pos == std::string::npos)
    {
      return parts;
    }
    start = pos + 1;
  }
}

bool EndsWithNoCase(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() && Lower(s.substr(s.size() - suffix.size())) == suffix;
}

/** One command-line option: its name, argument placeholder (nullptr for flags), help, action. */
struct OptionSpec
{
  std::string Name;
  const char* Argument;
  std::string Help;
  std::function<void(Options&, const std::string&)> Apply;
};

/** A numeric option of a style pass; its range and default come from the pass's clamp macros. */
template <class Pass, class T>
struct PassNumber
{
  const char* Name;
  const char* Argument;
  const char* Help;
  T (Pass::*Get)();
  T (Pass::*Min)();
  T (Pass::*Max)();
  void (Pass::*Set)(T);
};

/** An on/off option of a style pass: sets Value. */
template <class Pass>
struct PassFlag
{
  const char* Name;
  const char* Help;
  void (Pass::*Set)(bool);
  bool Value;
};

/** The list of settings for a style's pass in StyleSettings. */
std::vector<std::function<void(vtkComicPass*)>>& SettingsOf(StyleSettings& s, vtkComicPass*)
{
  return s.Comic;
}
std::vector<std::function<void(vtkPixelArtPass*)>>& SettingsOf(StyleSettings& s, vtkPixelArtPass*)
{
  return s.Pixel;
}
std::vector<std::function<void(vtkSketchPass*)>>& SettingsOf(StyleSettings& s, vtkSketchPass*)
{
  return s.Sketch;
}

/** Adds numeric options; `d` is a default-constructed pass (ranges and defaults for --help). */
template <class Pass, class T, size_t N>
void AddNumberOptions(std::vector<OptionSpec>& t, Pass* d, const PassNumber<Pass, T> (&numbers)[N])
{
  auto format = [](T v) {
    if constexpr (std::is_integral_v<T>)
    {
      return std::to_string(v);
    }
    else
    {
      return FormatNumber(v);
    }
  };
  for (const auto& n : numbers)
  {
    const T lo = (d->*n.Min)();
    const T hi = (d->*n.Max)();
    const std::string name = n.Name;
    auto set = n.Set;
    t.push_back({ name, n.Argument,
      std::string(n.Help) + ", [" + format(lo) + ", " + format(hi) + "] (default: " +
        format((d->*n.Get)()) + ")",
      [name, lo, hi, set](Options& opt, const std::string& v) {
        T value;
        if constexpr (std::is_integral_v<T>)
        {
          value = IntInRange(name, v, lo, hi);
        }
        else
        {
          value = DoubleInRange(name, v, lo, hi);
        }
        SettingsOf(opt.StyleOptions, static_cast<Pass*>(nullptr))
          .push_back([set, value](Pass* p) { (p->*set)(value); });
      } });
  }
}

/** Adds on/off options. */
template <class Pass, size_t N>
void AddFlagOptions(std::vector<OptionSpec>& t, const PassFlag<Pass> (&flags)[N])
{
  for (const auto& f : flags)
  {
    auto set = f.Set;
    const bool value = f.Value;
    t.push_back({ f.Name, nullptr, f.Help, [set, value](Options& opt, const std::string&) {
                   SettingsOf(opt.StyleOptions, static_cast<Pass*>(nullptr))
                     .push_back([set, value](Pass* p) { (p->*set)(value); });
                 } });
  }
}

/** A keyword option of a style pass: each accepted keyword (case-insensitive) and its setting. */
template <class Pass>
struct PassKeyword
{
  const char* Name;
  const char* Argument;
  const char* Help;
  std::vector<std::pair<const char*, std::function<void(Pass*)>>> Values;
};

/** Adds keyword options; any other value is a usage error that lists the accepted ones. */
template <class Pass, size_t N>
void AddKeywordOptions(std::vector<OptionSpec>& t, const PassKeyword<Pass> (&keywords)[N])
{
  for (const auto& k : keywords)
  {
    const std::string name = k.Name;
    const auto values = k.Values;
    t.push_back({ name, k.Argument, k.Help, [name, values](Options& opt, const std::string& v) {
                   std::string known;
                   for (const auto& value : values)
                   {
                     if (Lower(v) == value.first)
                     {
                       SettingsOf(opt.StyleOptions, static_cast<Pass*>(nullptr))
                         .push_back(value.second);
                       return;
                     }
                     known += (known.empty() ? "" : ", ") + std::string(value.first);
                   }
                   UsageError("unknown value " + Quote(v) + " for " + name + " (expected " +
                     known + ")");
                 } });
  }
}

/** The option of the table with this name (it must exist). */
OptionSpec& FindOption(std::vector<OptionSpec>& t, const std::string& name)
{
  for (OptionSpec& o : t)
  {
    if (o.Name == name)
    {
      return o;
    }
  }
  throw std::logic_error("no option " + name);
}

/**
 * Makes an existing option also do `also` (after its own action, which validates the value
 * first) and appends `help` to its help text: options shared by several styles.
 */
void ExtendOption(std::vector<OptionSpec>& t, const std::string& name, const std::string& help,
  std::function<void(Options&, const std::string&)> also)
{
  OptionSpec& o = FindOption(t, name);
  auto first = o.Apply;
  o.Help += help;
  o.Apply = [first, also](Options& opt, const std::string& v) {
    first(opt, v);
    also(opt, v);
  };
}

/**
 * The comic options. Ranges and defaults come from vtkComicPass itself (its clamp macros'
 * Min/Max values and a default-constructed pass), so --help cannot drift from the class.
 */
void AddComicOptions(std::vector<OptionSpec>& t)
{
  vtkNew<vtkComicPass> d;
  const PassNumber<vtkComicPass, double> numbers[] = {
    { "--edge-width", "PT", "comic: edge width in points", &vtkComicPass::GetEdgeWidth,
      &vtkComicPass::GetEdgeWidthMinValue, &vtkComicPass::GetEdgeWidthMaxValue,
      &vtkComicPass::SetEdgeWidth },
    { "--depth-threshold", "T", "comic: depth-edge threshold (surface slope against the view ray)",
      &vtkComicPass::GetDepthThreshold, &vtkComicPass::GetDepthThresholdMinValue,
      &vtkComicPass::GetDepthThresholdMaxValue, &vtkComicPass::SetDepthThreshold },
    { "--normal-threshold", "T", "comic: normal-edge threshold (change of the unit normal)",
      &vtkComicPass::GetNormalThreshold, &vtkComicPass::GetNormalThresholdMinValue,
      &vtkComicPass::GetNormalThresholdMaxValue, &vtkComicPass::SetNormalThreshold },
    { "--color-threshold", "T", "comic: colour-edge threshold (change of RGB in [0, 1])",
      &vtkComicPass::GetColorThreshold, &vtkComicPass::GetColorThresholdMinValue,
      &vtkComicPass::GetColorThresholdMaxValue, &vtkComicPass::SetColorThreshold },
    { "--dot-spacing", "PT", "comic: halftone dot spacing in points", &vtkComicPass::GetDotSpacing,
      &vtkComicPass::GetDotSpacingMinValue, &vtkComicPass::GetDotSpacingMaxValue,
      &vtkComicPass::SetDotSpacing },
    { "--dot-angle", "DEG", "comic: screen angle of the dot grid in degrees",
      &vtkComicPass::GetDotAngle, &vtkComicPass::GetDotAngleMinValue,
      &vtkComicPass::GetDotAngleMaxValue, &vtkComicPass::SetDotAngle },
    { "--hatch-spacing", "PT", "comic: distance between hatch lines in points",
      &vtkComicPass::GetHatchSpacing, &vtkComicPass::GetHatchSpacingMinValue,
      &vtkComicPass::GetHatchSpacingMaxValue, &vtkComicPass::SetHatchSpacing },
    { "--hatch-width", "PT", "comic: hatch line width in points", &vtkComicPass::GetHatchWidth,
      &vtkComicPass::GetHatchWidthMinValue, &vtkComicPass::GetHatchWidthMaxValue,
      &vtkComicPass::SetHatchWidth },
    { "--hatch-angle", "DEG", "comic: hatch direction in degrees from the x axis",
      &vtkComicPass::GetHatchAngle, &vtkComicPass::GetHatchAngleMinValue,
      &vtkComicPass::GetHatchAngleMaxValue, &vtkComicPass::SetHatchAngle },
    { "--bright", "T", "comic: tone above which only dots are drawn (a1 of eq. 13)",
      &vtkComicPass::GetBrightThreshold, &vtkComicPass::GetBrightThresholdMinValue,
      &vtkComicPass::GetBrightThresholdMaxValue, &vtkComicPass::SetBrightThreshold },
    { "--dark", "T", "comic: tone below which only hatching is drawn (a2 of eq. 13)",
      &vtkComicPass::GetDarkThreshold, &vtkComicPass::GetDarkThresholdMinValue,
      &vtkComicPass::GetDarkThresholdMaxValue, &vtkComicPass::SetDarkThreshold },
    { "--cross-threshold", "T", "comic: tone below which the hatching is crossed",
      &vtkComicPass::GetCrossThreshold, &vtkComicPass::GetCrossThresholdMinValue,
      &vtkComicPass::GetCrossThresholdMaxValue, &vtkComicPass::SetCrossThreshold },
    { "--reference-height", "PX",
      "comic: height of the image in which a point is a pixel (0: window pixels)",
      &vtkComicPass::GetReferenceHeight, &vtkComicPass::GetReferenceHeightMinValue,
      &vtkComicPass::GetReferenceHeightMaxValue, &vtkComicPass::SetReferenceHeight },
  };
  AddNumberOptions(t, d.Get(), numbers);
  t.push_back({ "--edge-weights", "D,N,C",
    "comic: weights of the depth, normal and colour edges, each in [0, 1], normalized to sum "
    "1 (default: 1,1,1)",
    [](Options& opt, const std::string& v) {
      const auto parts = Split(v, ',');
      double w[3];
      if (parts.size() != 3)
      {
        UsageError("invalid value " + Quote(v) + " for --edge-weights: expected D,N,C, e.g. 1,1,0");
      }
      for (int i = 0; i < 3; ++i)
      {
        w[i] = DoubleInRange("--edge-weights", parts[i], 0.0, 1.0);
      }
      opt.StyleOptions.Comic.push_back([w0 = w[0], w1 = w[1], w2 = w[2]](vtkComicPass* p) {
        p->SetEdgeWeights(w0, w1, w2);
      });
    } });
  t.push_back({ "--hatch-directions", "N",
    "comic: hatch direction follows the screen normal in N steps over 180 degrees, [" +
      std::to_string(d->GetHatchDirectionsMinValue()) + ", " +
      std::to_string(d->GetHatchDirectionsMaxValue()) + "], 0 = one direction (default: " +
      std::to_string(d->GetHatchDirections()) + ")",
    [lo = d->GetHatchDirectionsMinValue(), hi = d->GetHatchDirectionsMaxValue()](
      Options& opt, const std::string& v) {
      const int n = IntInRange("--hatch-directions", v, lo, hi);
      opt.StyleOptions.Comic.push_back([n](vtkComicPass* p) { p->SetHatchDirections(n); });
    } });
  t.push_back({ "--anchor", "screen|object",
    "comic: anchor the dots and hatching to the screen or to the surface (default: screen)",
    [](Options& opt, const std::string& v) {
      const std::string l = Lower(v);
      if (l != "screen" && l != "object")
      {
        UsageError("unknown anchor " + Quote(v) + " for --anchor (expected screen, object)");
      }
      const int a = l == "object" ? vtkComicPass::OBJECT : vtkComicPass::SCREEN;
      opt.StyleOptions.Comic.push_back([a](vtkComicPass* p) { p->SetAnchor(a); });
    } });
  const PassFlag<vtkComicPass> flags[] = {
    { "--no-edges", "comic: no edges (default: edges on)", &vtkComicPass::SetEdges, false },
    { "--no-dots", "comic: no halftone dots, the bright zone keeps its tone (default: dots on)",
      &vtkComicPass::SetDots, false },
    { "--no-hatching", "comic: no hatching, the dark zone keeps its tone (default: hatching on)",
      &vtkComicPass::SetHatching, false },
    { "--no-cross", "comic: no cross-hatching in the darkest zone (default: crossed)",
      &vtkComicPass::SetCrossHatching, false },
    { "--tinted", "comic: keep the data's colours under the ink (default: black and white)",
      &vtkComicPass::SetTinted, true },
  };
  AddFlagOptions(t, flags);
}

/** Parses "R,G,B" with components in [0, 1], or "#rrggbb". */
std::array<double, 3> ParseColor(const std::string& option, const std::string& v)
{
  std::array<double, 3> c{};
  if (!v.empty() && v[0] == '#')
  {
    if (v.size() != 7 || v.find_first_not_of("0123456789abcdefABCDEF", 1) != std::string::npos)
    {
      UsageError("invalid colour " + Quote(v) + " for " + option + ": expected #rrggbb or R,G,B");
    }
    for (int i = 0; i < 3; ++i)
    {
      c[i] = std::stoi(v.substr(1 + 2 * i, 2), nullptr, 16) / 255.0;
    }
    return c;
  }
  const auto parts = Split(v, ',');
  if (parts.size() != 3)
  {
    UsageError("invalid colour " + Quote(v) + " for " + option + ": expected #rrggbb or R,G,B");
  }
  for (int i = 0; i < 3; ++i)
  {
    c[i] = DoubleInRange(option, parts[i], 0.0, 1.0);
  }
  return c;
}

/**
 * The pixel-art options. Ranges and defaults come from vtkPixelArtPass itself, as for comic.
 * --depth-threshold and --normal-threshold (comic options with the same ranges) also set the
 * pixel-art pass's thresholds.
 */
void AddPixelOptions(std::vector<OptionSpec>& t)
{
  vtkNew<vtkPixelArtPass> d;
  using P = vtkPixelArtPass;
  const PassNumber<P, double> numbers[] = {
    { "--low-threshold", "T", "pixel: Canny low threshold on the Sobel magnitude of the gray image",
      &P::GetLowThreshold, &P::GetLowThresholdMinValue, &P::GetLowThresholdMaxValue,
      &P::SetLowThreshold },
    { "--high-threshold", "T",
      "pixel: Canny high threshold (and the Sobel detector's threshold)", &P::GetHighThreshold,
      &P::GetHighThresholdMinValue, &P::GetHighThresholdMaxValue, &P::SetHighThreshold },
    { "--dither-strength", "S", "pixel: share of the dither matrix's threshold range used",
      &P::GetDitherStrength, &P::GetDitherStrengthMinValue, &P::GetDitherStrengthMaxValue,
      &P::SetDitherStrength },
  };
  AddNumberOptions(t, d.Get(), numbers);
  const PassNumber<P, int> integers[] = {
    { "--pixel-size", "PX", "pixel: art pixel size in window pixels", &P::GetPixelSize,
      &P::GetPixelSizeMinValue, &P::GetPixelSizeMaxValue, &P::SetPixelSize },
    { "--art-pixels", "N", "pixel: art pixels across the image width, 0 = use --pixel-size",
      &P::GetArtPixelsAcross, &P::GetArtPixelsAcrossMinValue, &P::GetArtPixelsAcrossMaxValue,
      &P::SetArtPixelsAcross },
    { "--hysteresis", "N", "pixel: Canny hysteresis steps (0 = strong edges only)",
      &P::GetHysteresisIterations, &P::GetHysteresisIterationsMinValue,
      &P::GetHysteresisIterationsMaxValue, &P::SetHysteresisIterations },
    { "--levels", "K", "pixel: levels per channel (levels palette) or of gray (grays palette)",
      &P::GetLevels, &P::GetLevelsMinValue, &P::GetLevelsMaxValue, &P::SetLevels },
    { "--dither-size", "N", "pixel: art pixels per cell of the 8x8 dither matrix",
      &P::GetDitherSize, &P::GetDitherSizeMinValue, &P::GetDitherSizeMaxValue,
      &P::SetDitherSize },
    { "--colormap-colors", "N", "pixel: colormap palette: values sampled from the colormap",
      &P::GetColormapColors, &P::GetColormapColorsMinValue, &P::GetColormapColorsMaxValue,
      &P::SetColormapColors },
    { "--colormap-shades", "N", "pixel: colormap palette: shades of each sampled colour",
      &P::GetColormapShades, &P::GetColormapShadesMinValue, &P::GetColormapShadesMaxValue,
      &P::SetColormapShades },
  };
  AddNumberOptions(t, d.Get(), integers);
  const PassKeyword<P> keywords[] = {
    { "--mode", "fast|faithful",
      "pixel: render at the art-pixel resolution (fast) or at full resolution and average each "
      "block (faithful) (default: faithful)",
      { { "fast", [](P* p) { p->SetModeToFast(); } },
        { "faithful", [](P* p) { p->SetModeToFaithful(); } } } },
    { "--edge-detector", "none|sobel|canny",
      "pixel: edges of the lit art-pixel image (default: canny)",
      { { "none", [](P* p) { p->SetEdgeDetector(P::NO_EDGES); } },
        { "sobel", [](P* p) { p->SetEdgeDetector(P::SOBEL); } },
        { "canny", [](P* p) { p->SetEdgeDetector(P::CANNY); } } } },
    { "--palette", "levels|grays|1bit|4grays|16|custom|colormap",
      "pixel: levels per channel, grays, black and white, 4 grays, the 16-colour DawnBringer "
      "palette, the --colors list, or the data's colormap (default: levels)",
      { { "levels", [](P* p) { p->SetPalette(P::LEVELS); } },
        { "grays", [](P* p) { p->SetPalette(P::GRAYS); } },
        { "1bit", [](P* p) { p->SetPaletteToOneBit(); } },
        { "4grays", [](P* p) { p->SetPaletteToFourGrays(); } },
        { "16", [](P* p) { p->SetPalette(P::PALETTE16); } },
        { "custom", [](P* p) { p->SetPalette(P::CUSTOM); } },
        { "colormap", [](P* p) { p->SetPalette(P::COLORMAP); } } } },
    { "--dither-anchor", "screen|grid|surface",
      "pixel: attach the dither pattern to the window, to the world-aligned art-pixel grid, or "
      "to the surface (default: grid)",
      { { "screen", [](P* p) { p->SetDitherAnchor(P::SCREEN); } },
        { "grid", [](P* p) { p->SetDitherAnchor(P::GRID); } },
        { "surface", [](P* p) { p->SetDitherAnchor(P::SURFACE); } } } },
    { "--pixel-layer", "art|pixelated|edges",
      "pixel: write the pixel art, the art-pixel colours before edges and dither, or the edges "
      "alone (default: art)",
      { { "art", [](P* p) { p->SetLayer(P::PIXEL_ART); } },
        { "pixelated", [](P* p) { p->SetLayer(P::PIXELATED); } },
        { "edges", [](P* p) { p->SetLayer(P::EDGES); } } } },
  };
  AddKeywordOptions(t, keywords);
  t.push_back({ "--outline", "COLOR",
    "pixel: outline colour, R,G,B in [0, 1] or #rrggbb (default: 0,0,0)",
    [](Options& opt, const std::string& v) {
      const auto c = ParseColor("--outline", v);
      opt.StyleOptions.Pixel.push_back([c](P* p) { p->SetOutlineColor(c[0], c[1], c[2]); });
    } });
  t.push_back({ "--colors", "LIST",
    "pixel: the custom palette: colours (R,G,B or #rrggbb) separated by spaces or ';', at most "
    "256; selects --palette custom",
    [](Options& opt, const std::string& v) {
      // Colours separated by ';' or white space; hex colours may also be separated by ','.
      std::string list = v;
      for (size_t i = 0; i < list.size(); ++i)
      {
        const bool hexComma = list[i] == ',' && i + 1 < list.size() && list[i + 1] == '#';
        if (list[i] == ';' || std::isspace(static_cast<unsigned char>(list[i])) || hexComma)
        {
          list[i] = ' ';
        }
      }
      std::vector<std::array<double, 3>> colours;
      std::istringstream words(list);
      std::string part;
      while (words >> part)
      {
        colours.push_back(ParseColor("--colors", part));
      }
      if (colours.empty())
      {
        UsageError("--colors: no colour given");
      }
      if (colours.size() > 256)
      {
        UsageError("--colors: at most 256 colours");
      }
      opt.StyleOptions.Pixel.push_back([colours](P* p) {
        p->RemoveAllPaletteColors();
        for (const auto& c : colours)
        {
          p->AddPaletteColor(c[0], c[1], c[2]);
        }
        p->SetPalette(P::CUSTOM);
      });
    } });
  const PassFlag<P> flags[] = {
    { "--no-depth-edges", "pixel: no silhouette outlines (default: on)", &P::SetDepthEdges,
      false },
    { "--normal-edges", "pixel: outline creases (default: off)", &P::SetNormalEdges, true },
    { "--no-snap", "pixel: do not snap a parallel camera to the art-pixel grid (default: snap)",
      &P::SetSnapToGrid, false },
    { "--stylize-background", "pixel: dither and quantize the background too (default: off)",
      &P::SetStylizeBackground, true },
  };
  AddFlagOptions(t, flags);
  // Thresholds shared with comic (same ranges): set both passes.
  for (OptionSpec& o : t)
  {
    if (o.Name == "--depth-threshold" || o.Name == "--normal-threshold")
    {
      const bool depth = o.Name == "--depth-threshold";
      const std::string name = o.Name;
      const double lo = depth ? d->GetDepthThresholdMinValue() : d->GetNormalThresholdMinValue();
      const double hi = depth ? d->GetDepthThresholdMaxValue() : d->GetNormalThresholdMaxValue();
      auto comic = o.Apply;
      o.Help += "; pixel: the same for its depth and normal outlines (default: " +
        FormatNumber(depth ? d->GetDepthThreshold() : d->GetNormalThreshold()) + ")";
      o.Apply = [comic, depth, name, lo, hi](Options& opt, const std::string& v) {
        comic(opt, v);
        const double value = DoubleInRange(name, v, lo, hi);
        opt.StyleOptions.Pixel.push_back([depth, value](P* p) {
          if (depth)
          {
            p->SetDepthThreshold(value);
          }
          else
          {
            p->SetNormalThreshold(value);
          }
        });
      };
    }
  }
}

/** "R,G,B" of a colour, for --help. */
std::string FormatColor(const double c[3])
{
  return FormatNumber(c[0]) + "," + FormatNumber(c[1]) + "," + FormatNumber(c[2]);
}

/**
 * The sketch options. Ranges and defaults come from vtkSketchPass itself, as for comic.
 * --cross-threshold, --reference-height, --no-cross and --tinted (comic options) also set the
 * sketch pass. --direction-source model also makes the program compute the principal
 * directions of the surfaces (vtkStylizePrincipalCurvatures).
 */
void AddSketchOptions(std::vector<OptionSpec>& t)
{
  vtkNew<vtkSketchPass> d;
  using P = vtkSketchPass;
  t.push_back({ "--neighbors", "2|4|8",
    "sketch: neighbours of the per-pixel principal-direction estimate: 2 (one pair), 4 (smooth "
    "man-made shapes) or 8 (organic and coarse meshes) (default: " +
      std::to_string(d->GetNeighbors()) + ")",
    [](Options& opt, const std::string& v) {
      long n = 0;
      if (!ParseInt(v, n) || (n != 2 && n != 4 && n != 8))
      {
        UsageError("invalid value " + Quote(v) + " for --neighbors: expected 2, 4 or 8");
      }
      opt.StyleOptions.Sketch.push_back([n](P* p) { p->SetNeighbors(static_cast<int>(n)); });
    } });
  const PassNumber<P, double> numbers[] = {
    { "--neighbor-spacing", "PT",
      "sketch: smallest distance between the estimate's neighbours, points at the focal "
      "distance (the stride grows near the camera)",
      &P::GetNeighborSpacing, &P::GetNeighborSpacingMinValue, &P::GetNeighborSpacingMaxValue,
      &P::SetNeighborSpacing },
    { "--max-stride", "PT", "sketch: largest neighbour stride in points", &P::GetMaxStride,
      &P::GetMaxStrideMinValue, &P::GetMaxStrideMaxValue, &P::SetMaxStride },
    { "--planar-tolerance", "T",
      "sketch: neighbour pairs whose normal turns less than this (radians) are planar and "
      "skipped",
      &P::GetPlanarTolerance, &P::GetPlanarToleranceMinValue, &P::GetPlanarToleranceMaxValue,
      &P::SetPlanarTolerance },
    { "--umbilic-tolerance", "T",
      "sketch: pixels whose fit confidence is not above this have no direction and are filled",
      &P::GetUmbilicTolerance, &P::GetUmbilicToleranceMinValue, &P::GetUmbilicToleranceMaxValue,
      &P::SetUmbilicTolerance },
    { "--fill-radius", "PT",
      "sketch: farthest distance in points from which a pixel without a direction takes its "
      "surface's direction, 0 = no filling",
      &P::GetFillRadius, &P::GetFillRadiusMinValue, &P::GetFillRadiusMaxValue,
      &P::SetFillRadius },
    { "--fallback-angle", "DEG",
      "sketch: screen angle of the strokes where no direction and no lighting gradient exist",
      &P::GetFallbackAngle, &P::GetFallbackAngleMinValue, &P::GetFallbackAngleMaxValue,
      &P::SetFallbackAngle },
    { "--step-length", "PT", "sketch: stroke step length in points (long: soft pencil)",
      &P::GetStepLength, &P::GetStepLengthMinValue, &P::GetStepLengthMaxValue,
      &P::SetStepLength },
    { "--noise-size", "PT", "sketch: size of a noise texel in points at the focal distance",
      &P::GetNoiseSize, &P::GetNoiseSizeMinValue, &P::GetNoiseSizeMaxValue, &P::SetNoiseSize },
    { "--stroke-contrast", "C", "sketch: contrast of the strokes, 0 = flat tone",
      &P::GetStrokeContrast, &P::GetStrokeContrastMinValue, &P::GetStrokeContrastMaxValue,
      &P::SetStrokeContrast },
    { "--contrast", "C",
      "sketch: tone contrast against its blur, o + c (o - b), 0 = no blur", &P::GetContrast,
      &P::GetContrastMinValue, &P::GetContrastMaxValue, &P::SetContrast },
    { "--blur-radius", "PT", "sketch: radius (3 sigma) of the contrast blur in points",
      &P::GetBlurRadius, &P::GetBlurRadiusMinValue, &P::GetBlurRadiusMaxValue,
      &P::SetBlurRadius },
  };
  AddNumberOptions(t, d.Get(), numbers);
  const PassNumber<P, int> integers[] = {
    { "--smoothing", "N", "sketch: direction smoothing iterations over 3x3 pixels",
      &P::GetSmoothingIterations, &P::GetSmoothingIterationsMinValue,
      &P::GetSmoothingIterationsMaxValue, &P::SetSmoothingIterations },
    { "--steps", "N", "sketch: stroke steps on each side of a pixel", &P::GetSteps,
      &P::GetStepsMinValue, &P::GetStepsMaxValue, &P::SetSteps },
    { "--blur-stride", "K",
      "sketch: the contrast blur runs at 1/K of the resolution with taps K pixels apart",
      &P::GetBlurStride, &P::GetBlurStrideMinValue, &P::GetBlurStrideMaxValue,
      &P::SetBlurStride },
  };
  AddNumberOptions(t, d.Get(), integers);
  const PassKeyword<P> keywords[] = {
    { "--direction-source", "screen|model",
      "sketch: principal directions estimated per pixel on the screen, or the data's own "
      "(model: computed for the surfaces by vtkStylizePrincipalCurvatures; the screen estimate "
      "where they are missing) (default: screen)",
      { { "screen", [](P* p) { p->SetDirectionSource(P::SCREEN); } },
        { "model", [](P* p) { p->SetDirectionSource(P::MODEL); } } } },
    { "--direction", "minimum|maximum|bisector",
      "sketch: strokes along the principal direction of the smaller or larger |curvature|, or "
      "halfway between them (default: maximum)",
      { { "minimum", [](P* p) { p->SetDirection(P::MINIMUM); } },
        { "maximum", [](P* p) { p->SetDirection(P::MAXIMUM); } },
        { "bisector", [](P* p) { p->SetDirection(P::BISECTOR); } } } },
    { "--noise", "white|perlin|worley",
      "sketch: noise convolved along the strokes: hard, medium or soft pencil (default: white)",
      { { "white", [](P* p) { p->SetNoise(P::WHITE); } },
        { "perlin", [](P* p) { p->SetNoise(P::PERLIN); } },
        { "worley", [](P* p) { p->SetNoise(P::WORLEY); } } } },
    { "--noise-space", "object|screen",
      "sketch: fix the noise to the surface or to the image (strokes swim) (default: object)",
      { { "object", [](P* p) { p->SetNoiseSpace(P::OBJECT); } },
        { "screen", [](P* p) { p->SetNoiseSpace(P::SCREEN_SPACE); } } } },
    { "--lic", "perspective|screen2d",
      "sketch: strokes traced in world space and reprojected, or the classic screen-space line "
      "integral convolution (default: perspective)",
      { { "perspective", [](P* p) { p->SetLicMode(P::PERSPECTIVE); } },
        { "screen2d", [](P* p) { p->SetLicMode(P::SCREEN_2D); } } } },
    { "--sketch-layer", "sketch|directions|strokes|tone",
      "sketch: write the sketch, the stroke directions as hues, the strokes alone, or the tone "
      "before the strokes (default: sketch)",
      { { "sketch", [](P* p) { p->SetLayer(P::SKETCH); } },
        { "directions", [](P* p) { p->SetLayer(P::DIRECTIONS); } },
        { "strokes", [](P* p) { p->SetLayer(P::STROKES); } },
        { "tone", [](P* p) { p->SetLayer(P::TONE); } } } },
  };
  AddKeywordOptions(t, keywords);
  // The program computes the principal directions only when the pass uses them.
  ExtendOption(t, "--direction-source", "", [](Options& opt, const std::string& v) {
    opt.ModelDirections = Lower(v) == "model";
  });
  const double* bright = d->GetBrightThresholds();
  t.push_back({ "--bright-thresholds", "T1,T2",
    "sketch: tones above T1 are lifted to white, reached at T2; each in [0, 1], T2 below T1 is "
    "raised to T1 (default: " +
      FormatNumber(bright[0]) + "," + FormatNumber(bright[1]) + ")",
    [](Options& opt, const std::string& v) {
      const auto parts = Split(v, ',');
      if (parts.size() != 2)
      {
        UsageError(
          "invalid value " + Quote(v) + " for --bright-thresholds: expected T1,T2, e.g. 0.8,0.95");
      }
      const double t1 = DoubleInRange("--bright-thresholds", parts[0], 0.0, 1.0);
      const double t2 = DoubleInRange("--bright-thresholds", parts[1], 0.0, 1.0);
      opt.StyleOptions.Sketch.push_back([t1, t2](P* p) { p->SetBrightThresholds(t1, t2); });
    } });
  t.push_back({ "--pencil", "COLOR",
    "sketch: pencil colour, R,G,B in [0, 1] or #rrggbb (default: " +
      FormatColor(d->GetPencilColor()) + ")",
    [](Options& opt, const std::string& v) {
      const auto c = ParseColor("--pencil", v);
      opt.StyleOptions.Sketch.push_back([c](P* p) { p->SetPencilColor(c[0], c[1], c[2]); });
    } });
  t.push_back({ "--paper", "COLOR",
    "sketch: paper colour, R,G,B in [0, 1] or #rrggbb (default: " +
      FormatColor(d->GetPaperColor()) + ")",
    [](Options& opt, const std::string& v) {
      const auto c = ParseColor("--paper", v);
      opt.StyleOptions.Sketch.push_back([c](P* p) { p->SetPaperColor(c[0], c[1], c[2]); });
    } });

  // Comic options that also set the sketch pass.
  ExtendOption(t, "--cross-threshold",
    "; sketch: tone below which the cross strokes start (default: " +
      FormatNumber(d->GetCrossThreshold()) + ")",
    [lo = d->GetCrossThresholdMinValue(), hi = d->GetCrossThresholdMaxValue()](
      Options& opt, const std::string& v) {
      const double value = DoubleInRange("--cross-threshold", v, lo, hi);
      opt.StyleOptions.Sketch.push_back([value](P* p) { p->SetCrossThreshold(value); });
    });
  ExtendOption(t, "--reference-height",
    "; sketch: the same (0: window pixels; other values below " +
      FormatNumber(d->GetReferenceHeightMinValue()) + " count as " +
      FormatNumber(d->GetReferenceHeightMinValue()) + ") (default: " +
      FormatNumber(d->GetReferenceHeight()) + ")",
    [](Options& opt, const std::string& v) {
      double value = 0;
      ParseDouble(v, value); // validated by the comic option
      opt.StyleOptions.SketchWindowPoints = value == 0.0;
      if (value != 0.0)
      {
        opt.StyleOptions.Sketch.push_back([value](P* p) { p->SetReferenceHeight(value); });
      }
    });
  ExtendOption(t, "--no-cross", "; sketch: no cross strokes in dark zones (default: crossed)",
    [](Options& opt, const std::string&) {
      opt.StyleOptions.Sketch.push_back([](P* p) { p->SetCrossHatching(false); });
    });
  ExtendOption(t, "--tinted", "; sketch: paper tinted by the lit colour's hue (default: off)",
    [](Options& opt, const std::string&) {
      opt.StyleOptions.Sketch.push_back([](P* p) { p->SetTinted(true); });
    });
}

std::vector<OptionSpec> OptionTable(const LightingSettings& d)
{
  const Options o; // default values
  const std::string models = std::string(vtkStylizeLightingPass::GetModelName(0)) + "|" +
    vtkStylizeLightingPass::GetModelName(1) + "|" + vtkStylizeLightingPass::GetModelName(2);
  std::vector<OptionSpec> t;
  t.push_back({ "--style", "NAME",
    "style: " + StyleNames("|") + " (default: " + o.Style + ")",
    [](Options& opt, const std::string& v) {
      if (!FindStyle(v))
      {
        UsageError("unknown style " + Quote(v) + " for --style (expected " + StyleNames(", ") + ")");
      }
      opt.Style = v;
    } });
  t.push_back({ "--output", "FILE.png",
    "output PNG file, must end with .png (default: " + o.Output + ")",
    [](Options& opt, const std::string& v) {
      if (!EndsWithNoCase(v, ".png"))
      {
        UsageError("invalid value " + Quote(v) + " for --output: the file name must end with .png");
      }
      opt.Output = v;
    } });
  t.push_back({ "--size", "WxH",
    "image size in pixels, W and H in [1, " + std::to_string(MaxImageSize) + "] (default: " +
      std::to_string(o.Width) + "x" + std::to_string(o.Height) + ")",
    [](Options& opt, const std::string& v) {
      const auto parts = Split(Lower(v), 'x');
      long w = 0, h = 0;
      if (parts.size() != 2 || !ParseInt(parts[0], w) || !ParseInt(parts[1], h) ||
        !std::isdigit(static_cast<unsigned char>(parts[0][0])) ||
        !std::isdigit(static_cast<unsigned char>(parts[1][0])))
      {
        UsageError("invalid value " + Quote(v) + " for --size: expected WxH, e.g. 1280x720");
      }
      if (w < 1 || w > MaxImageSize || h < 1 || h > MaxImageSize)
      {
        UsageError("--size " + v + " is out of range: width and height must be in [1, " +
          std::to_string(MaxImageSize) + "]");
      }
      opt.Width = static_cast<int>(w);
      opt.Height = static_cast<int>(h);
    } });
  t.push_back({ "--lights", "N",
    "number of scene lights in [0, " + std::to_string(MaxLights) +
      "]: 0 none, 1 the headlight, N > 1 white lights spread over a sphere around the scene, "
      "alternately directional and positional, each of intensity min(1, 3/N) (default: " +
      std::to_string(o.Lights) + ")",
    [](Options& opt, const std::string& v) { opt.Lights = IntInRange("--lights", v, 0, MaxLights); } });
  t.push_back({ "--azimuth", "DEG",
    "camera azimuth in degrees, [-360, 360] (default: 0; " + FormatNumber(SceneAzimuth) +
      " for the built-in scene)",
    [](Options& opt, const std::string& v) {
      opt.Azimuth = DoubleInRange("--azimuth", v, -MaxAngle, MaxAngle);
    } });
  t.push_back({ "--elevation", "DEG",
    "camera elevation in degrees, [-360, 360] (default: 0; " + FormatNumber(SceneElevation) +
      " for the built-in scene)",
    [](Options& opt, const std::string& v) {
      opt.Elevation = DoubleInRange("--elevation", v, -MaxAngle, MaxAngle);
    } });
  t.push_back({ "--zoom", "F",
    "camera zoom factor, [" + FormatNumber(MinZoom) + ", " + FormatNumber(MaxZoom) +
      "] (default: " + FormatNumber(o.Zoom) + ")",
    [](Options& opt, const std::string& v) {
      opt.Zoom = DoubleInRange("--zoom", v, MinZoom, MaxZoom);
    } });
  t.push_back({ "--parallel", nullptr, "parallel projection (default: perspective)",
    [](Options& opt, const std::string&) { opt.Parallel = true; } });
  t.push_back({ "--background", "R,G,B",
    "background colour, each component in [0, 1] (default: 1,1,1)",
    [](Options& opt, const std::string& v) {
      const auto parts = Split(v, ',');
      double c[3];
      if (parts.size() != 3 || !ParseDouble(parts[0], c[0]) || !ParseDouble(parts[1], c[1]) ||
        !ParseDouble(parts[2], c[2]))
      {
        UsageError("invalid value " + Quote(v) + " for --background: expected R,G,B, e.g. 1,1,1");
      }
      for (int i = 0; i < 3; ++i)
      {
        if (c[i] < 0.0 || c[i] > 1.0)
        {
          UsageError("--background " + v + " is out of range: each component must be in [0, 1]");
        }
        opt.Background[i] = c[i];
      }
    } });
  t.push_back({ "--lighting", "MODEL",
    "lighting model: " + models + " (default: " + vtkStylizeLightingPass::GetModelName(d.Model) +
      ")",
    [models](Options& opt, const std::string& v) {
      const int m = vtkStylizeLightingPass::GetModelFromName(v.c_str());
      if (m < 0)
      {
        UsageError("unknown lighting model " + Quote(v) + " for --lighting (expected " + models + ")");
      }
      opt.Lighting.Model = m;
      opt.LightingModelGiven = true;
    } });
  t.push_back({ "--subject", "P1",
    "comic: subject factor of the ambient term, [0, 1] (default: " +
      FormatNumber(d.SubjectFactor) + ")",
    [](Options& opt, const std::string& v) {
      opt.Lighting.SubjectFactor = DoubleInRange("--subject", v, 0.0, 1.0);
    } });
  t.push_back({ "--levels-near", "N",
    "comic: gray levels at the near end of the depth range, [0, 100] (default: " +
      FormatNumber(d.GrayLevelsNear) + ")",
    [](Options& opt, const std::string& v) {
      opt.Lighting.GrayLevelsNear = DoubleInRange("--levels-near", v, 0.0, 100.0);
    } });
  t.push_back({ "--levels-far", "N",
    "comic: gray levels at the far end of the depth range, [0, 100] (default: " +
      FormatNumber(d.GrayLevelsFar) + ")",
    [](Options& opt, const std::string& v) {
      opt.Lighting.GrayLevelsFar = DoubleInRange("--levels-far", v, 0.0, 100.0);
    } });
  t.push_back({ "--specular-gain", "G",
    "comic: specular gain, [0, 100] (default: " + FormatNumber(d.SpecularGain) + ")",
    [](Options& opt, const std::string& v) {
      opt.Lighting.SpecularGain = DoubleInRange("--specular-gain", v, 0.0, 100.0);
    } });
  t.push_back({ "--scattering", "S",
    "pixelart: scattering degree of the lights, [0, 1] (default: " + FormatNumber(d.Scattering) +
      ")",
    [](Options& opt, const std::string& v) {
      opt.Lighting.Scattering = DoubleInRange("--scattering", v, 0.0, 1.0);
    } });
  t.push_back({ "--occlusion", "M",
    "pixelart: specular occlusion factor, [0, 1] (default: " +
      FormatNumber(d.SpecularOcclusion) + ")",
    [](Options& opt, const std::string& v) {
      opt.Lighting.SpecularOcclusion = DoubleInRange("--occlusion", v, 0.0, 1.0);
    } });
  t.push_back({ "--gbuffer", nullptr,
    "render through the shared G-buffer pass (default: the lighting pass alone)",
    [](Options& opt, const std::string&) { opt.GBuffer = true; } });
  AddComicOptions(t);
  AddPixelOptions(t);
  AddSketchOptions(t);
  t.push_back({ "--magnify", "N",
    "write an image N times the window size, rendered in N x N tiles (vtkWindowToImageFilter "
    "scale), [1, " + std::to_string(MaxMagnify) + "] (default: 1)",
    [](Options& opt, const std::string& v) {
      opt.Magnify = IntInRange("--magnify", v, 1, MaxMagnify);
    } });
  t.push_back({ "--iso", "VALUE",
    "image data only: contour value, any finite number (default: the middle of the scalar range)",
    [](Options& opt, const std::string& v) {
      double iso = 0;
      if (!ParseDouble(v, iso))
      {
        UsageError("invalid value " + Quote(v) + " for --iso: expected a number");
      }
      opt.IsoValue = iso;
    } });
  t.push_back({ "--color-by", "ARRAY",
    "colour by this point (or cell) array (default: the active point scalars, if any)",
    [](Options& opt, const std::string& v) {
      if (v.empty())
      {
        UsageError("invalid value '' for --color-by: expected an array name");
      }
      opt.ColorBy = v;
    } });
  t.push_back({ "--no-scalars", nullptr, "ignore all arrays: one solid colour (default: off)",
    [](Options& opt, const std::string&) { opt.NoScalars = true; } });
  t.push_back({ "--no-annotations", nullptr,
    "no title and no scalar bar (default: both are drawn)",
    [](Options& opt, const std::string&) { opt.NoAnnotations = true; } });
  t.push_back({ "--multisamples", "N",
    "multisample anti-aliasing samples, [0, " + std::to_string(MaxMultiSamples) +
      "] (default: " + std::to_string(o.MultiSamples) + ")",
    [](Options& opt, const std::string& v) {
      opt.MultiSamples = IntInRange("--multisamples", v, 0, MaxMultiSamples);
    } });
  t.push_back({ "--quiet", nullptr, "do not print the output path on success (default: off)",
    [](Options& opt, const std::string&) { opt.Quiet = true; } });
  t.push_back({ "--help", nullptr, "print this help and exit",
    [](Options& opt, const std::string&) { opt.Help = true; } });
  t.push_back({ "--version", nullptr, "print the version and exit",
    [](Options& opt, const std::string&) { opt.Version = true; } });
  return t;
}

std::string HelpText(const std::vector<OptionSpec>& table)
{
  std::ostringstream out;
  out << "Usage: vtkstylize [options] [INPUT]\n"
         "\n"
         "Renders INPUT, or the built-in scene when no INPUT is given, offscreen through the\n"
         "VTK Stylize render passes and writes a PNG image.\n"
         "\n"
         "INPUT formats, chosen by extension (case-insensitive):\n"
         "  .vtp .vtu .vts .vtr .vti .vtm  VTK XML files\n"
         "  .vtk                           VTK legacy files\n"
         "  .stl .obj .ply                 surface meshes\n"
         "Volumes and grids are drawn as their outer surface; image data with a point scalar\n"
         "array is drawn as a contour (see --iso); each block of a multiblock file is drawn as\n"
         "its own actor. Surfaces are coloured by their active point (else cell) scalars\n"
         "through a colour map unless --color-by or --no-scalars says otherwise.\n"
         "\n"
         "Options (--opt VALUE or --opt=VALUE):\n";
  for (const OptionSpec& o : table)
  {
    std::string head = "  " + o.Name + (o.Argument ? std::string(" ") + o.Argument : "");
    // Word-wrap the help at 79 columns, in a column starting at 24.
    const std::size_t column = 24;
    if (head.size() + 2 > column)
    {
      out << head << "\n";
      head.clear();
    }
    head.resize(column, ' ');
    std::istringstream words(o.Help);
    std::string word, line = head;
    bool first = true;
    while (words >> word)
    {
      if (!first && line.size() + 1 + word.size() > 79)
      {
        out << line << "\n";
        line = std::string(column, ' ');
        first = true;
      }
      line += (first ? "" : " ") + word;
      first = false;
    }
    out << line << "\n";
  }
  out << "\n"
         "On success the output path is printed on stdout. On failure one line starting with\n"
         "\"vtkstylize: \" is printed on stderr and no output file is written.\n"
         "Exit status: 0 success, 1 input, rendering or output error, 2 usage error (unknown\n"
         "option, bad option value, unsupported INPUT extension).\n"
         "Environment: VTKSTYLIZE_VERBOSE=1 also shows VTK's own messages on stderr.\n"
         "An X display (DISPLAY) is needed for OpenGL, even though rendering is offscreen.\n";
  return out.str();
}

Options ParseCommandLine(
  int argc, char* argv[], const std::vector<OptionSpec>& table, Options opt)
{
  std::vector<std::string> positional;
  bool optionsDone = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (optionsDone || arg.size() < 2 || arg[0] != '-')
    {
      positional.push_back(arg);
      continue;
    }
    if (arg == "--")
    {
      optionsDone = true;
      continue;
    }
    std::string name = arg;
    std::optional<std::string> value;
    const auto eq = arg.find('=');
    if (arg.rfind("--", 0) == 0 && eq != std::string::npos)
    {
      name = arg.substr(0, eq);
      value = arg.substr(eq + 1);
    }
    const OptionSpec* spec = nullptr;
    for (const OptionSpec& o : table)
    {
      if (o.Name == name)
      {
        spec = &o;
      }
    }
    if (!spec)
    {
      UsageError("unknown option " + Quote(name) + " (see --help)");
    }
    if (!spec->Argument)
    {
      if (value)
      {
        UsageError("option " + name + " takes no value");
      }
      spec->Apply(opt, std::string());
      continue;
    }
    if (!value)
    {
      if (i + 1 >= argc)
      {
        UsageError("option " + name + " requires an argument " + spec->Argument);
      }
      value = argv[++i];
    }
    spec->Apply(opt, *value);
  }
  if (opt.Help || opt.Version)
  {
    return opt;
  }
  if (positional.size() > 1)
  {
    UsageError("too many arguments: expected at most one INPUT file, got " +
      std::to_string(positional.size()) + " (" + Quote(positional[0]) + ", " +
      Quote(positional[1]) + (positional.size() > 2 ? ", ..." : "") + ")");
  }
  if (!positional.empty())
  {
    opt.Input = positional[0];
    if (opt.Input.empty())
    {
      UsageError("the INPUT file name is empty");
    }
  }
  return opt;
}

//==============================================================================
// 3. Scene
//==============================================================================

constexpr double SolidColor[3] = { 0.80, 0.80, 0.78 };

/** Diverging cool-to-warm colour map (Moreland) over [lo, hi]. */
vtkSmartPointer<vtkColorTransferFunction> CoolWarm(double lo, double hi)
{
  vtkNew<vtkColorTransferFunction> ctf;
  ctf->SetColorSpaceToDiverging();
  ctf->AddRGBPoint(lo, 0.230, 0.299, 0.754);
  ctf->AddRGBPoint(hi, 0.706, 0.016, 0.150);
  return ctf;
}

/** Viridis-like sequential colour map over [lo, hi]. */
vtkSmartPointer<vtkColorTransferFunction> Viridis(double lo, double hi)
{
  static const double nodes[5][3] = { { 0.267, 0.005, 0.329 }, { 0.229, 0.322, 0.546 },
    { 0.128, 0.567, 0.551 }, { 0.369, 0.789, 0.383 }, { 0.993, 0.906, 0.144 } };
  vtkNew<vtkColorTransferFunction> ctf;
  ctf->SetColorSpaceToLab();
  for (int i = 0; i < 5; ++i)
  {
    ctf->AddRGBPoint(lo + (hi - lo) * i / 4.0, nodes[i][0], nodes[i][1], nodes[i][2]);
  }
  return ctf;
}

/** How a part is coloured. */
struct Coloring
{
  std::string Array; // empty: solid
  int Association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  bool Direct = false; // unsigned char RGB(A): the values are the colours
};

vtkDataArray* FindArray(vtkPolyData* pd, const std::string& name, int& association)
{
  if (vtkDataArray* a = pd->GetPointData()->GetArray(name.c_str()))
  {
    association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
    return a;
  }
  if (vtkDataArray* a = pd->GetCellData()->GetArray(name.c_str()))
  {
    association = vtkDataObject::FIELD_ASSOCIATION_CELLS;
    return a;
  }
  return nullptr;
}

Coloring ChooseColoring(const Part& part, const Options& opt, bool builtIn)
{
  Coloring c;
  if (opt.NoScalars)
  {
    return c;
  }
  vtkPolyData* pd = part.Surface;
  std::string name = opt.ColorBy;
  if (name.empty())
  {
    if (builtIn)
    {
      name = part.Name == "parametric" ? "Height" : part.Name == "streamlines" ? "Speed" : "";
    }
    else if (vtkDataArray* s = pd->GetPointData()->GetScalars())
    {
      name = s->GetName() ? s->GetName() : "";
      if (name.empty())
      {
        s->SetName("Scalars");
        name = "Scalars";
      }
    }
    else if (vtkDataArray* cs = pd->GetCellData()->GetScalars())
    {
      name = cs->GetName() ? cs->GetName() : "";
      if (name.empty())
      {
        cs->SetName("CellScalars");
        name = "CellScalars";
      }
    }
  }
  if (name.empty())
  {
    return c;
  }
  int association = 0;
  vtkDataArray* array = FindArray(pd, name, association);
  if (!array)
  {
    return c;
  }
  c.Array = name;
  c.Association = association;
  c.Direct = vtkUnsignedCharArray::SafeDownCast(array) &&
    (array->GetNumberOfComponents() == 3 || array->GetNumberOfComponents() == 4) &&
    opt.ColorBy.empty();
  return c;
}

struct SceneAnnotations
{
  std::string Title;
  std::string ScalarBarArray; // array shown by the scalar bar, empty for none
};

void AddAnnotations(vtkRenderer* ren, const Options& opt, const SceneAnnotations& info,
  const std::map<std::string, vtkSmartPointer<vtkColorTransferFunction>>& maps)
{
  if (opt.NoAnnotations)
  {
    return;
  }
  const double luminance =
    0.299 * opt.Background[0] + 0.587 * opt.Background[1] + 0.114 * opt.Background[2];
  const double ink = luminance > 0.5 ? 0.1 : 0.95;
  const int fontSize = std::max(8, std::min(opt.Width, opt.Height) / 28);

  vtkNew<vtkTextActor> title;
  title->SetInput(info.Title.c_str());
  title->GetTextProperty()->SetFontSize(fontSize);
  title->GetTextProperty()->SetColor(ink, ink, ink);
  title->GetTextProperty()->SetJustificationToLeft();
  title->GetTextProperty()->SetVerticalJustificationToTop();
  title->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  title->GetPositionCoordinate()->SetValue(0.02, 0.97);
  ren->AddActor2D(title);

  const auto it = maps.find(info.ScalarBarArray);
  if (!info.ScalarBarArray.empty() && it != maps.end())
  {
    vtkNew<vtkScalarBarActor> bar;
    bar->SetLookupTable(it->second);
    bar->SetTitle(info.ScalarBarArray.c_str());
    bar->SetNumberOfLabels(4);
    bar->SetOrientationToVertical();
    bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    bar->GetPositionCoordinate()->SetValue(0.88, 0.1);
    bar->SetWidth(0.1);
    bar->SetHeight(0.8);
    for (vtkTextProperty* tp : { bar->GetTitleTextProperty(), bar->GetLabelTextProperty() })
    {
      tp->SetColor(ink, ink, ink);
      tp->ShadowOff();
      tp->ItalicOff();
    }
    bar->SetVerticalTitleSeparation(std::max(2, fontSize / 3));
    bar->SetMaximumWidthInPixels(std::max(40, opt.Width / 8));
    ren->AddActor2D(bar);
  }
}

/** Adds one actor per part, coloured as ChooseColoring() says. */
void AddParts(vtkRenderer* ren, const std::vector<Part>& parts, const Options& opt, bool builtIn,
  SceneAnnotations& info, const std::string& what)
{
  // Colour maps: one per array name, over the range of that array across all parts.
  std::vector<Coloring> colorings;
  std::map<std::string, std::array<double, 2>> ranges;
  bool anyColored = false;
  for (const Part& p : parts)
  {
    Coloring c = ChooseColoring(p, opt, builtIn);
    colorings.push_back(c);
    if (c.Array.empty() || c.Direct)
    {
      anyColored = anyColored || c.Direct;
      continue;
    }
    anyColored = true;
    int association = 0;
    vtkDataArray* array = FindArray(p.Surface, c.Array, association);
    double r[2];
    array->GetRange(r, array->GetNumberOfComponents() > 1 ? -1 : 0);
    auto found = ranges.find(c.Array);
    if (found == ranges.end())
    {
      ranges[c.Array][0] = r[0];
      ranges[c.Array][1] = r[1];
    }
    else
    {
      found->second[0] = std::min(found->second[0], r[0]);
      found->second[1] = std::max(found->second[1], r[1]);
    }
  }
  if (!opt.ColorBy.empty() && !anyColored)
  {
    Fail(what + ": no point or cell array named " + Quote(opt.ColorBy) + " (see --color-by)");
  }
  std::map<std::string, vtkSmartPointer<vtkColorTransferFunction>> maps;
  for (auto& r : ranges)
  {
    double lo = r.second[0], hi = r.second[1];
    // A constant array (up to float rounding): centre it in a unit range.
    if (!(hi - lo > 1e-6 * std::max({ 1.0, std::abs(lo), std::abs(hi) })))
    {
      lo -= 0.5;
      hi += 0.5;
    }
    maps[r.first] = (builtIn && r.first == "Speed") ? Viridis(lo, hi) : CoolWarm(lo, hi);
    if (info.ScalarBarArray.empty() || (builtIn && r.first == "Speed"))
    {
      info.ScalarBarArray = r.first;
    }
  }

  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    const Coloring& c = colorings[i];
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(parts[i].Surface);
    if (c.Array.empty())
    {
      mapper->ScalarVisibilityOff();
    }
    else
    {
      mapper->ScalarVisibilityOn();
      mapper->SetScalarMode(c.Association == vtkDataObject::FIELD_ASSOCIATION_CELLS
          ? VTK_SCALAR_MODE_USE_CELL_FIELD_DATA
          : VTK_SCALAR_MODE_USE_POINT_FIELD_DATA);
      mapper->SelectColorArray(c.Array.c_str());
      if (c.Direct)
      {
        mapper->SetColorModeToDirectScalars();
      }
      else
      {
        vtkColorTransferFunction* ctf = maps[c.Array];
        int association = 0;
        vtkDataArray* array = FindArray(parts[i].Surface, c.Array, association);
        if (array->GetNumberOfComponents() > 1)
        {
          ctf->SetVectorModeToMagnitude();
        }
        mapper->SetColorModeToMapScalars();
        mapper->SetLookupTable(ctf);
        mapper->UseLookupTableScalarRangeOn();
        mapper->InterpolateScalarsBeforeMappingOn();
      }
    }
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkProperty* prop = actor->GetProperty();
    prop->SetColor(SolidColor[0], SolidColor[1], SolidColor[2]);
    // At most 0.1 + 0.75 + 0.15 = 1: a face seen head-on under the headlight is not saturated.
    prop->SetAmbient(0.1);
    prop->SetDiffuse(0.75);
    prop->SetSpecular(0.15);
    prop->SetSpecularPower(30.0);
    ren->AddActor(actor);
  }
  AddAnnotations(ren, opt, info, maps);
}

/**
 * Lights: 0 none; 1 the headlight; N > 1 white scene lights on a Fibonacci sphere around the
 * scene, alternately directional and positional (point lights), each of intensity min(1, 3/N)
 * so that the summed diffuse light (about N/4 lights face a point) stays below 1.
 */
void AddLights(vtkRenderer* ren, int count, const double bounds[6])
{
  ren->AutomaticLightCreationOff();
  ren->RemoveAllLights();
  if (count == 0)
  {
    return;
  }
  if (count == 1)
  {
    vtkNew<vtkLight> headlight;
    headlight->SetLightTypeToHeadlight();
    ren->AddLight(headlight);
    return;
  }
  const double center[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  const double radius = 1.5 * std::max(diagonal, 1e-6);
  const double intensity = std::min(1.0, 3.0 / count);
  const double golden = vtkMath::Pi() * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i)
  {
    const double y = 1.0 - 2.0 * (i + 0.5) / count;
    const double r = std::sqrt(std::max(0.0, 1.0 - y * y));
    const double phi = golden * i;
    const double dir[3] = { r * std::cos(phi), y, r * std::sin(phi) };
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetColor(1.0, 1.0, 1.0);
    light->SetIntensity(intensity);
    light->SetFocalPoint(center[0], center[1], center[2]);
    light->SetPosition(
      center[0] + radius * dir[0], center[1] + radius * dir[1], center[2] + radius * dir[2]);
    if (i % 2 == 1)
    {
      light->PositionalOn();
      light->SetConeAngle(90.0); // >= 90: a point light, not a spot
      light->SetAttenuationValues(1.0, 0.0, 0.0);
    }
    else
    {
      light->PositionalOff();
    }
    ren->AddLight(light);
  }
}

void SetUpCamera(vtkRenderer* ren, const Options& opt, bool builtIn)
{
  vtkCamera* camera = ren->GetActiveCamera();
  camera->SetPosition(0, 0, 1);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelProjection(opt.Parallel);
  ren->ResetCamera();
  const double azimuth = opt.Azimuth ? *opt.Azimuth : (builtIn ? SceneAzimuth : 0.0);
  const double elevation = opt.Elevation ? *opt.Elevation : (builtIn ? SceneElevation : 0.0);
  camera->Azimuth(azimuth);
  double before[3];
  camera->GetDirectionOfProjection(before);
  camera->Elevation(elevation);
  // Looking straight up or down: the old view-up is parallel to the view; use the old forward
  // direction instead so that the view transform stays well defined.
  double dop[3], up[3];
  camera->GetDirectionOfProjection(dop);
  camera->GetViewUp(up);
  if (std::abs(vtkMath::Dot(dop, up)) > 0.999)
  {
    const double sign = vtkMath::Dot(dop, up) > 0 ? -1.0 : 1.0;
    camera->SetViewUp(sign * before[0], sign * before[1], sign * before[2]);
  }
  camera->OrthogonalizeViewUp();
  camera->Zoom(opt.Zoom);
  ren->ResetCameraClippingRange();
}

//==============================================================================
// 4. Rendering and writing
//==============================================================================

std::string Directory(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos)
  {
    return ".";
  }
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string BaseName(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

/** Fails unless OUTPUT names a file (not a directory) in an existing, writable directory. */
void CheckOutputPath(const std::string& path)
{
  const std::string what = "cannot write " + Quote(path);
  if (BaseName(path).size() <= 4)
  {
    Fail(what + ": the file name is empty");
  }
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
  {
    Fail(what + ": is a directory");
  }
  const std::string dir = Directory(path);
  if (::stat(dir.c_str(), &st) != 0)
  {
    Fail(what + ": directory " + Quote(dir) + ": " + std::strerror(errno));
  }
  if (!S_ISDIR(st.st_mode))
  {
    Fail(what + ": " + Quote(dir) + " is not a directory");
  }
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
  {
    Fail(what + ": directory " + Quote(dir) + ": " + std::strerror(errno));
  }
}

#ifdef VTKSTYLIZE_HAVE_X11
/** VTK aborts when it cannot open the X display; check it first. */
void CheckDisplay(vtkRenderWindow* window)
{
  if (!window->IsA("vtkXOpenGLRenderWindow"))
  {
    return;
  }
  Display* display = XOpenDisplay(nullptr);
  if (!display)
  {
    const char* name = std::getenv("DISPLAY");
    Fail(std::string("cannot render: cannot open the X display ") +
      (name && *name ? Quote(name) : std::string("(DISPLAY is not set)")) +
      "; an X server is needed even for offscreen rendering");
  }
  XCloseDisplay(display);
}
#else
void CheckDisplay(vtkRenderWindow*) {}
#endif

/** The offscreen window of the requested size, holding the renderer. */
vtkSmartPointer<vtkRenderWindow> MakeWindow(vtkRenderer* ren, const Options& opt)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(opt.MultiSamples);
  window->SetSize(opt.Width, opt.Height);
  window->AddRenderer(ren);
  CheckDisplay(window);
  return window;
}

/** Renders the window into an image of the requested size and writes it to opt.Output. */
void RenderAndWrite(vtkRenderWindow* window, const Options& opt)
{
  ClearVTKErrors();
  window->Render();
  CheckVTKErrors("rendering failed");

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->SetScale(opt.Magnify);
  grab->Update();
  CheckVTKErrors("reading the rendered image failed");
  int dims[3];
  grab->GetOutput()->GetDimensions(dims);
  if (dims[0] != opt.Width * opt.Magnify || dims[1] != opt.Height * opt.Magnify)
  {
    Fail("rendering failed: got a " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) +
      " image instead of " + std::to_string(opt.Width * opt.Magnify) + "x" +
      std::to_string(opt.Height * opt.Magnify));
  }

  // Write to a temporary file beside the output, then rename: never a partial output file.
  const std::string what = "cannot write " + Quote(opt.Output);
  std::string pattern = Directory(opt.Output) + "/." + BaseName(opt.Output) + ".XXXXXX";
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back(0);
  TemporaryFileGuard temporary;
  const int fd = ::mkstemp(buffer.data());
  if (fd < 0)
  {
    Fail(what + ": " + std::strerror(errno));
  }
  temporary.Set(buffer.data());
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  ::close(fd);

  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(temporary.Get().c_str());
  writer->Write();
  CheckVTKErrors(what);
  if (writer->GetErrorCode() != vtkErrorCode::NoError)
  {
    const char* code = vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode());
    Fail(what + ": " + (code ? code : "write error"));
  }
  if (std::rename(temporary.Get().c_str(), opt.Output.c_str()) != 0)
  {
    Fail(what + ": " + std::strerror(errno));
  }
  temporary.Release();
}

//==============================================================================
// 5. Main
//==============================================================================

int Run(int argc, char* argv[])
{
  const LightingSettings lightingDefaults = LightingSettings::FromDefaultPass();
  const std::vector<OptionSpec> table = OptionTable(lightingDefaults);
  Options defaults;
  defaults.Lighting = lightingDefaults;
  Options opt = ParseCommandLine(argc, argv, table, defaults);
  if (opt.Help)
  {
    std::cout << HelpText(table) << std::flush;
    return 0;
  }
  if (opt.Version)
  {
    std::cout << "vtkstylize " << VTKSTYLIZE_VERSION << " (VTK " << vtkVersion::GetVTKVersion()
              << ")\n"
              << std::flush;
    return 0;
  }
  const bool builtIn = opt.Input.empty();
  if (!builtIn && !IsSupportedInput(opt.Input))
  {
    UsageError("unsupported file type " + Quote(opt.Input) + " (supported: " +
      SupportedExtensions() + ")");
  }
  CheckOutputPath(opt.Output);

  // Input -> parts.
  std::vector<Part> parts;
  SceneAnnotations info;
  const std::string what = builtIn ? "built-in scene" : Quote(opt.Input);
  if (builtIn)
  {
    vtkNew<vtkStylizeDemoScene> scene;
    ClearVTKErrors();
    scene->Update();
    CheckVTKErrors("cannot build the built-in scene");
    CollectParts(scene->GetOutput(), opt.IsoValue, what, parts);
    info.Title = "VTK Stylize: built-in scene";
  }
  else
  {
    vtkSmartPointer<vtkDataObject> data = ReadInput(opt.Input);
    CollectParts(data, opt.IsoValue, what, parts);
    info.Title = BaseName(opt.Input);
  }
  FinishParts(parts, what);
  if (opt.ModelDirections && opt.Style == "sketch")
  {
    AddPrincipalDirections(parts, what);
  }

  // Scene.
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(opt.Background);
  AddParts(ren, parts, opt, builtIn, info, what);
  double bounds[6];
  ren->ComputeVisiblePropBounds(bounds);
  if (!vtkMath::AreBoundsInitialized(bounds))
  {
    Fail(what + ": nothing visible to render");
  }
  AddLights(ren, opt.Lights, bounds);
  vtkSmartPointer<vtkRenderWindow> window = MakeWindow(ren, opt); // before the camera: aspect
  SetUpCamera(ren, opt, builtIn);

  // Passes.
  const StyleSpec* style = FindStyle(opt.Style);
  if (!opt.LightingModelGiven && style->DefaultModel >= 0)
  {
    opt.Lighting.Model = style->DefaultModel;
  }
  vtkNew<vtkStylizeLightingPass> lighting;
  opt.Lighting.ApplyTo(lighting);
  vtkSmartPointer<vtkStylizeGBufferPass> gbuffer;
  if (opt.GBuffer)
  {
    gbuffer = vtkSmartPointer<vtkStylizeGBufferPass>::New();
    gbuffer->SetLightingPass(lighting);
  }
  opt.StyleOptions.WindowHeight = opt.Height;
  ren->SetPass(style->MakePass(lighting, gbuffer, opt.StyleOptions));

  RenderAndWrite(window, opt);
  if (!opt.Quiet)
  {
    std::cout << opt.Output << "\n" << std::flush;
  }
  return 0;
}

} // namespace

int main(int argc, char* argv[])
{
  const bool verbose = std::getenv("VTKSTYLIZE_VERBOSE") && *std::getenv("VTKSTYLIZE_VERBOSE") &&
    std::string(std::getenv("VTKSTYLIZE_VERBOSE")) != "0";

  // Keep the real stderr for our one line; send everything else written to fd 2 to /dev/null.
  if (!verbose)
  {
    const int saved = ::dup(2);
    const int null = ::open("/dev/null", O_WRONLY);
    if (saved >= 0 && null >= 0)
    {
      ErrorDescriptor = saved;
      ::fcntl(saved, F_SETFD, FD_CLOEXEC);
      ::dup2(null, 2);
    }
    if (null >= 0)
    {
      ::close(null);
    }
  }
  for (int sig : { SIGSEGV, SIGBUS, SIGFPE, SIGABRT, SIGINT, SIGTERM, SIGHUP })
  {
    std::signal(sig, CrashHandler);
  }

  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  vtkObject::GlobalWarningDisplayOn();
  InstallMessageCapture(verbose ? 2 : -1);

  int code = 0;
  try
  {
    code = Run(argc, argv);
  }
  catch (const CliError& e)
  {
    WriteError(e.Message);
    code = e.Code;
  }
  catch (const std::bad_alloc&)
  {
    WriteError("out of memory");
    code = ExitFailure;
  }
  catch (const std::exception& e)
  {
    WriteError(std::string("internal error: ") + e.what());
    code = ExitFailure;
  }
  std::cout.flush();
  RemoveMessageCapture();
  return code;
}
