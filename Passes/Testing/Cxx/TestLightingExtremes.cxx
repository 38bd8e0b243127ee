#include "LightingExtremesTestHelpers.h"
#include "vtkInformation.h"
#include "vtkPolyData.h"
#include "vtkStylizeLightingPass.h"
#include <limits>

using namespace stylizetest;

namespace
{
vtkIdType SurfacePixels(Buffers& b)
{
  vtkIdType n = 0;
  for (vtkIdType i = 0; i < b.Normal->GetNumberOfTuples(); ++i)
  {
    n += b.Normal->GetComponent(i, 3) == 1.0 ? 1 : 0;
  }
  return n;
}

void AddSphere(vtkRenderer* ren, double specPow = 20, double specular = 0.4, double ambient = 0.1)
{
  vtkNew<vtkSphereSource> s;
  s->SetThetaResolution(32);
  s->SetPhiResolution(24);
  vtkNew<vtkPolyDataMapper> m;
  m->SetInputConnection(s->GetOutputPort());
  vtkNew<vtkActor> a;
  a->SetMapper(m);
  a->GetProperty()->SetSpecular(specular);
  a->GetProperty()->SetSpecularPower(specPow);
  a->GetProperty()->SetAmbient(ambient);
  ren->AddActor(a);
  PlaceCamera(ren, 1.0, 0, 0, 3.2, 0.0, ren->GetActiveCamera()->GetParallelProjection());
}

// A triangulated grid whose normals are all zero, or all NaN.
// The test actors, the light kit and the camera, all at `scale` (the picture does not change).
void KitScene(vtkRenderer* ren, double scale)
{
  AddTestActors(ren, scale);
  SetupLights(ren, "kit", scale);
  PlaceCamera(ren, scale, 20, 15, 16.0, 0.37, ren->GetActiveCamera()->GetParallelProjection());
}

void AddBadNormalsSurface(vtkRenderer* ren, double value)
{
  vtkNew<vtkSphereSource> s;
  s->SetThetaResolution(24);
  s->SetPhiResolution(16);
  s->Update();
  vtkNew<vtkPolyData> pd;
  pd->DeepCopy(s->GetOutput());
  vtkDataArray* normals = pd->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
  {
    normals->SetTuple3(i, value, value, value);
  }
  vtkNew<vtkPolyDataMapper> m;
  m->SetInputData(pd);
  vtkNew<vtkActor> a;
  a->SetMapper(m);
  a->GetProperty()->SetSpecular(0.5);
  ren->AddActor(a);
  PlaceCamera(ren, 1.0, 0, 0, 3.2, 0.0, ren->GetActiveCamera()->GetParallelProjection());
}
}

int TestLightingExtremes(int, char*[])
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int model = 0; model <= 2; ++model)
  {
    for (bool parallel : { false, true })
    {
      Buffers b;
      // beta = 0: pow(0, 0) must not produce NaN.
      RenderBuffers(
        model, parallel, [](vtkRenderer* r, vtkStylizeLightingPass*) { AddSphere(r, 0.0, 1.0); }, b,
        "specular power 0");
      // Zero-length and NaN normals fall back to the facet normal.
      RenderBuffers(
        model, parallel,
        [](vtkRenderer* r, vtkStylizeLightingPass*) { AddBadNormalsSurface(r, 0.0); }, b,
        "zero-length normals");
      STYLIZE_CHECK(SurfacePixels(b) > 1000, "zero-length normals: surface not rendered");
      RenderBuffers(
        model, parallel,
        [&](vtkRenderer* r, vtkStylizeLightingPass*) { AddBadNormalsSurface(r, nan); }, b,
        "NaN normals");
      STYLIZE_CHECK(SurfacePixels(b) > 1000, "NaN normals: surface not rendered");
      // 0 and 1000 lights.
      RenderBuffers(
        model, parallel,
        [](vtkRenderer* r, vtkStylizeLightingPass*)
        {
          AddSphere(r);
          SetupLights(r, "none");
        },
        b, "no lights");
      RenderBuffers(
        model, parallel,
        [](vtkRenderer* r, vtkStylizeLightingPass*)
        {
          AddSphere(r);
          SetupLights(r, "many:1000");
        },
        b, "1000 lights");
      // Scene scaled by 1e-6 and 1e6 with lights scaled alike: finite, and the same picture.
      Buffers ref;
      RenderBuffers(
        model, parallel, [](vtkRenderer* r, vtkStylizeLightingPass*) { KitScene(r, 1.0); }, ref,
        "scale 1");
      for (double scale : { 1e-6, 1e6 })
      {
        RenderBuffers(
          model, parallel, [scale](vtkRenderer* r, vtkStylizeLightingPass*) { KitScene(r, scale); },
          b, scale < 1 ? "scale 1e-6" : "scale 1e6");
        StrictCompare(b.Image, ref.Image, 2, 0.0, 2,
          std::string("scale ") + (scale < 1 ? "1e-6" : "1e6") + " vs 1, " +
            vtkStylizeLightingPass::GetModelName(model) +
            (parallel ? " parallel" : " perspective"));
      }
      // Near/far ratio 1e7.
      RenderBuffers(
        model, parallel,
        [](vtkRenderer* r, vtkStylizeLightingPass*)
        {
          KitScene(r, 1.0);
          SetNearFarRatio(r, 1e-7);
        },
        b, "near/far 1e-7");
      STYLIZE_CHECK(SurfacePixels(b) > 1000, "near/far 1e7: surface not rendered");
    }
  }

  // pd = 0 gives black: Comic with zero gray levels, no ambient and no specular.
  {
    Buffers b;
    RenderBuffers(
      vtkStylizeLightingPass::COMIC, false,
      [](vtkRenderer* r, vtkStylizeLightingPass* l)
      {
        AddSphere(r, 20, 0.0, 0.0);
        l->SetSubjectFactor(0.0);
        l->SetGrayLevelsNear(0);
        l->SetGrayLevelsFar(0);
      },
      b, "comic pd = 0");
    double brightest = 0;
    for (vtkIdType i = 0; i < b.Color->GetNumberOfTuples(); ++i)
    {
      if (b.Normal->GetComponent(i, 3) == 1.0)
      {
        for (int c = 0; c < 3; ++c)
        {
          brightest = std::max(brightest, static_cast<double>(b.Color->GetComponent(i, c)));
        }
      }
    }
    std::printf("comic pd = 0: brightest surface value %g\n", brightest);
    STYLIZE_CHECK(brightest == 0.0, "pd = 0 is not black: %g", brightest);
    STYLIZE_CHECK(SurfacePixels(b) > 1000, "pd = 0: no surface");
  }
  // Setters clamp.
  {
    vtkNew<vtkStylizeLightingPass> l;
    l->SetSubjectFactor(7);
    l->SetGrayLevelsNear(-3);
    l->SetGrayLevelsFar(1e9);
    l->SetSpecularGain(-1);
    l->SetScattering(2);
    l->SetSpecularOcclusion(-5);
    l->SetModel(42);
    STYLIZE_CHECK(l->GetSubjectFactor() == 1.0 && l->GetGrayLevelsNear() == 0.0 &&
        l->GetGrayLevelsFar() == 100.0 && l->GetSpecularGain() == 0.0 &&
        l->GetScattering() == 1.0 && l->GetSpecularOcclusion() == 0.0 &&
        l->GetModel() == vtkStylizeLightingPass::PIXEL_ART,
      "setters do not clamp");
    vtkNew<vtkActor> a;
    vtkStylizeLightingPass::SetActorSubjectFactor(a, nan);
    STYLIZE_CHECK(a->GetPropertyKeys()->Get(vtkStylizeLightingPass::SUBJECT_FACTOR()) == 0.0,
      "NaN per-actor value not clamped");
  }
  return stylizetest::Failures == 0 ? 0 : 1;
}
