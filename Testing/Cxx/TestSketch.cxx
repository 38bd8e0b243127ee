// vtkSketchPass: regression images of the directions, the strokes, the tone and the sketch with
// its options; the noise textures against their definitions; the extremes (umbilic and planar
// surfaces, a cylinder through the near plane, scales 1e-6 and 1e6, lines and points, no
// lights, a 1x1 window, out-of-range settings): no NaN or Inf, no pixel without a direction.
#include "vtkAlgorithmOutput.h"
#include "vtkClipPolyData.h"
#include "vtkPlane.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkReverseSense.h"
#include "vtkSketchPass.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizePrincipalCurvatures.h"
#include "vtkStylizeTestUtilities.h"

#include <limits>

using namespace stylizetest;

namespace
{
constexpr int W = 400, H = 300;
using Configure = std::function<void(vtkRenderer*, vtkSketchPass*)>;

/** Puts vtkStylizePrincipalCurvatures behind every actor's mapper (model-space directions). */
void AddCurvatureArrays(vtkRenderer* ren)
{
  ForEachActor(ren,
    [](vtkActor* a)
    {
      vtkMapper* m = a->GetMapper();
      vtkNew<vtkStylizePrincipalCurvatures> filter;
      filter->SetInputConnection(m->GetInputConnection(0, 0));
      m->SetInputConnection(filter->GetOutputPort());
    });
}

/** Surface pixels whose resolved direction is missing or not unit length; all non-finite. */
void CheckField(vtkSketchPass* pass, const std::string& tag, bool expectSurface)
{
  vtkNew<vtkFloatArray> field;
  STYLIZE_CHECK(pass->DownloadDirections(field), "%s: no direction field", tag.c_str());
  CheckFinite(field, tag + " direction field");
  vtkIdType surface = 0, undefined = 0;
  for (vtkIdType i = 0; i < field->GetNumberOfTuples(); ++i)
  {
    const float* v = field->GetPointer(4 * i);
    if (v[3] > 0.0f)
    {
      ++surface;
      const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      undefined += std::abs(len - 1.0) < 1e-2 ? 0 : 1;
    }
  }
  std::printf("%-52s %lld surface pixels, %lld without a direction\n", tag.c_str(),
    static_cast<long long>(surface), static_cast<long long>(undefined));
  STYLIZE_CHECK(undefined == 0, "%s: %lld surface pixels without a direction", tag.c_str(),
    static_cast<long long>(undefined));
  STYLIZE_CHECK(!expectSurface || surface > 0, "%s: no surface pixels", tag.c_str());
}
}

int TestSketchRegression(int argc, char* argv[])
{
  using P = vtkSketchPass;
  const std::map<std::string, Configure> variants = {
    { "sketch", nullptr },
    { "directions", [](vtkRenderer*, P* p) { p->SetLayer(P::DIRECTIONS); } },
    { "strokes", [](vtkRenderer*, P* p) { p->SetLayer(P::STROKES); } },
    { "tone", [](vtkRenderer*, P* p) { p->SetLayer(P::TONE); } },
    { "perlin", [](vtkRenderer*, P* p) { p->SetNoise(P::PERLIN); } },
    { "worley", [](vtkRenderer*, P* p) { p->SetNoise(P::WORLEY); } },
    { "sparse", [](vtkRenderer*, P* p) { p->SetNoise(P::SPARSE); } },
    { "bisector", [](vtkRenderer*, P* p) { p->SetDirection(P::BISECTOR); } },
    { "minimum", [](vtkRenderer*, P* p) { p->SetDirection(P::MINIMUM); } },
    { "neighbors-2",
      [](vtkRenderer*, P* p)
      {
        p->SetNeighbors(2);
        p->SetLayer(P::DIRECTIONS);
      } },
    { "model",
      [](vtkRenderer* r, P* p)
      {
        AddCurvatureArrays(r);
        p->SetDirectionSource(P::MODEL);
      } },
    { "model-directions",
      [](vtkRenderer* r, P* p)
      {
        AddCurvatureArrays(r);
        p->SetDirectionSource(P::MODEL);
        p->SetLayer(P::DIRECTIONS);
      } },
    { "screen-lic", [](vtkRenderer*, P* p) { p->SetLicMode(P::SCREEN_2D); } },
    { "screen-noise", [](vtkRenderer*, P* p) { p->SetNoiseSpace(P::SCREEN_SPACE); } },
    { "long-strokes",
      [](vtkRenderer*, P* p)
      {
        p->SetStepLength(4);
        p->SetSteps(16);
      } },
    { "high-contrast",
      [](vtkRenderer*, P* p)
      {
        p->SetContrast(2.0);
        p->SetBlurStride(6);
        p->SetBrightThresholds(0.6, 0.8);
      } },
    { "no-cross", [](vtkRenderer*, P* p) { p->CrossHatchingOff(); } },
    { "tinted",
      [](vtkRenderer*, P* p)
      {
        p->TintedOn();
        p->SetPencilColor(0.2, 0.1, 0.3);
      } },
    { "kit-lights", [](vtkRenderer* r, P*) { SetupLights(r, "kit"); } },
  };
  // Besides the image: every surface pixel has a unit direction.
  return RunStyleVariant<P>(argc, argv, "TestSketchRegression", variants, W, H, nullptr,
    [](P* pass, const std::string& name) { CheckField(pass, "sketch." + name, true); });
}

// The noise textures: finite values in [0, 1], periodic, with the statistics of their kind.
int TestSketchNoise(int, char*[])
{
  const int n = 32;
  for (int kind :
    { vtkSketchPass::WHITE, vtkSketchPass::PERLIN, vtkSketchPass::WORLEY, vtkSketchPass::SPARSE })
  {
    vtkNew<vtkFloatArray> noise;
    vtkSketchPass::GenerateNoise(kind, n, noise);
    STYLIZE_CHECK(noise->GetNumberOfTuples() == n * n * n, "noise %d: size", kind);
    CheckFinite(noise, "noise " + std::to_string(kind));
    double lo = 1e30, hi = -1e30, sum = 0, sum2 = 0;
    for (vtkIdType i = 0; i < noise->GetNumberOfTuples(); ++i)
    {
      const double v = noise->GetValue(i);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      sum += v;
      sum2 += v * v;
    }
    const double mean = sum / noise->GetNumberOfTuples();
    const double sd = std::sqrt(sum2 / noise->GetNumberOfTuples() - mean * mean);
    // Mean absolute difference of neighbours, inside and across the period's seam (x).
    auto at = [&](int x, int y, int z) { return noise->GetValue((z * n + y) * n + x); };
    double inside = 0, seam = 0;
    for (int z = 0; z < n; ++z)
    {
      for (int y = 0; y < n; ++y)
      {
        inside += std::abs(at(n / 2, y, z) - at(n / 2 - 1, y, z));
        seam += std::abs(at(0, y, z) - at(n - 1, y, z));
      }
    }
    inside /= n * n;
    seam /= n * n;
    std::printf("noise %d: range [%.3f, %.3f], mean %.3f, sd %.3f, neighbour difference %.3f "
                "inside, %.3f across the seam\n",
      kind, lo, hi, mean, sd, inside, seam);
    STYLIZE_CHECK(lo >= 0.0 && hi <= 1.0, "noise %d: out of [0, 1]", kind);
    STYLIZE_CHECK(seam < 1.5 * inside + 0.01, "noise %d: not periodic", kind);
    if (kind == vtkSketchPass::SPARSE)
    {
      // paper (1) with dark dots (0) on 5% of the texels
      long long other = 0;
      for (vtkIdType i = 0; i < noise->GetNumberOfTuples(); ++i)
      {
        const float v = noise->GetValue(i);
        other += (v == 0.0f || v == 1.0f) ? 0 : 1;
      }
      STYLIZE_CHECK(other == 0 && std::abs((1.0 - mean) - 0.05) < 0.005,
        "sparse noise: %lld values neither 0 nor 1, dots on %.4f of the texels", other, 1.0 - mean);
    }
    else if (kind == vtkSketchPass::WHITE)
    {
      STYLIZE_CHECK(std::abs(mean - 0.5) < 0.01 && std::abs(sd - std::sqrt(1.0 / 12.0)) < 0.01,
        "white noise: mean %.3f sd %.3f", mean, sd);
    }
    else
    {
      // smooth noises: neighbours close, compared with white noise (about 1/3)
      STYLIZE_CHECK(inside < 0.15, "noise %d: not smooth (%.3f)", kind, inside);
    }
  }
  return Failures == 0 ? 0 : 1;
}

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

// MINIMUM and MAXIMUM mean the same in SCREEN and MODEL mode: by absolute curvature, along and
// around a cylinder, whether it is seen from outside (convex) or from inside (concave, normals
// towards the viewer, where the signed minimum curvature runs around it). The share of surface
// pixels whose direction is within 20 degrees of the expected one must be at least 90%.
int TestSketchCylinders(int, char*[])
{
  using P = vtkSketchPass;
  for (bool concave : { false, true })
  {
    for (int source : { P::SCREEN, P::MODEL })
    {
      for (int direction : { P::MINIMUM, P::MAXIMUM })
      {
        vtkNew<vtkCylinderSource> cylinder; // axis along y
        cylinder->SetRadius(2.0);
        cylinder->SetHeight(6.0);
        cylinder->SetResolution(256);
        cylinder->CappingOff();
        vtkSmartPointer<vtkPolyDataAlgorithm> surface = cylinder;
        vtkNew<vtkClipPolyData> clip; // the half at z < 0: a trough seen from +z
        vtkNew<vtkReverseSense> inward;
        if (concave)
        {
          vtkNew<vtkPlane> plane;
          plane->SetNormal(0, 0, -1);
          clip->SetInputConnection(cylinder->GetOutputPort());
          clip->SetClipFunction(plane);
          inward->SetInputConnection(clip->GetOutputPort());
          inward->ReverseCellsOn();
          inward->ReverseNormalsOn();
          surface = inward;
        }
        vtkNew<vtkStylizePrincipalCurvatures> curvatures;
        curvatures->SetInputConnection(surface->GetOutputPort());
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputConnection(curvatures->GetOutputPort());
        vtkNew<vtkActor> actor;
        actor->SetMapper(mapper);
        auto window = MakeWindow(240, 180);
        vtkNew<vtkRenderer> ren;
        window->AddRenderer(ren);
        ren->SetBackground(1, 1, 1);
        ren->AddActor(actor);
        vtkCamera* cam = ren->GetActiveCamera();
        cam->SetFocalPoint(0, 0, concave ? -1.0 : 0.0);
        cam->SetPosition(0, 0, 12);
        cam->SetViewUp(0, 1, 0);
        cam->SetViewAngle(30);
        ren->ResetCameraClippingRange();
        vtkNew<P> pass;
        pass->SetDirectionSource(source);
        pass->SetDirection(direction);
        ren->SetPass(pass);
        window->Render();
        vtkNew<vtkFloatArray> field;
        const std::string tag = std::string(concave ? "concave" : "convex") + " cylinder, " +
          (source == P::SCREEN ? "screen" : "model") + " mode, " +
          (direction == P::MINIMUM ? "MINIMUM" : "MAXIMUM");
        STYLIZE_CHECK(pass->DownloadDirections(field), "%s: no field", tag.c_str());
        // View space is world space turned by nothing here: the axis is view y.
        vtkIdType surfacePixels = 0, expected = 0;
        const double cos20 = std::cos(vtkMath::RadiansFromDegrees(20.0));
        for (vtkIdType i = 0; i < field->GetNumberOfTuples(); ++i)
        {
          const float* v = field->GetPointer(4 * i);
          if (!(v[3] > 0.0f))
          {
            continue;
          }
          ++surfacePixels;
          const double along = std::abs(v[1]) /
            std::max(
              1e-12, std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]));
          const bool ok = direction == P::MINIMUM
            ? along > cos20
            : along < std::sin(vtkMath::RadiansFromDegrees(20.0));
          expected += ok ? 1 : 0;
        }
        const double share = surfacePixels ? double(expected) / surfacePixels : 0.0;
        std::printf("%-44s %6lld surface pixels, %5.1f%% %s\n", tag.c_str(),
          static_cast<long long>(surfacePixels), 100.0 * share,
          direction == P::MINIMUM ? "along the axis" : "around it");
        STYLIZE_CHECK(surfacePixels > 5000, "%s: too few surface pixels", tag.c_str());
        STYLIZE_CHECK(share >= 0.9, "%s: %.1f%% of the pixels in the expected direction",
          tag.c_str(), 100.0 * share);
        window->Finalize();
      }
    }
  }
  return Failures == 0 ? 0 : 1;
}
