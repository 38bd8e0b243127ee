// Lighting pass tests: regression images per model and light set-up (VTK's harness plus a strict
// comparison of our own), and Standard == VTK's own lighting.
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkRegressionTestImage.h"
#include "vtkShaderProgram.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeTestUtilities.h"
#include "vtkTesting.h"

#include <vtksys/SystemTools.hxx>

using namespace stylizetest;

namespace
{
/**
 * The lighting tests' scene: a w x h window, the test actors on a dark gray-blue background lit
 * by the light set-up, seen from azimuth 25, elevation 20, 12 units away.
 */
TestScene MakeLightingScene(const std::string& setup, bool parallel, int w, int h)
{
  TestScene scene;
  scene.Window = MakeWindow(w, h);
  scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
  scene.Window->AddRenderer(scene.Renderer);
  scene.Renderer->SetBackground(0.3, 0.32, 0.36);
  AddTestActors(scene.Renderer);
  SetupLights(scene.Renderer, setup);
  PlaceCamera(scene.Renderer, 1.0, 25, 20, 12.0, 0.37, parallel);
  return scene;
}

vtkSmartPointer<vtkImageData> RenderScene(
  int model, const std::string& setup, bool parallel, int mode, int w = 300, int h = 240)
{
  // mode: 0 plain VTK, 1 lighting pass, 2 lighting pass inside the G-buffer
  auto scene = MakeLightingScene(setup, parallel, w, h);
  vtkRenderWindow* win = scene.Window;
  vtkRenderer* ren = scene.Renderer;
  vtkNew<vtkStylizeLightingPass> lighting;
  lighting->SetModel(model);
  vtkNew<vtkStylizeGBufferPass> gbuffer;
  gbuffer->SetLightingPass(lighting);
  gbuffer->SetChannels(vtkStylizeGBufferPass::NORMAL);
  if (mode == 1)
  {
    ren->SetPass(lighting);
  }
  else if (mode == 2)
  {
    ren->SetPass(gbuffer);
  }
  win->Render();
  auto img = Capture(win);
  win->Finalize();
  return img;
}
}

// Regression image of one model and light set-up: VTK's harness, then our strict comparison.
int TestLightingRegression(int argc, char* argv[])
{
  Args args = ParseArgs(argc, argv);
  if (args.Positional.size() < 2)
  {
    std::fprintf(stderr, "usage: TestLightingRegression MODEL SETUP -V baseline -T dir\n");
    return 1;
  }
  const int model = vtkStylizeLightingPass::GetModelFromName(args.Positional[0].c_str());
  const std::string setup = args.Positional[1];
  const bool parallel = args.Positional.size() > 2 && args.Positional[2] == "parallel";

  auto scene = MakeLightingScene(setup, parallel, 300, 240);
  vtkRenderWindow* win = scene.Window;
  vtkNew<vtkStylizeLightingPass> lighting;
  lighting->SetModel(model);
  scene.Renderer->SetPass(lighting);
  win->Render();
  const int verdict = RegressionVerdict(win, argc, argv, args, 2, 0.0005, 24);
  win->Finalize();
  return verdict;
}

// Standard equals VTK's own lighting to within 2/255, through the lighting pass alone and
// through the G-buffer, for every light set-up and both projections.
int TestStandardMatchesVTK(int, char*[])
{
  for (const char* setup : { "headlight", "kit", "none", "many:100" })
  {
    for (bool parallel : { false, true })
    {
      auto plain = RenderScene(0, setup, parallel, 0);
      auto lit = RenderScene(vtkStylizeLightingPass::STANDARD, setup, parallel, 1);
      auto gbuf = RenderScene(vtkStylizeLightingPass::STANDARD, setup, parallel, 2);
      const std::string what = std::string(setup) + (parallel ? " parallel" : " perspective");
      StrictCompare(lit, plain, 2, 0.0, 2, "standard vs VTK, " + what);
      StrictCompare(gbuf, plain, 2, 0.0, 2, "standard via G-buffer vs VTK, " + what);
    }
  }
  return stylizetest::Failures == 0 ? 0 : 1;
}

// The compiled program does not change when only the number of lights changes (VTK's own
// lighting compiles a new program for each count), and 1000 lights render.
int TestLightCountNoRebuild(int, char*[])
{
  auto win = MakeWindow(200, 160);
  vtkNew<vtkRenderer> ren;
  win->AddRenderer(ren);
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  ren->AddActor(actor);
  PlaceCamera(ren, 1.0, 0, 0, 3.0, 0.0);
  vtkNew<vtkStylizeLightingPass> lighting;
  lighting->SetModelToComic();
  ren->SetPass(lighting);
  auto* ogl = vtkOpenGLRenderWindow::SafeDownCast(win);

  // One program per light class: VTK's single headlight, and every other set of lights (any
  // count); returning to a class finds its program again (built once).
  vtkShaderProgram* headlightProgram = nullptr;
  vtkShaderProgram* generalProgram = nullptr;
  for (const char* setup :
    { "headlight", "many:8", "many:100", "none", "many:1000", "kit", "headlight", "many:2" })
  {
    SetupLights(ren, setup);
    win->Render();
    vtkShaderProgram* program = ogl->GetShaderCache()->GetLastShaderBound();
    const bool headlight = std::string(setup) == "headlight";
    std::printf("%-10s lights packed: %4d, program %p (%s class)\n", setup,
      lighting->GetNumberOfLights(), static_cast<void*>(program),
      headlight ? "headlight" : "general");
    vtkShaderProgram*& first = headlight ? headlightProgram : generalProgram;
    if (!first)
    {
      first = program;
    }
    STYLIZE_CHECK(program == first, "the program changed with the light set-up %s", setup);
    if (std::string(setup) == "many:1000")
    {
      STYLIZE_CHECK(lighting->GetNumberOfLights() == 1000, "1000 lights: packed %d",
        lighting->GetNumberOfLights());
      auto img = Capture(win);
      const double bg[3] = { 0, 0, 0 };
      STYLIZE_CHECK(CountForeground(img, bg) > 1000, "1000 lights: the sphere is not visible");
    }
  }
  STYLIZE_CHECK(headlightProgram && generalProgram && headlightProgram != generalProgram,
    "the single headlight has no program of its own");
  std::printf("maximum number of lights: %d\n", lighting->GetMaximumNumberOfLights());
  STYLIZE_CHECK(lighting->GetMaximumNumberOfLights() >= 1000, "limit %d < 1000",
    lighting->GetMaximumNumberOfLights());
  win->Finalize();
  return stylizetest::Failures == 0 ? 0 : 1;
}
