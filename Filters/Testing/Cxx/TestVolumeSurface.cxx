// vtkStylizeVolumeSurface on f = 1 - r sampled over [-1, 1]^3: with an opacity rising from 0 at
// 0 to 1 at 1 and the threshold 0.5 the surface is the sphere r = 0.5 with normals pointing
// out of it (and the triangles' own normals agreeing); a falling opacity makes the outside
// opaque: the same sphere, normals pointing in, and the box's faces closing the region where
// it meets the image's edge, with the data's values there; isovalues replace the crossings; an
// opacity that is solid everywhere gives the outer faces and one solid nowhere nothing; the same
// field as an unstructured grid (vtkContourFilter's path) gives the sphere; cell scalars are
// moved to the points; a crossing is found to 1e-9 and a threshold of NaN or an empty input give
// nothing; NaN values in an unstructured grid leave out the cells they touch (no NaN point or
// normal), infinite ones leave the surface of the finite range; a piece of the image is closed at
// its cut unless the whole image's extent is given; an unstructured grid's opaque shell is closed
// by the grid's outer faces, but a piece of it not where the other piece's outer points are shared
// (SetSharedPoints).
#include "vtkStylizeTestChecks.h"
#include "vtkStylizeVolumeSurface.h"

#include "vtkAppendFilter.h"
#include "vtkCellData.h"
#include "vtkExtractVOI.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkUnstructuredGrid.h"

#include <array>
#include <cmath>
#include <limits>

using namespace stylizetest;

namespace
{
constexpr int N = 41; // samples along each axis over [-1, 1]

/** f = 1 - |p| on the points (or the cells' centres) of a 41^3 image over [-1, 1]^3. */
vtkNew<vtkImageData> Field(bool cells = false)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(N, N, N);
  image->SetOrigin(-1, -1, -1);
  const double h = 2.0 / (N - 1);
  image->SetSpacing(h, h, h);
  vtkNew<vtkFloatArray> f;
  f->SetName("f");
  const vtkIdType n = cells ? image->GetNumberOfCells() : image->GetNumberOfPoints();
  f->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    if (cells)
    {
      int sub;
      double pc[3], w[8];
      image->GetCell(i)->GetParametricCenter(pc);
      image->GetCell(i)->EvaluateLocation(sub, pc, p, w);
    }
    else
    {
      image->GetPoint(i, p);
    }
    f->SetValue(i, static_cast<float>(1.0 - vtkMath::Norm(p)));
  }
  if (cells)
  {
    image->GetCellData()->SetScalars(f);
  }
  else
  {
    image->GetPointData()->SetScalars(f);
  }
  return image;
}

vtkNew<vtkPiecewiseFunction> Ramp(double at0, double at1)
{
  vtkNew<vtkPiecewiseFunction> ramp;
  ramp->AddPoint(0.0, at0);
  ramp->AddPoint(1.0, at1);
  return ramp;
}

struct Shape
{
  vtkIdType Points = 0;
  double MeanRadius = 0.0, MaxRadiusError = 0.0; // over the points inside the box's faces
  double Outward = 0.0; // share of sphere points whose normal points away from the centre
  double Agreeing =
    0.0; // share of triangles (not slivers) whose own normal agrees with their points'
  vtkIdType OnFaces = 0; // points on the box's faces (|x|, |y| or |z| about 1)
};

Shape Measure(vtkPolyData* pd, double radius)
{
  Shape s;
  s.Points = pd->GetNumberOfPoints();
  vtkDataArray* normals = pd->GetPointData()->GetNormals();
  vtkIdType sphere = 0, outward = 0;
  for (vtkIdType i = 0; i < s.Points; ++i)
  {
    double p[3];
    pd->GetPoint(i, p);
    if (std::max({ std::abs(p[0]), std::abs(p[1]), std::abs(p[2]) }) > 0.99)
    {
      ++s.OnFaces;
      continue;
    }
    const double r = vtkMath::Norm(p);
    s.MeanRadius += r;
    s.MaxRadiusError = std::max(s.MaxRadiusError, std::abs(r - radius));
    double n[3] = { 0, 0, 0 };
    if (normals)
    {
      normals->GetTuple(i, n);
    }
    outward += vtkMath::Dot(n, p) > 0.0 ? 1 : 0;
    ++sphere;
  }
  s.MeanRadius /= std::max<vtkIdType>(1, sphere);
  s.Outward = static_cast<double>(outward) / std::max<vtkIdType>(1, sphere);
  vtkIdType agreeing = 0, triangles = 0;
  for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c)
  {
    vtkCell* cell = pd->GetCell(c);
    if (cell->GetNumberOfPoints() < 3 || !normals)
    {
      continue;
    }
    double own[3], n[3] = { 0, 0, 0 }, m[3];
    vtkPolygon::ComputeNormal(cell->GetPoints(), own);
    if (vtkMath::Norm(own) == 0.0)
    {
      continue; // (a sliver where the isovalue meets a sample)
    }
    for (int k = 0; k < cell->GetNumberOfPoints(); ++k)
    {
      normals->GetTuple(cell->GetPointId(k), m);
      vtkMath::Add(n, m, n);
    }
    agreeing += vtkMath::Dot(own, n) > 0.0 ? 1 : 0;
    ++triangles;
  }
  s.Agreeing = static_cast<double>(agreeing) / std::max<vtkIdType>(1, triangles);
  return s;
}

vtkSmartPointer<vtkPolyData> Surface(vtkDataObject* data, vtkPiecewiseFunction* opacity,
  double threshold, std::vector<double> iso = {}, const std::vector<vtkTypeUInt64>& shared = {})
{
  vtkNew<vtkStylizeVolumeSurface> surface;
  surface->SetInputData(data);
  surface->SetScalarOpacity(opacity);
  surface->SetOpacityThreshold(threshold);
  surface->SetIsoValues(iso);
  surface->SetSharedPoints(shared);
  surface->Update();
  return surface->GetOutput();
}

/** The half of `image` with x <= 0 (`low`) or x >= 0, as an unstructured grid. */
vtkSmartPointer<vtkUnstructuredGrid> Half(vtkImageData* image, bool low)
{
  vtkNew<vtkExtractVOI> voi;
  voi->SetInputData(image);
  voi->SetVOI(low ? 0 : N / 2, low ? N / 2 : N - 1, 0, N - 1, 0, N - 1);
  vtkNew<vtkAppendFilter> grid;
  grid->SetInputConnection(voi->GetOutputPort());
  grid->Update();
  return grid->GetOutput();
}

/** The points of `surface` on the plane x = 0 whose normal is along x: faces closing a cut. */
vtkIdType OnCut(vtkPolyData* surface)
{
  vtkIdType count = 0;
  vtkDataArray* n = surface->GetPointData()->GetNormals();
  for (vtkIdType i = 0; n && i < surface->GetNumberOfPoints(); ++i)
  {
    double p[3], m[3];
    surface->GetPoint(i, p);
    n->GetTuple(i, m);
    count += std::abs(p[0]) < 1e-9 && std::abs(m[0]) > 0.9 ? 1 : 0;
  }
  return count;
}

/**
 * `field` split at x = 0 into two pieces (ParaView's ranks): each closed at the cut alone, not
 * with the other piece's outer points shared, the box's faces closing both either way.
 */
void CheckSplit(vtkImageData* field, vtkPiecewiseFunction* down)
{
  auto low = Half(field, true);
  auto high = Half(field, false);
  const auto lowKeys = vtkStylizeVolumeSurface::OuterPointKeys(low);
  const auto highKeys = vtkStylizeVolumeSurface::OuterPointKeys(high);
  auto alone = Surface(low, down, 0.5);
  auto joined = Surface(low, down, 0.5, {}, highKeys);
  auto other = Surface(high, down, 0.5, {}, lowKeys);
  const Shape a = Measure(alone, 0.5), j = Measure(joined, 0.5), o = Measure(other, 0.5);
  STYLIZE_CHECK(OnCut(alone) > (N - 2) * (N - 2) / 4 && OnCut(joined) == 0 && OnCut(other) == 0 &&
      j.OnFaces > a.OnFaces / 2 && o.OnFaces > a.OnFaces / 2 &&
      lowKeys.size() > 6 * (N / 2) * (N / 2),
    "split: %lld, %lld and %lld points closing the cut (alone, shared, the other piece), "
    "%lld and %lld on the box's faces, %zu keys",
    static_cast<long long>(OnCut(alone)), static_cast<long long>(OnCut(joined)),
    static_cast<long long>(OnCut(other)), static_cast<long long>(j.OnFaces),
    static_cast<long long>(o.OnFaces), lowKeys.size());
}

/** The box's faces that close `field`'s opaque shell carry f there (the point moved onto the
 * face), not the isovalue. */
void CheckCapValues(vtkImageData* field, vtkPiecewiseFunction* down)
{
  const double h = 2.0 / (N - 1);
  auto shell = Surface(field, down, 0.5);
  vtkDataArray* f = shell->GetPointData()->GetScalars();
  double worst = 0.0;
  vtkIdType capped = 0;
  for (vtkIdType i = 0; f && i < shell->GetNumberOfPoints(); ++i)
  {
    double p[3];
    shell->GetPoint(i, p);
    if (std::max(std::abs(p[0]), std::max(std::abs(p[1]), std::abs(p[2]))) > 1.0 + 1e-6)
    {
      for (double& c : p)
      {
        c = std::min(1.0, std::max(-1.0, c));
      }
      worst = std::max(worst, std::abs(f->GetComponent(i, 0) - (1.0 - vtkMath::Norm(p))));
      ++capped;
    }
  }
  STYLIZE_CHECK(capped > 6 * (N - 2) * (N - 2) / 2 && worst < 0.5 * h,
    "box faces' values: %lld points, error %g", static_cast<long long>(capped), worst);
}

/**
 * NaN values in a block of `grid` (x > 0.2, y > 0.2): the contour's edges with a NaN end (NaN
 * points) are left out with their cells; the rest of the sphere stays, every point and normal
 * finite.
 */
void CheckNaNValues(vtkUnstructuredGrid* grid, vtkPiecewiseFunction* up)
{
  const double h = 2.0 / (N - 1);
  vtkNew<vtkUnstructuredGrid> holed;
  holed->DeepCopy(grid);
  vtkDataArray* values = holed->GetPointData()->GetScalars();
  vtkIdType nans = 0;
  for (vtkIdType i = 0; i < holed->GetNumberOfPoints(); ++i)
  {
    double p[3];
    holed->GetPoint(i, p);
    if (p[0] > 0.2 && p[1] > 0.2)
    {
      values->SetTuple1(i, std::numeric_limits<double>::quiet_NaN());
      ++nans;
    }
  }
  auto holedSurface = Surface(holed, up, 0.5);
  vtkIdType bad = 0;
  vtkDataArray* normals = holedSurface->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < holedSurface->GetNumberOfPoints(); ++i)
  {
    double p[3], m[3] = { 0.0, 0.0, 1.0 };
    holedSurface->GetPoint(i, p);
    if (normals)
    {
      normals->GetTuple(i, m);
    }
    bad += std::isfinite(p[0] + p[1] + p[2] + m[0] + m[1] + m[2]) ? 0 : 1;
  }
  Shape s = Measure(holedSurface, 0.5);
  STYLIZE_CHECK(nans > 0 && bad == 0 && normals && s.Points > 500 && s.MaxRadiusError < 0.25 * h,
    "NaN values: %lld non-finite points or normals of %lld, error %g", static_cast<long long>(bad),
    static_cast<long long>(s.Points), s.MaxRadiusError);
  // An infinite value at each end of the range (the range of the finite values is used).
  vtkNew<vtkUnstructuredGrid> infinite;
  infinite->DeepCopy(grid);
  infinite->GetPointData()->GetScalars()->SetTuple1(0, std::numeric_limits<double>::infinity());
  infinite->GetPointData()->GetScalars()->SetTuple1(1, -std::numeric_limits<double>::infinity());
  auto infiniteSurface = Surface(infinite, up, 0.5);
  bad = 0;
  for (vtkIdType i = 0; i < infiniteSurface->GetNumberOfPoints(); ++i)
  {
    double p[3];
    infiniteSurface->GetPoint(i, p);
    bad += std::isfinite(p[0] + p[1] + p[2]) ? 0 : 1;
  }
  s = Measure(infiniteSurface, 0.5);
  STYLIZE_CHECK(bad == 0 && s.Points > 1000 && s.MaxRadiusError < 0.25 * h,
    "infinite values: %lld non-finite points of %lld, error %g", static_cast<long long>(bad),
    static_cast<long long>(s.Points), s.MaxRadiusError);
}
}

int TestVolumeSurface(int, char*[])
{
  const double h = 2.0 / (N - 1);
  // The crossings of a rising and a falling ramp, and of a bump.
  {
    std::vector<bool> rising;
    auto up = Ramp(0.0, 1.0);
    std::vector<double> x = vtkStylizeVolumeSurface::Crossings(up, 0.3, -1.0, 2.0, &rising);
    STYLIZE_CHECK(x.size() == 1 && std::abs(x[0] - 0.3) < 1e-9 && rising[0], "rising ramp");
    vtkNew<vtkPiecewiseFunction> bump;
    bump->AddPoint(0.0, 0.0);
    bump->AddPoint(1.0, 1.0);
    bump->AddPoint(2.0, 0.0);
    x = vtkStylizeVolumeSurface::Crossings(bump, 0.5, 0.0, 2.0, &rising);
    STYLIZE_CHECK(x.size() == 2 && std::abs(x[0] - 0.5) < 1e-9 && std::abs(x[1] - 1.5) < 1e-9 &&
        rising[0] && !rising[1],
      "bump: %zu crossings", x.size());
    STYLIZE_CHECK(
      vtkStylizeVolumeSurface::Crossings(bump, 0.5, 0.6, 1.4).empty(), "inside the bump");
  }

  auto field = Field();
  // Rising: the ball r < 0.5 is opaque.
  {
    auto up = Ramp(0.0, 1.0);
    Shape s = Measure(Surface(field, up, 0.5), 0.5);
    STYLIZE_CHECK(s.Points > 1000 && s.OnFaces == 0, "sphere: %lld points, %lld on the faces",
      static_cast<long long>(s.Points), static_cast<long long>(s.OnFaces));
    STYLIZE_CHECK(s.MaxRadiusError < 0.25 * h, "sphere radius error %g", s.MaxRadiusError);
    STYLIZE_CHECK(s.Outward > 0.999 && s.Agreeing > 0.999,
      "sphere normals: outward %g, agreeing %g", s.Outward, s.Agreeing);
  }
  // Falling: the shell r > 0.5 is opaque, closed by the box's faces.
  {
    auto down = Ramp(1.0, 0.0);
    Shape s = Measure(Surface(field, down, 0.5), 0.5);
    STYLIZE_CHECK(s.MaxRadiusError < 0.25 * h, "inner sphere radius error %g", s.MaxRadiusError);
    STYLIZE_CHECK(s.Outward < 0.001 && s.Agreeing > 0.999, "shell normals: outward %g, agreeing %g",
      s.Outward, s.Agreeing);
    STYLIZE_CHECK(s.OnFaces > 6 * (N - 2) * (N - 2) / 2, "box faces: %lld points",
      static_cast<long long>(s.OnFaces));
    CheckCapValues(field, down);
  }
  // A piece of the image (x <= 0, a process's half, given as data): closed at its own face x = 0
  // unless the whole image's extent says that face is a cut, where the next piece goes on.
  {
    vtkNew<vtkImageData> piece;
    piece->ShallowCopy(field);
    piece->Crop(std::array<int, 6>{ 0, N / 2, 0, N - 1, 0, N - 1 }.data());
    auto down = Ramp(1.0, 0.0);
    auto onCut = [&](vtkPolyData* pd)
    {
      vtkIdType count = 0;
      for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
      {
        double p[3];
        pd->GetPoint(i, p);
        count += p[0] > 1e-6 ? 1 : 0; // (a cap lies between the cut and the padding sample)
      }
      return count;
    };
    const vtkIdType closed = onCut(Surface(piece, down, 0.5));
    vtkNew<vtkStylizeVolumeSurface> surface;
    surface->SetInputData(piece);
    surface->SetScalarOpacity(down);
    surface->SetOpacityThreshold(0.5);
    surface->SetWholeExtent(0, N - 1, 0, N - 1, 0, N - 1);
    surface->Update();
    const vtkIdType open = onCut(surface->GetOutput());
    Shape s = Measure(surface->GetOutput(), 0.5);
    STYLIZE_CHECK(
      closed > (N - 2) * (N - 2) / 2 && open == 0 && s.OnFaces > 0 && s.MaxRadiusError < 0.25 * h,
      "piece: %lld points on the cut closed, %lld with the whole extent, %lld on the box's faces",
      static_cast<long long>(closed), static_cast<long long>(open),
      static_cast<long long>(s.OnFaces));
  }
  // Isovalues instead of the crossings.
  {
    auto up = Ramp(0.0, 1.0);
    Shape s = Measure(Surface(field, up, 0.5, { 0.25 }), 0.75);
    STYLIZE_CHECK(
      s.Points > 1000 && s.MaxRadiusError < 0.25 * h, "isovalue 0.25: error %g", s.MaxRadiusError);
  }
  // Solid everywhere, nowhere; NaN threshold; empty input.
  {
    auto solid = Ramp(1.0, 1.0);
    auto pd = Surface(field, solid, 0.5);
    double b[6];
    pd->GetBounds(b);
    STYLIZE_CHECK(
      pd->GetNumberOfCells() > 0 && std::abs(b[0] + 1) < 1e-6 && std::abs(b[5] - 1) < 1e-6,
      "solid: the outer faces");
    auto clear = Ramp(0.0, 0.1);
    STYLIZE_CHECK(Surface(field, clear, 0.5)->GetNumberOfCells() == 0, "clear: nothing");
    auto up = Ramp(0.0, 1.0);
    STYLIZE_CHECK(
      Surface(field, up, std::numeric_limits<double>::quiet_NaN())->GetNumberOfCells() == 0,
      "NaN threshold: nothing");
    vtkNew<vtkImageData> empty;
    STYLIZE_CHECK(Surface(empty, up, 0.5)->GetNumberOfCells() == 0, "empty input");
  }
  // An unstructured grid, and cell scalars.
  {
    vtkNew<vtkAppendFilter> grid;
    grid->SetInputData(field);
    grid->Update();
    auto up = Ramp(0.0, 1.0);
    Shape s = Measure(Surface(grid->GetOutput(), up, 0.5), 0.5);
    STYLIZE_CHECK(s.Points > 1000 && s.MaxRadiusError < 0.25 * h && s.Agreeing > 0.99,
      "unstructured: error %g, agreeing %g", s.MaxRadiusError, s.Agreeing);
    // the shell r > 0.5, closed by the mesh's outer faces (no padding there: its boundary cut
    // along the isovalue), their normals pointing out of the box
    auto down = Ramp(1.0, 0.0);
    auto shell = Surface(grid->GetOutput(), down, 0.5);
    s = Measure(shell, 0.5);
    vtkIdType outward = 0, faces = 0;
    vtkDataArray* n = shell->GetPointData()->GetNormals();
    for (vtkIdType i = 0; n && i < shell->GetNumberOfPoints(); ++i)
    {
      double p[3], m[3];
      shell->GetPoint(i, p);
      n->GetTuple(i, m);
      const int axis = std::abs(p[0]) > std::abs(p[1]) ? (std::abs(p[0]) > std::abs(p[2]) ? 0 : 2)
                                                       : (std::abs(p[1]) > std::abs(p[2]) ? 1 : 2);
      if (std::abs(p[axis]) > 0.999 && std::abs(m[axis]) > 0.9)
      {
        ++faces;
        outward += m[axis] * p[axis] > 0.0 ? 1 : 0;
      }
    }
    STYLIZE_CHECK(s.OnFaces > 6 * (N - 2) * (N - 2) / 2 && faces > 0 && outward == faces &&
        s.MaxRadiusError < 0.25 * h,
      "unstructured shell: %lld points on the box's faces, %lld of %lld face normals outward",
      static_cast<long long>(s.OnFaces), static_cast<long long>(outward),
      static_cast<long long>(faces));
    CheckSplit(field, down);
    auto cells = Field(true);
    s = Measure(Surface(cells, up, 0.5), 0.5);
    STYLIZE_CHECK(
      s.Points > 1000 && s.MaxRadiusError < 0.5 * h, "cell scalars: error %g", s.MaxRadiusError);
    CheckNaNValues(grid->GetOutput(), up);
  }
  return Failures == 0 ? 0 : 1;
}
