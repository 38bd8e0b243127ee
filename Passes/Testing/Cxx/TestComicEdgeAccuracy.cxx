#include "ComicTestHelpers.h"
#include "vtkComicPass.h"
#include <algorithm>

using namespace stylizetest;

namespace
{
/**
 * F-score of the edge layer (e < 0.5) against an analytic silhouette given as circles in pixel
 * coordinates (centre x, y, radius), with a tolerance of 1 pixel beyond the pixel's half-diagonal.
 */
struct Circle
{
  double X, Y, R;
};

double FScore(vtkImageData* edges, const std::vector<Circle>& circles, int w, int h,
  double* precisionOut, double* recallOut)
{
  const double tol = 1.0 + 0.5;
  std::vector<unsigned char> detected(static_cast<size_t>(w) * h);
  vtkIdType nDetected = 0, nCorrect = 0;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const vtkIdType i = static_cast<vtkIdType>(y) * w + x;
      detected[i] = Gray(edges, i) < 128 ? 1 : 0;
      if (!detected[i])
      {
        continue;
      }
      ++nDetected;
      double best = 1e30;
      for (const Circle& c : circles)
      {
        best = std::min(best, std::abs(std::hypot(x + 0.5 - c.X, y + 0.5 - c.Y) - c.R));
      }
      nCorrect += best <= tol ? 1 : 0;
    }
  }
  vtkIdType nSamples = 0, nFound = 0;
  for (const Circle& c : circles)
  {
    const int n = static_cast<int>(2 * vtkMath::Pi() * c.R) + 1;
    for (int k = 0; k < n; ++k)
    {
      const double px = c.X + c.R * std::cos(2 * vtkMath::Pi() * k / n);
      const double py = c.Y + c.R * std::sin(2 * vtkMath::Pi() * k / n);
      ++nSamples;
      bool found = false;
      for (int dy = -2; dy <= 2 && !found; ++dy)
      {
        for (int dx = -2; dx <= 2 && !found; ++dx)
        {
          const int x = static_cast<int>(std::floor(px)) + dx;
          const int y = static_cast<int>(std::floor(py)) + dy;
          if (x >= 0 && y >= 0 && x < w && y < h && detected[static_cast<size_t>(y) * w + x] &&
            std::hypot(x + 0.5 - px, y + 0.5 - py) <= tol)
          {
            found = true;
          }
        }
      }
      nFound += found ? 1 : 0;
    }
  }
  const double precision = nDetected ? static_cast<double>(nCorrect) / nDetected : 0.0;
  const double recall = nSamples ? static_cast<double>(nFound) / nSamples : 0.0;
  *precisionOut = precision;
  *recallOut = recall;
  return precision + recall > 0 ? 2 * precision * recall / (precision + recall) : 0.0;
}
}

// Edge accuracy: F-score of the edge layer against the analytic silhouettes of a sphere and of a
// torus seen along its axis, at three resolutions and three scene scales.
int TestComicEdgeAccuracy(int, char*[])
{
  const double viewAngle = 30.0;
  const double distance = 6.0;
  double worst = 1.0;
  std::printf("| object | resolution | scale | edges | precision | recall | F |\n");
  std::printf("| --- | --- | ---: | --- | ---: | ---: | ---: |\n");
  for (int object = 0; object < 2; ++object)
  {
    for (int h : { 240, 480, 960 })
    {
      const int w = h * 4 / 3;
      for (double scale : { 1e-3, 1.0, 1e3 })
      {
        for (int weights = 0; weights < 2; ++weights)
        {
          auto win = MakeWindow(w, h);
          vtkNew<vtkRenderer> ren;
          win->AddRenderer(ren);
          ren->SetBackground(1, 1, 1);
          vtkNew<vtkPolyDataMapper> m;
          const double R = 1.0, r = 0.35;
          if (object == 0)
          {
            vtkNew<vtkSphereSource> s;
            s->SetRadius(R * scale);
            s->SetThetaResolution(256);
            s->SetPhiResolution(128);
            m->SetInputConnection(s->GetOutputPort());
            m->Update();
          }
          else
          {
            vtkNew<vtkParametricTorus> t;
            t->SetRingRadius(R * scale);
            t->SetCrossSectionRadius(r * scale);
            vtkNew<vtkParametricFunctionSource> src;
            src->SetParametricFunction(t);
            src->SetUResolution(256);
            src->SetVResolution(96);
            src->SetScalarModeToNone();
            m->SetInputConnection(src->GetOutputPort());
            m->Update();
          }
          vtkNew<vtkActor> a;
          a->SetMapper(m);
          ren->AddActor(a);
          vtkCamera* cam = ren->GetActiveCamera();
          cam->SetFocalPoint(0, 0, 0);
          cam->SetPosition(0, 0, distance * scale);
          cam->SetViewUp(0, 1, 0);
          cam->SetViewAngle(viewAngle);
          ren->ResetCameraClippingRange();
          vtkNew<vtkComicPass> comic;
          comic->SetReferenceHeight(h);
          comic->SetLayer(vtkComicPass::EDGES);
          if (weights == 1)
          {
            comic->SetEdgeWeights(1, 1, 0);
          }
          ren->SetPass(comic);
          win->Render();
          auto img = Capture(win);
          win->Finalize();

          // Analytic silhouettes in pixels: focal length f = (h/2) / tan(angle/2).
          const double f = 0.5 * h / std::tan(vtkMath::RadiansFromDegrees(viewAngle) * 0.5);
          std::vector<Circle> circles;
          if (object == 0)
          {
            // cone tangent to the sphere: half-angle asin(R/D)
            circles.push_back({ 0.5 * w, 0.5 * h, f * std::tan(std::asin(R / distance)) });
          }
          else
          {
            // tube circle at rho = R, z = 0 seen from (0, D): tangent rays at atan(R/D) +-
            // asin(r/L)
            const double a0 = std::atan(R / distance);
            const double b = std::asin(r / std::hypot(R, distance));
            circles.push_back({ 0.5 * w, 0.5 * h, f * std::tan(a0 + b) });
            circles.push_back({ 0.5 * w, 0.5 * h, f * std::tan(a0 - b) });
          }
          double p, rc;
          const double F = FScore(img, circles, w, h, &p, &rc);
          std::printf("| %s | %dx%d | %g | %s | %.3f | %.3f | %.3f |\n",
            object == 0 ? "sphere" : "torus", w, h, scale,
            weights == 0 ? "all (1/3 each)" : "depth+normal", p, rc, F);
          worst = std::min(worst, F);
          STYLIZE_CHECK(F >= 0.9, "F-score %.3f < 0.9", F);
          // The metric must be able to fail: silhouettes 3 pixels off score low.
          std::vector<Circle> shifted = circles;
          for (Circle& c : shifted)
          {
            c.R += 3.0;
          }
          double ps, rs;
          const double Fs = FScore(img, shifted, w, h, &ps, &rs);
          STYLIZE_CHECK(Fs < 0.3, "F-score against circles 3 px off is %.3f", Fs);
        }
      }
    }
  }
  std::printf("lowest F-score: %.3f\n", worst);
  return stylizetest::Failures == 0 ? 0 : 1;
}
