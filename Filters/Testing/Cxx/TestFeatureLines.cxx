// vtkStylizeFeatureLines against analytic lines: a sphere's contour (a circle), a cube's
// creases, a plane's boundary, a Gaussian ridge and its valleys, suggestive contours on a torus
// and none on a sphere; the same lines at scale 1e-6 and 1e6; degenerate input.
#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCubeSource.h"
#include "vtkCylinderSource.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricTorus.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkShrinkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkStylizeFeatureLines.h"
#include "vtkStylizeTestChecks.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

using namespace stylizetest;

namespace
{
using Kind = vtkStylizeFeatureLines;

/** Per kind: the number of polylines, their total length and their points. */
struct Lines
{
  std::array<int, Kind::NUMBER_OF_KINDS> Count{};
  std::array<double, Kind::NUMBER_OF_KINDS> Length{};
  std::array<std::vector<std::array<double, 3>>, Kind::NUMBER_OF_KINDS> Points;
};

Lines Measure(vtkPolyData* lines)
{
  Lines out;
  vtkDataArray* kinds = lines->GetCellData()->GetArray("FeatureKind");
  vtkDataArray* strength = lines->GetPointData()->GetArray("FeatureStrength");
  STYLIZE_CHECK(kinds && strength, "output arrays missing");
  if (!kinds || !strength)
  {
    return out;
  }
  vtkIdType cell = 0, n;
  const vtkIdType* ids;
  vtkCellArray* cells = lines->GetLines();
  for (cells->InitTraversal(); cells->GetNextCell(n, ids); ++cell)
  {
    const int kind = static_cast<int>(kinds->GetComponent(cell, 0));
    ++out.Count[kind];
    for (vtkIdType i = 0; i < n; ++i)
    {
      std::array<double, 3> p;
      lines->GetPoint(ids[i], p.data());
      const double s = strength->GetComponent(ids[i], 0);
      STYLIZE_CHECK(std::isfinite(p[0] + p[1] + p[2]) && s >= 0.0 && s <= 1.0,
        "non-finite point or strength %g out of [0, 1]", s);
      out.Points[kind].push_back(p);
      if (i > 0)
      {
        double q[3];
        lines->GetPoint(ids[i - 1], q);
        out.Length[kind] += std::sqrt(vtkMath::Distance2BetweenPoints(p.data(), q));
      }
    }
  }
  return out;
}

/** The lines of source (scaled, and the camera with it) at thresholds low enough for the
 * analytic shapes' gentle curvature (the defaults are tuned on real data). */
Lines Run(vtkPolyDataAlgorithm* source, vtkCamera* camera, int mask, double scale = 1.0)
{
  vtkNew<vtkTransform> t;
  t->Scale(scale, scale, scale);
  vtkNew<vtkTransformPolyDataFilter> scaled;
  scaled->SetInputConnection(source->GetOutputPort());
  scaled->SetTransform(t);
  vtkNew<vtkStylizeFeatureLines> lines;
  lines->SetInputConnection(scaled->GetOutputPort());
  lines->SetKindMask(mask);
  lines->SetRidgeThreshold(1.0);
  lines->SetSuggestiveThreshold(1.0);
  if (camera)
  {
    vtkNew<vtkCamera> c;
    c->DeepCopy(camera);
    double p[3], f[3];
    camera->GetPosition(p);
    camera->GetFocalPoint(f);
    c->SetPosition(p[0] * scale, p[1] * scale, p[2] * scale);
    c->SetFocalPoint(f[0] * scale, f[1] * scale, f[2] * scale);
    c->SetParallelScale(camera->GetParallelScale() * scale);
    lines->SetCamera(c);
    lines->Update();
    return Measure(lines->GetOutput());
  }
  lines->Update();
  return Measure(lines->GetOutput());
}

int Bit(int kind)
{
  return 1 << kind;
}

/** The sphere's contour seen from (0, 0, d): the circle p.c = r^2 on the sphere. */
void SphereContour()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(120);
  sphere->SetPhiResolution(90);
  for (bool parallel : { false, true })
  {
    vtkNew<vtkCamera> camera;
    camera->SetPosition(0.3, 0.2, 4.0);
    camera->SetFocalPoint(0, 0, 0);
    camera->SetParallelProjection(parallel);
    const Lines l = Run(sphere, camera, Bit(Kind::CONTOUR));
    const double c[3] = { 0.3, 0.2, 4.0 };
    const double d = vtkMath::Norm(c);
    double worst = 0.0;
    for (const auto& p : l.Points[Kind::CONTOUR])
    {
      // perspective: p.c = r^2; parallel: p.c = 0
      const double target = parallel ? 0.0 : 1.0;
      worst = std::max(worst, std::abs(vtkMath::Dot(p.data(), c) / d - target / d));
    }
    const double rho = parallel ? 1.0 : std::sqrt(1.0 - 1.0 / (d * d));
    const double expected = 2.0 * vtkMath::Pi() * rho;
    std::printf("sphere contour (%s): %d chains, length %.4f (circle %.4f), largest distance "
                "from the contour's plane %.2e\n",
      parallel ? "parallel" : "perspective", l.Count[Kind::CONTOUR], l.Length[Kind::CONTOUR],
      expected, worst);
    STYLIZE_CHECK(l.Count[Kind::CONTOUR] == 1, "%d contour chains, expected 1 closed chain",
      l.Count[Kind::CONTOUR]);
    STYLIZE_CHECK(std::abs(l.Length[Kind::CONTOUR] / expected - 1.0) < 0.01,
      "contour length %.4f, circle %.4f", l.Length[Kind::CONTOUR], expected);
    STYLIZE_CHECK(worst < 0.01, "contour off the analytic circle by %.3g", worst);
  }
}

/** A cube's 12 creases (total length 12), a plane's boundary (length 4), no creases on a
 * sphere; the cube seen by a camera has contours only along its creases' faces. */
void EdgesOfShapes()
{
  vtkNew<vtkCubeSource> cube;
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(cube->GetOutputPort());
  const Lines l = Run(triangles, nullptr, Bit(Kind::CREASE) | Bit(Kind::BOUNDARY));
  std::printf("cube: %d creases, length %.4f; %d boundaries\n", l.Count[Kind::CREASE],
    l.Length[Kind::CREASE], l.Count[Kind::BOUNDARY]);
  STYLIZE_CHECK(l.Count[Kind::CREASE] == 12 && std::abs(l.Length[Kind::CREASE] - 12.0) < 1e-9,
    "cube: %d creases of total length %.6f, expected 12 and 12", l.Count[Kind::CREASE],
    l.Length[Kind::CREASE]);
  STYLIZE_CHECK(l.Count[Kind::BOUNDARY] == 0,
    "cube: %d boundaries (its faces' split points are "
    "merged)",
    l.Count[Kind::BOUNDARY]);

  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(7, 5);
  vtkNew<vtkTriangleFilter> planeTriangles;
  planeTriangles->SetInputConnection(plane->GetOutputPort());
  const Lines b = Run(planeTriangles, nullptr, Bit(Kind::CREASE) | Bit(Kind::BOUNDARY));
  std::printf("plane: %d boundary chains, length %.4f; %d creases\n", b.Count[Kind::BOUNDARY],
    b.Length[Kind::BOUNDARY], b.Count[Kind::CREASE]);
  STYLIZE_CHECK(b.Count[Kind::BOUNDARY] == 1 && std::abs(b.Length[Kind::BOUNDARY] - 4.0) < 1e-9,
    "plane: %d boundary chains of length %.6f, expected one closed chain of 4",
    b.Count[Kind::BOUNDARY], b.Length[Kind::BOUNDARY]);
  STYLIZE_CHECK(b.Count[Kind::CREASE] == 0, "plane: %d creases", b.Count[Kind::CREASE]);
}

/** z = h exp(-x^2 / 2 s^2) on [-1, 1]^2: a ridge on x = 0 and valleys at the feet, where the
 * curvature is most negative (|x| = sqrt(3) s for small h). */
vtkSmartPointer<vtkPolyData> GaussianRidge(int n)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1, -1, 0);
  plane->SetPoint1(1, -1, 0);
  plane->SetPoint2(-1, 1, 0);
  plane->SetResolution(n, n);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(plane->GetOutputPort());
  triangles->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(triangles->GetOutput());
  const double h = 0.1, s = 0.2;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    p[2] = h * std::exp(-p[0] * p[0] / (2 * s * s));
    mesh->GetPoints()->SetPoint(i, p);
  }
  mesh->GetPointData()->Initialize();
  return mesh;
}

void RidgesAndValleys()
{
  // A cylinder's curvature is the same all around: every point is an extreme, none a ridge.
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetResolution(64);
  cylinder->CappingOff();
  const Lines c = Run(cylinder, nullptr, Bit(Kind::RIDGE) | Bit(Kind::VALLEY));
  std::printf("cylinder: %d ridges, %d valleys\n", c.Count[Kind::RIDGE], c.Count[Kind::VALLEY]);
  STYLIZE_CHECK(c.Count[Kind::RIDGE] == 0 && c.Count[Kind::VALLEY] == 0,
    "cylinder: %d ridges and %d valleys, expected none", c.Count[Kind::RIDGE],
    c.Count[Kind::VALLEY]);

  vtkNew<vtkTriangleFilter> source; // a pass-through, so that Run() can scale the data
  source->SetInputData(GaussianRidge(120));
  for (double scale : { 1.0, 1e-6, 1e6 })
  {
    const Lines l = Run(source, nullptr, Bit(Kind::RIDGE) | Bit(Kind::VALLEY), scale);
    double ridgeX = 0.0, valleyX = 0.0;
    for (const auto& p : l.Points[Kind::RIDGE])
    {
      ridgeX = std::max(ridgeX, std::abs(p[0] / scale));
    }
    double valleyMin = 1e30, valleyMax = 0.0;
    for (const auto& p : l.Points[Kind::VALLEY])
    {
      valleyMin = std::min(valleyMin, std::abs(p[0] / scale));
      valleyMax = std::max(valleyMax, std::abs(p[0] / scale));
      valleyX = valleyMax;
    }
    std::printf("gaussian ridge at scale %g: %d ridges (length %.3f, |x| <= %.4f), %d valleys "
                "(length %.3f, |x| in [%.3f, %.3f])\n",
      scale, l.Count[Kind::RIDGE], l.Length[Kind::RIDGE] / scale, ridgeX, l.Count[Kind::VALLEY],
      l.Length[Kind::VALLEY] / scale, valleyMin, valleyX);
    STYLIZE_CHECK(l.Count[Kind::RIDGE] >= 1 && l.Length[Kind::RIDGE] / scale > 1.6,
      "scale %g: ridge length %.3f, expected about 2", scale, l.Length[Kind::RIDGE] / scale);
    STYLIZE_CHECK(ridgeX < 0.02, "scale %g: ridge off x = 0 by %.4f", scale, ridgeX);
    STYLIZE_CHECK(l.Count[Kind::VALLEY] >= 2 && valleyMin > 0.25 && valleyMax < 0.45,
      "scale %g: valleys at |x| in [%.3f, %.3f], expected near %.3f", scale, valleyMin, valleyMax,
      std::sqrt(3.0) * 0.2);
  }
}

/** A sphere (convex: no suggestive contours) and a torus seen from the side (suggestive
 * contours on its inner, saddle-shaped half), at scales 1e-6, 1 and 1e6. */
void SuggestiveContours()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(80);
  sphere->SetPhiResolution(60);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(1.0, 2.0, 6.0);
  camera->SetFocalPoint(0, 0, 0);
  const Lines s = Run(sphere, camera, Bit(Kind::SUGGESTIVE_CONTOUR));
  STYLIZE_CHECK(s.Count[Kind::SUGGESTIVE_CONTOUR] == 0, "sphere: %d suggestive contours",
    s.Count[Kind::SUGGESTIVE_CONTOUR]);

  vtkNew<vtkParametricTorus> torus;
  torus->SetRingRadius(1.0);
  torus->SetCrossSectionRadius(0.4);
  vtkNew<vtkParametricFunctionSource> source;
  source->SetParametricFunction(torus);
  source->SetUResolution(160);
  source->SetVResolution(80);
  source->SetScalarModeToNone();
  vtkNew<vtkCamera> side;
  side->SetPosition(0.0, -6.0, 2.0);
  side->SetFocalPoint(0, 0, 0);
  std::array<int, 3> counts{};
  int i = 0;
  for (double scale : { 1.0, 1e-6, 1e6 })
  {
    const Lines l = Run(source, side, Bit(Kind::SUGGESTIVE_CONTOUR) | Bit(Kind::CONTOUR), scale);
    double outer = 0.0;
    for (const auto& p : l.Points[Kind::SUGGESTIVE_CONTOUR])
    {
      outer = std::max(outer, std::hypot(p[0], p[1]) / scale);
    }
    std::printf("torus at scale %g: %d contours (length %.3f), %d suggestive contours (length "
                "%.3f, distance from the axis <= %.3f)\n",
      scale, l.Count[Kind::CONTOUR], l.Length[Kind::CONTOUR] / scale,
      l.Count[Kind::SUGGESTIVE_CONTOUR], l.Length[Kind::SUGGESTIVE_CONTOUR] / scale, outer);
    STYLIZE_CHECK(l.Count[Kind::SUGGESTIVE_CONTOUR] > 0, "torus: no suggestive contours");
    // K < 0 where the distance from the axis is below the ring radius.
    STYLIZE_CHECK(outer <= 1.02,
      "torus: suggestive contour at distance %.3f from the axis "
      "(outside the saddle region)",
      outer);
    counts[i++] = l.Count[Kind::SUGGESTIVE_CONTOUR];
  }
  STYLIZE_CHECK(counts[0] == counts[1] && counts[0] == counts[2],
    "suggestive contours differ with scale: %d, %d, %d", counts[0], counts[1], counts[2]);
}

/** A torus of u x v quads, without scalars. */
vtkSmartPointer<vtkParametricFunctionSource> Torus(int u, int v)
{
  vtkNew<vtkParametricTorus> torus;
  auto source = vtkSmartPointer<vtkParametricFunctionSource>::New();
  source->SetParametricFunction(torus);
  source->SetUResolution(u);
  source->SetVResolution(v);
  source->SetScalarModeToNone();
  return source;
}

/** Feature lines of `source` seen by `camera`, ridges and suggestive contours at threshold 1. */
vtkSmartPointer<vtkStylizeFeatureLines> LinesOf(vtkAlgorithm* source, vtkCamera* camera)
{
  auto lines = vtkSmartPointer<vtkStylizeFeatureLines>::New();
  lines->SetInputConnection(source->GetOutputPort());
  lines->SetCamera(camera);
  lines->SetRidgeThreshold(1.0);
  lines->SetSuggestiveThreshold(1.0);
  return lines;
}

/** `kept`'s lines (updated) against a new filter's with the same input, camera and settings. */
void SameAsNew(
  vtkStylizeFeatureLines* kept, vtkAlgorithm* source, vtkCamera* camera, const char* what)
{
  vtkSmartPointer<vtkStylizeFeatureLines> fresh = LinesOf(source, camera);
  fresh->SetCreaseAngle(kept->GetCreaseAngle());
  fresh->SetKindMask(kept->GetKindMask());
  fresh->Update();
  kept->Update();
  const Lines a = Measure(kept->GetOutput()), b = Measure(fresh->GetOutput());
  for (int k = 0; k < Kind::NUMBER_OF_KINDS; ++k)
  {
    STYLIZE_CHECK(a.Count[k] == b.Count[k] && a.Length[k] == b.Length[k],
      "%s: %s lines differ from a new filter's (%d of length %.17g, %d of length %.17g)", what,
      vtkStylizeFeatureLines::GetKindName(k), a.Count[k], a.Length[k], b.Count[k], b.Length[k]);
  }
}

/** A filter run again with a new camera, or a changed input, gives what a new filter gives: the
 * kept view-independent part follows the input and its settings. */
void Reuse()
{
  vtkSmartPointer<vtkParametricFunctionSource> source = Torus(80, 40);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.0, -6.0, 2.0);
  vtkSmartPointer<vtkStylizeFeatureLines> kept = LinesOf(source, camera);
  kept->Update();
  camera->Azimuth(30.0);
  SameAsNew(kept, source, camera, "new camera");
  source->SetUResolution(60);
  SameAsNew(kept, source, camera, "changed input");
  kept->SetCreaseAngle(20.0);
  camera->Elevation(20.0);
  SameAsNew(kept, source, camera, "changed crease angle");
}

/** A drag in a GUI: interactive frames (contours, boundaries, creases: no curvature) and still
 * frames (every kind) in turn, each with a new camera. The welded mesh and the curvature are
 * built once (issue 52: each switch rebuilt them, seconds on a 400k-face scan), and the still
 * frames' lines are a new filter's; a changed input builds both again. */
void KindMaskSwitches()
{
  vtkSmartPointer<vtkParametricFunctionSource> source = Torus(60, 30);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.0, -6.0, 2.0);
  vtkSmartPointer<vtkStylizeFeatureLines> kept = LinesOf(source, camera);
  const int interactive = (1 << Kind::CONTOUR) | (1 << Kind::BOUNDARY) | (1 << Kind::CREASE);
  const int still = 63;
  for (int frame = 0; frame < 6; ++frame)
  {
    camera->Azimuth(7.0);
    kept->SetKindMask(frame % 3 == 2 ? still : interactive);
    kept->Update();
  }
  kept->SetKindMask(still);
  camera->Elevation(10.0);
  kept->Update();
  STYLIZE_CHECK(kept->GetViewIndependentBuilds() == 1 && kept->GetCurvatureBuilds() == 1,
    "interactive and still frames in turn: %d builds of the mesh, %d of the curvature (1 each)",
    kept->GetViewIndependentBuilds(), kept->GetCurvatureBuilds());
  SameAsNew(kept, source, camera, "after the switches");
  source->SetUResolution(50);
  kept->SetKindMask(interactive);
  kept->Update();
  kept->SetKindMask(still);
  kept->Update();
  STYLIZE_CHECK(kept->GetViewIndependentBuilds() == 2 && kept->GetCurvatureBuilds() == 2,
    "a changed input: %d builds of the mesh, %d of the curvature (2 each)",
    kept->GetViewIndependentBuilds(), kept->GetCurvatureBuilds());
}

/** Empty data, points without faces, non-finite points, one triangle, a camera on the surface:
 * no crash, finite output. */
void Degenerate()
{
  vtkNew<vtkCamera> camera;
  for (int which = 0; which < 4; ++which)
  {
    vtkNew<vtkPolyData> data;
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> polys;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (which >= 1)
    {
      points->InsertNextPoint(0, 0, 0);
      points->InsertNextPoint(1, 0, 0);
      points->InsertNextPoint(0, 1, 0);
    }
    if (which == 2)
    {
      points->SetPoint(1, nan, 0, 0);
    }
    if (which >= 2)
    {
      const vtkIdType tri[3] = { 0, 1, 2 };
      polys->InsertNextCell(3, tri);
    }
    if (which == 3)
    {
      camera->SetPosition(0, 0, 0); // on the surface
      camera->SetFocalPoint(0, 0, -1);
    }
    data->SetPoints(points);
    data->SetPolys(polys);
    vtkNew<vtkStylizeFeatureLines> lines;
    lines->SetInputData(data);
    lines->SetCamera(camera);
    lines->Update();
    const Lines l = Measure(lines->GetOutput());
    std::printf("degenerate input %d: %lld line points\n", which,
      static_cast<long long>(lines->GetOutput()->GetNumberOfPoints()));
  }
}
}

/**
 * The weld: a triangle soup (every triangle its own three points, by vtkShrinkPolyData at
 * factor 1) of a unit sphere and of a sphere 1e-5 across beside it, whose thousands of points
 * all fall in one grid cell of the weld, each point's copies far apart in index: every copy is
 * merged, so no boundary line is left.
 */
void WeldedSoup()
{
  vtkNew<vtkSphereSource> big;
  big->SetThetaResolution(48);
  big->SetPhiResolution(24);
  vtkNew<vtkSphereSource> tiny;
  tiny->SetRadius(1e-5);
  tiny->SetCenter(1.5, 0.0, 0.0);
  tiny->SetThetaResolution(48);
  tiny->SetPhiResolution(24);
  vtkNew<vtkAppendPolyData> both;
  both->AddInputConnection(big->GetOutputPort());
  both->AddInputConnection(tiny->GetOutputPort());
  vtkNew<vtkShrinkPolyData> soup;
  soup->SetInputConnection(both->GetOutputPort());
  soup->SetShrinkFactor(1.0);
  const Lines l = Run(soup, nullptr, Bit(Kind::BOUNDARY));
  std::printf("triangle soup of two spheres: %d boundary chains\n", l.Count[Kind::BOUNDARY]);
  STYLIZE_CHECK(l.Count[Kind::BOUNDARY] == 0,
    "triangle soup: %d boundary chains (copies of a point left apart)", l.Count[Kind::BOUNDARY]);
}

int TestFeatureLines(int, char*[])
{
  WeldedSoup();
  SphereContour();
  EdgesOfShapes();
  RidgesAndValleys();
  SuggestiveContours();
  Reuse();
  KindMaskSwitches();
  Degenerate();
  return Failures == 0 ? 0 : 1;
}
