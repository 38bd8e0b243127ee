#include "ComicTestHelpers.h"
#include "vtkCamera.h"
#include "vtkComicPass.h"
#include "vtkMath.h"
#include "vtkPlaneSource.h"
#include <algorithm>
#include <cmath>

using namespace stylizetest;

// Patterns anchored to the surface never drawn finer than the pixels can show (issue 52): dots
// and hatching on a floor seen at grazing angles, out to the horizon, and on a facet at 45
// degrees to two coordinate planes seen face on (where the triplanar projection's two planes
// tie). Per pixel, the pattern's frequency on the screen (cycles per pixel) comes from the
// G-buffer's positions projected as the shader projects them; the pattern's amplitude is the
// PATTERN layer against the tone it stands for (the FIGURE_INPUTS layer's red).
// - above Nyquist (frequency > 1/2): no amplitude (its share of the squared amplitude ~ 0);
// - resolved (frequency < 1/3, a cell of three pixels or more): the full pattern, whose mean
//   |pattern - tone| is 2 tone (1 - tone) for ink covering 1 - tone (at least 0.7 of it: the
//   anti-aliased edges take some).
namespace
{
struct Case
{
  const char* Name;
  bool Dots;       // dots, else hatch lines
  bool Facet;      // the 45 degree facet face on, else the floor at grazing angles
  double MinAbove; // pixels above Nyquist the case must have (the floor reaches the horizon)
};

constexpr double Spacing = 8.0; // DotSpacing and HatchSpacing, points = pixels (ReferenceHeight H)

/** The case's scene: one plane actor, the camera, a comic pass set up for the case. */
StyledScene<vtkComicPass> MakeScene(const Case& c)
{
  StyledScene<vtkComicPass> scene;
  scene.Window = MakeWindow(W, H);
  scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
  scene.Window->AddRenderer(scene.Renderer);
  scene.Renderer->SetBackground(1, 1, 1);
  vtkNew<vtkPlaneSource> plane;
  vtkCamera* cam = scene.Renderer->GetActiveCamera();
  cam->SetViewAngle(30.0);
  if (c.Facet)
  {
    // x + y = 0, 6 x 6, seen along -(1, 1, 0) from 10 away
    plane->SetOrigin(3.0 / std::sqrt(2.0), -3.0 / std::sqrt(2.0), -3.0);
    plane->SetPoint1(-3.0 / std::sqrt(2.0), 3.0 / std::sqrt(2.0), -3.0);
    plane->SetPoint2(3.0 / std::sqrt(2.0), -3.0 / std::sqrt(2.0), 3.0);
    cam->SetFocalPoint(0.0, 0.0, 0.0);
    cam->SetPosition(10.0 / std::sqrt(2.0), 10.0 / std::sqrt(2.0), 0.0);
    cam->SetViewUp(0.0, 0.0, 1.0);
    // lit at 60 degrees from its normal: a mid tone (the headlight would light it white)
    scene.Renderer->AutomaticLightCreationOff();
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPosition(3.54, 3.54, 8.66);
    light->SetFocalPoint(0.0, 0.0, 0.0);
    scene.Renderer->AddLight(light);
  }
  else
  {
    // z = 0 out to 300 ahead, the eye 0.6 above it
    plane->SetOrigin(-60.0, -2.0, 0.0);
    plane->SetPoint1(60.0, -2.0, 0.0);
    plane->SetPoint2(-60.0, 300.0, 0.0);
    cam->SetFocalPoint(0.0, 10.0, 0.0);
    cam->SetPosition(0.0, -4.0, 0.6);
    cam->SetViewUp(0.0, 0.0, 1.0);
  }
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.75, 0.75, 0.75);
  actor->GetProperty()->SetSpecular(0.0);
  scene.Renderer->AddActor(actor);
  scene.Renderer->ResetCameraClippingRange();

  scene.Pass = vtkSmartPointer<vtkComicPass>::New();
  vtkComicPass* comic = scene.Pass;
  comic->SetReferenceHeight(H);
  comic->SetAnchorToObject();
  comic->EdgesOff();
  comic->SetDots(c.Dots);
  comic->SetHatching(!c.Dots);
  comic->SetDotSpacing(Spacing);
  comic->SetHatchSpacing(Spacing);
  comic->SetDotAngle(0.0);
  comic->SetHatchAngle(0.0);
  comic->SetHatchDirections(0); // lines along x: across them, the plane's second coordinate
  comic->CrossHatchingOff();
  // one zone everywhere: dots (t = 1 for any tone) or hatching (t = 0 below 1)
  comic->SetBrightThreshold(c.Dots ? 0.0 : 1.0);
  comic->SetDarkThreshold(c.Dots ? 0.0 : 1.0);
  scene.Renderer->SetPass(comic);
  return scene;
}

/**
 * The pattern's frequency at pixel (x, y), cycles per pixel: the plane coordinates' screen
 * gradient (the shader's projection: the facet's tie goes to the yz plane, the floor's plane is
 * xy) divided by the spacing; dots: the larger of the two coordinates', hatch lines: across them
 * (the second coordinate). Negative where there is no surface.
 */
double Frequency(const float* pos, int x, int y, bool facet, bool dots, double spacingWorld)
{
  auto at = [pos](int i, int j) { return pos + 4 * (static_cast<size_t>(j) * W + i); };
  const float* p = at(x, y);
  if (p[3] < 0.5f)
  {
    return -1.0;
  }
  auto project = [facet](const double d[3], double uv[2])
  {
    uv[0] = facet ? d[1] : d[0];
    uv[1] = facet ? d[2] : d[1];
  };
  double grad[2][2]; // grad[coordinate][screen axis]
  for (int a = 0; a < 2; ++a)
  {
    double best[3] = { 0, 0, 0 };
    double bestLength = -1.0;
    for (int sign : { 1, -1 })
    {
      const int i = x + (a == 0 ? sign : 0), j = y + (a == 1 ? sign : 0);
      if (i < 0 || j < 0 || i >= W || j >= H || at(i, j)[3] < 0.5f)
      {
        continue;
      }
      const float* q = at(i, j);
      const double d[3] = { sign * (q[0] - p[0]), sign * (q[1] - p[1]), sign * (q[2] - p[2]) };
      const double length = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      if (bestLength < 0 || length < bestLength)
      {
        std::copy(d, d + 3, best);
        bestLength = length;
      }
    }
    if (bestLength < 0)
    {
      return 1.0e6; // a sliver: the shader treats its step as unbounded
    }
    double uv[2];
    project(best, uv);
    grad[0][a] = uv[0] / spacingWorld;
    grad[1][a] = uv[1] / spacingWorld;
  }
  const double fu = std::hypot(grad[0][0], grad[0][1]);
  const double fv = std::hypot(grad[1][0], grad[1][1]);
  return dots ? std::max(fu, fv) : fv;
}
}

int TestComicGrazing(int argc, char* argv[])
{
  const Args args = ParseArgs(argc, argv);
  const Case cases[] = {
    { "floor-dots", true, false, 2000 },
    { "floor-hatch", false, false, 2000 },
    { "facet-dots", true, true, 0 },
    { "facet-hatch", false, true, 0 },
  };
  std::printf("%-12s %10s %10s %12s %10s %10s %10s\n", "case", "resolved", "above", "above-share",
    "above-max", "resolved", "between");
  std::printf("%-12s %10s %10s %12s %10s %10s %10s\n", "", "pixels", "pixels", "(amp^2)",
    "(levels)", "amplitude", "pixels");
  for (const Case& c : cases)
  {
    auto scene = MakeScene(c);
    vtkComicPass* comic = scene.Pass;
    comic->SetLayer(vtkComicPass::PATTERN);
    scene.Window->Render();
    auto pattern = Capture(scene.Window);
    comic->SetLayer(vtkComicPass::FIGURE_INPUTS);
    scene.Window->Render();
    auto inputs = Capture(scene.Window);
    vtkNew<vtkFloatArray> positions;
    RenderPositions(scene.Renderer, scene.Window, positions);
    vtkCamera* cam = scene.Renderer->GetActiveCamera();
    // the spacing's world length: Spacing pixels at the focal distance (vertical view angle)
    const double spacingWorld = Spacing * cam->GetDistance() * 2.0 *
      std::tan(vtkMath::RadiansFromDegrees(cam->GetViewAngle()) / 2.0) / H;
    WritePNG(pattern, args.TempDir + "/comic-grazing-" + c.Name + ".png");

    const float* pos = positions->GetPointer(0);
    vtkDataArray* ps = pattern->GetPointData()->GetScalars();
    vtkDataArray* is = inputs->GetPointData()->GetScalars();
    double total = 0, above = 0, aboveMax = 0, resolvedAmplitude = 0, resolvedExpected = 0;
    long aboveCount = 0, resolvedCount = 0, betweenCount = 0;
    for (int y = 0; y < H; ++y)
    {
      for (int x = 0; x < W; ++x)
      {
        const vtkIdType i = static_cast<vtkIdType>(y) * W + x;
        const double f = Frequency(pos, x, y, c.Facet, c.Dots, spacingWorld);
        if (f < 0 || is->GetComponent(i, 2) < 128) // no surface
        {
          continue;
        }
        const double tone = is->GetComponent(i, 0) / 255.0;
        const double amplitude = ps->GetComponent(i, 0) / 255.0 - tone;
        total += amplitude * amplitude;
        if (f > 0.5)
        {
          above += amplitude * amplitude;
          aboveMax = std::max(aboveMax, std::abs(amplitude) * 255.0);
          ++aboveCount;
        }
        else if (f < 1.0 / 3.0)
        {
          resolvedAmplitude += std::abs(amplitude);
          resolvedExpected += 2.0 * tone * (1.0 - tone);
          ++resolvedCount;
        }
        else
        {
          ++betweenCount;
        }
      }
    }
    const double share = total > 0 ? above / total : 0.0;
    const double resolved = resolvedExpected > 0 ? resolvedAmplitude / resolvedExpected : 0.0;
    std::printf("%-12s %10ld %10ld %12.2e %10.0f %10.3f %10ld\n", c.Name, resolvedCount, aboveCount,
      share, aboveMax, resolved, betweenCount);
    STYLIZE_CHECK(
      resolvedCount > 20000, "%s: only %ld pixels with a resolved pattern", c.Name, resolvedCount);
    STYLIZE_CHECK(
      aboveCount >= c.MinAbove, "%s: only %ld pixels above Nyquist", c.Name, aboveCount);
    STYLIZE_CHECK(share <= 1.0e-4 && aboveMax <= 3.0,
      "%s: pattern above the Nyquist frequency: %.2e of the squared amplitude, up to %.0f levels",
      c.Name, share, aboveMax);
    STYLIZE_CHECK(
      resolved >= 0.7, "%s: the resolved pattern has %.3f of its amplitude", c.Name, resolved);
    scene.Window->Finalize();
  }
  return Failures == 0 ? 0 : 1;
}
