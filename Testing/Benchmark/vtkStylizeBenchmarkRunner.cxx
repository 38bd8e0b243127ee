// vtkStylizeBenchmark: the windows the configurations render in, and the timed frames.

#include "vtkStylizeBenchmarkRunner.h"

#include "vtkStylizeBenchmarkReport.h"
#include "vtkStylizeBenchmarkScenes.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkStylizeStylePass.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

namespace vtkstylizebenchmark
{
namespace
{
double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

/** One configuration: its own render window, renderer, actor and passes. */
struct Bench
{
  std::string Config;
  ConfigPasses Passes;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkPolyDataMapper> Mapper;
  vtkSmartPointer<vtkActor> Actor;
  vtkSmartPointer<vtkVolume> Volume; // the volume scenes' prop, in the renderer for them only
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
    this->Actor = vtkSmartPointer<vtkActor>::New();
    vtkActor* actor = this->Actor;
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
    if (this->Passes.AddProps)
    {
      this->Passes.AddProps(this->Renderer, actor);
    }
    if (this->Passes.Root)
    {
      this->Renderer->SetPass(this->Passes.Root);
    }
    this->Initial = vtkSmartPointer<vtkCamera>::New();
    this->Volume = MakeVolumeProp();
  }

  /**
   * Shows the mesh's actor, or the volume of `image` (a volume scene) in its place, and sets
   * the scene's first view: the mesh's ResetCamera(), or the volume seen from the front at 30
   * degrees as realdata.volumes sees headsq.
   */
  void ShowScene(vtkPolyData* mesh, vtkImageData* image)
  {
    this->Mapper->SetInputData(mesh);
    if (this->Passes.SetMesh)
    {
      this->Passes.SetMesh(mesh);
    }
    this->Actor->SetVisibility(image ? 0 : 1);
    // (a mesh after a volume scene is seen along VTK's default direction, not the volume's)
    const bool hadVolume = this->Renderer->GetVolumes()->IsItemPresent(this->Volume) != 0;
    this->Renderer->RemoveVolume(this->Volume);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    if (hadVolume && !image)
    {
      camera->SetFocalPoint(0.0, 0.0, 0.0);
      camera->SetPosition(0.0, 0.0, 1.0);
      camera->SetViewUp(0.0, 1.0, 0.0);
    }
    if (image)
    {
      this->Volume->GetMapper()->SetInputDataObject(image);
      this->Renderer->AddVolume(this->Volume);
      camera->SetFocalPoint(0.0, 0.0, 0.0);
      camera->SetPosition(0.0, -1.0, 0.0);
      camera->SetViewUp(0.0, 0.0, -1.0);
    }
    this->Renderer->ResetCamera();
    if (image)
    {
      camera->Azimuth(30.0);
      camera->Elevation(30.0);
      camera->OrthogonalizeViewUp();
      camera->Zoom(1.2);
    }
    this->Initial->DeepCopy(camera);
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
    this->Actor = nullptr;
    this->Volume = nullptr;
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

  /** Lights and the initial view of a case, then the untimed warm-up frames. */
  void WarmUp(const Framing& framing, int lights, const Options& opt)
  {
    SetLights(this->Renderer, lights, framing.Center, 0.5 * framing.Diagonal / std::sqrt(3.0));
    // Every configuration sees the same sequence of views.
    this->Renderer->GetActiveCamera()->DeepCopy(this->Initial);
    this->Renderer->ResetCameraClippingRange();
    this->Times.clear();
    const auto w0 = Clock::now();
    for (int i = 0; i < opt.Warmup; ++i)
    {
      this->Frame();
    }
    this->Warmup = std::chrono::duration<double>(Clock::now() - w0).count();
  }
};

/**
 * Per-stage costs of a style: three more frames with stage timing on (each stage then waits
 * for the renderer, so these frames are a little slower than the timed ones). False for a
 * configuration that is not a style.
 */
bool TimeStages(Bench& b, const Options& opt, StageResult& sr)
{
  auto* style = vtkStylizeStylePass::SafeDownCast(b.Passes.Root);
  if (!style)
  {
    return false;
  }
  style->StageTimingOn();
  std::map<std::string, std::vector<double>> times;
  std::vector<std::string> order;
  std::vector<double> frames;
  for (int i = 0; i < 3; ++i)
  {
    frames.push_back(b.Frame());
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
  sr.BytesPerPixel =
    static_cast<double>(style->GetTextureBytes()) / (double(opt.Width) * opt.Height);
  sr.Config = b.Config;
  sr.Frame = Median(frames);
  for (const auto& name : order)
  {
    sr.Stages.emplace_back(name, Median(times[name]));
  }
  return true;
}

/** The last frame of a case as DIR/<scene>-<lights>-<config>.png (--images). */
void WriteImage(Bench& b, const std::string& scene, int lights, const Options& opt)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(b.Window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> png;
  png->SetInputConnection(grab->GetOutputPort());
  png->SetFileName(
    (opt.Images + "/" + scene + "-" + std::to_string(lights) + "-" + b.Config + ".png").c_str());
  png->Write();
}

/** A configuration's timed frames of one case as a Result, printed as one line. */
Result Summarize(
  const Bench& b, const std::string& scene, vtkPolyData* mesh, int lights, const Options& opt)
{
  Result r;
  r.Scene = scene;
  r.Triangles = mesh->GetNumberOfPolys();
  r.Lights = lights;
  r.Config = b.Config;
  r.Median = Median(b.Times);
  r.Min = *std::min_element(b.Times.begin(), b.Times.end());
  r.Max = *std::max_element(b.Times.begin(), b.Times.end());
  r.Frames = opt.Frames;
  std::cout << "  " << std::left << std::setw(20) << b.Config << std::right << " median "
            << std::setw(9) << Fixed(r.Median, 1) << " ms  (min " << Fixed(r.Min, 1) << ", max "
            << Fixed(r.Max, 1) << "; warm-up " << Fixed(b.Warmup, 1) << " s)" << std::endl;
  return r;
}

/**
 * One (scene, lights) case over every configuration: every configuration first renders its
 * warm-up frames, then the timed frames are interleaved (frame 1 of every configuration,
 * frame 2 of every configuration, and so on), so a burst of load from other processes on this
 * shared machine spreads over all configurations instead of falling on one.
 */
void RunCase(std::vector<std::unique_ptr<Bench>>& benches, const SceneSpec& scene,
  vtkPolyData* mesh, const Framing& framing, int lights, const Options& opt,
  std::vector<Result>& results, std::vector<StageResult>& stageResults)
{
  std::cout << SceneLabel(scene.Name) << ", " << lights << (lights == 1 ? " light" : " lights")
            << std::endl;
  for (auto& b : benches)
  {
    b->WarmUp(framing, lights, opt);
  }
  for (int i = 0; i < opt.Frames; ++i)
  {
    for (auto& b : benches)
    {
      b->Times.push_back(b->Frame());
    }
  }
  for (auto& b : benches)
  {
    StageResult sr;
    sr.Scene = scene.Name;
    sr.Lights = lights;
    if (TimeStages(*b, opt, sr))
    {
      stageResults.push_back(sr);
    }
  }
  for (auto& b : benches)
  {
    results.push_back(Summarize(*b, scene.Name, mesh, lights, opt));
    if (!opt.Images.empty())
    {
      WriteImage(*b, scene.Name, lights, opt);
    }
  }
}
}

/*
 * Every configuration has its own window, kept for the whole run (only the mapper's input and
 * the lights change), so the shader programs compiled for a light setup stay in that window's
 * shader cache.
 */
void RunAll(const Options& opt, const std::vector<vtkSmartPointer<vtkPolyData>>& meshes,
  std::vector<Result>& results, std::vector<StageResult>& stageResults)
{
  const Framing first = FrameMesh(meshes[0], opt);
  std::vector<std::unique_ptr<Bench>> benches;
  for (const auto& config : opt.Configs)
  {
    benches.emplace_back(new Bench(config, opt, first.Diagonal));
  }

  for (size_t si = 0; si < opt.Scenes.size(); ++si)
  {
    vtkPolyData* mesh = meshes[si];
    const Framing framing = FrameMesh(mesh, opt);
    // (a volume scene's image, read again here: its mesh holds only its bounds)
    vtkSmartPointer<vtkImageData> image = opt.Scenes[si].Volume ? ReadSceneVolume(opt) : nullptr;
    for (auto& b : benches)
    {
      b->ShowScene(mesh, image);
    }
    for (int lights : opt.Lights)
    {
      RunCase(benches, opt.Scenes[si], mesh, framing, lights, opt, results, stageResults);
    }
  }

  for (auto& b : benches)
  {
    b->Release();
  }
}

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
}
