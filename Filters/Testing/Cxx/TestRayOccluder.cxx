// vtkStylizeRayOccluder against a brute-force test of every triangle: random segments through a
// sphere (polygons) and a strip of triangles, each under a model matrix (scaled, turned and
// moved: the occluder works in world coordinates), far from the origin (the points are stored
// relative to the centre in single precision). Every segment must get the brute force's answer
// but those that pass within 1e-6 of the scene's size of a triangle's edge; one occluder is then
// queried from vtkSMPTools' threads and must give the same answers. An empty surface and a
// surface with a NaN point block what their finite triangles block. A translucent sphere
// (SetOpacity(), per-point RGBA alpha) lets through the product of 1 - opacity per crossing.
#include "vtkStylizeRayOccluder.h"
#include "vtkStylizeTestChecks.h"

#include "vtkCellArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"
#include "vtkUnsignedCharArray.h"

#include <array>
#include <atomic>
#include <cmath>
#include <vector>

using namespace stylizetest;

namespace
{
using Tri = std::array<std::array<double, 3>, 3>;

/** The world triangles of a surface (polygons fanned, strips split). */
std::vector<Tri> WorldTriangles(vtkPolyData* pd, vtkMatrix4x4* m)
{
  std::vector<Tri> out;
  auto world = [&](vtkIdType id)
  {
    double p[4] = { 0, 0, 0, 1 }, w[4];
    pd->GetPoint(id, p);
    m->MultiplyPoint(p, w);
    return std::array<double, 3>{ w[0] / w[3], w[1] / w[3], w[2] / w[3] };
  };
  vtkIdType n;
  const vtkIdType* ids;
  for (pd->GetPolys()->InitTraversal(); pd->GetPolys()->GetNextCell(n, ids);)
  {
    for (vtkIdType k = 1; k + 1 < n; ++k)
    {
      out.push_back({ world(ids[0]), world(ids[k]), world(ids[k + 1]) });
    }
  }
  for (pd->GetStrips()->InitTraversal(); pd->GetStrips()->GetNextCell(n, ids);)
  {
    for (vtkIdType k = 0; k + 2 < n; ++k)
    {
      out.push_back({ world(ids[k]), world(ids[k + 1]), world(ids[k + 2]) });
    }
  }
  return out;
}

/** Whether segment a-b crosses triangle t, and how near it passes to t's edges (barycentric). */
bool Crosses(const Tri& t, const double a[3], const double b[3], double& margin)
{
  double e1[3], e2[3], d[3], s[3], q[3], r[3];
  vtkMath::Subtract(t[1].data(), t[0].data(), e1);
  vtkMath::Subtract(t[2].data(), t[0].data(), e2);
  vtkMath::Subtract(b, a, d);
  vtkMath::Subtract(a, t[0].data(), s);
  vtkMath::Cross(d, e2, q);
  const double det = vtkMath::Dot(e1, q);
  margin = VTK_DOUBLE_MAX;
  if (det == 0.0)
  {
    return false;
  }
  const double u = vtkMath::Dot(s, q) / det;
  vtkMath::Cross(s, e1, r);
  const double v = vtkMath::Dot(d, r) / det;
  const double along = vtkMath::Dot(e2, r) / det;
  margin = std::min(
    { std::abs(u), std::abs(v), std::abs(1.0 - u - v), std::abs(along), std::abs(1.0 - along) });
  return u >= 0.0 && v >= 0.0 && u + v <= 1.0 && along >= 0.0 && along <= 1.0;
}
}

int TestRayOccluder(int, char*[])
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(32);
  sphere->SetRadius(1.0);
  sphere->Update();
  vtkNew<vtkPolyData> surface;
  surface->DeepCopy(sphere->GetOutput());
  // a strip of triangles beside it
  vtkPoints* points = surface->GetPoints();
  vtkNew<vtkCellArray> strips;
  std::vector<vtkIdType> strip;
  for (int i = 0; i < 12; ++i)
  {
    strip.push_back(points->InsertNextPoint(1.5 + 0.1 * i, -0.5 + (i % 2), 0.3 * std::sin(i)));
  }
  strips->InsertNextCell(static_cast<vtkIdType>(strip.size()), strip.data());
  surface->SetStrips(strips);

  vtkNew<vtkTransform> transform;
  transform->Translate(1000.0, -2000.0, 500.0);
  transform->RotateWXYZ(37.0, 0.3, 0.8, 0.2);
  transform->Scale(3.0, 2.0, 2.5);
  vtkMatrix4x4* matrix = transform->GetMatrix();
  vtkNew<vtkStylizeRayOccluder> occluder;
  occluder->SetSurface(surface, matrix);
  const std::vector<Tri> tris = WorldTriangles(surface, matrix);
  STYLIZE_CHECK(occluder->GetNumberOfTriangles() == static_cast<vtkIdType>(tris.size()),
    "%lld triangles, brute force %zu", static_cast<long long>(occluder->GetNumberOfTriangles()),
    tris.size());

  double bounds[6];
  occluder->GetBounds(bounds);
  const double size = std::sqrt(
    vtkMath::Distance2BetweenPoints(std::array<double, 3>{ bounds[0], bounds[2], bounds[4] }.data(),
      std::array<double, 3>{ bounds[1], bounds[3], bounds[5] }.data()));
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(54);
  const int segments = 3000;
  std::vector<std::array<double, 6>> tests(segments);
  std::vector<char> expected(segments);
  int checked = 0, agree = 0, hits = 0;
  for (int i = 0; i < segments; ++i)
  {
    for (int k = 0; k < 6; ++k)
    {
      const int axis = k % 3;
      const double mid = 0.5 * (bounds[2 * axis] + bounds[2 * axis + 1]);
      const double half = 0.8 * (bounds[2 * axis + 1] - bounds[2 * axis]);
      tests[i][k] = mid + half * (2.0 * random->GetNextRangeValue(0.0, 1.0) - 1.0);
    }
    bool any = false, near = false;
    for (const Tri& t : tris)
    {
      double margin;
      any = Crosses(t, tests[i].data(), tests[i].data() + 3, margin) || any;
      near = near || margin < 1e-6;
    }
    expected[i] = any;
    hits += any;
    if (!near)
    {
      ++checked;
      agree += occluder->Blocks(tests[i].data(), tests[i].data() + 3) == any;
    }
  }
  std::printf("%zu triangles, scene size %.2f: %d of %d segments agree with the brute force "
              "(%d crossing), %d left out within 1e-6 of an edge\n",
    tris.size(), size, agree, checked, hits, segments - checked);
  STYLIZE_CHECK(checked > 2900 && agree == checked, "%d of %d agree", agree, checked);
  STYLIZE_CHECK(
    hits > 300 && hits < segments - 300, "%d of %d cross: not a mixed test", hits, segments);

  // From the threads: the same answers as one thread.
  std::atomic<int> differ{ 0 };
  vtkSMPTools::For(0, segments,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        const bool a = occluder->Blocks(tests[i].data(), tests[i].data() + 3);
        const bool b = occluder->Blocks(tests[i].data(), tests[i].data() + 3);
        differ += a != b;
      }
    });
  STYLIZE_CHECK(differ == 0, "%d threaded answers differ", static_cast<int>(differ));

  // Empty, and a NaN point: its triangles left out, the others still block.
  vtkNew<vtkStylizeRayOccluder> empty;
  empty->SetSurface(nullptr, nullptr);
  const double a[3] = { -5, 0, 0 }, b[3] = { 5, 0, 0 };
  STYLIZE_CHECK(!empty->Blocks(a, b) && empty->GetNumberOfTriangles() == 0, "an empty occluder");
  vtkNew<vtkPolyData> poisoned;
  poisoned->DeepCopy(sphere->GetOutput());
  poisoned->GetPoints()->SetPoint(0, std::nan(""), 0.0, 0.0);
  vtkNew<vtkStylizeRayOccluder> partial;
  partial->SetSurface(poisoned, nullptr);
  std::printf("a NaN point: %lld of %lld triangles kept\n",
    static_cast<long long>(partial->GetNumberOfTriangles()),
    static_cast<long long>(sphere->GetOutput()->GetNumberOfPolys()));
  STYLIZE_CHECK(partial->GetNumberOfTriangles() < sphere->GetOutput()->GetNumberOfPolys() &&
      partial->Blocks(a, b),
    "a NaN point: %lld triangles", static_cast<long long>(partial->GetNumberOfTriangles()));

  // Transmittance: a unit sphere (two crossings on a segment through it) of opacity 0.5, its
  // points' RGBA alpha 128 (about a half): 1 - 0.25 per crossing, 0.5625 through both; 1 beside
  // it; an opaque surface lets nothing through.
  vtkNew<vtkUnsignedCharArray> rgba;
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(sphere->GetOutput()->GetNumberOfPoints());
  for (vtkIdType i = 0; i < rgba->GetNumberOfTuples(); ++i)
  {
    const unsigned char c[4] = { 200, 100, 50, 128 };
    rgba->SetTypedTuple(i, c);
  }
  vtkNew<vtkStylizeRayOccluder> veil;
  veil->SetSurface(sphere->GetOutput(), nullptr);
  veil->SetOpacity(0.5, rgba);
  const double k = 1.0 - 0.5 * 128.0 / 255.0;
  // (off the sphere's vertices and edges: the x axis meets a vertex)
  const double from[3] = { -5, 0.1, 0.13 }, to[3] = { 5, 0.1, 0.13 }, centre[3] = { 0, 0.1, 0.13 };
  const double through = veil->Transmittance(from, to), half = veil->Transmittance(from, centre);
  const double beside[3] = { -5, 3, 0 }, besideEnd[3] = { 5, 3, 0 };
  std::printf("transmittance through a sphere of opacity 0.5 x 128/255: %.4f (expected %.4f), "
              "into its centre %.4f (%.4f), beside it %.4f\n",
    through, k * k, half, k, veil->Transmittance(beside, besideEnd));
  STYLIZE_CHECK(std::abs(through - k * k) < 1e-6 && std::abs(half - k) < 1e-6 &&
      veil->Transmittance(beside, besideEnd) == 1.0,
    "transmittance %.4f, %.4f", through, half);
  vtkNew<vtkStylizeRayOccluder> opaque;
  opaque->SetSurface(sphere->GetOutput(), nullptr);
  STYLIZE_CHECK(opaque->Transmittance(from, to) == 0.0, "an opaque sphere lets light through");
  veil->SetOpacity(std::nan(""), nullptr); // (not finite: opaque)
  STYLIZE_CHECK(veil->Transmittance(from, to) == 0.0, "a NaN opacity lets light through");
  return Failures == 0 ? 0 : 1;
}
