#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeTestUtilities.h"

using namespace stylizetest;

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
