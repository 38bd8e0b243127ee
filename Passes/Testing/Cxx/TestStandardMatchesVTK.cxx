#include "LightingTestHelpers.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"

using namespace stylizetest;

namespace
{
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
