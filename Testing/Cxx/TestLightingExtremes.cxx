// Extremes, checked in the float G-buffer (full precision) and not only in the 8-bit image:
// pd = 0, beta = 0, zero-length and NaN normals, 0 and 1000 lights, scene scaled by 1e-6 and
// 1e6, near/far ratio 1e7, parallel and perspective projection: no NaN or Inf anywhere.
#include "vtkCellArray.h"
#include "vtkInformation.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeTestUtilities.h"
#include <limits>

using namespace stylizetest;

namespace
{
struct Buffers
{
  vtkNew<vtkFloatArray> Color, Normal, Position, Depth;
  vtkSmartPointer<vtkImageData> Image;
};

using SceneBuilder = std::function<void(vtkRenderer*, vtkStylizeLightingPass*)>;

void Render(int model, bool parallel, const SceneBuilder& build, Buffers& out,
  const std::string& what, int w = 200, int h = 160)
{
  auto win = MakeWindow(w, h);
  vtkNew<vtkRenderer> ren;
  win->AddRenderer(ren);
  ren->SetBackground(0.3, 0.3, 0.3);
  vtkNew<vtkStylizeLightingPass> lighting;
  lighting->SetModel(model);
  vtkNew<vtkStylizeGBufferPass> gbuffer;
  gbuffer->SetLightingPass(lighting);
  gbuffer->SetChannels(vtkStylizeGBufferPass::NORMAL | vtkStylizeGBufferPass::POSITION);
  gbuffer->SetPrecision(vtkStylizeGBufferPass::FULL);
  ren->SetPass(gbuffer);
  ren->GetActiveCamera()->SetParallelProjection(parallel);
  build(ren, lighting);
  win->Render();
  gbuffer->DownloadChannel(vtkStylizeGBufferPass::COLOR_BUFFER, out.Color);
  gbuffer->DownloadChannel(vtkStylizeGBufferPass::NORMAL_BUFFER, out.Normal);
  gbuffer->DownloadChannel(vtkStylizeGBufferPass::POSITION_BUFFER, out.Position);
  gbuffer->DownloadChannel(vtkStylizeGBufferPass::DEPTH_BUFFER, out.Depth);
  out.Image = Capture(win);
  win->Finalize();
  const std::string tag = what + " [" + vtkStylizeLightingPass::GetModelName(model) +
    (parallel ? ", parallel]" : ", perspective]");
  bool ok = CheckFinite(out.Color, tag + " colour");
  ok = CheckFinite(out.Normal, tag + " normal") && ok;
  ok = CheckFinite(out.Position, tag + " position") && ok;
  ok = CheckFinite(out.Depth, tag + " depth") && ok;
  // Every surface sample carries a unit normal.
  vtkIdType surface = 0, badNormals = 0;
  for (vtkIdType i = 0; i < out.Normal->GetNumberOfTuples(); ++i)
  {
    double n[4];
    out.Normal->GetTuple(i, n);
    if (n[3] == 1.0)
    {
      ++surface;
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      badNormals += std::abs(len - 1.0) > 1e-3 ? 1 : 0;
    }
  }
  STYLIZE_CHECK(
    badNormals == 0, "%s: %lld non-unit normals", tag.c_str(), static_cast<long long>(badNormals));
  std::printf("%-44s surface pixels %6lld, non-finite: none%s\n", tag.c_str(),
    static_cast<long long>(surface), ok ? "" : " (FAILED)");
}

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
      Render(
        model, parallel, [](vtkRenderer* r, vtkStylizeLightingPass*) { AddSphere(r, 0.0, 1.0); }, b,
        "specular power 0");
      // Zero-length and NaN normals fall back to the facet normal.
      Render(
        model, parallel,
        [](vtkRenderer* r, vtkStylizeLightingPass*) { AddBadNormalsSurface(r, 0.0); }, b,
        "zero-length normals");
      STYLIZE_CHECK(SurfacePixels(b) > 1000, "zero-length normals: surface not rendered");
      Render(
        model, parallel,
        [&](vtkRenderer* r, vtkStylizeLightingPass*) { AddBadNormalsSurface(r, nan); }, b,
        "NaN normals");
      STYLIZE_CHECK(SurfacePixels(b) > 1000, "NaN normals: surface not rendered");
      // 0 and 1000 lights.
      Render(
        model, parallel,
        [](vtkRenderer* r, vtkStylizeLightingPass*)
        {
          AddSphere(r);
          SetupLights(r, "none");
        },
        b, "no lights");
      Render(
        model, parallel,
        [](vtkRenderer* r, vtkStylizeLightingPass*)
        {
          AddSphere(r);
          SetupLights(r, "many:1000");
        },
        b, "1000 lights");
      // Scene scaled by 1e-6 and 1e6 with lights scaled alike: finite, and the same picture.
      Buffers ref;
      Render(
        model, parallel, [](vtkRenderer* r, vtkStylizeLightingPass*) { KitScene(r, 1.0); }, ref,
        "scale 1");
      for (double scale : { 1e-6, 1e6 })
      {
        Render(
          model, parallel, [scale](vtkRenderer* r, vtkStylizeLightingPass*) { KitScene(r, scale); },
          b, scale < 1 ? "scale 1e-6" : "scale 1e6");
        StrictCompare(b.Image, ref.Image, 2, 0.0, 2,
          std::string("scale ") + (scale < 1 ? "1e-6" : "1e6") + " vs 1, " +
            vtkStylizeLightingPass::GetModelName(model) +
            (parallel ? " parallel" : " perspective"));
      }
      // Near/far ratio 1e7.
      Render(
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
    Render(
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
