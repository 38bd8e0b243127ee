// vtkStylizeCurvatureAccuracy: the accuracy and time of vtkStylizePrincipalCurvatures' tensor
// smoothing (SmoothingRadius) by its cell size (SmoothingCellSize; 0: every neighbour on its
// own) on analytic surfaces at rising resolution: the error against the analytic curvatures
// and directions, the difference from the exact (cell size 0) result, and the time.
//
//   vtkStylizeCurvatureAccuracy [--markdown FILE] [--quick] [--check]
//
// --quick: the coarser meshes only; --check: exit 1 unless the default cell size (0.2) is as
// accurate as exact against the analytic values (the bounds below), and the result does not
// depend on the thread count. The checked-in study is
// Testing/Benchmark/results/curvature-accuracy.md.
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStylizeAnalyticSurfaces.h"
#include "vtkStylizePrincipalCurvatures.h"
#include "vtkTimerLog.h"

#include <algorithm>
#include <array>
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
double Percentile(std::vector<double> v, double q)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * (v.size() - 1) + 0.5))];
}

/** Angle in degrees between two lines (directions modulo pi); 0 when either is zero. */
double LineAngle(const double a[3], const double b[3])
{
  const double n = vtkMath::Norm(a) * vtkMath::Norm(b);
  if (!(n > 0.0))
  {
    return 0.0;
  }
  const double c = std::abs(vtkMath::Dot(a, b)) / n;
  return vtkMath::DegreesFromRadians(std::acos(std::min(1.0, c)));
}

struct Run
{
  vtkSmartPointer<vtkPolyData> Out;
  double Seconds = 0.0;
};

/** The filter's output and its best time of `repeat` runs (one when a run takes over 5 s). */
Run Curvatures(vtkPolyData* mesh, double radius, double cell, int repeat)
{
  Run r;
  r.Seconds = 1e300;
  for (int k = 0; k < repeat && (k == 0 || r.Seconds < 5.0); ++k)
  {
    vtkNew<vtkStylizePrincipalCurvatures> filter;
    filter->SetInputData(mesh);
    filter->SetSmoothingRadius(radius);
    filter->SetSmoothingCellSize(cell);
    filter->SetMaximumNeighbors(100000);
    const double t0 = vtkTimerLog::GetUniversalTime();
    filter->Update();
    r.Seconds = std::min(r.Seconds, vtkTimerLog::GetUniversalTime() - t0);
    r.Out = filter->GetOutput();
  }
  return r;
}

struct Surface
{
  std::string Name;
  vtkSmartPointer<vtkPolyData> Mesh;
  std::function<Truth(const double*)> Exact;
  double Scale; // curvature errors are divided by this
};

struct Row
{
  double KMedian, KP95, AMedian, AP95; // against the analytic values (curvature / scale, deg)
  double DK95, DA95;                   // against the exact smoothing: 95th percentiles
  double Seconds;
};

Row Measure(const Surface& s, const Run& run, const Run& exact)
{
  vtkPointData* pd = run.Out->GetPointData();
  vtkPointData* ex = exact.Out->GetPointData();
  vtkDataArray* k[2] = { pd->GetArray("PrincipalCurvatureMax"),
    pd->GetArray("PrincipalCurvatureMin") };
  vtkDataArray* d[2] = { pd->GetArray("PrincipalDirectionMax"),
    pd->GetArray("PrincipalDirectionMin") };
  vtkDataArray* ek[2] = { ex->GetArray("PrincipalCurvatureMax"),
    ex->GetArray("PrincipalCurvatureMin") };
  vtkDataArray* ed = ex->GetArray("PrincipalDirectionMinAbs");
  vtkDataArray* dm = pd->GetArray("PrincipalDirectionMinAbs");
  std::vector<double> kerr, aerr, dk, da;
  for (vtkIdType i = 0; i < run.Out->GetNumberOfPoints(); ++i)
  {
    double x[3];
    run.Out->GetPoint(i, x);
    const Truth t = s.Exact(x);
    if (!t.Use)
    {
      continue;
    }
    const double truthK[2] = { t.K1, t.K2 };
    const std::array<double, 3>* truthD[2] = { &t.D1, &t.D2 };
    for (int c = 0; c < 2; ++c)
    {
      kerr.push_back(std::abs(k[c]->GetComponent(i, 0) - truthK[c]) / s.Scale);
      dk.push_back(std::abs(k[c]->GetComponent(i, 0) - ek[c]->GetComponent(i, 0)) / s.Scale);
      if (vtkMath::Norm(truthD[c]->data()) > 0.0)
      {
        double v[3];
        d[c]->GetTuple(i, v);
        aerr.push_back(LineAngle(v, truthD[c]->data()));
      }
    }
    double a[3], b[3];
    dm->GetTuple(i, a);
    ed->GetTuple(i, b);
    if (vtkMath::Norm(a) > 0.0 && vtkMath::Norm(b) > 0.0)
    {
      da.push_back(LineAngle(a, b));
    }
  }
  return { Percentile(kerr, 0.5), Percentile(kerr, 0.95), Percentile(aerr, 0.5),
    Percentile(aerr, 0.95), Percentile(dk, 0.95), Percentile(da, 0.95), run.Seconds };
}

/** The output arrays of two runs are bit for bit the same. */
bool Identical(vtkPolyData* a, vtkPolyData* b)
{
  vtkPointData* pa = a->GetPointData();
  vtkPointData* pb = b->GetPointData();
  for (int i = 0; i < pa->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* x = pa->GetArray(i);
    vtkDataArray* y = pb->GetArray(x->GetName());
    if (!y || x->GetNumberOfValues() != y->GetNumberOfValues())
    {
      return false;
    }
    for (vtkIdType v = 0; v < x->GetNumberOfValues(); ++v)
    {
      if (x->GetComponent(v / x->GetNumberOfComponents(), v % x->GetNumberOfComponents()) !=
        y->GetComponent(v / y->GetNumberOfComponents(), v % y->GetNumberOfComponents()))
      {
        return false;
      }
    }
  }
  return true;
}

}

int main(int argc, char* argv[])
{
  std::string markdown;
  bool quick = false, check = false;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--markdown") && i + 1 < argc)
    {
      markdown = argv[++i];
    }
    else if (!std::strcmp(argv[i], "--quick"))
    {
      quick = true;
    }
    else if (!std::strcmp(argv[i], "--check"))
    {
      check = true;
    }
    else
    {
      std::fprintf(stderr, "usage: %s [--markdown FILE] [--quick] [--check]\n", argv[0]);
      return 2;
    }
  }
  std::ostringstream table;
  table << "| surface | points | radius | cell | k error median | k error 95% | direction "
           "median (deg) | direction 95% (deg) | k vs exact 95% | direction vs exact 95% (deg) "
           "| seconds |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  bool ok = true;
  const std::vector<int> levels = quick ? std::vector<int>{ 2 } : std::vector<int>{ 1, 2, 4, 8 };
  for (const int level : levels)
  {
    const double R = 2.0, a = 0.6, ax[3] = { 3.0, 2.0, 1.0 };
    std::vector<Surface> surfaces;
    surfaces.push_back({ "torus R=2 a=0.6", TorusMesh(R, a, 96 * level, 48 * level),
      [=](const double* x) { return TorusTruth(R, a, x); }, 1.0 / a });
    surfaces.push_back({ "ellipsoid 3x2x1", EllipsoidMesh(ax, 128 * level, 64 * level),
      [=](const double* x) { return EllipsoidTruth(ax, x); }, 1.0 });
    surfaces.push_back(
      { "cylinder r=1.5, 0.5% noise", NoisyCylinderMesh(1.5, 6.0, 64 * level, 32 * level, 0.005, 7),
        [](const double* x)
        {
          Truth t = CylinderTruth(1.5, x);
          t.Use = t.Use && std::abs(x[2]) < 1.8; // away from the open ends
          return t;
        },
        1.0 / 1.5 });
    for (const Surface& s : surfaces)
    {
      for (const double radius : { 0.01, 0.03 })
      {
        const int repeat = quick ? 1 : 3;
        const Run exact = Curvatures(s.Mesh, radius, 0.0, repeat);
        Row reference{};
        for (const double cell : { 0.0, 0.5, 0.25, 0.2, 0.125 })
        {
          const Run run = cell == 0.0 ? exact : Curvatures(s.Mesh, radius, cell, repeat);
          const Row r = Measure(s, run, exact);
          char line[512];
          std::snprintf(line, sizeof(line),
            "| %s | %lld | %.2f | %s | %.4f | %.4f | %.2f | %.2f | %.4f | %.2f | %.3f |\n",
            s.Name.c_str(), static_cast<long long>(s.Mesh->GetNumberOfPoints()), radius,
            cell == 0.0 ? "exact" : std::to_string(cell).substr(0, 5).c_str(), r.KMedian, r.KP95,
            r.AMedian, r.AP95, r.DK95, r.DA95, r.Seconds);
          table << line;
          std::fputs(line, stdout);
          std::fflush(stdout);
          // The default cell size as accurate as exact against the analytic surface: the
          // curvature errors within 10% (plus 0.001 of the scale), the direction errors within
          // 0.5 degree, at the median and the 95th percentile. (Against exact itself it differs
          // most where the radius is about the point spacing: exact takes a neighbour at the
          // radius or not, the clusters' taper takes it by half.)
          if (cell == 0.0)
          {
            reference = r;
          }
          const auto worse = [](double a, double b) { return a > 1.1 * b + 0.001; };
          if (check && cell == 0.2 &&
            (worse(r.KMedian, reference.KMedian) || worse(r.KP95, reference.KP95) ||
              r.AMedian > reference.AMedian + 0.5 || r.AP95 > reference.AP95 + 0.5))
          {
            std::printf(
              "FAIL: %s radius %.2f: cell 0.2 less accurate than exact\n", s.Name.c_str(), radius);
            ok = false;
          }
        }
      }
    }
    if (check)
    {
      // The same result on 1 thread as on all.
      vtkSMPTools::Initialize(1);
      const Run one = Curvatures(surfaces[0].Mesh, 0.03, 0.2, 1);
      vtkSMPTools::Initialize(0);
      const Run all = Curvatures(surfaces[0].Mesh, 0.03, 0.2, 1);
      if (!Identical(one.Out, all.Out))
      {
        std::printf("FAIL: the result depends on the thread count\n");
        ok = false;
      }
    }
  }
  if (!markdown.empty())
  {
    std::ofstream out(markdown);
    out << "### Curvature smoothing: cell size against exact\n\n" << table.str();
  }
  return ok ? 0 : 1;
}
