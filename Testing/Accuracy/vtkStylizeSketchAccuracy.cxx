// vtkStylizeSketchAccuracy: the sketch pass's accuracy study (issue 5). A program, not a timed
// test; it prints Markdown tables.
//
// 1. Directions: angular error (modulo 180 degrees) of the per-pixel principal direction against
//    the analytic direction on a torus, a cylinder and an ellipsoid, for 2 / 4 / 8 neighbours,
//    smoothing on and off, near and far, parallel and perspective, and for the model-space mode
//    (vtkStylizePrincipalCurvatures' arrays). Median, 95th percentile, and the number of
//    surface pixels left without a direction.
// 2. LIC: SSIM of the stroke layer with 5 / 10 / 20 / 60 steps against 128 steps (same stroke
//    length), with ms per frame; the classic screen-space 2D LIC beside it.
// 3. Blur stride: SSIM of the tone layer with stride 2, 4, 6 against stride 1, with ms per frame.
//
// Options: --size W H (default 1920 1080), --quick (480x270, fewer cases), --check (exit 1 when
// the torus target is missed: 8 neighbours, median <= 5 degrees, 0 undefined pixels),
// --markdown FILE (also write the tables there).
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSketchPass.h"
#include "vtkSmartPointer.h"
#include "vtkStylizeImageMetrics.h"
#include "vtkStylizePrincipalCurvatures.h"
#include "vtkTimerLog.h"
#include "vtkWindowToImageFilter.h"

#include "vtkStylizeAnalyticSurfaces.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

using namespace stylizetest;

namespace
{
struct Surface
{
  std::string Name;
  vtkSmartPointer<vtkPolyData> Mesh; // with normals and the filter's arrays
  std::function<Truth(const double*)> Exact;
};

Surface MakeTorus()
{
  const double R = 2.0, a = 0.6;
  return { "torus R=2 a=0.6", TorusMesh(R, a, 384, 192),
    [=](const double* x) { return TorusTruth(R, a, x); } };
}

Surface MakeCylinder()
{
  const double r = 1.0, h = 4.0;
  return { "cylinder r=1 h=4", CylinderMesh(r, h, 256, 128),
    [=](const double* x) { return CylinderTruth(r, x); } };
}

Surface MakeEllipsoid()
{
  static const double ax[3] = { 3.0, 2.0, 1.0 };
  return { "ellipsoid 3x2x1", EllipsoidMesh(ax, 384, 192),
    [](const double* x) { return EllipsoidTruth(ax, x); } };
}

/** Adds smooth normals and the curvature filter's arrays. */
void Prepare(Surface& s)
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(s.Mesh);
  normals->SplittingOff();
  normals->ConsistencyOn();
  normals->AutoOrientNormalsOn();
  vtkNew<vtkStylizePrincipalCurvatures> curvatures;
  curvatures->SetInputConnection(normals->GetOutputPort());
  curvatures->Update();
  s.Mesh = curvatures->GetOutput();
}

double Percentile(std::vector<double> v, double q)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * (v.size() - 1) + 0.5))];
}

struct Study
{
  int W = 1920, H = 1080;
  bool Quick = false;
  std::ostringstream Out;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkActor> Actor;
  vtkSmartPointer<vtkSketchPass> Pass;

  void Setup()
  {
    this->Window = vtkSmartPointer<vtkRenderWindow>::New();
    this->Window->SetSize(this->W, this->H);
    this->Window->SetMultiSamples(0);
    this->Window->OffScreenRenderingOn();
    this->Renderer = vtkSmartPointer<vtkRenderer>::New();
    this->Renderer->SetBackground(1, 1, 1);
    this->Window->AddRenderer(this->Renderer);
    this->Actor = vtkSmartPointer<vtkActor>::New();
    vtkNew<vtkPolyDataMapper> mapper;
    this->Actor->SetMapper(mapper);
    this->Renderer->AddActor(this->Actor);
    this->Pass = vtkSmartPointer<vtkSketchPass>::New();
    this->Renderer->SetPass(this->Pass);
  }

  void Show(vtkPolyData* mesh)
  {
    vtkPolyDataMapper::SafeDownCast(this->Actor->GetMapper())->SetInputData(mesh);
  }

  /** Far: the whole surface in view, from 35 degrees above. Near: 4x closer. */
  void PlaceCamera(bool parallel, bool near)
  {
    vtkCamera* cam = this->Renderer->GetActiveCamera();
    cam->SetParallelProjection(parallel);
    cam->SetFocalPoint(0, 0, 0);
    cam->SetPosition(0, -1, 0.7);
    cam->SetViewUp(0, 0, 1);
    cam->SetViewAngle(30.0);
    this->Renderer->ResetCamera();
    if (near)
    {
      cam->Dolly(4.0);
      if (parallel)
      {
        cam->SetParallelScale(cam->GetParallelScale() / 4.0);
      }
      this->Renderer->ResetCameraClippingRange();
    }
  }

  struct DirectionResult
  {
    double Median = 0, P95 = 0;
    long Undefined = 0, Compared = 0, Surface = 0;
  };

  /** Renders and compares the resolved field with the truth's direction `which` (1 or 2). */
  DirectionResult Directions(const Surface& s)
  {
    this->Window->Render();
    vtkNew<vtkFloatArray> field;
    DirectionResult r;
    if (!this->Pass->DownloadDirections(field))
    {
      std::printf("could not read the direction field\n");
      return r;
    }
    vtkCamera* cam = this->Renderer->GetActiveCamera();
    const bool parallel = cam->GetParallelProjection() != 0;
    vtkMatrix4x4* p = cam->GetProjectionTransformMatrix(this->Renderer);
    vtkNew<vtkMatrix4x4> inverseView;
    vtkMatrix4x4::Invert(cam->GetViewTransformMatrix(), inverseView);
    std::vector<double> errors;
    const int direction = this->Pass->GetDirection();
    for (int y = 0; y < this->H; ++y)
    {
      for (int x = 0; x < this->W; ++x)
      {
        const float* v = field->GetPointer(4 * (static_cast<vtkIdType>(y) * this->W + x));
        const double d = v[3];
        if (!(d > 0.0))
        {
          continue;
        }
        ++r.Surface;
        const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (!(len > 0.5) || !std::isfinite(len))
        {
          ++r.Undefined;
          continue;
        }
        // The pixel's view position, then world position and direction.
        const double ndc[2] = { (x + 0.5) / this->W * 2.0 - 1.0, (y + 0.5) / this->H * 2.0 - 1.0 };
        double view[4];
        for (int a = 0; a < 2; ++a)
        {
          const double paa = p->GetElement(a, a);
          view[a] = parallel ? (ndc[a] - p->GetElement(a, 3)) / paa
                             : d * (ndc[a] + p->GetElement(a, 2)) / paa;
        }
        view[2] = -d;
        view[3] = 1.0;
        double world[4];
        inverseView->MultiplyPoint(view, world);
        const double dv[4] = { v[0], v[1], v[2], 0.0 };
        double dw[4];
        inverseView->MultiplyPoint(dv, dw);
        const Truth t = s.Exact(world);
        // MAXIMUM: the larger |k|; MINIMUM: the smaller; BISECTOR: halfway.
        std::array<double, 3> ref = std::abs(t.K1) >= std::abs(t.K2) ? t.D1 : t.D2;
        std::array<double, 3> other = std::abs(t.K1) >= std::abs(t.K2) ? t.D2 : t.D1;
        if (direction == vtkSketchPass::MINIMUM)
        {
          std::swap(ref, other);
        }
        if (!t.Use || vtkMath::Norm(ref.data()) == 0.0)
        {
          continue;
        }
        double error;
        auto lineAngle = [&](const std::array<double, 3>& a)
        {
          const double c = std::abs(vtkMath::Dot(dw, a.data())) /
            std::max(1e-300, vtkMath::Norm(dw) * vtkMath::Norm(a.data()));
          return vtkMath::DegreesFromRadians(std::acos(std::min(1.0, c)));
        };
        if (direction == vtkSketchPass::BISECTOR)
        {
          // either bisector of the two lines is right
          std::array<double, 3> b1, b2;
          for (int i = 0; i < 3; ++i)
          {
            b1[i] = ref[i] + other[i];
            b2[i] = ref[i] - other[i];
          }
          error = std::min(lineAngle(b1), lineAngle(b2));
        }
        else
        {
          error = lineAngle(ref);
        }
        errors.push_back(error);
      }
    }
    r.Compared = static_cast<long>(errors.size());
    r.Median = Percentile(errors, 0.5);
    r.P95 = Percentile(errors, 0.95);
    return r;
  }

  vtkSmartPointer<vtkImageData> Grab()
  {
    vtkNew<vtkWindowToImageFilter> w2i;
    w2i->SetInput(this->Window);
    w2i->ReadFrontBufferOff();
    w2i->Update();
    auto img = vtkSmartPointer<vtkImageData>::New();
    img->DeepCopy(w2i->GetOutput());
    return img;
  }

  /** Median ms of `frames` renders (after one warm-up). */
  double Time(int frames)
  {
    this->Window->Render();
    std::vector<double> t;
    for (int i = 0; i < frames; ++i)
    {
      vtkNew<vtkTimerLog> timer;
      timer->StartTimer();
      this->Window->Render();
      this->Renderer->GetRenderWindow()->WaitForCompletion();
      timer->StopTimer();
      t.push_back(1000.0 * timer->GetElapsedTime());
    }
    return Percentile(t, 0.5);
  }
};
}

int main(int argc, char* argv[])
{
  Study study;
  bool check = false;
  std::string markdown;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--size") && i + 2 < argc)
    {
      study.W = std::max(16, std::atoi(argv[++i]));
      study.H = std::max(16, std::atoi(argv[++i]));
    }
    else if (!std::strcmp(argv[i], "--quick"))
    {
      study.Quick = true;
      study.W = 480;
      study.H = 270;
    }
    else if (!std::strcmp(argv[i], "--check"))
    {
      check = true;
    }
    else if (!std::strcmp(argv[i], "--markdown") && i + 1 < argc)
    {
      markdown = argv[++i];
    }
    else
    {
      std::fprintf(
        stderr, "usage: %s [--size W H] [--quick] [--check] [--markdown FILE]\n", argv[0]);
      return 2;
    }
  }
  study.Setup();
  std::ostringstream& out = study.Out;
  int failures = 0;

  // ---- 1. directions
  std::vector<Surface> surfaces = { MakeTorus(), MakeCylinder(), MakeEllipsoid() };
  for (Surface& s : surfaces)
  {
    Prepare(s);
  }
  out << "### Principal directions: angular error against the analytic direction\n\n"
      << study.W << "x" << study.H
      << ", direction MAXIMUM (the larger |curvature|), degrees modulo 180. Scale `2 pt`: "
         "neighbours 2 points apart, no object scale (the estimate's own accuracy); `defaults`: "
         "the pass's (NeighborSpacing 16 points, ObjectScale 1%, chosen for scanned meshes). "
         "Smoothing `off`: "
         "no smoothing radius and no iterations; `defaults`: the pass's (SmoothingRadius 16 "
         "points, SmoothingIterations 2). `undefined`: surface pixels left without a direction "
         "(after fill and fallbacks).\n\n"
      << "| surface | camera | source | scale | neighbours | smoothing | median | 95th pct | "
         "undefined | pixels |\n| --- | --- | --- | --- | ---: | --- | ---: | ---: | ---: | ---: "
         "|\n";
  auto pass = study.Pass;
  vtkNew<vtkSketchPass> defaults; // the pass's default settings, for the "defaults" rows
  pass->SetLayer(vtkSketchPass::DIRECTIONS);
  pass->SetDirection(vtkSketchPass::MAXIMUM);
  for (const Surface& s : surfaces)
  {
    study.Show(s.Mesh);
    for (int cameraCase = 0; cameraCase < 4; ++cameraCase)
    {
      const bool parallel = cameraCase >= 2;
      const bool near = cameraCase % 2 == 1;
      if (study.Quick && s.Name.find("torus") == std::string::npos && cameraCase > 0)
      {
        continue;
      }
      study.PlaceCamera(parallel, near);
      const std::string camera =
        std::string(near ? "near" : "far") + (parallel ? ", parallel" : ", perspective");
      // The fine scale (neighbours 2 points apart, no object scale: the estimate's own
      // accuracy) for every neighbour count, with and without smoothing; then the shipped
      // defaults (16 points, 1% of the object), chosen for scanned meshes.
      struct Case
      {
        int Source, Neighbors, Smoothing;
        bool DefaultScale;
      };
      std::vector<Case> cases;
      for (int n : { 2, 4, 8 })
      {
        for (int smoothing : { 0, 2 })
        {
          cases.push_back({ vtkSketchPass::SCREEN, n, smoothing, false });
        }
      }
      cases.push_back({ vtkSketchPass::SCREEN, 8, 0, true });
      cases.push_back({ vtkSketchPass::SCREEN, 8, 2, true });
      cases.push_back({ vtkSketchPass::MODEL, 8, 0, false });
      for (const Case& c : cases)
      {
        pass->SetNeighborSpacing(c.DefaultScale ? defaults->GetNeighborSpacing() : 2.0);
        pass->SetObjectScale(c.DefaultScale ? defaults->GetObjectScale() : 0.0);
        pass->SetDirectionSource(c.Source);
        pass->SetNeighbors(c.Neighbors);
        // Smoothing off: no pyramid and no iterations; on: the pass's defaults.
        pass->SetSmoothingIterations(c.Smoothing ? defaults->GetSmoothingIterations() : 0);
        pass->SetSmoothingRadius(c.Smoothing ? defaults->GetSmoothingRadius() : 0.0);
        const auto r = study.Directions(s);
        char line[512];
        std::snprintf(line, sizeof(line),
          "| %s | %s | %s | %s | %s | %s | %.2f | %.2f | %ld | %ld |\n", s.Name.c_str(),
          camera.c_str(), c.Source == vtkSketchPass::MODEL ? "model" : "screen",
          c.Source == vtkSketchPass::MODEL ? "-" : (c.DefaultScale ? "defaults" : "2 pt"),
          c.Source == vtkSketchPass::MODEL ? "-" : std::to_string(c.Neighbors).c_str(),
          c.Source == vtkSketchPass::MODEL ? "-" : (c.Smoothing ? "defaults" : "off"), r.Median,
          r.P95, r.Undefined, r.Surface);
        out << line;
        std::printf("%s", line);
        std::fflush(stdout);
        if (r.Undefined != 0)
        {
          ++failures;
        }
        if (check && c.Source == vtkSketchPass::SCREEN && c.Neighbors == 8 && c.Smoothing &&
          s.Name.find("torus") != std::string::npos && !near && !parallel && !(r.Median <= 5.0))
        {
          std::printf("FAIL: torus median %.2f > 5 degrees\n", r.Median);
          ++failures;
        }
        if (check && c.Source == vtkSketchPass::MODEL && !(r.Median <= 1.0))
        {
          std::printf("FAIL: model-space median %.2f > 1 degree\n", r.Median);
          ++failures;
        }
      }
    }
  }
  pass->SetDirectionSource(vtkSketchPass::SCREEN);
  pass->SetNeighbors(8);
  pass->SetSmoothingIterations(defaults->GetSmoothingIterations());
  pass->SetSmoothingRadius(defaults->GetSmoothingRadius());
  pass->SetNeighborSpacing(defaults->GetNeighborSpacing());
  pass->SetObjectScale(defaults->GetObjectScale());

  // ---- 2. LIC steps at a fixed stroke length, near the torus in a wide perspective
  const int frames = study.Quick ? 1 : 3;
  study.Show(surfaces[0].Mesh);
  study.PlaceCamera(false, false);
  study.Renderer->GetActiveCamera()->SetViewAngle(60.0);
  study.Renderer->ResetCamera();
  study.Renderer->GetActiveCamera()->Dolly(1.6);
  study.Renderer->ResetCameraClippingRange();
  pass->SetLayer(vtkSketchPass::STROKES);
  const double strokeLength = 15.0; // points: the default 10 steps of 1.5
  auto licAt = [&](int mode, int steps)
  {
    pass->SetLicMode(mode);
    pass->SetSteps(steps);
    pass->SetStepLength(strokeLength / steps);
    const double ms = study.Time(frames);
    return std::make_pair(study.Grab(), ms);
  };
  auto reference = licAt(vtkSketchPass::PERSPECTIVE, 128);
  out << "\n### LIC: SSIM against 128 perspective-correct steps (stroke length " << strokeLength
      << " points)\n\n"
      << "Torus seen from near with a 60 degree view angle; stroke layer; " << study.W << "x"
      << study.H << ". ms: whole frame, median of " << frames << ".\n\n"
      << "| steps | perspective-correct SSIM | ms | screen-space 2D LIC SSIM | ms |\n"
      << "| ---: | ---: | ---: | ---: | ---: |\n";
  for (int steps : { 5, 10, 20, 60, 128 })
  {
    auto p = licAt(vtkSketchPass::PERSPECTIVE, steps);
    auto c = licAt(vtkSketchPass::SCREEN_2D, steps);
    char line[256];
    std::snprintf(line, sizeof(line), "| %d | %.4f | %.1f | %.4f | %.1f |\n", steps,
      vtkStylizeImageMetrics::SSIM(p.first, reference.first, 255.0), p.second,
      vtkStylizeImageMetrics::SSIM(c.first, reference.first, 255.0), c.second);
    out << line;
    std::printf("%s", line);
    std::fflush(stdout);
  }
  pass->SetLicMode(vtkSketchPass::PERSPECTIVE);
  pass->SetSteps(10);
  pass->SetStepLength(1.5);

  // ---- 3. blur stride
  pass->SetLayer(vtkSketchPass::TONE);
  pass->SetContrast(1.0);
  study.PlaceCamera(false, false);
  auto blurAt = [&](int stride)
  {
    pass->SetBlurStride(stride);
    const double ms = study.Time(frames);
    return std::make_pair(study.Grab(), ms);
  };
  pass->SetContrast(0.0);
  const double noBlurMs = study.Time(frames);
  pass->SetContrast(1.0);
  auto blur1 = blurAt(1);
  out << "\n### Blur stride: SSIM of the tone layer against stride 1\n\n"
      << "Contrast 1, blur radius 36 points (a 73x73 Gaussian at 1080 lines); " << study.W << "x"
      << study.H << "; ms: whole frame (" << noBlurMs << " ms without the blur).\n\n"
      << "| stride | SSIM | ms |\n| ---: | ---: | ---: |\n";
  for (int stride : { 1, 2, 4, 6 })
  {
    auto b = stride == 1 ? blur1 : blurAt(stride);
    char line[128];
    std::snprintf(line, sizeof(line), "| %d | %.4f | %.1f |\n", stride,
      vtkStylizeImageMetrics::SSIM(b.first, blur1.first, 255.0), b.second);
    out << line;
    std::printf("%s", line);
  }
  pass->SetContrast(0.5);
  pass->SetBlurStride(4);

  std::printf("\n%s", out.str().c_str());
  if (!markdown.empty())
  {
    std::ofstream(markdown) << out.str();
  }
  study.Renderer->SetPass(nullptr);
  study.Pass->ReleaseGraphicsResources(study.Window);
  return failures == 0 ? 0 : 1;
}
