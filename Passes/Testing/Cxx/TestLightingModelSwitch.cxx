#include "LightingExtremesTestHelpers.h"
#include "vtkStylizeLightingPass.h"

using namespace stylizetest;

// Each lighting model is its own shader program: switching the model of a pass that has already
// rendered rebuilds the mappers' shaders, so every model renders exactly as a fresh pass does
// (and differs from the model before it).
int TestLightingModelSwitch(int, char*[])
{
  const int w = 240, h = 180;
  auto render = [&](vtkStylizeLightingPass* pass, vtkRenderWindow* win)
  {
    win->Render();
    return Capture(win);
  };
  auto live = MakeTestScene(w, h);
  vtkNew<vtkStylizeLightingPass> switched;
  live.Renderer->SetPass(switched);
  vtkSmartPointer<vtkImageData> previous = render(switched, live.Window);
  for (int model : { vtkStylizeLightingPass::COMIC, vtkStylizeLightingPass::PIXEL_ART,
         vtkStylizeLightingPass::STANDARD, vtkStylizeLightingPass::COMIC })
  {
    switched->SetModel(model);
    auto image = render(switched, live.Window);
    auto fresh = MakeTestScene(w, h);
    vtkNew<vtkStylizeLightingPass> pass;
    pass->SetModel(model);
    fresh.Renderer->SetPass(pass);
    auto reference = render(pass, fresh.Window);
    const double same = vtkStylizeImageMetrics::MaximumDifference(image, reference);
    const double changed = vtkStylizeImageMetrics::MaximumDifference(image, previous);
    std::printf("switched to %s: max difference %.0f against a fresh pass, %.0f against the "
                "model before\n",
      vtkStylizeLightingPass::GetModelName(model), same, changed);
    STYLIZE_CHECK(same == 0.0, "%s after a switch differs from a fresh pass (%.0f levels)",
      vtkStylizeLightingPass::GetModelName(model), same);
    STYLIZE_CHECK(changed > 4.0, "%s after a switch looks like the model before (%.0f levels)",
      vtkStylizeLightingPass::GetModelName(model), changed);
    fresh.Window->Finalize();
    previous = image;
  }
  live.Window->Finalize();
  return Failures == 0 ? 0 : 1;
}
