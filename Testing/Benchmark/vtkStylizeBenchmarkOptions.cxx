// vtkStylizeBenchmark: the scene, configuration and light-count lists and the command line.

#include "vtkStylizeBenchmarkOptions.h"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace vtkstylizebenchmark
{
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

const std::vector<SceneSpec>& VolumeScenes()
{
  static const std::vector<SceneSpec> scenes = { { "headsq", 0, 0, true } };
  return scenes;
}

const std::vector<std::string>& AllConfigs()
{
  static const std::vector<std::string> configs = { "plain", "sobel", "ssao", "edl",
    "light-standard", "light-comic", "light-pixelart", "gbuf-standard", "gbuf-comic",
    "gbuf-pixelart", "gbuf-standard-color", "gbuf-comic-lin", "comic", "comic-geometric",
    "pixel-fast-2", "pixel-fast-4", "pixel-fast-8", "pixel-faithful-2", "pixel-faithful-4",
    "pixel-faithful-8", "sketch-2", "sketch-4", "sketch-8", "sketch-8-stage", "comic-image",
    "pixel-image", "sketch-image", "comic-nocull", "sketch-8-nocull", "comic-interactive",
    "sketch-8-interactive", "pixel-faithful-4-interactive", "plain-translucent",
    "comic-translucent", "pixel-faithful-4-translucent", "sketch-8-translucent", "lines",
    "vtk-lines", "lines-interactive", "sketch-8-fullsize-interactive",
    "lines-fullsize-interactive" };
  return configs;
}

const std::vector<int>& AllLightCounts()
{
  static const std::vector<int> lights = { 1, 8, 100, 500 };
  return lights;
}

namespace
{
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
    << "                    triangles); default: all of these; also headsq (VTK's CT of a\n"
    << "                    head as a GPU ray-cast volume, each style drawing it as a volume)\n"
    << "  --bunny FILE      the scanned mesh (default: the real-data set's bunny.ply, written\n"
    << "                    by the test realdata.setup)\n"
    << "  --volume FILE     the volume scene's image (default: the real-data set's headsq.vti)\n"
    << "  --lights LIST     subset of light counts, e.g. 1,8,100,500 (any positive count)\n"
    << "  --configs LIST    subset of:";
  for (const auto& c : AllConfigs())
  {
    std::cout << " " << c;
  }
  std::cout
    << "\n"
    << "                    (NAME-nocull: the style NAME with background culling off;\n"
    << "                    NAME-interactive: its interactive variant, window rate 15;\n"
    << "                    NAME-fullsize: InteractiveImageReduction 1);\n"
    << "                    styles also report per-stage costs and memory per pixel\n"
    << "  --csv FILE        CSV output (default benchmark.csv)\n"
    << "  --markdown FILE   Markdown output (default benchmark.md), also printed to stdout\n"
    << "  --images DIR      also write the last frame of every case as "
       "DIR/<scene>-<lights>-<config>.png\n"
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

/** The command line, read one argument at a time; Next() takes an option's value. */
struct Arguments
{
  int Argc;
  char** Argv;
  int I;

  bool Next(const std::string& arg, std::string& value)
  {
    if (this->I + 1 >= this->Argc)
    {
      std::cerr << "Option " << arg << " needs a value\n";
      return false;
    }
    value = this->Argv[++this->I];
    return true;
  }
};

bool ParseSize(const std::string& value, Options& opt)
{
  const auto x = value.find_first_of("xX");
  if (x == std::string::npos || !ParseInt(value.substr(0, x), opt.Width) ||
    !ParseInt(value.substr(x + 1), opt.Height))
  {
    std::cerr << "Bad --size '" << value << "' (expected WxH)\n";
    return false;
  }
  return true;
}

bool ParseScenes(const std::string& value, Options& opt)
{
  opt.Scenes.clear();
  for (const auto& name : SplitList(value))
  {
    auto named = [&](const SceneSpec& s) { return s.Name == name; };
    auto it = std::find_if(AllScenes().begin(), AllScenes().end(), named);
    auto volume = std::find_if(VolumeScenes().begin(), VolumeScenes().end(), named);
    if (it == AllScenes().end() && volume == VolumeScenes().end())
    {
      std::cerr << "Unknown scene '" << name << "' (10k, 500k, 2M, bunny, iso970k, headsq)\n";
      return false;
    }
    opt.Scenes.push_back(it != AllScenes().end() ? *it : *volume);
  }
  return true;
}

bool ParseLights(const std::string& value, Options& opt)
{
  opt.Lights.clear();
  for (const auto& item : SplitList(value))
  {
    int n = 0;
    if (!ParseInt(item, n))
    {
      std::cerr << "Bad light count '" << item << "'\n";
      return false;
    }
    opt.Lights.push_back(n);
  }
  return true;
}

bool ParseConfigs(const std::string& value, Options& opt)
{
  opt.Configs.clear();
  for (const auto& name : SplitList(value))
  {
    if (std::find(AllConfigs().begin(), AllConfigs().end(), name) == AllConfigs().end())
    {
      std::cerr << "Unknown configuration '" << name << "'\n";
      return false;
    }
    opt.Configs.push_back(name);
  }
  return true;
}

/** Whether @p arg is an option with a file or folder value; @p target then points at it. */
bool IsPathOption(const std::string& arg, Options& opt, std::string*& target)
{
  target = arg == "--bunny" ? &opt.Bunny
    : arg == "--volume"     ? &opt.Volume
    : arg == "--csv"        ? &opt.Csv
    : arg == "--markdown"   ? &opt.Markdown
    : arg == "--images"     ? &opt.Images
                            : nullptr;
  return target != nullptr;
}

/** One option (and its value) at args.I. Returns 0 to go on, 1 for an error, 2 for --help. */
int ParseOne(Arguments& args, Options& opt)
{
  const std::string arg = args.Argv[args.I];
  std::string value;
  std::string* path = nullptr;
  if (arg == "--help" || arg == "-h")
  {
    PrintHelp(args.Argv[0]);
    return 2;
  }
  if (arg == "--quick")
  {
    return 0; // applied before the other options
  }
  if (arg == "--size")
  {
    return args.Next(arg, value) && ParseSize(value, opt) ? 0 : 1;
  }
  if (arg == "--frames" || arg == "--warmup")
  {
    if (!args.Next(arg, value) || !ParseInt(value, arg == "--frames" ? opt.Frames : opt.Warmup))
    {
      std::cerr << "Bad " << arg << " value\n";
      return 1;
    }
    if (opt.Warmup < 2)
    {
      std::cerr << "--warmup must be at least 2\n";
      return 1;
    }
    return 0;
  }
  if (arg == "--scenes")
  {
    return args.Next(arg, value) && ParseScenes(value, opt) ? 0 : 1;
  }
  if (arg == "--lights")
  {
    return args.Next(arg, value) && ParseLights(value, opt) ? 0 : 1;
  }
  if (arg == "--configs")
  {
    return args.Next(arg, value) && ParseConfigs(value, opt) ? 0 : 1;
  }
  if (IsPathOption(arg, opt, path))
  {
    return args.Next(arg, *path) ? 0 : 1;
  }
  if (arg == "--flat-tolerance")
  {
    int p = 0;
    if (!args.Next(arg, value) || !ParseInt(value, p))
    {
      std::cerr << "Bad --flat-tolerance value\n";
      return 1;
    }
    opt.FlatTolerance = p;
    return 0;
  }
  std::cerr << "Unknown option '" << arg << "' (see --help)\n";
  return 1;
}
}

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
  Arguments args{ argc, argv, 1 };
  for (; args.I < argc; ++args.I)
  {
    const int status = ParseOne(args, opt);
    if (status != 0)
    {
      return status;
    }
  }
  if (opt.Scenes.empty() || opt.Lights.empty() || opt.Configs.empty())
  {
    std::cerr << "Empty scene, light or configuration list\n";
    return 1;
  }
  return 0;
}
}
