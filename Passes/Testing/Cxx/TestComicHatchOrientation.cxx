#include "ComicTestHelpers.h"
#include "vtkComicPass.h"
#include "vtkStylizeLightingPass.h"
#include <algorithm>

using namespace stylizetest;

// HatchOrientation PRINCIPAL: the hatch lines run around the form. A vertical cylinder lit from
// the side, everything hatched (dark and bright thresholds 1), no edges, no crossing: with the
// principal field the lines run around it, horizontal on the screen, so the image changes
// along y far more than along x (ratio > 3); with the fixed 135-degree angle both are alike
// (ratio < 2), which shows that the measure tells the two apart.
int TestComicHatchOrientation(int, char*[])
{
  const int w = 400, h = 300;
  double ratio[2] = { 0, 0 };
  for (int orientation : { vtkComicPass::FIXED, vtkComicPass::PRINCIPAL })
  {
    vtkNew<vtkCylinderSource> cylinder; // axis along y
    cylinder->SetRadius(1.0);
    cylinder->SetHeight(4.0);
    cylinder->SetResolution(256);
    cylinder->CappingOff();
    auto scene = MakeSideLitScene(w, h, cylinder, 4.0, 3.0);
    vtkRenderWindow* window = scene.Window;
    vtkRenderer* ren = scene.Renderer;
    vtkCamera* cam = ren->GetActiveCamera();
    cam->SetPosition(0, 0, 8);
    cam->SetFocalPoint(0, 0, 0);
    cam->SetViewUp(0, 1, 0);
    cam->SetViewAngle(30);
    ren->ResetCameraClippingRange();
    vtkNew<vtkComicPass> comic;
    comic->SetReferenceHeight(h);
    comic->EdgesOff();
    comic->CrossHatchingOff();
    comic->SetDarkThreshold(1.0);
    comic->SetBrightThreshold(1.0);
    comic->SetHatchOrientation(orientation);
    comic->GetLightingPass()->SetModel(vtkStylizeLightingPass::STANDARD);
    ren->SetPass(comic);
    window->Render();
    auto img = Capture(window);
    // The cylinder spans about 70 px per unit: its middle, away from the silhouettes.
    double gx = 0, gy = 0;
    for (int y = h / 2 - 60; y < h / 2 + 60; ++y)
    {
      for (int x = w / 2 - 50; x < w / 2 + 50; ++x)
      {
        const double c = Gray(img, static_cast<vtkIdType>(y) * w + x);
        gx += std::abs(Gray(img, static_cast<vtkIdType>(y) * w + x + 1) - c);
        gy += std::abs(Gray(img, static_cast<vtkIdType>(y + 1) * w + x) - c);
      }
    }
    const int i = orientation == vtkComicPass::PRINCIPAL ? 1 : 0;
    ratio[i] = gy / std::max(gx, 1.0);
    std::printf("hatch orientation %s: change along y %.0f, along x %.0f, ratio %.2f\n",
      i ? "PRINCIPAL" : "FIXED (135 degrees)", gy, gx, ratio[i]);
    STYLIZE_CHECK(gx + gy > 1000.0, "%s: no hatching drawn", i ? "PRINCIPAL" : "FIXED");
    window->Finalize();
  }
  STYLIZE_CHECK(
    ratio[1] > 3.0, "PRINCIPAL: the lines do not run around the cylinder (%.2f)", ratio[1]);
  STYLIZE_CHECK(
    ratio[0] < 2.0, "FIXED: the measure does not tell the angles apart (%.2f)", ratio[0]);
  return Failures == 0 ? 0 : 1;
}
