/**
 * vtkStylizeBenchmark: the command line. Options holds what a run measures (image size, frames,
 * scenes, light counts, configurations) and where it writes; ParseOptions() fills it from argv
 * (--quick first, as defaults that later options override) and prints --help.
 */
#ifndef vtkStylizeBenchmarkOptions_h
#define vtkStylizeBenchmarkOptions_h

#include "vtkStylizeBenchmarkTypes.h"

#include <string>
#include <vector>

namespace vtkstylizebenchmark
{
/** Every scene, in report order: spheres 10k, 500k, 2M, then the scan and the isosurface. */
const std::vector<SceneSpec>& AllScenes();

/**
 * The volume scenes, only when named by --scenes: headsq, VTK's CT of a head (64 x 64 x 93) as
 * VTK's GPU ray caster draws it with the transfer functions of VTK's MedicalDemo4 example (the
 * realdata.volumes scene), each style drawing it as a volume (issue 55).
 */
const std::vector<SceneSpec>& VolumeScenes();

/** Every configuration name --configs accepts, in report order. */
const std::vector<std::string>& AllConfigs();

/** The default light counts: 1, 8, 100, 500. */
const std::vector<int>& AllLightCounts();

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
  std::string Bunny = VTKSTYLIZE_REALDATA_DIR "/bunny.ply";   // the scanned mesh
  std::string Volume = VTKSTYLIZE_REALDATA_DIR "/headsq.vti"; // the volume scene's image
  double FlatTolerance = 25.0;                                // percent
  double FlatFloor = 2.0;                                     // ms
};

/** Returns 0 to continue, 1 for an error (reported on stderr), 2 for --help (printed). */
int ParseOptions(int argc, char* argv[], Options& opt);
}

#endif
