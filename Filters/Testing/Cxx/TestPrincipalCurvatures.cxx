// vtkStylizePrincipalCurvatures against the analytic principal curvatures and directions of a
// sphere, a cylinder, a torus and an ellipsoid (directions compared modulo pi), at two mesh
// resolutions; plus degenerate input. Prints median, 95th percentile and maximum errors.
#include "vtkCellArray.h"
#include "vtkCleanPolyData.h"
#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSphereSource.h"
#include "vtkStylizeAnalyticSurfaces.h"
#include "vtkStylizeImageMetrics.h"
#include "vtkStylizePrincipalCurvatures.h"
#include "vtkStylizeTestChecks.h"

#include <algorithm>
#include <array>
#include <functional>
#include <limits>

using namespace stylizetest;

namespace
{
struct Errors
{
  std::vector<double> Curvature; // |k - k_true| / scale
  std::vector<double> Angle;     // degrees, modulo 180
};

double Percentile(std::vector<double> v, double q)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * (v.size() - 1) + 0.5))];
}

/** Angle in degrees between two lines (directions modulo pi). */
double LineAngle(const double a[3], const std::array<double, 3>& b)
{
  const double c = std::abs(vtkMath::Dot(a, b.data())) /
    std::max(1e-300, vtkMath::Norm(a) * vtkMath::Norm(b.data()));
  return vtkMath::DegreesFromRadians(std::acos(std::min(1.0, c)));
}

Errors Compare(vtkPolyData* mesh, const std::function<Truth(const double*)>& truth, double scale)
{
  vtkNew<vtkStylizePrincipalCurvatures> filter;
  filter->SetInputData(mesh);
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  vtkDataArray* k1 = out->GetPointData()->GetArray("PrincipalCurvatureMax");
  vtkDataArray* k2 = out->GetPointData()->GetArray("PrincipalCurvatureMin");
  vtkDataArray* d1 = out->GetPointData()->GetArray("PrincipalDirectionMax");
  vtkDataArray* d2 = out->GetPointData()->GetArray("PrincipalDirectionMin");
  Errors e;
  STYLIZE_CHECK(k1 && k2 && d1 && d2, "missing output arrays");
  if (!k1 || !k2 || !d1 || !d2)
  {
    return e;
  }
  for (const char* name :
    { "PrincipalCurvatureMax", "PrincipalCurvatureMin", "PrincipalDirectionMax",
      "PrincipalDirectionMin", "PrincipalDirectionBisector", "PrincipalDirectionMinAbs",
      "PrincipalDirectionMaxAbs", "MeanCurvature", "GaussianCurvature" })
  {
    vtkDataArray* a = out->GetPointData()->GetArray(name);
    STYLIZE_CHECK(a && vtkStylizeImageMetrics::CountNonFinite(a) == 0, "%s: NaN or Inf", name);
  }
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    const Truth t = truth(x);
    if (!t.Use)
    {
      continue;
    }
    e.Curvature.push_back(std::abs(k1->GetComponent(i, 0) - t.K1) / scale);
    e.Curvature.push_back(std::abs(k2->GetComponent(i, 0) - t.K2) / scale);
    if (vtkMath::Norm(t.D1.data()) > 0)
    {
      double a[3], b[3];
      d1->GetTuple(i, a);
      d2->GetTuple(i, b);
      e.Angle.push_back(LineAngle(a, t.D1));
      e.Angle.push_back(LineAngle(b, t.D2));
    }
  }
  return e;
}

void Report(const std::string& name, const Errors& e, double maxMedianK, double maxP95K,
  double maxMedianAngle, double maxP95Angle)
{
  const double mk = Percentile(e.Curvature, 0.5), pk = Percentile(e.Curvature, 0.95);
  const double xk = Percentile(e.Curvature, 1.0);
  std::printf(
    "%-34s curvature error / scale: median %.4f, 95%% %.4f, max %.4f", name.c_str(), mk, pk, xk);
  if (!e.Angle.empty())
  {
    std::printf("; direction error: median %.2f deg, 95%% %.2f deg, max %.2f deg",
      Percentile(e.Angle, 0.5), Percentile(e.Angle, 0.95), Percentile(e.Angle, 1.0));
  }
  std::printf(" (%zu points)\n", e.Curvature.size() / 2);
  STYLIZE_CHECK(e.Curvature.size() > 100, "%s: too few points compared", name.c_str());
  STYLIZE_CHECK(
    mk <= maxMedianK && pk <= maxP95K, "%s: curvature error %.4f / %.4f", name.c_str(), mk, pk);
  if (!e.Angle.empty())
  {
    STYLIZE_CHECK(
      Percentile(e.Angle, 0.5) <= maxMedianAngle && Percentile(e.Angle, 0.95) <= maxP95Angle,
      "%s: direction error %.2f / %.2f deg", name.c_str(), Percentile(e.Angle, 0.5),
      Percentile(e.Angle, 0.95));
  }
}

}

int TestPrincipalCurvatures(int, char*[])
{
  double torusMedian[2] = { 0, 0 };
  for (int level : { 1, 2 })
  {
    const std::string tag = level == 1 ? " (coarse)" : " (fine)";
    // Sphere, radius 2: k1 = k2 = 0.5 (umbilic: no directions).
    {
      vtkNew<vtkSphereSource> s;
      s->SetRadius(2.0);
      s->SetThetaResolution(64 * level);
      s->SetPhiResolution(32 * level);
      auto mesh = CleanMesh(s->GetOutputPort());
      auto e = Compare(
        mesh,
        [](const double*) {
          return Truth{ 0.5, 0.5, { 0, 0, 0 }, { 0, 0, 0 }, true };
        },
        0.5);
      Report("sphere r=2" + tag, e, 0.005, 0.03, 0, 0);
    }
    // Cylinder, radius 1.5: k1 = 1/1.5 around (outward normals), k2 = 0 along the axis.
    {
      const double r = 1.5, h = 6.0;
      auto mesh = CylinderMesh(r, h, 64 * level, 32 * level);
      auto e = Compare(
        mesh,
        [&](const double* x)
        {
          Truth t = CylinderTruth(r, x);
          t.Use = t.Use && std::abs(x[2]) < 0.5 * h - 1e-6; // not the boundary rows
          return t;
        },
        1.0 / r);
      Report("cylinder r=1.5" + tag, e, 0.005, 0.01, 0.5, 1.0);
    }
    // Torus, ring radius R = 2, tube radius a = 0.6 (vtkParametricTorus: ring in the xy plane).
    {
      const double R = 2.0, a = 0.6;
      auto mesh = TorusMesh(R, a, 96 * level, 48 * level);
      auto e = Compare(
        mesh, [&](const double* x) { return TorusTruth(R, a, x); }, 1.0 / a);
      Report("torus R=2 a=0.6" + tag, e, 0.005, 0.01, 0.5, 1.0);
      torusMedian[level - 1] = Percentile(e.Curvature, 0.5);
    }
    // Ellipsoid 3 x 2 x 1: principal curvatures from the implicit surface's shape operator
    // (the Hessian projected on the tangent plane over |grad F|), directions its eigenvectors.
    {
      const double ax[3] = { 3.0, 2.0, 1.0 };
      auto mesh = EllipsoidMesh(ax, 128 * level, 64 * level);
      auto e = Compare(
        mesh, [&](const double* x) { return EllipsoidTruth(ax, x); }, 1.0);
      Report("ellipsoid 3x2x1" + tag, e, 0.005, 0.03, 0.5, 2.0);
    }
  }

  // Scan noise: a fine cylinder (r = 1.5, axis z) with its points moved radially by up to 0.5% of
  // the radius. Each point's own estimate follows the noise; averaged over 5% of the diagonal
  // (SmoothingRadius 0.05) the direction of the smaller |curvature| runs along the axis again.
  {
    const double r = 1.5, h = 6.0;
    auto mesh = NoisyCylinderMesh(r, h, 128, 64, 0.005, 7);
    double p95[2] = { 0, 0 };
    for (int smoothed : { 0, 1 })
    {
      vtkNew<vtkStylizePrincipalCurvatures> filter;
      filter->SetInputData(mesh);
      filter->SetSmoothingRadius(smoothed ? 0.05 : 0.0);
      filter->Update();
      vtkDataArray* along =
        filter->GetOutput()->GetPointData()->GetArray("PrincipalDirectionMinAbs");
      std::vector<double> angles;
      vtkIdType undefined = 0;
      for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
      {
        double x[3], d[3];
        mesh->GetPoint(i, x);
        along->GetTuple(i, d);
        if (std::abs(x[2]) > 0.3 * h) // away from the open ends
        {
          continue;
        }
        if (vtkMath::Norm(d) == 0.0)
        {
          ++undefined;
          angles.push_back(90.0);
          continue;
        }
        angles.push_back(LineAngle(d, { 0.0, 0.0, 1.0 }));
      }
      p95[smoothed] = Percentile(angles, 0.95);
      std::printf("noisy cylinder, SmoothingRadius %.2f: MinAbs direction error median %.2f deg, "
                  "95%% %.2f deg, %lld points without a direction\n",
        smoothed ? 0.05 : 0.0, Percentile(angles, 0.5), p95[smoothed],
        static_cast<long long>(undefined));
    }
    STYLIZE_CHECK(p95[1] < 5.0 && p95[1] < 0.5 * p95[0],
      "noisy cylinder: smoothing does not recover the axis (95%% %.2f -> %.2f deg)", p95[0],
      p95[1]);
  }

  // Second-order convergence: halving the edge length divides the error by about 4.
  STYLIZE_CHECK(torusMedian[1] < 0.4 * torusMedian[0],
    "torus: error does not converge (%.5f -> %.5f)", torusMedian[0], torusMedian[1]);

  // Degenerate input: empty data, a single triangle, duplicate points, lines only.
  {
    vtkNew<vtkPolyData> empty;
    vtkNew<vtkStylizePrincipalCurvatures> f;
    f->SetInputData(empty);
    f->Update();
    STYLIZE_CHECK(f->GetOutput()->GetNumberOfPoints() == 0, "empty input");
    vtkNew<vtkPoints> pts;
    pts->InsertNextPoint(0, 0, 0);
    pts->InsertNextPoint(1, 0, 0);
    pts->InsertNextPoint(0, 1, 0);
    pts->InsertNextPoint(0, 1, 0);
    vtkNew<vtkCellArray> cells;
    const vtkIdType t1[3] = { 0, 1, 2 }, t2[3] = { 1, 2, 3 }, t3[3] = { 0, 0, 1 };
    cells->InsertNextCell(3, t1);
    cells->InsertNextCell(3, t2);
    cells->InsertNextCell(3, t3);
    vtkNew<vtkPolyData> odd;
    odd->SetPoints(pts);
    odd->SetPolys(cells);
    f->SetInputData(odd);
    f->Update();
    for (int a = 0; a < f->GetOutput()->GetPointData()->GetNumberOfArrays(); ++a)
    {
      STYLIZE_CHECK(
        vtkStylizeImageMetrics::CountNonFinite(f->GetOutput()->GetPointData()->GetArray(a)) == 0,
        "degenerate input: NaN or Inf");
    }
  }
  return Failures == 0 ? 0 : 1;
}
