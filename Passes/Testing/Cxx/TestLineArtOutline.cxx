// A small view's outline (issue 52): a thin plate (a box 4 x 1 x 0.1, as a FEM plate) seen from
// above at a slant, at the default ReferenceHeight (1080 lines: in a 160-pixel view the 2.5-point
// contour is 0.37 pixel, tapered to half of that with depth). Every pixel of the plate next to
// the background must have ink of at least a half within one pixel: a stroke narrower than a
// pixel, anti-aliased, broke into faint dashes as it crossed the pixel rows and left the far
// edges without a line. The plate is told from the background by colour: the background is pure
// blue, the line art's paper white, its ink black.
#include "vtkLineArtPass.h"
#include "vtkStylizeTestUtilities.h"

#include "vtkCamera.h"
#include "vtkCubeSource.h"

#include <algorithm>

using namespace stylizetest;

int TestLineArtOutline(int, char*[])
{
  double worst = 1.0;
  for (const int height : { 160, 300 })
  {
    const int w = 3 * height;
    vtkSmartPointer<vtkRenderWindow> win = MakeWindow(w, height);
    vtkNew<vtkRenderer> ren;
    win->AddRenderer(ren);
    ren->SetBackground(0.0, 0.0, 1.0);
    vtkNew<vtkCubeSource> plate;
    plate->SetXLength(4.0);
    plate->SetYLength(1.0);
    plate->SetZLength(0.1);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(plate->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    ren->AddActor(actor);
    vtkCamera* cam = ren->GetActiveCamera();
    cam->SetFocalPoint(0.0, 0.0, 0.0);
    cam->SetPosition(0.8, -2.2, 2.6);
    cam->SetViewUp(0.0, 0.0, 1.0);
    ren->ResetCamera();
    cam->Dolly(1.3);
    ren->ResetCameraClippingRange();
    vtkNew<vtkLineArtPass> lines; // ReferenceHeight 1080
    ren->SetPass(lines);
    win->Render();
    auto img = Capture(win);
    vtkDataArray* s = img->GetPointData()->GetScalars();
    auto at = [&](int x, int y) { return static_cast<vtkIdType>(y) * w + x; };
    auto background = [&](int x, int y)
    {
      const vtkIdType i = at(x, y);
      return s->GetComponent(i, 0) < 8 && s->GetComponent(i, 1) < 8 && s->GetComponent(i, 2) > 247;
    };
    auto ink = [&](int x, int y)
    {
      const vtkIdType i = at(x, y);
      return 1.0 -
        std::max({ s->GetComponent(i, 0), s->GetComponent(i, 1), s->GetComponent(i, 2) }) / 255.0;
    };
    long edge = 0, inked = 0;
    for (int y = 1; y + 1 < height; ++y)
    {
      for (int x = 1; x + 1 < w; ++x)
      {
        if (background(x, y) ||
          !(background(x - 1, y) || background(x + 1, y) || background(x, y - 1) ||
            background(x, y + 1)))
        {
          continue;
        }
        ++edge;
        double most = 0.0;
        for (int j = -1; j <= 1; ++j)
        {
          for (int i = -1; i <= 1; ++i)
          {
            most = std::max(most, ink(x + i, y + j));
          }
        }
        inked += most >= 0.5 ? 1 : 0;
      }
    }
    const double share = edge > 0 ? static_cast<double>(inked) / edge : 0.0;
    std::printf("%dx%d: %ld pixels of the plate next to the background, %.3f with ink >= 0.5 "
                "within a pixel\n",
      w, height, edge, share);
    STYLIZE_CHECK(edge > 200, "%dx%d: only %ld outline pixels", w, height, edge);
    worst = std::min(worst, share);
    win->Finalize();
  }
  STYLIZE_CHECK(worst >= 0.98, "the outline has ink on only %.3f of its pixels", worst);
  return Failures == 0 ? 0 : 1;
}
