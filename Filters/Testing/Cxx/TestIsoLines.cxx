// vtkStylizeFeatureLines' iso-lines against analytic ones: the levels ComputeIsoLevels() places
// (round, even, bands, log scale, invalid ranges); the straight iso-lines of a linear field on a
// plane (on their level to rounding, their analytic length); closed circles on a sphere; a
// vector array's magnitude and one component; a log-scaled field; NaN values, a missing array
// and a missing component.
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkStylizeFeatureLines.h"
#include "vtkStylizeTestChecks.h"
#include "vtkTriangleFilter.h"

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

using namespace stylizetest;

namespace
{
using FL = vtkStylizeFeatureLines;

/** The iso-line polylines of an output: their points. */
std::vector<std::vector<std::array<double, 3>>> IsoChains(vtkPolyData* lines)
{
  std::vector<std::vector<std::array<double, 3>>> chains;
  vtkDataArray* kinds = lines->GetCellData()->GetArray("FeatureKind");
  vtkIdType cell = 0, n;
  const vtkIdType* ids;
  vtkCellArray* cells = lines->GetLines();
  for (cells->InitTraversal(); kinds && cells->GetNextCell(n, ids); ++cell)
  {
    if (static_cast<int>(kinds->GetComponent(cell, 0)) != FL::ISOLINE)
    {
      continue;
    }
    chains.emplace_back();
    for (vtkIdType i = 0; i < n; ++i)
    {
      std::array<double, 3> p;
      lines->GetPoint(ids[i], p.data());
      chains.back().push_back(p);
    }
  }
  return chains;
}

double Length(const std::vector<std::array<double, 3>>& chain)
{
  double length = 0.0;
  for (size_t i = 1; i < chain.size(); ++i)
  {
    length += std::sqrt(vtkMath::Distance2BetweenPoints(chain[i - 1].data(), chain[i].data()));
  }
  return length;
}

/** A triangulated surface with a point-data array of `components` made by f(point). */
vtkSmartPointer<vtkPolyData> WithField(vtkPolyDataAlgorithm* source, const char* name,
  int components, const std::function<void(const double*, double*)>& f)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(source->GetOutputPort());
  triangles->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(triangles->GetOutput());
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(out->GetNumberOfPoints());
  std::vector<double> tuple(components);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    f(out->GetPoint(i), tuple.data());
    a->SetTuple(i, tuple.data());
  }
  out->GetPointData()->AddArray(a);
  return out;
}

vtkSmartPointer<vtkPolyData> Iso(vtkPolyData* data, const std::function<void(FL*)>& configure)
{
  vtkNew<FL> lines;
  lines->SetInputData(data);
  lines->SetKindMask(1 << FL::ISOLINE);
  configure(lines);
  lines->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(lines->GetOutput());
  return out;
}

bool Same(const std::vector<double>& a, const std::vector<double>& b)
{
  bool same = a.size() == b.size();
  for (size_t i = 0; same && i < a.size(); ++i)
  {
    same = std::fabs(a[i] - b[i]) <= 1e-12 * std::max(1.0, std::fabs(b[i]));
  }
  return same;
}

void Levels()
{
  struct Case
  {
    double Low, High;
    int Count, Spacing, Bands;
    bool Log;
    std::vector<double> Expected;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Case cases[] = {
    { 0, 1, 9, FL::ROUND, 0, false, { 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9 } },
    { 0, 1, 10, FL::ROUND, 0, false, { 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9 } },
    { 0, 100, 4, FL::ROUND, 0, false, { 20, 40, 60, 80 } },
    { -3, 7, 3, FL::ROUND, 0, false, { 0, 5 } },
    { 37.4, 38.9, 5, FL::ROUND, 0, false, { 37.5, 38.0, 38.5 } },
    { 0, 1, 3, FL::EVEN, 0, false, { 0.25, 0.5, 0.75 } },
    { 0, 1, 99, FL::BANDS, 4, false, { 0.25, 0.5, 0.75 } },
    { 1, 1000, 10, FL::ROUND, 0, true, { 2, 5, 10, 20, 50, 100, 200, 500 } },
    { 1, 1e10, 5, FL::ROUND, 0, true, { 1e2, 1e4, 1e6, 1e8 } },
    { 1, 1e4, 2, FL::EVEN, 0, true, { 10.0 * std::cbrt(10.0), 100.0 * std::cbrt(100.0) } },
    { 1, 0, 5, FL::ROUND, 0, false, {} },
    { 0, nan, 5, FL::ROUND, 0, false, {} },
    { 0, 10, 5, FL::ROUND, 0, true, {} },
    { 0, 1, 0, FL::ROUND, 0, false, {} },
  };
  for (const Case& c : cases)
  {
    const std::vector<double> got =
      FL::ComputeIsoLevels(c.Low, c.High, c.Count, c.Spacing, c.Bands, c.Log);
    std::string text;
    for (double v : got)
    {
      text += " " + std::to_string(v);
    }
    STYLIZE_CHECK(Same(got, c.Expected), "levels of [%g, %g], count %d, spacing %d%s:%s", c.Low,
      c.High, c.Count, c.Spacing, c.Log ? ", log" : "", text.c_str());
  }
  // Far from 0 (a range of 3e4 at 1e20, where doubles are 16384 apart): at most `count` levels
  // in the range, and an end (a loop adding 1 to a multiple past 2^53 never ended).
  const std::vector<double> far = FL::ComputeIsoLevels(1e20, 1e20 + 3e4, 5, FL::ROUND, 0, false);
  bool inside = far.size() <= 5;
  for (double v : far)
  {
    inside = inside && v >= 1e20 && v <= 1e20 + 3e4;
  }
  STYLIZE_CHECK(inside, "levels of [1e20, 1e20 + 3e4]: %zu, not all in the range", far.size());
}

/** f = x + y / 2 on the unit square: each level one straight chain, on its level, as long as
 * the line's part inside the square. */
void PlaneLines()
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(0, 0, 0);
  plane->SetPoint1(1, 0, 0);
  plane->SetPoint2(0, 1, 0);
  plane->SetResolution(37, 23);
  vtkSmartPointer<vtkPolyData> data =
    WithField(plane, "f", 1, [](const double* p, double* f) { f[0] = p[0] + 0.5 * p[1]; });
  const auto chains = IsoChains(Iso(data,
    [](FL* l)
    {
      l->SetIsoLineArrayName("f");
      l->SetIsoLineCount(9);
    }));
  // range [0, 1.5], at most 9 round levels: 0.2, 0.4, ..., 1.4
  STYLIZE_CHECK(chains.size() == 7, "plane: %zu iso-lines (7)", chains.size());
  double worstLevel = 0.0, worstLength = 0.0;
  for (const auto& chain : chains)
  {
    const double c = chain.front()[0] + 0.5 * chain.front()[1];
    const double level = 0.2 * std::round(c / 0.2);
    for (const auto& p : chain)
    {
      worstLevel = std::max(worstLevel, std::fabs(p[0] + 0.5 * p[1] - level));
    }
    const double y0 = std::max(0.0, 2.0 * (level - 1.0)), y1 = std::min(1.0, 2.0 * level);
    const double expected = (y1 - y0) * std::sqrt(1.25);
    worstLength = std::max(worstLength, std::fabs(Length(chain) - expected) / expected);
  }
  std::printf("plane: %zu iso-lines, off their level by %.2g, length error %.2g\n", chains.size(),
    worstLevel, worstLength);
  STYLIZE_CHECK(worstLevel < 1e-12, "plane: a point %g off its level", worstLevel);
  STYLIZE_CHECK(worstLength < 1e-9, "plane: length off by %g", worstLength);
}

/** f = z on a sphere of radius 0.5, 4 even levels of [-0.5, 0.5]: four closed circles at
 * z = -0.3, -0.1, 0.1 and 0.3. */
void SphereCircles()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(33);
  vtkSmartPointer<vtkPolyData> data =
    WithField(sphere, "z", 1, [](const double* p, double* f) { f[0] = p[2]; });
  data->GetPointData()->SetActiveScalars("z");
  const auto chains = IsoChains(Iso(data,
    [](FL* l)
    {
      l->SetIsoLineCount(4);
      l->SetIsoLineSpacing(FL::EVEN);
    }));
  int closed = 0;
  double worst = 0.0;
  for (const auto& chain : chains)
  {
    closed += chain.size() > 3 && chain.front() == chain.back();
    const double level = -0.5 + 0.2 * std::round((chain.front()[2] + 0.5) / 0.2);
    for (const auto& p : chain)
    {
      worst = std::max(worst, std::fabs(p[2] - level));
    }
  }
  std::printf(
    "sphere: %zu iso-lines, %d closed, off their level by %.2g\n", chains.size(), closed, worst);
  STYLIZE_CHECK(chains.size() == 4 && closed == 4, "sphere: %zu iso-lines, %d closed (4, 4)",
    chains.size(), closed);
  STYLIZE_CHECK(worst < 1e-12, "sphere: a point %g off its level", worst);
}

/** A vector (x, 0, 0) on [-1, 1]^2: its magnitude |x| crosses 0.5 twice, its component 0 once;
 * a component it lacks, a missing array: none. */
void Components()
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1, -1, 0);
  plane->SetPoint1(1, -1, 0);
  plane->SetPoint2(-1, 1, 0);
  plane->SetResolution(30, 10);
  vtkSmartPointer<vtkPolyData> data = WithField(plane, "v", 3,
    [](const double* p, double* f)
    {
      f[0] = p[0];
      f[1] = f[2] = 0.0;
    });
  auto count = [&](int component, const char* name)
  {
    return IsoChains(Iso(data,
                       [&](FL* l)
                       {
                         l->SetIsoLineArrayName(name);
                         l->SetIsoLineComponent(component);
                         l->SetIsoLineCount(1);
                         l->SetIsoLineSpacing(FL::EVEN);
                         l->SetIsoLineRange(0.0, 1.0);
                       }))
      .size();
  };
  const size_t magnitude = count(-1, "v"), x = count(0, "v"), z = count(2, "v");
  const size_t missing = count(5, "v"), none = count(-1, "nothing");
  std::printf("vector: magnitude %zu, x %zu, z %zu, component 5 %zu, no array %zu lines\n",
    magnitude, x, z, missing, none);
  STYLIZE_CHECK(magnitude == 2 && x == 1 && z == 0 && missing == 0 && none == 0,
    "vector: magnitude %zu (2), x %zu (1), z %zu (0), missing %zu (0), no array %zu (0)", magnitude,
    x, z, missing, none);
}

/** f = 10^(3x) on the unit square, log scale, at most 10 round levels: 2, 5, 10, ..., 500. */
void LogScale()
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(60, 5);
  plane->SetOrigin(0, 0, 0);
  plane->SetPoint1(1, 0, 0);
  plane->SetPoint2(0, 1, 0);
  vtkSmartPointer<vtkPolyData> data =
    WithField(plane, "f", 1, [](const double* p, double* f) { f[0] = std::pow(10.0, 3.0 * p[0]); });
  const auto chains = IsoChains(Iso(data,
    [](FL* l)
    {
      l->SetIsoLineArrayName("f");
      l->SetIsoLineCount(10);
      l->SetIsoLineLogScale(true);
    }));
  std::printf("log scale: %zu iso-lines\n", chains.size());
  STYLIZE_CHECK(chains.size() == 8, "log scale: %zu iso-lines (8)", chains.size());
}

/** NaN values: their triangles draw nothing, the others their lines; no crash. */
void NotFinite()
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(10, 10);
  vtkSmartPointer<vtkPolyData> data = WithField(plane, "f", 1,
    [](const double* p, double* f)
    { f[0] = p[0] > 0.2 ? std::numeric_limits<double>::quiet_NaN() : p[0]; });
  const auto chains = IsoChains(Iso(data,
    [](FL* l)
    {
      l->SetIsoLineArrayName("f");
      l->SetIsoLineCount(5);
      l->SetIsoLineRange(-0.5, 0.2);
      l->SetIsoLineSpacing(FL::EVEN);
    }));
  bool finite = true;
  for (const auto& chain : chains)
  {
    for (const auto& p : chain)
    {
      finite = finite && std::isfinite(p[0] + p[1] + p[2]) && p[0] <= 0.2;
    }
  }
  std::printf("NaN values: %zu iso-lines\n", chains.size());
  STYLIZE_CHECK(
    finite && !chains.empty(), "NaN values: %zu iso-lines, finite %d", chains.size(), finite);
}
}

int TestIsoLines(int, char*[])
{
  Levels();
  PlaneLines();
  SphereCircles();
  Components();
  LogScale();
  NotFinite();
  return Failures == 0 ? 0 : 1;
}
