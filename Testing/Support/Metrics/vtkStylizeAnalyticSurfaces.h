// Analytic surfaces shared by the curvature filter's test and the sketch accuracy study: the
// principal curvatures and directions of a cylinder, a torus and an ellipsoid at a point, and
// the meshes they are compared on. Header-only.
#ifndef vtkStylizeAnalyticSurfaces_h
#define vtkStylizeAnalyticSurfaces_h

#include "vtkCellArray.h"
#include "vtkCleanPolyData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkParametricEllipsoid.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricTorus.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <array>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace stylizetest
{
/** Analytic values at a point: k1 >= k2 and their unit directions (zero when undefined). */
struct Truth
{
  double K1, K2;
  std::array<double, 3> D1, D2;
  bool Use; // false: skip (boundary, umbilic)
};

/** Cylinder of radius r about the z axis (outward normals): 1/r around, 0 along. */
inline Truth CylinderTruth(double r, const double* x)
{
  Truth t;
  t.K1 = 1.0 / r;
  t.K2 = 0.0;
  const double len = std::hypot(x[0], x[1]);
  t.D1 = { -x[1] / len, x[0] / len, 0.0 };
  t.D2 = { 0.0, 0.0, 1.0 };
  t.Use = len > 0.0;
  return t;
}

/** Torus about the z axis, ring radius R, tube radius a (vtkParametricTorus). */
inline Truth TorusTruth(double R, double a, const double* x)
{
  Truth t;
  const double rho = std::hypot(x[0], x[1]);
  const double cosPhi = (rho - R) / a; // phi: angle on the tube, 0 outside
  // Around the tube (meridian): 1/a; along the ring (parallel): cos(phi) / rho.
  const double kTube = 1.0 / a, kRing = cosPhi / rho;
  const std::array<double, 3> ring = { -x[1] / rho, x[0] / rho, 0.0 };
  const double n[3] = { (rho - R) / a * x[0] / rho, (rho - R) / a * x[1] / rho, x[2] / a };
  double c[3];
  vtkMath::Cross(n, ring.data(), c);
  const std::array<double, 3> tube = { c[0], c[1], c[2] };
  t.K1 = std::max(kTube, kRing);
  t.K2 = std::min(kTube, kRing);
  t.D1 = kTube >= kRing ? tube : ring;
  t.D2 = kTube >= kRing ? ring : tube;
  t.Use = rho > 0.0;
  return t;
}

/**
 * Ellipsoid with semi-axes ax (x, y, z): principal curvatures from the implicit surface's shape
 * operator (the Hessian projected on the tangent plane over |grad F|), directions its
 * eigenvectors. Near the umbilics (k1 - k2 < 5% of k1) the directions are left zero.
 */
inline Truth EllipsoidTruth(const double ax[3], const double* x)
{
  double g[3], n[3];
  for (int i = 0; i < 3; ++i)
  {
    g[i] = 2.0 * x[i] / (ax[i] * ax[i]);
    n[i] = g[i];
  }
  const double gl = vtkMath::Normalize(n);
  // S = P H P / |g|, H = diag(2 / a_i^2), P = I - n n^T.
  double s[3][3];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      double v = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        const double pik = (i == k ? 1.0 : 0.0) - n[i] * n[k];
        const double pkj = (k == j ? 1.0 : 0.0) - n[k] * n[j];
        v += pik * 2.0 / (ax[k] * ax[k]) * pkj;
      }
      s[i][j] = v / gl;
    }
  }
  double* rows[3] = { s[0], s[1], s[2] };
  double w[3], vv[3][3];
  double* vrows[3] = { vv[0], vv[1], vv[2] };
  vtkMath::Jacobi(rows, w, vrows); // eigenvalues descending, vectors in columns
  // Drop the normal's eigenvector (eigenvalue 0): keep the two tangent ones.
  std::vector<std::pair<double, std::array<double, 3>>> tangent;
  for (int c = 0; c < 3; ++c)
  {
    const std::array<double, 3> v = { vv[0][c], vv[1][c], vv[2][c] };
    if (std::abs(vtkMath::Dot(v.data(), n)) < 0.5)
    {
      tangent.push_back({ w[c], v });
    }
  }
  Truth t{ 0, 0, { 0, 0, 0 }, { 0, 0, 0 }, false };
  if (tangent.size() == 2)
  {
    if (tangent[0].first < tangent[1].first)
    {
      std::swap(tangent[0], tangent[1]);
    }
    t.K1 = tangent[0].first;
    t.K2 = tangent[1].first;
    t.D1 = tangent[0].second;
    t.D2 = tangent[1].second;
    t.Use = true;
    if (t.K1 - t.K2 < 0.05 * t.K1)
    {
      t.D1 = t.D2 = { 0, 0, 0 };
    }
  }
  return t;
}

/** The output of vtkCleanPolyData (merges parametric seams), without normals. */
inline vtkSmartPointer<vtkPolyData> CleanMesh(vtkAlgorithmOutput* port)
{
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputConnection(port);
  clean->SetTolerance(1e-9);
  clean->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(clean->GetOutput());
  out->GetPointData()->SetNormals(nullptr);
  return out;
}

/**
 * A torus about the z axis (vtkParametricTorus: ring radius R, tube radius a) sampled u x v,
 * cleaned, without normals.
 */
inline vtkSmartPointer<vtkPolyData> TorusMesh(double R, double a, int u, int v)
{
  vtkNew<vtkParametricTorus> torus;
  torus->SetRingRadius(R);
  torus->SetCrossSectionRadius(a);
  vtkNew<vtkParametricFunctionSource> src;
  src->SetParametricFunction(torus);
  src->SetUResolution(u);
  src->SetVResolution(v);
  src->GenerateNormalsOff();
  return CleanMesh(src->GetOutputPort());
}

/** An ellipsoid with semi-axes ax (x, y, z) sampled u x v, cleaned, without normals. */
inline vtkSmartPointer<vtkPolyData> EllipsoidMesh(const double ax[3], int u, int v)
{
  vtkNew<vtkParametricEllipsoid> ell;
  ell->SetXRadius(ax[0]);
  ell->SetYRadius(ax[1]);
  ell->SetZRadius(ax[2]);
  vtkNew<vtkParametricFunctionSource> src;
  src->SetParametricFunction(ell);
  src->SetUResolution(u);
  src->SetVResolution(v);
  src->GenerateNormalsOff();
  return CleanMesh(src->GetOutputPort());
}

/** An open cylinder of radius r along z, n around, m along, height h, triangulated. */
inline vtkSmartPointer<vtkPolyData> CylinderMesh(double r, double h, int n, int m)
{
  vtkNew<vtkPoints> pts;
  for (int j = 0; j <= m; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double a = 2.0 * vtkMath::Pi() * (i + 0.5 * (j % 2)) / n;
      pts->InsertNextPoint(r * std::cos(a), r * std::sin(a), -0.5 * h + h * j / m);
    }
  }
  vtkNew<vtkCellArray> tris;
  for (int j = 0; j < m; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const vtkIdType a = j * n + i, b = j * n + (i + 1) % n;
      const vtkIdType c = (j + 1) * n + i, d = (j + 1) * n + (i + 1) % n;
      if (j % 2 == 0)
      {
        const vtkIdType t1[3] = { a, b, c }, t2[3] = { b, d, c };
        tris->InsertNextCell(3, t1);
        tris->InsertNextCell(3, t2);
      }
      else
      {
        const vtkIdType t1[3] = { a, d, c }, t2[3] = { a, b, d };
        tris->InsertNextCell(3, t1);
        tris->InsertNextCell(3, t2);
      }
    }
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(pts);
  pd->SetPolys(tris);
  return pd;
}

/**
 * CylinderMesh(r, h, n, m) with its points moved radially by up to `noise` times r, uniformly
 * at random (std::mt19937 seeded with `seed`): scan noise on a known surface.
 */
inline vtkSmartPointer<vtkPolyData> NoisyCylinderMesh(
  double r, double h, int n, int m, double noise, unsigned seed)
{
  auto mesh = CylinderMesh(r, h, n, m);
  vtkPoints* points = mesh->GetPoints();
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-noise * r, noise * r);
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    const double rho = std::hypot(x[0], x[1]);
    const double s = rho > 0.0 ? (rho + jitter(random)) / rho : 1.0;
    points->SetPoint(i, x[0] * s, x[1] * s, x[2]);
  }
  points->Modified();
  return mesh;
}
}

#endif
