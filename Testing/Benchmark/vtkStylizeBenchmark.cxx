// vtkStylizeBenchmark: frame-time comparison of VTK's plain rendering, VTK's own screen-space
// passes (Sobel, SSAO, EDL) and VTK Stylize's lighting and G-buffer passes.
//
// One run renders every (scene, light count, configuration) case offscreen at a fixed size with
// multisampling off, warms up (shader compilation, buffer uploads) and then times N frames, each
// with a small camera azimuth step so that nothing is cached, and glFinish (WaitForCompletion)
// before the clock stops. It writes a CSV with one row per case and a Markdown report (median
// ms, ratios to plain, light-count slopes, triangle-count flatness). Run with --help.

#include "vtkCamera.h"
#include "vtkContourFilter.h"
#include "vtkPLYReader.h"
#include "vtkPolyDataNormals.h"
#include "vtkRTAnalyticSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkCameraPass.h"
#include "vtkComicPass.h"
#include "vtkPixelArtPass.h"
#include "vtkSketchPass.h"
#include "vtkEDLShading.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPNGWriter.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkActor.h"
#include "vtkRenderPass.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSSAOPass.h"
#include "vtkSmartPointer.h"
#include "vtkSobelGradientMagnitudePass.h"
#include "vtkSphereSource.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeStylePass.h"
#include "vtkVersion.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace
{
//------------------------------------------------------------------------------------------------
// Options

struct SceneSpec
{
  std::string Name; // "10k", "500k", "2M", "bunny", "iso970k"
  int Theta;        // spheres: vtkSphereSource resolutions, 2 * Theta * (Phi - 1) triangles;
  int Phi;          // 0 for the real scenes
};

// Real scenes beside the spheres (issue 15): a scanned mesh (the real-data set's bunny, 69k
// triangles, written by the realdata.setup test) and a fine isosurface of VTK's wavelet
// (extent +-120, value 160: 969k triangles). Spheres are umbilic everywhere and send every
// sketch pixel down its fallback path; these have principal directions and real depth edges.
const std::vector<SceneSpec>& AllScenes()
{
  static const std::vector<SceneSpec> scenes = { { "10k", 100, 52 }, { "500k", 500, 502 },
    { "2M", 1000, 1002 }, { "bunny", 0, 0 }, { "iso970k", 0, 0 } };
  return scenes;
}

const std::vector<std::string>& AllConfigs()
{
  static const std::vector<std::string> configs = { "plain", "sobel", "ssao", "edl",
    "light-standard", "light-comic", "light-pixelart", "gbuf-standard", "gbuf-comic",
    "gbuf-pixelart", "gbuf-standard-color", "gbuf-comic-lin", "comic", "comic-geometric", "pixel-fast-2",
    "pixel-fast-4", "pixel-fast-8", "pixel-faithful-2", "pixel-faithful-4", "pixel-faithful-8", "sketch-2", "sketch-4", "sketch-8",
    "sketch-8-stage", "comic-image", "pixel-image", "sketch-image", "comic-nocull",
    "sketch-8-nocull", "comic-interactive", "sketch-8-interactive", "pixel-faithful-4-interactive",
    "plain-translucent", "comic-translucent", "pixel-faithful-4-translucent",
    "sketch-8-translucent" };
  return configs;
}

/** How a scene is named in the reports: "sphere 10k", "bunny (scan)", "iso970k (isosurface)". */
std::string SceneLabel(const std::string& name)
{
  if (name == "bunny")
  {
    return "bunny (scan)";
  }
  if (name == "iso970k")
  {
    return "iso970k (isosurface)";
  }
  return "sphere " + name;
}

const std::vector<int>& AllLightCounts()
{
  static const std::vector<int> lights = { 1, 8, 100, 500 };
  return lights;
}

struct Options
{
  int Width = 1920;
  int Height = 1080;
  int Frames = 7;
  int Warmup = 2;
  std::vector<SceneSpec> Scenes = AllScenes();
  std::vector<int> Lights = AllLightCounts();
  std::vector<std::string> Configs = AllConfigs();
  std::string Csv = "benchmark.csv";
  std::string Markdown = "benchmark.md";
  std::string Images; // folder for one PNG per case (after the timed frames), empty: none
  std::string Bunny = VTKSTYLIZE_REALDATA_DIR "/bunny.ply"; // the scanned mesh
  double FlatTolerance = 25.0; // percent
  double FlatFloor = 2.0;      // ms
};

void PrintHelp(const char* argv0)
{
  std::cout
    << "Usage: " << argv0 << " [options]\n"
    << "Times VTK's plain rendering, VTK's Sobel, SSAO and EDL passes and VTK Stylize's lighting\n"
    << "and G-buffer passes on sphere scenes with 1 to 500 lights (offscreen, no multisampling).\n"
    << "\n"
    << "Options:\n"
    << "  --size WxH        image size (default 1920x1080)\n"
    << "  --frames N        timed frames per case, median reported (default 7)\n"
    << "  --warmup N        untimed warm-up frames per case, at least 2 (default 2)\n"
    << "  --scenes LIST     subset of 10k,500k,2M (sphere triangle counts), bunny (a scanned\n"
    << "                    mesh, 69k triangles) and iso970k (a wavelet isosurface, 969k\n"
    << "                    triangles); default: all\n"
    << "  --bunny FILE      the scanned mesh (default: the real-data set's bunny.ply, written\n"
    << "                    by the test realdata.setup)\n"
    << "  --lights LIST     subset of light counts, e.g. 1,8,100,500 (any positive count)\n"
    << "  --configs LIST    subset of:";
  for (const auto& c : AllConfigs())
  {
    std::cout << " " << c;
  }
  std::cout
    << "\n"
    << "                    (NAME-nocull: the style NAME with background culling off;\n"
    << "                    NAME-interactive: its interactive variant, window rate 15);\n"
    << "                    styles also report per-stage costs and memory per pixel\n"
    << "  --csv FILE        CSV output (default benchmark.csv)\n"
    << "  --markdown FILE   Markdown output (default benchmark.md), also printed to stdout\n"
    << "  --images DIR      also write the last frame of every case as DIR/<scene>-<lights>-<config>.png\n"
    << "  --flat-tolerance P  percent change of the added cost over plain between the smallest\n"
    << "                    and the largest scene still called flat (default 25)\n"
    << "  --quick           smoke mode: 640x360, scene 10k, lights 1,8, 3 frames\n"
    << "  --help            this text\n";
}

std::vector<std::string> SplitList(const std::string& s)
{
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
  {
    if (!item.empty())
    {
      out.push_back(item);
    }
  }
  return out;
}

bool ParseInt(const std::string& s, int& value)
{
  char* end = nullptr;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (end == s.c_str() || *end != '\0' || v <= 0 || v > 1000000)
  {
    return false;
  }
  value = static_cast<int>(v);
  return true;
}

// Returns 0 to continue, 1 for an error, 2 for --help.
int ParseOptions(int argc, char* argv[], Options& opt)
{
  // --quick sets defaults that later options may override.
  for (int i = 1; i < argc; ++i)
  {
    if (std::string(argv[i]) == "--quick")
    {
      opt.Width = 640;
      opt.Height = 360;
      opt.Scenes = { AllScenes()[0] };
      opt.Lights = { 1, 8 };
      opt.Frames = 3;
    }
  }
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto next = [&](std::string& value) -> bool {
      if (i + 1 >= argc)
      {
        std::cerr << "Option " << arg << " needs a value\n";
        return false;
      }
      value = argv[++i];
      return true;
    };
    std::string value;
    if (arg == "--help" || arg == "-h")
    {
      PrintHelp(argv[0]);
      return 2;
    }
    else if (arg == "--quick")
    {
    }
    else if (arg == "--size")
    {
      if (!next(value))
      {
        return 1;
      }
      const auto x = value.find_first_of("xX");
      if (x == std::string::npos || !ParseInt(value.substr(0, x), opt.Width) ||
        !ParseInt(value.substr(x + 1), opt.Height))
      {
        std::cerr << "Bad --size '" << value << "' (expected WxH)\n";
        return 1;
      }
    }
    else if (arg == "--frames" || arg == "--warmup")
    {
      if (!next(value) || !ParseInt(value, arg == "--frames" ? opt.Frames : opt.Warmup))
      {
        std::cerr << "Bad " << arg << " value\n";
        return 1;
      }
      if (opt.Warmup < 2)
      {
        std::cerr << "--warmup must be at least 2\n";
        return 1;
      }
    }
    else if (arg == "--scenes")
    {
      if (!next(value))
      {
        return 1;
      }
      opt.Scenes.clear();
      for (const auto& name : SplitList(value))
      {
        auto it = std::find_if(AllScenes().begin(), AllScenes().end(),
          [&](const SceneSpec& s) { return s.Name == name; });
        if (it == AllScenes().end())
        {
          std::cerr << "Unknown scene '" << name << "' (10k, 500k, 2M, bunny, iso970k)\n";
          return 1;
        }
        opt.Scenes.push_back(*it);
      }
    }
    else if (arg == "--bunny")
    {
      if (!next(opt.Bunny))
      {
        return 1;
      }
    }
    else if (arg == "--lights")
    {
      if (!next(value))
      {
        return 1;
      }
      opt.Lights.clear();
      for (const auto& item : SplitList(value))
      {
        int n = 0;
        if (!ParseInt(item, n))
        {
          std::cerr << "Bad light count '" << item << "'\n";
          return 1;
        }
        opt.Lights.push_back(n);
      }
    }
    else if (arg == "--configs")
    {
      if (!next(value))
      {
        return 1;
      }
      opt.Configs.clear();
      for (const auto& name : SplitList(value))
      {
        if (std::find(AllConfigs().begin(), AllConfigs().end(), name) == AllConfigs().end())
        {
          std::cerr << "Unknown configuration '" << name << "'\n";
          return 1;
        }
        opt.Configs.push_back(name);
      }
    }
    else if (arg == "--csv")
    {
      if (!next(opt.Csv))
      {
        return 1;
      }
    }
    else if (arg == "--markdown")
    {
      if (!next(opt.Markdown))
      {
        return 1;
      }
    }
    else if (arg == "--images")
    {
      if (!next(opt.Images))
      {
        return 1;
      }
    }
    else if (arg == "--flat-tolerance")
    {
      int p = 0;
      if (!next(value) || !ParseInt(value, p))
      {
        std::cerr << "Bad --flat-tolerance value\n";
        return 1;
      }
      opt.FlatTolerance = p;
    }
    else
    {
      std::cerr << "Unknown option '" << arg << "' (see --help)\n";
      return 1;
    }
  }
  if (opt.Scenes.empty() || opt.Lights.empty() || opt.Configs.empty())
  {
    std::cerr << "Empty scene, light or configuration list\n";
    return 1;
  }
  return 0;
}

//------------------------------------------------------------------------------------------------
// Lights: the same deterministic set for every configuration.

/**
 * Fills the renderer with @p count lights. One light is VTK's default headlight. More lights are
 * scene lights spread over a sphere of radius 4 R around the object (golden-angle spiral), in
 * turn directional, positional point (cone 180 degrees) and positional spot (cone 30 degrees,
 * exponent 2) lights, all aimed at the centre, white, intensity 1.5 / count so the summed
 * lighting stays in range.
 */
void SetLights(vtkRenderer* ren, int count, const double center[3], double radius)
{
  ren->RemoveAllLights();
  ren->AutomaticLightCreationOff();
  if (count == 1)
  {
    vtkNew<vtkLight> headlight; // what vtkRenderer::CreateLight() makes
    headlight->SetLightTypeToHeadlight();
    ren->AddLight(headlight);
    return;
  }
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
    light->SetIntensity(1.5 / count);
    light->SetFocalPoint(center[0], center[1], center[2]);
    light->SetPosition(center[0] + 4.0 * radius * dir[0], center[1] + 4.0 * radius * dir[1],
      center[2] + 4.0 * radius * dir[2]);
    switch (i % 3)
    {
      case 0:
        light->PositionalOff(); // directional, from the position towards the focal point
        break;
      case 1:
        light->PositionalOn();
        light->SetConeAngle(180.0); // point light
        break;
      default:
        light->PositionalOn();
        light->SetConeAngle(30.0); // spot light on the object
        light->SetExponent(2.0);
        break;
    }
    ren->AddLight(light);
  }
}

//------------------------------------------------------------------------------------------------
// Configurations

/** The passes of one configuration; they live as long as the render window that uses them. */
struct ConfigPasses
{
  vtkSmartPointer<vtkRenderPass> Root; // set on the renderer; nullptr for "plain"
  std::vector<vtkSmartPointer<vtkRenderPass>> Keep;
  std::string Description;
};

ConfigPasses MakeConfig(const std::string& name, double diagonal);

/**
 * NAME-nocull: configuration NAME (a style) with background culling off
 * (vtkStylizeStylePass::BackgroundCullingOff(): every stage over every pixel, the styles' cost
 * before issue 15's culling; the pictures are identical).
 */
ConfigPasses MakeNoCullConfig(const std::string& name, double diagonal)
{
  ConfigPasses c = MakeConfig(name.substr(0, name.size() - 7), diagonal);
  if (auto* style = vtkStylizeStylePass::SafeDownCast(c.Root))
  {
    style->BackgroundCullingOff();
    c.Description += "; background culling off (every stage over every pixel)";
  }
  return c;
}

bool EndsWith(const std::string& s, const std::string& tail)
{
  return s.size() > tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

ConfigPasses MakeConfig(const std::string& name, double diagonal)
{
  if (EndsWith(name, "-nocull"))
  {
    return MakeNoCullConfig(name, diagonal);
  }
  if (EndsWith(name, "-translucent"))
  {
    // NAME-translucent: NAME with the actor at opacity 0.35 (Bench sets it): a style draws
    // its translucent layers (TranslucentLayers, default 4), plain VTK peels with its own depth
    // peeling (the renderer's UseDepthPeeling, 4 peels).
    ConfigPasses c = MakeConfig(name.substr(0, name.size() - 12), diagonal);
    c.Description += c.Root ? "; the actor at opacity 0.35 (the style's translucent layers, 4)"
                            : "; the actor at opacity 0.35, VTK's depth peeling (4 peels)";
    return c;
  }
  if (EndsWith(name, "-interactive"))
  {
    // NAME-interactive: the style NAME while the window asks for an interactive rate (15 frames
    // per second, as VTK's interactors do while the user drags): its interactive variant.
    ConfigPasses c = MakeConfig(name.substr(0, name.size() - 12), diagonal);
    c.Description += "; the window's desired update rate 15 (the interactive variant)";
    return c;
  }
  ConfigPasses c;
  auto lighting = [&](const std::string& model) {
    auto pass = vtkSmartPointer<vtkStylizeLightingPass>::New();
    pass->SetModel(vtkStylizeLightingPass::GetModelFromName(model.c_str()));
    return pass;
  };
  if (name == "plain")
  {
    c.Description = "VTK's default rendering, no pass";
  }
  else if (name == "sobel")
  {
    auto steps = vtkSmartPointer<vtkRenderStepsPass>::New();
    auto sobel = vtkSmartPointer<vtkSobelGradientMagnitudePass>::New();
    sobel->SetDelegatePass(steps);
    c.Root = sobel;
    c.Keep = { steps };
    c.Description = "vtkSobelGradientMagnitudePass, delegate vtkRenderStepsPass";
  }
  else if (name == "ssao")
  {
    auto steps = vtkSmartPointer<vtkRenderStepsPass>::New();
    auto ssao = vtkSmartPointer<vtkSSAOPass>::New();
    ssao->SetDelegatePass(steps);
    ssao->SetRadius(0.1 * diagonal);
    ssao->SetBias(0.001 * diagonal);
    std::ostringstream d;
    d << "vtkSSAOPass, delegate vtkRenderStepsPass, radius 0.1 x diagonal, bias 0.001 x "
         "diagonal, kernel "
      << ssao->GetKernelSize() << ", blur " << (ssao->GetBlur() ? "on" : "off");
    c.Root = ssao;
    c.Keep = { steps };
    c.Description = d.str();
  }
  else if (name == "edl")
  {
    auto steps = vtkSmartPointer<vtkRenderStepsPass>::New();
    auto edl = vtkSmartPointer<vtkEDLShading>::New();
    edl->SetDelegatePass(steps);
    c.Root = edl;
    c.Keep = { steps };
    c.Description = "vtkEDLShading, delegate vtkRenderStepsPass";
  }
  else if (name.rfind("light-", 0) == 0)
  {
    auto pass = lighting(name.substr(6));
    c.Root = pass;
    c.Description = "vtkStylizeLightingPass (" + name.substr(6) + "), default delegate";
  }
  else if (name == "gbuf-comic-lin")
  {
    // What the comic pass renders before its screen-space stage: the Comic lighting into a
    // G-buffer with the comic pass's default channels, composited.
    auto pass = lighting("comic");
    auto gbuf = vtkSmartPointer<vtkStylizeGBufferPass>::New();
    gbuf->SetLightingPass(pass);
    gbuf->SetChannels(vtkStylizeGBufferPass::NORMAL | vtkStylizeGBufferPass::LINEAR_DEPTH);
    c.Root = gbuf;
    c.Keep = { pass };
    c.Description = "vtkStylizeGBufferPass with vtkStylizeLightingPass (comic), channels "
                    "NORMAL|LINEAR_DEPTH (the comic pass's G-buffer, without its screen stage)";
  }
  else if (name == "comic" || name == "comic-geometric")
  {
    auto comic = vtkSmartPointer<vtkComicPass>::New();
    if (name == "comic-geometric")
    {
      comic->SetEdgeWeights(1, 1, 0);
    }
    c.Root = comic;
    c.Description = name == "comic"
      ? "vtkComicPass, defaults (depth and normal edges, dots, hatching, screen anchor)"
      : "vtkComicPass, depth and normal edges (the defaults' edges since issue 14), dots, "
        "hatching";
  }
  else if (name == "comic-image" || name == "pixel-image" || name == "sketch-image")
  {
    // The image path (ParaView's, after IceT): the style runs over its delegate's colour and
    // depth, lit by the style's own lighting pass (default delegate), normals reconstructed.
    vtkSmartPointer<vtkStylizeStylePass> style;
    if (name == "comic-image")
    {
      style = vtkSmartPointer<vtkComicPass>::New();
    }
    else if (name == "pixel-image")
    {
      style = vtkSmartPointer<vtkPixelArtPass>::New();
    }
    else
    {
      style = vtkSmartPointer<vtkSketchPass>::New();
    }
    auto camera = vtkSmartPointer<vtkCameraPass>::New();
    camera->SetDelegatePass(style->GetLightingPass());
    style->SetDelegatePass(camera);
    c.Root = style;
    c.Keep = { camera };
    c.Description = std::string(style->GetClassName()) +
      " over its delegate's image (camera pass -> its lighting pass), defaults: the path ParaView "
      "takes after compositing";
  }
  else if (name.rfind("pixel-", 0) == 0)
  {
    // pixel-MODE-SIZE: vtkPixelArtPass with its defaults (Canny and depth edges, 4 levels per
    // channel, grid-anchored dither) in the given mode at the given art pixel size.
    const auto dash = name.rfind('-');
    const std::string mode = name.substr(6, dash - 6);
    const int size = std::atoi(name.c_str() + dash + 1);
    auto pixel = vtkSmartPointer<vtkPixelArtPass>::New();
    pixel->SetMode(mode == "fast" ? vtkPixelArtPass::FAST : vtkPixelArtPass::FAITHFUL);
    pixel->SetPixelSize(std::max(1, size));
    c.Root = pixel;
    c.Description = "vtkPixelArtPass, " + mode + " pixelation, art pixel " +
      std::to_string(std::max(1, size)) + " px, defaults (Canny + depth edges, 4 levels, dither)";
  }
  else if (name == "sketch-8-stage")
  {
    // The sketch pass's own G-buffer alone (standard lighting, full precision, normals, linear
    // depth and object positions): sketch-8 minus this is the screen-space sketch stage.
    auto gbuf = vtkSmartPointer<vtkStylizeGBufferPass>::New();
    gbuf->SetLightingPass(lighting("standard"));
    gbuf->SetPrecision(vtkStylizeGBufferPass::FULL);
    gbuf->SetPositionSpace(vtkStylizeGBufferPass::OBJECT);
    gbuf->SetChannels(vtkStylizeGBufferPass::NORMAL | vtkStylizeGBufferPass::POSITION |
      vtkStylizeGBufferPass::LINEAR_DEPTH);
    c.Root = gbuf;
    c.Description = "the G-buffer vtkSketchPass renders (standard lighting, full precision, "
                    "normal, object position, linear depth), composited";
  }
  else if (name.rfind("sketch-", 0) == 0)
  {
    // sketch-N: vtkSketchPass with its defaults (10 LIC steps, white noise, cross-hatching,
    // contrast with blur stride 4) and N neighbours.
    auto sketch = vtkSmartPointer<vtkSketchPass>::New();
    sketch->SetNeighbors(std::atoi(name.c_str() + 7));
    c.Root = sketch;
    c.Description = "vtkSketchPass, " + std::to_string(sketch->GetNeighbors()) +
      " neighbours, defaults (10 LIC steps each side, white noise, cross-hatching, blur stride 4)";
  }
  else if (name.rfind("gbuf-", 0) == 0)
  {
    const bool colorOnly = name == "gbuf-standard-color";
    const std::string model = colorOnly ? "standard" : name.substr(5);
    auto pass = lighting(model);
    auto gbuf = vtkSmartPointer<vtkStylizeGBufferPass>::New();
    gbuf->SetLightingPass(pass);
    gbuf->SetChannels(
      colorOnly ? 0 : (vtkStylizeGBufferPass::NORMAL | vtkStylizeGBufferPass::POSITION));
    c.Root = gbuf;
    c.Keep = { pass };
    c.Description = "vtkStylizeGBufferPass with vtkStylizeLightingPass (" + model + "), " +
      (colorOnly ? "colour and depth only" : "channels NORMAL|POSITION");
  }
  return c;
}

//------------------------------------------------------------------------------------------------
// Measurements

/** Per-stage milliseconds of a style (vtkStylizeStylePass::StageTimingOn()), medians. */
struct StageResult
{
  std::string Scene;
  int Lights = 0;
  std::string Config;
  std::vector<std::pair<std::string, double>> Stages; // name (with runs), median ms
  double Frame = 0.0; // median of the timed frames' totals (waits between stages included)
  double BytesPerPixel = 0.0; // the style's textures (GetTextureBytes()) per viewport pixel
};
std::vector<StageResult> StageResults;

struct Result
{
  std::string Scene;
  vtkIdType Triangles = 0;
  int Lights = 0;
  std::string Config;
  double Median = 0.0;
  double Min = 0.0;
  double Max = 0.0;
  int Frames = 0;
};

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

std::string Fixed(double v, int digits)
{
  if (!std::isfinite(v))
  {
    return "n/a";
  }
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

std::string FormatCount(vtkIdType n)
{
  std::string s = std::to_string(n);
  for (int i = static_cast<int>(s.size()) - 3; i > 0; i -= 3)
  {
    s.insert(static_cast<size_t>(i), ",");
  }
  return s;
}

/** Extracts "OpenGL renderer string: ..." (and version) from ReportCapabilities(). */
std::string RendererString(vtkRenderWindow* renWin, std::string* version)
{
  const char* caps = renWin->ReportCapabilities();
  std::string renderer = "unknown";
  if (!caps)
  {
    return renderer;
  }
  std::istringstream in(caps);
  std::string line;
  while (std::getline(in, line))
  {
    const auto colon = line.find(':');
    if (colon == std::string::npos)
    {
      continue;
    }
    std::string value = line.substr(colon + 1);
    value.erase(0, value.find_first_not_of(" \t"));
    if (line.find("renderer string") != std::string::npos)
    {
      renderer = value;
    }
    else if (version && line.find("version string") != std::string::npos)
    {
      *version = value;
    }
  }
  return renderer;
}

//------------------------------------------------------------------------------------------------
// Report

class Report
{
public:
  Report(const Options& opt, std::vector<Result> results)
    : Opt(opt)
    , Results(std::move(results))
  {
    for (const auto& r : this->Results)
    {
      this->Index[Key(r.Scene, r.Lights, r.Config)] = &r;
      this->TriangleCount[r.Scene] = r.Triangles;
    }
  }

  const Result* Find(const std::string& scene, int lights, const std::string& config) const
  {
    auto it = this->Index.find(Key(scene, lights, config));
    return it == this->Index.end() ? nullptr : it->second;
  }

  double MedianOf(const std::string& scene, int lights, const std::string& config) const
  {
    const Result* r = this->Find(scene, lights, config);
    return r ? r->Median : NAN;
  }

  void Write(std::ostream& os, const std::string& header) const
  {
    const auto& cfgs = this->Opt.Configs;
    os << header;

    // Table 1: median ms.
    os << "\n### Median ms per frame\n\n";
    os << "| scene | triangles | lights |";
    for (const auto& c : cfgs)
    {
      os << " " << c << " |";
    }
    os << "\n| --- | ---: | ---: |";
    for (size_t i = 0; i < cfgs.size(); ++i)
    {
      os << " ---: |";
    }
    os << "\n";
    for (const auto& sc : this->Opt.Scenes)
    {
      for (int n : this->Opt.Lights)
      {
        os << "| " << SceneLabel(sc.Name) << " | " << FormatCount(this->Triangles(sc.Name)) << " | "
           << n << " |";
        for (const auto& c : cfgs)
        {
          os << " " << Fixed(this->MedianOf(sc.Name, n, c), 1) << " |";
        }
        os << "\n";
      }
    }

    // Table 2: ratios to plain.
    const bool hasPlain = std::find(cfgs.begin(), cfgs.end(), "plain") != cfgs.end();
    if (hasPlain)
    {
      os << "\n### Ratio to plain (same scene, same lights, same run)\n\n";
      os << "light-standard / plain compares our lighting pass with VTK's own equivalent "
            "(the same Phong model, VTK's generated per-light shader vs. our light buffer).\n\n";
      os << "| scene | lights |";
      for (const auto& c : cfgs)
      {
        if (c != "plain")
        {
          os << " " << c << " |";
        }
      }
      os << "\n| --- | ---: |";
      for (size_t i = 1; i < cfgs.size(); ++i)
      {
        os << " ---: |";
      }
      os << "\n";
      for (const auto& sc : this->Opt.Scenes)
      {
        for (int n : this->Opt.Lights)
        {
          const double plain = this->MedianOf(sc.Name, n, "plain");
          os << "| " << SceneLabel(sc.Name) << " | " << n << " |";
          for (const auto& c : cfgs)
          {
            if (c != "plain")
            {
              os << " " << Fixed(this->MedianOf(sc.Name, n, c) / plain, 2) << " |";
            }
          }
          os << "\n";
        }
      }
    }

    // The speed targets of issue 15, per scene and light count: each style against the VTK pass
    // that does comparable work, measured in the same run.
    const auto has = [&](const char* c) { return std::find(cfgs.begin(), cfgs.end(), c) != cfgs.end(); };
    if (hasPlain)
    {
      auto ratio = [&](const std::string& scene, int n, const char* a, const char* b, bool added) {
        if (!has(a) || !has(b))
        {
          return std::string("—");
        }
        const double plain = this->MedianOf(scene, n, "plain");
        const double x = this->MedianOf(scene, n, a) - (added ? plain : 0.0);
        const double y = this->MedianOf(scene, n, b) - (added ? plain : 0.0);
        // An added cost within the frame-to-frame noise (under 2 ms or 2% of the frame) makes
        // no ratio: say what it was instead.
        if (added && !(y > std::max(2.0, 0.02 * plain)))
        {
          return std::string("n/a (") + b + " adds " + Fixed(y, 1) + " ms)";
        }
        return Fixed(x / y, 2);
      };
      os << "\n### Targets (issue 15)\n\n";
      os << "Lighting: light-standard / plain (target <= 1.10 at 1 and 8 lights). Comic: what comic "
            "adds over plain / what sobel adds (target <= 1.0). Sketch: what sketch-8 adds / what "
            "ssao adds (target <= 0.75). Pixel art: pixel-fast-4 / plain (target <= 0.8 on the "
            "scan, <= 1.0 on the isosurface).\n\n";
      os << "| scene | lights | lighting / plain | comic added / sobel added | sketch-8 added / "
            "ssao added | pixel-fast-4 / plain |\n";
      os << "| --- | ---: | ---: | ---: | ---: | ---: |\n";
      for (const auto& sc : this->Opt.Scenes)
      {
        for (int n : this->Opt.Lights)
        {
          os << "| " << SceneLabel(sc.Name) << " | " << n << " | "
             << ratio(sc.Name, n, "light-standard", "plain", false) << " | "
             << ratio(sc.Name, n, "comic", "sobel", true) << " | "
             << ratio(sc.Name, n, "sketch-8", "ssao", true) << " | "
             << ratio(sc.Name, n, "pixel-fast-4", "plain", false) << " |\n";
        }
      }
    }

    // Comic: the screen-space stage next to VTK's own screen-space passes.
    if (has("plain") && has("sobel") && has("comic") && has("gbuf-comic-lin"))
    {
      os << "\n### Comic: added cost per frame next to VTK's screen-space passes (ms)\n\n";
      os << "Added = configuration − plain. Comic stage = comic − gbuf-comic-lin: the comic "
            "pass's screen-space stage (edges, dots, hatching) over its own G-buffer, the cost "
            "the target compares with VTK's single colour Sobel pass (sobel − plain, which "
            "includes its own render to a texture).\n\n";
      os << "| scene | lights | sobel added | ssao added | comic added | comic stage | "
            "comic-geometric stage | comic stage / sobel added |\n";
      os << "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
      for (const auto& sc : this->Opt.Scenes)
      {
        for (int n : this->Opt.Lights)
        {
          const double plain = this->MedianOf(sc.Name, n, "plain");
          const double base = this->MedianOf(sc.Name, n, "gbuf-comic-lin");
          const double sobel = this->MedianOf(sc.Name, n, "sobel") - plain;
          const double ssao = has("ssao") ? this->MedianOf(sc.Name, n, "ssao") - plain : NAN;
          const double comic = this->MedianOf(sc.Name, n, "comic");
          const double geo =
            has("comic-geometric") ? this->MedianOf(sc.Name, n, "comic-geometric") - base : NAN;
          os << "| " << SceneLabel(sc.Name) << " | " << n << " | " << Fixed(sobel, 1) << " | "
             << Fixed(ssao, 1) << " | " << Fixed(comic - plain, 1) << " | "
             << Fixed(comic - base, 1) << " | " << Fixed(geo, 1) << " | "
             << Fixed((comic - base) / sobel, 2) << " |\n";
        }
      }
    }

    // Pixel art: the target, read from the ratio table above.
    if (hasPlain && has("pixel-fast-4"))
    {
      os << "\n### Pixel art target\n\n";
      os << "pixel-fast-4 / plain must be <= 0.5 at 10k triangles and <= 1 at 2M (1 light); the "
            "ratios of every pixel configuration are in the ratio table above.\n\n";
      for (const auto& sc : this->Opt.Scenes)
      {
        const int n = this->Opt.Lights.front();
        os << "- " << SceneLabel(sc.Name) << ", " << n << " light(s): pixel-fast-4 / plain = "
           << Fixed(this->MedianOf(sc.Name, n, "pixel-fast-4") / this->MedianOf(sc.Name, n, "plain"), 2)
           << "\n";
      }
    }

    // Sketch: the target against SSAO.
    if (hasPlain && has("ssao") && has("sketch-8"))
    {
      os << "\n### Sketch against SSAO: added cost per frame (ms)\n\n";
      os << "Added = configuration − plain. Target: sketch-8 (8 neighbours, 10 LIC steps) adds at "
            "most 0.75 × what ssao adds. sketch-8 − sketch-8-stage is the screen-space sketch stage "
            "over its own G-buffer.\n\n";
      os << "| scene | lights | ssao added | sketch-2 added | sketch-4 added | sketch-8 added | "
            "sketch-8 stage | sketch-8 added / ssao added |\n";
      os << "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
      for (const auto& sc : this->Opt.Scenes)
      {
        for (int n : this->Opt.Lights)
        {
          const double plain = this->MedianOf(sc.Name, n, "plain");
          const double ssao = this->MedianOf(sc.Name, n, "ssao") - plain;
          auto added = [&](const char* config) {
            return has(config) ? this->MedianOf(sc.Name, n, config) - plain : NAN;
          };
          const double stage = has("sketch-8-stage")
            ? this->MedianOf(sc.Name, n, "sketch-8") - this->MedianOf(sc.Name, n, "sketch-8-stage")
            : NAN;
          os << "| " << SceneLabel(sc.Name) << " | " << n << " | " << Fixed(ssao, 1) << " | "
             << Fixed(added("sketch-2"), 1) << " | " << Fixed(added("sketch-4"), 1) << " | "
             << Fixed(added("sketch-8"), 1) << " | " << Fixed(stage, 1) << " | "
             << Fixed(added("sketch-8") / ssao, 2) << " |\n";
        }
      }
    }

    // Table 3: light-count slope.
    if (this->Opt.Lights.size() >= 2)
    {
      os << "\n### Light-count slope (ms per light)\n\n";
      os << "Least-squares fit of median ms against light count (";
      for (size_t i = 0; i < this->Opt.Lights.size(); ++i)
      {
        os << (i ? ", " : "") << this->Opt.Lights[i];
      }
      os << " lights) per scene and configuration; the intercept is in parentheses.\n\n";
      os << "| configuration |";
      for (const auto& sc : this->Opt.Scenes)
      {
        os << " " << SceneLabel(sc.Name) << " |";
      }
      os << "\n| --- |";
      for (size_t i = 0; i < this->Opt.Scenes.size(); ++i)
      {
        os << " ---: |";
      }
      os << "\n";
      for (const auto& c : cfgs)
      {
        os << "| " << c << " |";
        for (const auto& sc : this->Opt.Scenes)
        {
          double slope = NAN, intercept = NAN;
          this->Fit(sc.Name, c, slope, intercept);
          os << " " << Fixed(slope, 3) << " (" << Fixed(intercept, 1) << ") |";
        }
        os << "\n";
      }
    }

    // Table 4: flatness in triangle count.
    if (hasPlain && this->Opt.Scenes.size() >= 2)
    {
      const SceneSpec& small = *std::min_element(this->Opt.Scenes.begin(),
        this->Opt.Scenes.end(), [this](const SceneSpec& a, const SceneSpec& b) {
          return this->Triangles(a.Name) < this->Triangles(b.Name);
        });
      const SceneSpec& large = *std::max_element(this->Opt.Scenes.begin(),
        this->Opt.Scenes.end(), [this](const SceneSpec& a, const SceneSpec& b) {
          return this->Triangles(a.Name) < this->Triangles(b.Name);
        });
      os << "\n### Is the added cost flat in triangle count?\n\n";
      os << "Added cost = configuration − plain (median ms, same lights), at " << SceneLabel(small.Name)
         << " (" << FormatCount(this->Triangles(small.Name)) << " triangles) and "
         << SceneLabel(large.Name) << " (" << FormatCount(this->Triangles(large.Name))
         << " triangles). Verdict \"flat\" when the added cost changes by less than "
         << Fixed(this->Opt.FlatTolerance, 0) << "% of the larger of the two, or by less than "
         << Fixed(this->Opt.FlatFloor, 0)
         << " ms (timing noise); \"grows\" or \"shrinks\" otherwise.\n\n";
      os << "Read the verdict at 1 light for the overhead of the pass itself. With many lights the "
            "added cost is dominated by the difference in lighting cost (negative: cheaper than "
            "VTK's lighting), which is paid per shaded fragment. On a software rasterizer such as "
            "llvmpipe the number of shaded fragments grows with the triangle count (sub-pixel "
            "triangles are shaded in 2x2 quads), so per-fragment work in the geometry pass (a "
            "heavier lighting shader, extra G-buffer targets) grows with triangles too; full-screen "
            "post-processing does not.\n\n";
      os << "| configuration | lights | added @ " << small.Name << " | added @ " << large.Name
         << " | change | verdict |\n";
      os << "| --- | ---: | ---: | ---: | ---: | --- |\n";
      for (const auto& c : cfgs)
      {
        if (c == "plain")
        {
          continue;
        }
        for (int n : this->Opt.Lights)
        {
          const double a =
            this->MedianOf(small.Name, n, c) - this->MedianOf(small.Name, n, "plain");
          const double b =
            this->MedianOf(large.Name, n, c) - this->MedianOf(large.Name, n, "plain");
          const double change = b - a;
          const double ref = std::max(std::abs(a), std::abs(b));
          std::string verdict = "n/a";
          std::string pct = "n/a";
          if (std::isfinite(change))
          {
            if (ref > 0)
            {
              pct = (change >= 0 ? "+" : "") + Fixed(100.0 * change / ref, 0) + "%";
            }
            const bool flat = std::abs(change) < this->Opt.FlatFloor ||
              std::abs(change) < this->Opt.FlatTolerance / 100.0 * ref;
            verdict = flat ? "flat" : (change > 0 ? "grows" : "shrinks");
          }
          os << "| " << c << " | " << n << " | " << Fixed(a, 1) << " | " << Fixed(b, 1) << " | "
             << (std::isfinite(change) ? (change >= 0 ? "+" : "") + Fixed(change, 1) : "n/a")
             << " ms (" << pct << ") | " << verdict << " |\n";
        }
      }
    }
  }

  void WriteCsv(std::ostream& os) const
  {
    os << "scene,triangles,lights,configuration,median_ms,min_ms,max_ms,frames\n";
    for (const auto& r : this->Results)
    {
      os << "sphere-" << r.Scene << "," << r.Triangles << "," << r.Lights << "," << r.Config
         << "," << Fixed(r.Median, 3) << "," << Fixed(r.Min, 3) << "," << Fixed(r.Max, 3) << ","
         << r.Frames << "\n";
    }
  }

private:
  static std::string Key(const std::string& scene, int lights, const std::string& config)
  {
    return scene + "|" + std::to_string(lights) + "|" + config;
  }

  vtkIdType Triangles(const std::string& scene) const
  {
    auto it = this->TriangleCount.find(scene);
    return it == this->TriangleCount.end() ? 0 : it->second;
  }

  void Fit(const std::string& scene, const std::string& config, double& slope,
    double& intercept) const
  {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (int lights : this->Opt.Lights)
    {
      const double y = this->MedianOf(scene, lights, config);
      if (!std::isfinite(y))
      {
        continue;
      }
      sx += lights;
      sy += y;
      sxx += double(lights) * lights;
      sxy += lights * y;
      ++n;
    }
    const double den = n * sxx - sx * sx;
    if (n < 2 || den == 0)
    {
      slope = intercept = NAN;
      return;
    }
    slope = (n * sxy - sx * sy) / den;
    intercept = (sy - slope * sx) / n;
  }

  const Options& Opt;
  std::vector<Result> Results;
  std::map<std::string, const Result*> Index;
  std::map<std::string, vtkIdType> TriangleCount;
};

//------------------------------------------------------------------------------------------------
// Running one (scene, configuration) pair over all light counts in one window.

using Clock = std::chrono::steady_clock;

/** Camera framing of a scene: VTK's ResetCamera() view of the mesh. */
struct Framing
{
  double Center[3];
  double Diagonal;
  double CoveredPixels; // approximate number of pixels the sphere covers
};

/**
 * The scene's mesh with point normals, moved and scaled into the unit sphere's box (centred at
 * the origin, largest half-extent 1) so that every scene is framed alike. nullptr (and a line on
 * stderr) when the scanned mesh cannot be read.
 */
vtkSmartPointer<vtkPolyData> MakeSceneMesh(const SceneSpec& scene, const Options& opt)
{
  vtkSmartPointer<vtkPolyData> raw;
  if (scene.Theta > 0)
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(scene.Theta);
    sphere->SetPhiResolution(scene.Phi);
    sphere->SetRadius(1.0);
    sphere->Update();
    return sphere->GetOutput(); // already in place, with normals
  }
  if (scene.Name == "bunny")
  {
    vtkNew<vtkPLYReader> reader;
    if (!reader->CanReadFile(opt.Bunny.c_str()))
    {
      std::cerr << "Cannot read the scanned mesh " << opt.Bunny
                << " (run the test realdata.setup, or give --bunny FILE)\n";
      return nullptr;
    }
    reader->SetFileName(opt.Bunny.c_str());
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputConnection(reader->GetOutputPort());
    normals->SplittingOff();
    normals->ConsistencyOn();
    normals->Update();
    raw = normals->GetOutput();
  }
  else
  {
    vtkNew<vtkRTAnalyticSource> wavelet;
    wavelet->SetWholeExtent(-120, 120, -120, 120, -120, 120);
    vtkNew<vtkContourFilter> contour;
    contour->SetInputConnection(wavelet->GetOutputPort());
    contour->SetValue(0, 160.0);
    contour->ComputeNormalsOn();
    contour->ComputeScalarsOff();
    contour->Update();
    raw = contour->GetOutput();
  }
  double b[6];
  raw->GetBounds(b);
  const double half = 0.5 * std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] });
  vtkNew<vtkTransform> t;
  t->Scale(1.0 / half, 1.0 / half, 1.0 / half);
  t->Translate(-0.5 * (b[0] + b[1]), -0.5 * (b[2] + b[3]), -0.5 * (b[4] + b[5]));
  vtkNew<vtkTransformPolyDataFilter> place;
  place->SetInputData(raw);
  place->SetTransform(t);
  place->Update();
  return place->GetOutput();
}

Framing FrameMesh(vtkPolyData* mesh, const Options& opt)
{
  Framing f;
  double b[6];
  mesh->GetBounds(b);
  for (int i = 0; i < 3; ++i)
  {
    f.Center[i] = 0.5 * (b[2 * i] + b[2 * i + 1]);
  }
  f.Diagonal = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
    (b[5] - b[4]) * (b[5] - b[4]));
  vtkNew<vtkRenderer> ren;
  ren->ResetCamera(b);
  vtkCamera* cam = ren->GetActiveCamera();
  const double radius = 0.5 * (b[1] - b[0]);
  const double angular = std::asin(std::min(1.0, radius / cam->GetDistance()));
  const double halfHeight = std::tan(vtkMath::RadiansFromDegrees(0.5 * cam->GetViewAngle()));
  const double pixelRadius = 0.5 * opt.Height * std::tan(angular) / halfHeight;
  f.CoveredPixels = vtkMath::Pi() * pixelRadius * pixelRadius;
  return f;
}

/** One configuration: its own render window, renderer, actor and passes. */
struct Bench
{
  std::string Config;
  ConfigPasses Passes;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkPolyDataMapper> Mapper;
  vtkSmartPointer<vtkCamera> Initial;
  std::vector<double> Times;
  double Warmup = 0.0;

  Bench(const std::string& config, const Options& opt, double diagonal)
    : Config(config)
    , Passes(MakeConfig(config, diagonal))
  {
    this->Window = vtkSmartPointer<vtkRenderWindow>::New();
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(opt.Width, opt.Height);
    if (EndsWith(config, "-interactive"))
    {
      this->Window->SetDesiredUpdateRate(15.0);
    }
    this->Renderer = vtkSmartPointer<vtkRenderer>::New();
    this->Renderer->SetBackground(0.1, 0.1, 0.15);
    this->Window->AddRenderer(this->Renderer);
    this->Mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    this->Mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(this->Mapper);
    actor->GetProperty()->SetColor(0.9, 0.75, 0.6);
    actor->GetProperty()->SetSpecular(0.3);
    actor->GetProperty()->SetSpecularPower(20.0);
    if (EndsWith(config, "-translucent"))
    {
      actor->GetProperty()->SetOpacity(0.35);
      this->Renderer->UseDepthPeelingOn();
      this->Renderer->SetMaximumNumberOfPeels(4);
      this->Renderer->SetOcclusionRatio(0.0);
    }
    this->Renderer->AddActor(actor);
    if (this->Passes.Root)
    {
      this->Renderer->SetPass(this->Passes.Root);
    }
    this->Initial = vtkSmartPointer<vtkCamera>::New();
  }

  /** Frees every GL resource (passes included) while the context exists, then detaches. */
  void Release()
  {
    // VTK's Sobel pass and friends complain in their destructors about resources the window
    // did not release: Finalize() releases them through the renderer first.
    this->Window->Finalize();
    this->Renderer->SetPass(nullptr);
    this->Renderer->RemoveAllLights();
    this->Renderer->RemoveAllViewProps();
    this->Window->RemoveRenderer(this->Renderer);
    this->Passes = ConfigPasses();
    this->Mapper = nullptr;
    this->Renderer = nullptr;
    this->Window = nullptr;
  }

  /** One frame: a 0.5 degree azimuth step, Render() and glFinish. Returns milliseconds. */
  double Frame()
  {
    this->Renderer->GetActiveCamera()->Azimuth(0.5);
    const auto t0 = Clock::now();
    this->Window->Render();
    this->Window->WaitForCompletion(); // glFinish
    const auto t1 = Clock::now();
    return std::chrono::duration<double, std::milli>(t1 - t0).count();
  }
};

/**
 * Times all configurations over all scenes and light counts. Every configuration has its own
 * window, kept for the whole run (only the mapper's input and the lights change), so the shader
 * programs compiled for a light setup stay in that window's shader cache. For each (scene,
 * lights) case every configuration first renders its warm-up frames, then the timed frames are
 * interleaved: frame 1 of every configuration, frame 2 of every configuration, and so on, so a
 * burst of load from other processes on this shared machine spreads over all configurations
 * instead of falling on one.
 */
void RunAll(const Options& opt, const std::vector<vtkSmartPointer<vtkPolyData>>& meshes,
  std::vector<Result>& results)
{
  const Framing first = FrameMesh(meshes[0], opt);
  std::vector<std::unique_ptr<Bench>> benches;
  for (const auto& config : opt.Configs)
  {
    benches.emplace_back(new Bench(config, opt, first.Diagonal));
  }

  for (size_t si = 0; si < opt.Scenes.size(); ++si)
  {
    const SceneSpec& scene = opt.Scenes[si];
    vtkPolyData* mesh = meshes[si];
    const Framing framing = FrameMesh(mesh, opt);
    for (auto& b : benches)
    {
      b->Mapper->SetInputData(mesh);
      b->Renderer->ResetCamera();
      b->Initial->DeepCopy(b->Renderer->GetActiveCamera());
    }
    for (int lights : opt.Lights)
    {
      std::cout << SceneLabel(scene.Name) << ", " << lights << (lights == 1 ? " light" : " lights")
                << std::endl;
      for (auto& b : benches)
      {
        SetLights(b->Renderer, lights, framing.Center, 0.5 * framing.Diagonal / std::sqrt(3.0));
        // Every configuration sees the same sequence of views.
        b->Renderer->GetActiveCamera()->DeepCopy(b->Initial);
        b->Renderer->ResetCameraClippingRange();
        b->Times.clear();
        const auto w0 = Clock::now();
        for (int i = 0; i < opt.Warmup; ++i)
        {
          b->Frame();
        }
        b->Warmup = std::chrono::duration<double>(Clock::now() - w0).count();
      }
      for (int i = 0; i < opt.Frames; ++i)
      {
        for (auto& b : benches)
        {
          b->Times.push_back(b->Frame());
        }
      }
      // Per-stage costs: three more frames of each style with stage timing on (each stage
      // then waits for the renderer, so these frames are a little slower than the timed ones).
      for (auto& b : benches)
      {
        auto* style = vtkStylizeStylePass::SafeDownCast(b->Passes.Root);
        if (!style)
        {
          continue;
        }
        style->StageTimingOn();
        std::map<std::string, std::vector<double>> times;
        std::vector<std::string> order;
        std::vector<double> frames;
        for (int i = 0; i < 3; ++i)
        {
          frames.push_back(b->Frame());
          for (int k = 0; k < style->GetNumberOfTimedStages(); ++k)
          {
            std::string name = style->GetTimedStageName(k);
            const int runs = style->GetTimedStageRuns(k);
            if (runs > 1)
            {
              name += " x" + std::to_string(runs);
            }
            if (!times.count(name))
            {
              order.push_back(name);
            }
            times[name].push_back(style->GetTimedStageMilliseconds(k));
          }
        }
        style->StageTimingOff();
        StageResult sr;
        sr.BytesPerPixel =
          static_cast<double>(style->GetTextureBytes()) / (double(opt.Width) * opt.Height);
        sr.Scene = scene.Name;
        sr.Lights = lights;
        sr.Config = b->Config;
        sr.Frame = Median(frames);
        for (const auto& name : order)
        {
          sr.Stages.emplace_back(name, Median(times[name]));
        }
        StageResults.push_back(sr);
      }
      for (auto& b : benches)
      {
        Result r;
        r.Scene = scene.Name;
        r.Triangles = mesh->GetNumberOfPolys();
        r.Lights = lights;
        r.Config = b->Config;
        r.Median = Median(b->Times);
        r.Min = *std::min_element(b->Times.begin(), b->Times.end());
        r.Max = *std::max_element(b->Times.begin(), b->Times.end());
        r.Frames = opt.Frames;
        results.push_back(r);
        std::cout << "  " << std::left << std::setw(20) << b->Config << std::right << " median "
                  << std::setw(9) << Fixed(r.Median, 1) << " ms  (min " << Fixed(r.Min, 1)
                  << ", max " << Fixed(r.Max, 1) << "; warm-up " << Fixed(b->Warmup, 1) << " s)"
                  << std::endl;
        if (!opt.Images.empty())
        {
          vtkNew<vtkWindowToImageFilter> grab;
          grab->SetInput(b->Window);
          grab->ReadFrontBufferOff();
          vtkNew<vtkPNGWriter> png;
          png->SetInputConnection(grab->GetOutputPort());
          png->SetFileName((opt.Images + "/" + scene.Name + "-" + std::to_string(lights) + "-" +
            b->Config + ".png")
                             .c_str());
          png->Write();
        }
      }
    }
  }

  for (auto& b : benches)
  {
    b->Release();
  }
}

std::string Now()
{
  const std::time_t t = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof(buf), "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
  return buf;
}
}

int main(int argc, char* argv[])
{
  Options opt;
  const int parsed = ParseOptions(argc, argv, opt);
  if (parsed != 0)
  {
    return parsed == 2 ? EXIT_SUCCESS : EXIT_FAILURE;
  }

  // GL renderer first, from a small window that stays open for the whole run: each measured
  // window opens and closes its own display connection, and an X server without -noreset (Xvfb's
  // default) resets when its last client leaves, refusing the next window's connection for a
  // moment ("bad X server connection ... Aborting"). Holding this window avoids that race.
  std::string rendererString, glVersion;
  vtkNew<vtkRenderWindow> probe;
  vtkNew<vtkRenderer> probeRenderer;
  probe->SetOffScreenRendering(1);
  probe->SetMultiSamples(0);
  probe->SetSize(16, 16);
  probe->AddRenderer(probeRenderer);
  probe->Render();
  rendererString = RendererString(probe, &glVersion);
  std::cout << "GL_RENDERER: " << rendererString << "\n";
  std::cout << "GL_VERSION:  " << glVersion << "\n";
  std::cout << "VTK " << vtkVersion::GetVTKVersion() << ", " << opt.Width << "x" << opt.Height
            << ", multisampling off, " << opt.Warmup << " warm-up + " << opt.Frames
            << " timed frames per case\n\n";

  const auto start = Clock::now();
  std::vector<Result> results;
  std::map<std::string, std::string> descriptions;
  std::vector<vtkSmartPointer<vtkPolyData>> meshes;
  for (const auto& scene : opt.Scenes)
  {
    vtkSmartPointer<vtkPolyData> mesh = MakeSceneMesh(scene, opt);
    if (!mesh)
    {
      return 1;
    }
    meshes.push_back(mesh);
    std::cout << "Scene " << scene.Name << ": " << FormatCount(mesh->GetNumberOfPolys())
              << " triangles, " << FormatCount(mesh->GetNumberOfPoints()) << " points"
              << std::endl;
  }
  const Framing framing = FrameMesh(meshes[0], opt);
  std::cout << "The unit sphere covers about " << Fixed(framing.CoveredPixels / 1000.0, 0)
            << "k pixels (" << Fixed(100.0 * framing.CoveredPixels / opt.Width / opt.Height, 1)
            << "% of the image)\n\n";
  for (const auto& config : opt.Configs)
  {
    descriptions[config] = MakeConfig(config, 1.0).Description;
  }
  RunAll(opt, meshes, results);
  // Rows in report order: scene, light count, configuration.
  auto rank = [&opt](const Result& r) {
    size_t s = 0, l = 0, c = 0;
    while (s < opt.Scenes.size() && opt.Scenes[s].Name != r.Scene)
    {
      ++s;
    }
    while (l < opt.Lights.size() && opt.Lights[l] != r.Lights)
    {
      ++l;
    }
    while (c < opt.Configs.size() && opt.Configs[c] != r.Config)
    {
      ++c;
    }
    return std::make_tuple(s, l, c);
  };
  std::stable_sort(results.begin(), results.end(),
    [&rank](const Result& a, const Result& b) { return rank(a) < rank(b); });
  const double totalSeconds = std::chrono::duration<double>(Clock::now() - start).count();

  std::ostringstream header;
  header << "## VTK Stylize benchmark\n\n";
  header << "- Renderer: " << rendererString << " (OpenGL " << glVersion << "), VTK "
         << vtkVersion::GetVTKVersion() << "\n";
  header << "- " << opt.Width << "x" << opt.Height
         << ", offscreen, multisampling off; per case " << opt.Warmup
         << " warm-up frames (shader compilation excluded), then the median of " << opt.Frames
         << " timed frames, each a 0.5° camera azimuth step, Render() + glFinish, wall clock; "
            "one window per configuration, timed frames interleaved across configurations\n";
  header << "- Scenes: spheres (vtkSphereSource with point normals), a scanned mesh (bunny: "
            "the real-data set's, normals by vtkPolyDataNormals) and a wavelet isosurface "
            "(vtkRTAnalyticSource extent +-120, vtkContourFilter at 160 with normals), each "
            "moved into the unit sphere's box; one actor (Phong, specular 0.3), framed by "
            "ResetCamera() as the unit sphere, which covers about "
         << Fixed(framing.CoveredPixels / 1000.0, 0) << "k pixels ("
         << Fixed(100.0 * framing.CoveredPixels / opt.Width / opt.Height, 1)
         << "% of the image)\n";
  header << "- Lights: 1 = VTK's default headlight; more = scene lights on a golden-angle "
            "spiral around the object (1/3 directional, 1/3 point, 1/3 spot), white, "
            "intensity 1.5 / count; the same for every configuration\n";
  header << "- Configurations:\n";
  for (const auto& c : opt.Configs)
  {
    header << "  - `" << c << "`: " << descriptions[c] << "\n";
  }
  header << "- Run time: " << Fixed(totalSeconds, 0) << " s, " << Now() << "\n";

  Report report(opt, results);
  std::ostringstream md;
  report.Write(md, header.str());
  if (!StageResults.empty())
  {
    md << "\n### Per-stage cost\n\n"
       << "Median ms of each stage over 3 frames with stage timing on "
          "(vtkStylizeStylePass::StageTimingOn(): glFinish before and after each stage). "
          "SCENE: the lighting and G-buffer render of the geometry; BACKGROUND: the background "
          "written around the scene's rectangle; OUTPUT: a final stage without a name; AFTER: "
          "what follows the stylized image; xN: the stage ran N times (summed). Memory: bytes "
          "per pixel of the style's textures (G-buffer, intermediate targets, direction field; "
          "vtkStylizeStylePass::GetTextureBytes()).\n\n"
       << "| scene | lights | configuration | frame (timed) | memory (B/pixel) | stages |\n"
       << "| --- | ---: | --- | ---: | ---: | --- |\n";
    for (const auto& sr : StageResults)
    {
      md << "| " << SceneLabel(sr.Scene) << " | " << sr.Lights << " | " << sr.Config << " | "
         << Fixed(sr.Frame, 1) << " | " << Fixed(sr.BytesPerPixel, 1) << " |";
      const char* sep = " ";
      for (const auto& st : sr.Stages)
      {
        md << sep << st.first << " " << Fixed(st.second, 1);
        sep = ", ";
      }
      md << " |\n";
    }
  }

  bool ok = true;
  {
    std::ofstream csv(opt.Csv);
    report.WriteCsv(csv);
    csv.close();
    if (!csv)
    {
      std::cerr << "Could not write " << opt.Csv << "\n";
      ok = false;
    }
  }
  {
    std::ofstream out(opt.Markdown);
    out << md.str();
    out.close();
    if (!out)
    {
      std::cerr << "Could not write " << opt.Markdown << "\n";
      ok = false;
    }
  }
  probe->Finalize();
  std::cout << "\n" << md.str() << "\nCSV: " << opt.Csv << "\nMarkdown: " << opt.Markdown
            << std::endl;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
