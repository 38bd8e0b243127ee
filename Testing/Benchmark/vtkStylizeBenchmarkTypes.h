/**
 * vtkStylizeBenchmark: the types shared by its parts. A scene is named by SceneSpec (options,
 * scenes); the runner measures Result (one per scene, light count and configuration) and
 * StageResult (a style's per-stage costs), which the report prints.
 */
#ifndef vtkStylizeBenchmarkTypes_h
#define vtkStylizeBenchmarkTypes_h

#include "vtkType.h" // vtkIdType

#include <string>
#include <utility>
#include <vector>

namespace vtkstylizebenchmark
{
struct SceneSpec
{
  std::string Name;    // "10k", "500k", "2M", "bunny", "iso970k", "headsq"
  int Theta;           // spheres: vtkSphereSource resolutions, 2 * Theta * (Phi - 1) triangles;
  int Phi;             // 0 for the real scenes
  bool Volume = false; // a volume (GPU ray casting) instead of a mesh
};

/** The timed frames of one (scene, light count, configuration) case, in milliseconds. */
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

/** Per-stage milliseconds of a style (vtkStylizeStylePass::StageTimingOn()), medians. */
struct StageResult
{
  std::string Scene;
  int Lights = 0;
  std::string Config;
  std::vector<std::pair<std::string, double>> Stages; // name (with runs), median ms
  double Frame = 0.0;         // median of the timed frames' totals (waits between stages included)
  double BytesPerPixel = 0.0; // the style's textures (GetTextureBytes()) per viewport pixel
};
}

#endif
