/**
 * vtkstylize: the command line, parsed with CLI11.
 *
 * The pass settings are options generated from the classes (vtkstylizeSettings.inc, written by
 * scripts/parameters.py from the wrapped classes): their ranges and defaults are read from the
 * classes at run time, their meaning is the class's comment. The other options (scene, camera,
 * output) are declared in Options.cxx. Values are validated by CLI11 while parsing and applied in
 * command-line order, so a later option overrides an earlier one.
 */
#ifndef vtkstylizeOptions_h
#define vtkstylizeOptions_h

#include "vtkSmartPointer.h"

#include <functional>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

class vtkComicPass;
class vtkPixelArtPass;
class vtkRenderPass;
class vtkSketchPass;
class vtkLineArtPass;
class vtkStylizeGBufferPass;
class vtkStylizeLightingPass;

namespace vtkstylize
{
constexpr int MaxImageSize = 16384;
constexpr int MaxLights = 10000;
constexpr int MaxMultiSamples = 16;
constexpr int MaxMagnify = 8;
constexpr double MaxAngle = 360.0;
constexpr double MinZoom = 0.01;
constexpr double MaxZoom = 100.0;

// Camera defaults for the built-in scene (files use 0 / 0: looking down -z).
constexpr int MaxOrbitFrames = 3600;
constexpr double SceneAzimuth = 30.0;
constexpr double SceneElevation = 20.0;
/** Files: the share of the image's width or height the data fills before --zoom. */
constexpr double FrameFill = 0.85;

/** The settings given for each pass class, applied in command-line order to the passes built. */
struct PassSettings
{
  template <class Pass>
  using List = std::vector<std::function<void(Pass*)>>;
  std::tuple<List<vtkStylizeLightingPass>, List<vtkComicPass>, List<vtkPixelArtPass>,
    List<vtkSketchPass>, List<vtkLineArtPass>>
    Lists;

  template <class Pass>
  List<Pass>& Of()
  {
    return std::get<List<Pass>>(this->Lists);
  }
  template <class Pass>
  void ApplyTo(Pass* pass) const
  {
    for (const auto& apply : std::get<List<Pass>>(this->Lists))
    {
      apply(pass);
    }
  }
};

struct Options
{
  std::string Style = "none";
  std::string Output = "stylized.png";
  int Width = 1280;
  int Height = 720;
  int Lights = 1;
  std::optional<double> Azimuth;
  std::optional<double> Elevation;
  std::string Up = "+y"; // --up: the data's up axis, lower case
  double Zoom = 1.0;
  bool Parallel = false;
  double Background[3] = { 1.0, 1.0, 1.0 };
  int LightingModel = -1; // --lighting; -1: the style's own model
  PassSettings Passes;
  bool ModelDirections = false; // --direction-source model: compute the principal directions
  int Magnify = 1;
  int Orbit = 0;               // --orbit N: frames of an orbit animation; 0: a still
  double OrbitDegrees = 360.0; // --orbit-degrees
  double OrbitElevation = 0.0; // --orbit-elevation
  int FramesPerSecond = 25;    // --fps
  bool AnchorGiven = false;    // --anchor, --dither-anchor or --noise-space was given
  bool NoiseGiven = false;     // --noise was given
  int TimeStep = 0;
  bool TimeStepGiven = false; // --time-step was given (a warning when there is no INPUT)
  bool GBuffer = false;
  std::optional<double> IsoValue;
  std::string ColorBy;
  bool NoScalars = false;
  bool NoAnnotations = false;
  int MultiSamples = 0;
  double MemoryLimit = -1.0;  // MiB; -1: the default (3/4 of the machine's memory), 0: none
  double ReadTimeLimit = 0.0; // s of processor time for reading; 0: the reader's automatic one
  bool Quiet = false;
  std::vector<std::string> Warnings; // options that do not apply, printed after a success
  bool ScalarBar = false; // --scalar-bar: the colour legend on black-and-white output too
  bool Help = false;
  bool Version = false;
  std::string Input; // empty: the built-in scene
};

/**
 * A style: its name for --style, a one-line description for --help, the lighting model it uses
 * unless --lighting says otherwise (-1: the lighting pass's default), and the function that
 * builds the renderer's pass from the lighting pass (and the G-buffer pass when --gbuffer is
 * given). New styles are added to Styles().
 */
struct StyleSpec
{
  const char* Name;
  const char* Description;
  int DefaultModel;
  std::function<vtkSmartPointer<vtkRenderPass>(
    vtkStylizeLightingPass*, vtkStylizeGBufferPass*, const Options&)>
    MakePass;
};

const std::vector<StyleSpec>& Styles();
const StyleSpec* FindStyle(const std::string& name);

/**
 * Parses the command line. Usage errors throw (UsageError: exit status 2). With --help or
 * --version only those are set.
 */
Options ParseCommandLine(int argc, char* argv[]);

/** The --help text. */
std::string HelpText();
}

#endif
