/**
 * vtkStylizeBenchmark: the timing. RunAll() renders every (scene, light count, configuration)
 * case offscreen, one window per configuration, warms up, then times interleaved frames
 * (Render() + glFinish) and keeps their median, minimum and maximum; for the styles it also
 * measures per-stage costs and texture memory per pixel.
 */
#ifndef vtkStylizeBenchmarkRunner_h
#define vtkStylizeBenchmarkRunner_h

#include "vtkStylizeBenchmarkOptions.h"
#include "vtkStylizeBenchmarkTypes.h"

#include "vtkSmartPointer.h"

#include <chrono>
#include <string>
#include <vector>

class vtkPolyData;
class vtkRenderWindow;

namespace vtkstylizebenchmark
{
using Clock = std::chrono::steady_clock;

/**
 * Times all configurations over all scenes (@p meshes, one per opt.Scenes) and light counts,
 * printing each case's line as it goes. Appends one Result per case, in run order, and one
 * StageResult per case of a style.
 */
void RunAll(const Options& opt, const std::vector<vtkSmartPointer<vtkPolyData>>& meshes,
  std::vector<Result>& results, std::vector<StageResult>& stageResults);

/** Extracts "OpenGL renderer string: ..." (and version) from ReportCapabilities(). */
std::string RendererString(vtkRenderWindow* renWin, std::string* version);
}

#endif
