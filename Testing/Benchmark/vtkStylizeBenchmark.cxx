// vtkStylizeBenchmark: frame-time comparison of VTK's plain rendering, VTK's own screen-space
// passes (Sobel, SSAO, EDL) and VTK Stylize's lighting and G-buffer passes.
//
// One run renders every (scene, light count, configuration) case offscreen at a fixed size with
// multisampling off, warms up (shader compilation, buffer uploads) and then times N frames, each
// with a small camera azimuth step so that nothing is cached, and glFinish (WaitForCompletion)
// before the clock stops. It writes a CSV with one row per case and a Markdown report (median
// ms, ratios to plain, light-count slopes, triangle-count flatness). Run with --help.
//
// The parts: vtkStylizeBenchmarkOptions (command line), vtkStylizeBenchmarkScenes (meshes,
// lights, configurations' passes), vtkStylizeBenchmarkRunner (timing) and
// vtkStylizeBenchmarkReport (tables, CSV).

#include "vtkStylizeBenchmarkOptions.h"
#include "vtkStylizeBenchmarkReport.h"
#include "vtkStylizeBenchmarkRunner.h"
#include "vtkStylizeBenchmarkScenes.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVersion.h"

#include <cstdlib>
#include <iostream>
#include <sstream>

using namespace vtkstylizebenchmark;

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
  RunInfo info;
  vtkNew<vtkRenderWindow> probe;
  vtkNew<vtkRenderer> probeRenderer;
  probe->SetOffScreenRendering(1);
  probe->SetMultiSamples(0);
  probe->SetSize(16, 16);
  probe->AddRenderer(probeRenderer);
  probe->Render();
  info.Renderer = RendererString(probe, &info.GLVersion);
  std::cout << "GL_RENDERER: " << info.Renderer << "\n";
  std::cout << "GL_VERSION:  " << info.GLVersion << "\n";
  std::cout << "VTK " << vtkVersion::GetVTKVersion() << ", " << opt.Width << "x" << opt.Height
            << ", multisampling off, " << opt.Warmup << " warm-up + " << opt.Frames
            << " timed frames per case\n\n";

  const auto start = Clock::now();
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
              << " triangles, " << FormatCount(mesh->GetNumberOfPoints()) << " points" << std::endl;
  }
  info.CoveredPixels = FrameMesh(meshes[0], opt).CoveredPixels;
  std::cout << "The unit sphere covers about " << Fixed(info.CoveredPixels / 1000.0, 0)
            << "k pixels (" << Fixed(100.0 * info.CoveredPixels / opt.Width / opt.Height, 1)
            << "% of the image)\n\n";
  for (const auto& config : opt.Configs)
  {
    info.Descriptions[config] = MakeConfig(config, 1.0).Description;
  }
  std::vector<Result> results;
  std::vector<StageResult> stageResults;
  RunAll(opt, meshes, results, stageResults);
  SortResults(opt, results);
  info.Seconds = std::chrono::duration<double>(Clock::now() - start).count();

  Report report(opt, results);
  std::ostringstream md;
  report.Write(md, ReportHeader(opt, info));
  WriteStageTable(md, stageResults);
  const bool ok = WriteReportFiles(opt, report, md.str());
  probe->Finalize();
  std::cout << "\n"
            << md.str() << "\nCSV: " << opt.Csv << "\nMarkdown: " << opt.Markdown << std::endl;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
