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
 * The program's parts, one file each:
 *   main.cxx         error output, crash handling, the run from options to image
 *   Options.cxx      the command line (CLI11), the styles, --help
 *   vtkstylizeInput.cxx  readers and surfaces (vtkstylizeFileChecks.cxx: structural file checks)
 *   Scene.cxx        actors, colouring, annotations, lights, camera
 *   Render.cxx       the window, rendering and writing the PNG atomically
 *   vtkstylizeCommon.cxx  the error type and the capture of VTK's messages
 */

#include "Options.h"
#include "Render.h"
#include "Scene.h"
#include "VirtualDisplay.h"
#include "vtkstylizeCommon.h"
#include "vtkstylizeInput.h"

#include "vtkCamera.h"
#include "vtkLogger.h"
#include "vtkMath.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSketchPass.h"
#include "vtkStylizeAtomicFile.h"
#include "vtkStylizeDemoScene.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeOutputWindow.h"
#include "vtkStylizeStylePass.h"
#include "vtkVersion.h"

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#ifndef VTKSTYLIZE_VERSION
#define VTKSTYLIZE_VERSION "unknown"
#endif

#if defined(__SANITIZE_ADDRESS__)
#define VTKSTYLIZE_SANITIZED 1
#else
#define VTKSTYLIZE_SANITIZED 0
#endif

namespace
{
using namespace vtkstylize;

// Error output and crash handling

// Descriptor of the real stderr (fd 2 itself is redirected to /dev/null while VTK works).
int ErrorDescriptor = 2;

void WriteError(const std::string& message)
{
  ClearProgress();
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
  vtkStylizeAtomicFile::RemovePendingFile();
  StopVirtualDisplay();
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
  ClearProgress();
  ssize_t ignored = ::write(ErrorDescriptor, text, std::strlen(text));
  (void)ignored;
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

/** The smallest window side (pixels) with a title and a scalar bar: the title's font is 8 px. */
constexpr int MinimumAnnotatedSide = 16;

/**
 * --orbit N: N frames, the camera turned by opt.OrbitDegrees / N about the view-up axis between
 * them (after raising it by opt.OrbitElevation), written as STEM-0000.png ...; a .gif or .mp4
 * output is then encoded from them. The patterns are anchored to the surface (comic dots and
 * hatching, pixel-art dither, sketch noise) unless an anchor option was given: a pattern fixed
 * to the screen swims over the turning surface. Returns whether every frame drew something.
 */
bool RenderOrbit(vtkRenderWindow* window, vtkRenderer* ren, const Options& opt,
  const std::string& emptyFailure, std::vector<std::string>& written)
{
  auto* style = vtkStylizeStylePass::SafeDownCast(ren->GetPass());
  if (style && !opt.AnchorGiven)
  {
    style->AnchorPatternsToSurface(opt.NoiseGiven);
  }
  vtkCamera* camera = ren->GetActiveCamera();
  if (opt.OrbitElevation != 0.0)
  {
    camera->Elevation(opt.OrbitElevation);
    camera->OrthogonalizeViewUp();
  }
  const std::string ext = Lower(opt.Output.substr(opt.Output.size() - 4));
  const std::string stem = opt.Output.substr(0, opt.Output.size() - 4);
  const int digits = std::max(4, static_cast<int>(std::to_string(opt.Orbit - 1).size()));
  auto frameName = [&](int f)
  {
    std::string number = std::to_string(f);
    return stem + "-" + std::string(digits - number.size(), '0') + number + ".png";
  };
  bool drawn = true;
  for (int f = 0; f < opt.Orbit; ++f)
  {
    if (f > 0)
    {
      camera->Azimuth(opt.OrbitDegrees / opt.Orbit);
      camera->OrthogonalizeViewUp();
    }
    ren->ResetCameraClippingRange();
    drawn = RenderAndWrite(window, opt, frameName(f), emptyFailure) && drawn;
    written.push_back(frameName(f));
  }
  if (ext == ".gif" || ext == ".mp4")
  {
    // the pattern is escaped for ffmpeg's printf-style numbering
    std::string pattern;
    for (char ch : stem)
    {
      pattern += ch == '%' ? std::string("%%") : std::string(1, ch);
    }
    EncodeAnimation(
      pattern + "-%0" + std::to_string(digits) + "d.png", opt.FramesPerSecond, opt.Output);
    written.push_back(opt.Output);
  }
  if (style && !opt.AnchorGiven)
  {
    style->RestorePatternAnchors();
  }
  return drawn;
}

/**
 * The memory bound of the input stage (reading, conversion to surfaces, curvatures): by
 * default 3/4 of the machine's memory, so that no input can make the program take the machine
 * (legacy headers claiming a billion cells took 15 GB). Lifted before the window opens: the
 * OpenGL driver and X do not all survive a failed allocation, and what they take follows the
 * image size and the data already read.
 */
void LimitInputMemory(const Options& opt)
{
  double limit = opt.MemoryLimit;
  if (limit < 0.0)
  {
    const long pages = ::sysconf(_SC_PHYS_PAGES);
    const long pageSize = ::sysconf(_SC_PAGESIZE);
    limit = pages > 0 && pageSize > 0
      ? 0.75 * static_cast<double>(pages) * static_cast<double>(pageSize) / (1024.0 * 1024.0)
      : 0.0;
  }
  SetMemoryLimit(limit);
}

/** The parts of the built-in scene or of the input file; the title named after it. */
std::vector<Part> ReadParts(
  const Options& opt, bool builtIn, const std::string& what, SceneAnnotations& info)
{
  std::vector<Part> parts;
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
    vtkSmartPointer<vtkDataObject> data =
      ReadInput(opt.Input, opt.TimeStep, opt.MemoryLimit, opt.ReadTimeLimit);
    CollectParts(data, opt.IsoValue, what, parts);
    info.Title = BaseName(opt.Input);
  }
  return parts;
}

/**
 * Options that the input or the image size gives nothing to apply to: dropped, each with a
 * warning in opt.Warnings.
 */
void WarnIgnoredOptions(
  Options& opt, const std::vector<Part>& parts, bool builtIn, const std::string& what)
{
  const bool contoured =
    std::any_of(parts.begin(), parts.end(), [](const Part& p) { return p.Contour.has_value(); });
  if (opt.IsoValue && !contoured)
  {
    opt.Warnings.push_back("--iso applies to 3D image data with point scalars (.vti, .pvti, "
                           "legacy structured points), which the " +
      std::string(builtIn ? "built-in scene" : "input " + what) + " does not contain (ignored)");
  }
  if (opt.TimeStepGiven && builtIn)
  {
    opt.Warnings.push_back("--time-step applies to an INPUT file with time steps, not to the "
                           "built-in scene (ignored)");
  }
  if (!opt.ColorBy.empty() && opt.NoScalars)
  {
    opt.Warnings.push_back("--color-by does nothing with --no-scalars (ignored)");
    opt.ColorBy.clear();
  }
  if (!opt.NoAnnotations && std::min(opt.Width, opt.Height) < MinimumAnnotatedSide)
  {
    // (VTK's text actor fails on a viewport one pixel wide or high, and no text fits anyway)
    opt.NoAnnotations = true;
    opt.Warnings.push_back("the title and the scalar bar need an image of at least " +
      std::to_string(MinimumAnnotatedSide) + " pixels a side: left out of this " +
      std::to_string(opt.Width) + "x" + std::to_string(opt.Height) + " image");
  }
}

/** The warning for a picture of the background alone, with the data's bounds. */
std::string NothingDrawnWarning(const Options& opt, const double bounds[6], const std::string& what)
{
  std::string box;
  for (int i = 0; i < 3; ++i)
  {
    box += std::string(i ? " x " : "") + "[" + FormatNumber(bounds[2 * i]) + ", " +
      FormatNumber(bounds[2 * i + 1]) + "]";
  }
  return "the picture shows nothing but the background: nothing of " + what +
    " covers a pixel of the " + std::to_string(opt.Width) + "x" + std::to_string(opt.Height) +
    " window (its bounds: " + box +
    "; a stray far point, a zero spacing or cells without "
    "area can leave the rest below a pixel)";
}

/**
 * The warnings and notes (on stderr, only once the image is written: a failure is one line),
 * then the paths written (on stdout), unless --quiet.
 */
void Report(const Options& opt, const std::vector<std::string>& written)
{
  ClearProgress(); // (a bar left by a step that did not end)
  for (const std::string& warning : opt.Warnings)
  {
    WriteError("warning: " + warning);
  }
  for (const std::string& warning : Warnings())
  {
    WriteError("warning: " + warning);
  }
  if (!opt.Quiet)
  {
    for (const std::string& note : Notes())
    {
      WriteError("note: " + note);
    }
    for (const std::string& path : written)
    {
      std::cout << path << "\n";
    }
    std::cout << std::flush;
  }
}

int Run(int argc, char* argv[])
{
  Options opt = ParseCommandLine(argc, argv);
  if (opt.Help)
  {
    std::cout << HelpText() << std::flush;
    return 0;
  }
  if (opt.Version)
  {
    for (const std::string& warning : opt.Warnings)
    {
      WriteError("warning: " + warning);
    }
    std::cout << "vtkstylize " << VTKSTYLIZE_VERSION << " (VTK " << vtkVersion::GetVTKVersion()
              << ")\n"
              << std::flush;
    return 0;
  }
  if (opt.Quiet)
  {
    SetProgressDescriptor(-1);
  }
  LimitInputMemory(opt);
  const bool builtIn = opt.Input.empty();
  if (!builtIn && !IsSupportedInput(opt.Input))
  {
    UsageError(
      "unsupported file type " + Quote(opt.Input) + " (supported: " + SupportedExtensions() + ")");
  }
  CheckOutputPath(opt.Output);

  // Input -> parts.
  SceneAnnotations info;
  const std::string what = builtIn ? "built-in scene" : Quote(opt.Input);
  std::vector<Part> parts = ReadParts(opt, builtIn, what, info);
  WarnIgnoredOptions(opt, parts, builtIn, what);
  FinishParts(parts, what);
  if (opt.ModelDirections && opt.Style == "sketch")
  {
    // The curvature is averaged at the sketch's object scale (one setting for both modes).
    vtkNew<vtkSketchPass> settings;
    opt.Passes.ApplyTo(settings.Get());
    AddPrincipalDirections(parts, what, settings->GetObjectScale());
  }

  SetMemoryLimit(0.0);

  // Scene.
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(opt.Background);
  AddParts(ren, parts, opt, builtIn, info, what);
  opt.Warnings.insert(opt.Warnings.end(), info.Warnings.begin(), info.Warnings.end());
  double bounds[6];
  ren->ComputeVisiblePropBounds(bounds);
  if (!vtkMath::AreBoundsInitialized(bounds))
  {
    Fail(what + ": nothing visible to render");
  }
  AddLights(ren, opt.Lights, bounds);
  vtkSmartPointer<vtkRenderWindow> window = MakeWindow(ren, opt); // before the camera: aspect
  SetUpCamera(ren, opt);

  // Passes.
  const StyleSpec* style = FindStyle(opt.Style);
  vtkNew<vtkStylizeLightingPass> lighting;
  if (opt.LightingModel >= 0)
  {
    lighting->SetModel(opt.LightingModel);
  }
  else if (style->DefaultModel >= 0)
  {
    lighting->SetModel(style->DefaultModel);
  }
  opt.Passes.ApplyTo(lighting.Get());
  vtkSmartPointer<vtkStylizeGBufferPass> gbuffer;
  if (opt.GBuffer)
  {
    gbuffer = vtkSmartPointer<vtkStylizeGBufferPass>::New();
    gbuffer->SetLightingPass(lighting);
  }
  ren->SetPass(style->MakePass(lighting, gbuffer, opt));
  ReportProgress(ren->GetPass(), "finding the lines"); // (the line art's first frame)

  // A picture of the background alone: an error when the data has no extent (no framing can
  // show it), else a warning (a stray far point, a zero spacing, cells without area or an image
  // one pixel high can leave everything below a pixel).
  const bool extentless =
    bounds[0] == bounds[1] && bounds[2] == bounds[3] && bounds[4] == bounds[5];
  const std::string empty = "the picture would show nothing but the background: " + what +
    " has no extent (all its points lie at " + FormatNumber(bounds[0]) + ", " +
    FormatNumber(bounds[2]) + ", " + FormatNumber(bounds[4]) + ")";
  bool drawn = true;
  std::vector<std::string> written;
  if (opt.Orbit > 0)
  {
    drawn = RenderOrbit(window, ren, opt, extentless ? empty : std::string(), written);
  }
  else
  {
    drawn = RenderAndWrite(window, opt, opt.Output, extentless ? empty : std::string());
    written.push_back(opt.Output);
  }
  if (!drawn)
  {
    opt.Warnings.push_back(NothingDrawnWarning(opt, bounds, what));
  }
  Report(opt, written);
  return 0;
}

} // namespace

int main(int argc, char* argv[])
{
  const bool verbose = std::getenv("VTKSTYLIZE_VERBOSE") && *std::getenv("VTKSTYLIZE_VERBOSE") &&
    std::string(std::getenv("VTKSTYLIZE_VERBOSE")) != "0";

  // Keep the real stderr for our one line; send everything else written to fd 2 to /dev/null
  // (the sanitizers' reports go to the real stderr: ReportSanitizersTo()).
  if (!verbose)
  {
    const int saved = ::dup(2);
    const int null = ::open("/dev/null", O_WRONLY);
    if (saved >= 0 && null >= 0)
    {
      ErrorDescriptor = saved;
      SetProgressDescriptor(::isatty(saved) ? saved : -1);
      ::fcntl(saved, F_SETFD, FD_CLOEXEC);
      ::dup2(null, 2);
    }
    if (null >= 0)
    {
      ::close(null);
    }
  }
#if VTKSTYLIZE_SANITIZED
  // Under the sanitizers their own handlers report a fault (with its stack) on stderr: the
  // program's one-line handler is kept for the terminating signals only.
  vtkStylizeOutputWindow::ReportSanitizersTo(ErrorDescriptor);
  for (int sig : { SIGINT, SIGTERM, SIGHUP })
#else
  for (int sig : { SIGSEGV, SIGBUS, SIGFPE, SIGABRT, SIGINT, SIGTERM, SIGHUP })
#endif
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
    WriteError("out of memory" + MemoryLimitText());
    code = ExitFailure;
  }
  catch (const std::exception& e)
  {
    WriteError(std::string("internal error: ") + e.what());
    code = ExitFailure;
  }
  std::cout.flush();
  StopVirtualDisplay();
  RemoveMessageCapture();
  return code;
}
