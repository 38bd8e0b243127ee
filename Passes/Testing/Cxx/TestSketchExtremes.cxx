#include "SketchTestHelpers.h"
#include "vtkPlaneSource.h"
#include "vtkSketchPass.h"
#include "vtkStylizeGBufferPass.h"
#include <limits>

using namespace stylizetest;

int TestSketchExtremes(int, char*[])
{
  using P = vtkSketchPass;
  auto only = [](vtkRenderer* r, vtkPolyDataAlgorithm* source)
  {
    r->RemoveAllViewProps();
    vtkNew<vtkPolyDataMapper> m;
    m->SetInputConnection(source->GetOutputPort());
    vtkNew<vtkActor> a;
    a->SetMapper(m);
    r->AddActor(a);
  };
  struct Case
  {
    std::string Name;
    int Width, Height;
    double Scale;
    Configure Setup;
    bool ExpectSurface;
  };
  const std::vector<Case> cases = {
    { "sphere only (umbilic)", 240, 180, 1.0,
      [&](vtkRenderer* r, P*)
      {
        vtkNew<vtkSphereSource> s;
        s->SetRadius(3.0);
        s->SetThetaResolution(64);
        s->SetPhiResolution(32);
        only(r, s);
      },
      true },
    { "plane only (planar)", 240, 180, 1.0,
      [&](vtkRenderer* r, P*)
      {
        vtkNew<vtkPlaneSource> s;
        s->SetOrigin(-4, -3, 0);
        s->SetPoint1(4, -3, 0);
        s->SetPoint2(-4, 3, 0);
        s->SetResolution(20, 20);
        only(r, s);
      },
      true },
    { "cylinder through the near plane", 240, 180, 1.0,
      [&](vtkRenderer* r, P*)
      {
        vtkNew<vtkCylinderSource> c;
        c->SetRadius(1.0);
        c->SetHeight(40.0);
        c->SetResolution(64);
        c->CappingOff();
        only(r, c);
        vtkCamera* cam = r->GetActiveCamera();
        cam->SetPosition(0, -15, 2.5);
        cam->SetFocalPoint(0, 0, 0);
        cam->SetViewUp(0, 0, 1);
        r->ResetCameraClippingRange();
        double range[2];
        cam->GetClippingRange(range);
        cam->SetClippingRange(0.05, range[1]);
      },
      true },
    { "0 lights", 240, 180, 1.0, [](vtkRenderer* r, P*) { SetupLights(r, "none"); }, true },
    { "200 lights", 240, 180, 1.0, [](vtkRenderer* r, P*) { SetupLights(r, "many:200"); }, true },
    { "scale 1e-6", 240, 180, 1e-6, nullptr, true },
    { "scale 1e6", 240, 180, 1e6, nullptr, true },
    { "near/far 1e7", 240, 180, 1.0, [](vtkRenderer* r, P*) { SetNearFarRatio(r, 1e-7); }, true },
    { "1x1 window", 1, 1, 1.0, nullptr, false },
    { "every option at its limits", 240, 180, 1.0,
      [](vtkRenderer*, P* p)
      {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        p->SetNeighbors(-5);
        p->SetNeighborSpacing(nan);
        p->SetMaxStride(1e9);
        p->SetPlanarTolerance(2);
        p->SetUmbilicTolerance(nan);
        p->SetSmoothingIterations(1000);
        p->SetFillRadius(1e9);
        p->SetStepLength(0);
        p->SetSteps(100000);
        p->SetNoiseSize(nan);
        p->SetStrokeContrast(1e9);
        p->SetContrast(-1);
        p->SetBlurRadius(1e9);
        p->SetBlurStride(0);
        p->SetBrightThresholds(nan, -3);
        p->SetPencilColor(nan, 2, -1);
        p->SetPaperColor(nan, nan, nan);
        p->SetReferenceHeight(0);
      },
      true },
    { "model mode without arrays", 240, 180, 1.0,
      [](vtkRenderer*, P* p) { p->SetDirectionSource(P::MODEL); }, true },
    { "lines and points only", 240, 180, 1.0,
      [](vtkRenderer* r, P*)
      {
        int i = 0;
        ForEachActor(r,
          [&i](vtkActor* a)
          {
            if (i++ % 2)
            {
              a->GetProperty()->SetRepresentationToWireframe();
            }
            else
            {
              a->GetProperty()->SetRepresentationToPoints();
              a->GetProperty()->SetPointSize(3);
            }
          });
      },
      false },
    { "empty data", 240, 180, 1.0, [](vtkRenderer* r, P*) { SetEmptyScene(r); }, false },
  };
  for (const Case& k : cases)
  {
    for (bool parallel : { false, true })
    {
      auto scene = MakeTestScene(k.Width, k.Height, parallel, k.Scale);
      vtkRenderWindow* win = scene.Window;
      vtkRenderer* ren = scene.Renderer;
      vtkNew<P> pass;
      ren->SetPass(pass);
      if (k.Setup)
      {
        k.Setup(ren, pass);
      }
      win->Render();
      const std::string tag = k.Name + (parallel ? " [parallel]" : " [perspective]");
      vtkStylizeGBufferPass* g = pass->GetGBufferPass();
      CheckChannelsFinite(g, tag);
      CheckField(pass, tag, k.ExpectSurface && k.Width > 1);
      auto img = Capture(win);
      const double white[3] = { 1, 1, 1 };
      const vtkIdType ink = CountForeground(img, white);
      STYLIZE_CHECK(!k.ExpectSurface || k.Width == 1 || ink > 0, "%s: nothing drawn", tag.c_str());
      win->Finalize();
    }
  }
  return Failures == 0 ? 0 : 1;
}
