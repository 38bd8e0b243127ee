#include "vtkStylizeVolumeSurface.h"

#include "vtkAppendPolyData.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellDataToPointData.h"
#include "vtkCleanPolyData.h"
#include "vtkClipPolyData.h"
#include "vtkContourFilter.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkFlyingEdges3D.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <iterator>

vtkStandardNewMacro(vtkStylizeVolumeSurface);
vtkCxxSetObjectMacro(vtkStylizeVolumeSurface, ScalarOpacity, vtkPiecewiseFunction);

namespace
{
/** Samples of the opacity function over the data's range when looking for its crossings: a
 * crossing closer than range/4096 to another one may be missed (both then vanish together). */
constexpr int Samples = 4096;

/** The chosen component of `array` as one float (double for double input) per point. */
vtkSmartPointer<vtkDataArray> ComponentOf(vtkDataArray* array, int component)
{
  vtkSmartPointer<vtkDataArray> out = array->GetDataType() == VTK_DOUBLE
    ? vtkSmartPointer<vtkDataArray>(vtkSmartPointer<vtkDoubleArray>::New())
    : vtkSmartPointer<vtkDataArray>(vtkSmartPointer<vtkFloatArray>::New());
  out->SetName(array->GetName() ? array->GetName() : "Scalars");
  out->SetNumberOfTuples(array->GetNumberOfTuples());
  vtkSMPTools::For(0, array->GetNumberOfTuples(),
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        out->SetComponent(i, 0, array->GetComponent(i, component));
      }
    });
  return out;
}

/**
 * The image's scalar on an extent grown by one sample on each face of `whole` that it touches
 * and where `opaque` holds for a sample on that face, the new samples set to `pad`: the opaque
 * region then ends inside the image. Returns null when nothing needs padding.
 */
vtkSmartPointer<vtkImageData> Padded(vtkImageData* image, vtkDataArray* values, const int whole[6],
  double pad, const std::function<bool(double)>& opaque)
{
  int e[6];
  image->GetExtent(e);
  int grown[6];
  std::copy(e, e + 6, grown);
  bool any = false;
  for (int face = 0; face < 6; ++face)
  {
    const int axis = face / 2;
    if (e[face] != whole[face] || e[2 * axis] > e[2 * axis + 1])
    {
      continue;
    }
    // Whether any sample on this face is opaque.
    int f[6];
    std::copy(e, e + 6, f);
    f[2 * axis] = f[2 * axis + 1] = e[face];
    bool hit = false;
    for (int k = f[4]; k <= f[5] && !hit; ++k)
    {
      for (int j = f[2]; j <= f[3] && !hit; ++j)
      {
        for (int i = f[0]; i <= f[1] && !hit; ++i)
        {
          int ijk[3] = { i, j, k };
          hit = opaque(values->GetComponent(image->ComputePointId(ijk), 0));
        }
      }
    }
    if (hit)
    {
      grown[face] += face % 2 ? 1 : -1;
      any = true;
    }
  }
  if (!any)
  {
    return nullptr;
  }
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->SetOrigin(image->GetOrigin());
  out->SetSpacing(image->GetSpacing());
  out->SetDirectionMatrix(image->GetDirectionMatrix());
  out->SetExtent(grown);
  vtkSmartPointer<vtkDataArray> padded;
  padded.TakeReference(values->NewInstance());
  padded->SetName(values->GetName());
  padded->SetNumberOfTuples(out->GetNumberOfPoints());
  const int nx = grown[1] - grown[0] + 1, ny = grown[3] - grown[2] + 1;
  vtkSMPTools::For(grown[4], grown[5] + 1,
    [&](int first, int last)
    {
      for (int k = first; k < last; ++k)
      {
        for (int j = grown[2]; j <= grown[3]; ++j)
        {
          for (int i = grown[0]; i <= grown[1]; ++i)
          {
            const vtkIdType o =
              (static_cast<vtkIdType>(k - grown[4]) * ny + (j - grown[2])) * nx + (i - grown[0]);
            const bool inside =
              i >= e[0] && i <= e[1] && j >= e[2] && j <= e[3] && k >= e[4] && k <= e[5];
            int ijk[3] = { i, j, k };
            padded->SetComponent(
              o, 0, inside ? values->GetComponent(image->ComputePointId(ijk), 0) : pad);
          }
        }
      }
    });
  out->GetPointData()->SetScalars(padded);
  return out;
}

/**
 * Turns the normals (and the triangles' order) of the surfaces at the values where the opaque
 * side is the lower one: every normal then points out of the opaque region, the contour filters'
 * normals pointing towards lower values.
 */
void OrientOutwards(
  vtkPolyData* surface, const std::vector<double>& values, const std::vector<bool>& rising)
{
  vtkDataArray* scalars = surface->GetPointData()->GetScalars();
  vtkDataArray* normals = surface->GetPointData()->GetNormals();
  if (!scalars || !normals || rising.size() != values.size())
  {
    return;
  }
  // (the nearest isovalue: the output's scalars may be floats)
  auto falling = [&](double s)
  {
    size_t nearest = 0;
    for (size_t v = 1; v < values.size(); ++v)
    {
      nearest = std::abs(s - values[v]) < std::abs(s - values[nearest]) ? v : nearest;
    }
    return !values.empty() && !rising[nearest];
  };
  for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
  {
    if (falling(scalars->GetComponent(p, 0)))
    {
      for (int c = 0; c < 3; ++c)
      {
        normals->SetComponent(p, c, -normals->GetComponent(p, c));
      }
    }
  }
  vtkCellArray* polys = surface->GetPolys();
  vtkNew<vtkCellArray> turned;
  turned->AllocateExact(polys->GetNumberOfCells(), polys->GetNumberOfConnectivityIds());
  std::vector<vtkIdType> ids;
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    vtkIdType n;
    const vtkIdType* pts;
    polys->GetCellAtId(c, n, pts);
    ids.assign(pts, pts + n);
    if (n > 0 && falling(scalars->GetComponent(pts[0], 0)))
    {
      std::reverse(ids.begin(), ids.end());
    }
    turned->InsertNextCell(n, ids.data());
  }
  surface->SetPolys(turned);
}

/**
 * The caps that close an image's opaque region at its whole extent's faces (the surface's points
 * past `image`'s own samples, toward the padding) take the data's value at the face (the image
 * trilinearly interpolated there), not the isovalue: a volume cut by its extent (a CT's top and
 * bottom) shows its data on the cut, as VTK's ray caster does. After OrientOutwards(), which
 * reads the isovalues.
 */
void ColourCaps(vtkPolyData* surface, vtkImageData* image, vtkDataArray* values)
{
  vtkDataArray* scalars = surface->GetPointData()->GetScalars();
  int e[6];
  image->GetExtent(e);
  if (!scalars || !values || e[0] > e[1] || e[2] > e[3] || e[4] > e[5])
  {
    return;
  }
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double x[3], ijk[3];
    surface->GetPoint(i, x);
    image->TransformPhysicalPointToContinuousIndex(x, ijk);
    bool outside = false;
    int lo[3];
    double t[3];
    for (int a = 0; a < 3; ++a)
    {
      outside = outside || ijk[a] < e[2 * a] - 1e-6 || ijk[a] > e[2 * a + 1] + 1e-6;
      const double c = std::min(std::max(ijk[a], double(e[2 * a])), double(e[2 * a + 1]));
      lo[a] = std::min(static_cast<int>(std::floor(c)), std::max(e[2 * a + 1] - 1, e[2 * a]));
      t[a] = c - lo[a];
    }
    if (!outside)
    {
      continue;
    }
    double v = 0.0;
    for (int corner = 0; corner < 8; ++corner)
    {
      int at[3];
      double w = 1.0;
      for (int a = 0; a < 3; ++a)
      {
        const int up = (corner >> a) & 1;
        at[a] = std::min(lo[a] + up, e[2 * a + 1]);
        w *= up ? t[a] : 1.0 - t[a];
      }
      if (w > 0.0)
      {
        v += w * values->GetComponent(image->ComputePointId(at), 0);
      }
    }
    scalars->SetComponent(i, 0, v);
  }
}

/** A key of a point's exact coordinates (-0 taken as 0): equal coordinates, equal keys. */
vtkTypeUInt64 PointKey(const double x[3])
{
  vtkTypeUInt64 h = 1469598103934665603ULL; // FNV-1a over the coordinates' bytes
  for (int i = 0; i < 3; ++i)
  {
    const double v = x[i] == 0.0 ? 0.0 : x[i];
    vtkTypeUInt64 bits;
    std::memcpy(&bits, &v, sizeof(bits));
    for (int b = 0; b < 8; ++b)
    {
      h = (h ^ ((bits >> (8 * b)) & 0xffu)) * 1099511628211ULL;
    }
  }
  return h;
}

/**
 * The outer faces of `data` (vtkDataSetSurfaceFilter), without those whose points all lie among
 * `shared` (sorted keys of other pieces' outer points: faces between pieces).
 */
vtkSmartPointer<vtkPolyData> OuterFaces(vtkDataSet* data, const std::vector<vtkTypeUInt64>& shared)
{
  vtkNew<vtkDataSetSurfaceFilter> faces;
  faces->SetInputData(data);
  faces->Update();
  auto outer = vtkSmartPointer<vtkPolyData>::New();
  outer->ShallowCopy(faces->GetOutput());
  if (shared.empty())
  {
    return outer;
  }
  vtkPoints* points = outer->GetPoints();
  std::vector<char> onShared(outer->GetNumberOfPoints());
  for (vtkIdType i = 0; i < outer->GetNumberOfPoints(); ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    onShared[i] = std::binary_search(shared.begin(), shared.end(), PointKey(x)) ? 1 : 0;
  }
  vtkNew<vtkCellArray> kept;
  vtkNew<vtkIdList> pts;
  vtkCellArray* polys = outer->GetPolys();
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    polys->GetCellAtId(c, pts);
    bool between = pts->GetNumberOfIds() > 0;
    for (vtkIdType k = 0; k < pts->GetNumberOfIds() && between; ++k)
    {
      between = onShared[pts->GetId(k)] != 0;
    }
    if (!between)
    {
      kept->InsertNextCell(pts);
    }
  }
  outer->GetCellData()->Initialize(); // (the kept faces no longer match the cell data)
  outer->SetPolys(kept);
  return outer;
}

/**
 * Where the opaque region (`opaque`: a scalar value's opacity at least the threshold) meets the
 * outer faces of a mesh that is not an image (no padding closes it there): those faces (but not
 * the faces between pieces: `shared`), cut along the isovalues, with their outward normals, so
 * that the region stays closed. The faces carry the scalar, so they are coloured by the data as
 * VTK's volume shows its boundary.
 */
vtkSmartPointer<vtkPolyData> BoundaryCaps(vtkDataSet* data, const std::vector<double>& isovalues,
  const std::vector<bool>& rising, const double range[2], const std::function<bool(double)>& opaque,
  const std::vector<vtkTypeUInt64>& shared)
{
  // The opaque intervals of the scalar: between a rising crossing and the next falling one,
  // from the range's start when the first crossing falls, to its end when the last rises.
  std::vector<std::pair<double, double>> intervals;
  double from = range[0];
  bool inside = isovalues.empty() ? opaque(0.5 * (range[0] + range[1])) : !rising[0];
  for (size_t i = 0; i < isovalues.size(); ++i)
  {
    if (rising[i])
    {
      from = isovalues[i];
      inside = true;
    }
    else if (inside)
    {
      intervals.emplace_back(from, isovalues[i]);
      inside = false;
    }
  }
  if (inside)
  {
    intervals.emplace_back(from, range[1]);
  }
  if (intervals.empty())
  {
    return nullptr;
  }
  vtkSmartPointer<vtkPolyData> faces = OuterFaces(data, shared);
  vtkNew<vtkAppendPolyData> append;
  for (const auto& interval : intervals)
  {
    vtkNew<vtkClipPolyData> above;
    above->SetInputData(faces);
    above->SetValue(interval.first);
    vtkNew<vtkClipPolyData> below;
    below->SetInputConnection(above->GetOutputPort());
    below->SetValue(interval.second);
    below->InsideOutOn();
    below->Update();
    vtkNew<vtkPolyData> piece;
    piece->ShallowCopy(below->GetOutput());
    append->AddInputData(piece);
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(append->GetOutputPort());
  normals->SplittingOff();
  normals->ConsistencyOff(); // (the surface filter's faces point out of the cells)
  normals->Update();
  return normals->GetOutput();
}

/**
 * `surface` without its cells that use a non-finite point, nor such points (a contour of
 * non-image data interpolates its edges' values: an edge with a NaN end gives a NaN point), and
 * each normal that is not finite replaced by the one the geometry gives there (the others kept:
 * the data's gradient); `surface` itself when all is finite.
 */
vtkSmartPointer<vtkPolyData> FiniteOnly(vtkPolyData* surface)
{
  auto finite = [](const double* v)
  { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); };
  const vtkIdType n = surface->GetNumberOfPoints();
  std::vector<char> bad(static_cast<size_t>(n), 0);
  bool any = false;
  for (vtkIdType i = 0; i < n; ++i)
  {
    bad[i] = !finite(surface->GetPoint(i));
    any = any || bad[i];
  }
  vtkDataArray* given = surface->GetPointData()->GetNormals();
  bool badNormals = false;
  for (vtkIdType i = 0; given && !badNormals && i < given->GetNumberOfTuples(); ++i)
  {
    badNormals = !bad[i] && !finite(given->GetTuple3(i));
  }
  if (!any && !badNormals)
  {
    return surface;
  }
  auto kept = vtkSmartPointer<vtkPolyData>::New();
  kept->DeepCopy(surface);
  if (any)
  {
    kept->BuildCells();
    for (vtkIdType c = 0; c < kept->GetNumberOfCells(); ++c)
    {
      vtkIdType count;
      const vtkIdType* ids;
      kept->GetCellPoints(c, count, ids);
      if (std::any_of(ids, ids + count, [&](vtkIdType id) { return bad[id] != 0; }))
      {
        kept->DeleteCell(c);
      }
    }
    kept->RemoveDeletedCells();
    vtkNew<vtkCleanPolyData> unused; // (drops the points no cell uses, merges none)
    unused->SetInputData(kept);
    unused->PointMergingOff();
    unused->Update();
    kept->ShallowCopy(unused->GetOutput());
  }
  vtkDataArray* normals = kept->GetPointData()->GetNormals();
  if (normals)
  {
    vtkNew<vtkPolyDataNormals> geometric; // (same points: no splitting)
    geometric->SetInputData(kept);
    geometric->SplittingOff();
    geometric->ConsistencyOff();
    geometric->Update();
    vtkDataArray* made = geometric->GetOutput()->GetPointData()->GetNormals();
    for (vtkIdType i = 0; made && i < normals->GetNumberOfTuples(); ++i)
    {
      if (!finite(normals->GetTuple3(i)))
      {
        normals->SetTuple(i, made->GetTuple3(i));
      }
    }
  }
  return kept;
}
}

//------------------------------------------------------------------------------
vtkStylizeVolumeSurface::vtkStylizeVolumeSurface()
{
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
vtkStylizeVolumeSurface::~vtkStylizeVolumeSurface()
{
  this->SetScalarOpacity(nullptr);
}

//------------------------------------------------------------------------------
void vtkStylizeVolumeSurface::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OpacityThreshold: " << this->OpacityThreshold << "\n";
  os << indent << "Component: " << this->Component << "\n";
  os << indent << "WholeExtent: " << this->WholeExtent[0] << " " << this->WholeExtent[1] << " "
     << this->WholeExtent[2] << " " << this->WholeExtent[3] << " " << this->WholeExtent[4] << " "
     << this->WholeExtent[5] << "\n";
  os << indent << "IsoValues: " << this->IsoValues.size() << "\n";
  os << indent << "SharedPoints: " << this->SharedPoints.size() << "\n";
  os << indent << "ScalarOpacity: " << this->ScalarOpacity << "\n";
}

//------------------------------------------------------------------------------
void vtkStylizeVolumeSurface::SetIsoValues(const std::vector<double>& values)
{
  std::vector<double> finite;
  std::copy_if(values.begin(), values.end(), std::back_inserter(finite),
    [](double v) { return std::isfinite(v); });
  if (finite != this->IsoValues)
  {
    this->IsoValues = finite;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkStylizeVolumeSurface::SetSharedPoints(const std::vector<vtkTypeUInt64>& keys)
{
  std::vector<vtkTypeUInt64> sorted = keys;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  if (sorted != this->SharedPoints)
  {
    this->SharedPoints.swap(sorted);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
std::vector<vtkTypeUInt64> vtkStylizeVolumeSurface::OuterPointKeys(vtkDataSet* data)
{
  std::vector<vtkTypeUInt64> keys;
  if (!data || data->GetNumberOfCells() == 0)
  {
    return keys;
  }
  vtkSmartPointer<vtkPolyData> outer = OuterFaces(data, {});
  keys.reserve(outer->GetNumberOfPoints());
  for (vtkIdType i = 0; i < outer->GetNumberOfPoints(); ++i)
  {
    double x[3];
    outer->GetPoint(i, x);
    keys.push_back(PointKey(x));
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkStylizeVolumeSurface::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  return this->ScalarOpacity ? std::max(t, this->ScalarOpacity->GetMTime()) : t;
}

//------------------------------------------------------------------------------
int vtkStylizeVolumeSurface::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  return 1;
}

//------------------------------------------------------------------------------
std::vector<double> vtkStylizeVolumeSurface::Crossings(vtkPiecewiseFunction* function,
  double threshold, double low, double high, std::vector<bool>* rising)
{
  std::vector<double> out;
  if (rising)
  {
    rising->clear();
  }
  if (!function || !(std::isfinite(low) && std::isfinite(high)) || !(high > low) ||
    !std::isfinite(threshold))
  {
    return out;
  }
  auto solid = [&](double x) { return function->GetValue(x) >= threshold; };
  double previous = low;
  bool was = solid(low);
  for (int i = 1; i <= Samples; ++i)
  {
    const double x = i == Samples ? high : low + (high - low) * i / Samples;
    const bool is = solid(x);
    if (is != was)
    {
      // Bisection to 1e-9 of the range (40 halvings of range/4096).
      double a = previous, b = x;
      for (int step = 0; step < 40; ++step)
      {
        const double m = 0.5 * (a + b);
        (solid(m) == was ? a : b) = m;
      }
      out.push_back(0.5 * (a + b));
      if (rising)
      {
        rising->push_back(is);
      }
    }
    previous = x;
    was = is;
  }
  return out;
}

//------------------------------------------------------------------------------
int vtkStylizeVolumeSurface::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  vtkDataArray* array = this->GetInputArrayToProcess(0, inputVector, association);
  if (!array && input && !input->GetPointData()->GetScalars())
  {
    array = input->GetCellData()->GetScalars(); // (as VTK's volume mappers fall back)
    association = vtkDataObject::FIELD_ASSOCIATION_CELLS;
  }
  if (!input || !array || input->GetNumberOfPoints() == 0)
  {
    return 1; // nothing to show
  }
  if (this->IsoValues.empty() && !this->ScalarOpacity)
  {
    vtkErrorMacro("No scalar opacity function and no isovalues.");
    return 0;
  }
  const int component = std::min(this->Component, array->GetNumberOfComponents() - 1);

  // The scalar on the points, one component.
  vtkSmartPointer<vtkDataSet> data;
  data.TakeReference(input->NewInstance());
  data->CopyStructure(input);
  vtkSmartPointer<vtkDataArray> values;
  if (association == vtkDataObject::FIELD_ASSOCIATION_CELLS)
  {
    vtkSmartPointer<vtkDataSet> cells;
    cells.TakeReference(input->NewInstance());
    cells->CopyStructure(input);
    cells->GetCellData()->SetScalars(ComponentOf(array, component));
    vtkNew<vtkCellDataToPointData> toPoints;
    toPoints->SetInputData(cells);
    toPoints->Update();
    values = toPoints->GetOutput()->GetPointData()->GetScalars();
  }
  else
  {
    values = ComponentOf(array, component);
  }
  if (!values)
  {
    return 1;
  }
  data->GetPointData()->SetScalars(values);

  // The isovalues: given, or where the opacity crosses the threshold.
  double range[2];
  values->GetFiniteRange(range, 0); // (an infinite value makes no range)
  std::vector<double> isovalues = this->IsoValues;
  std::vector<bool> rising(isovalues.size(), true);
  const bool crossings = isovalues.empty();
  const double threshold = this->OpacityThreshold;
  auto opaque = [&](double v) { return this->ScalarOpacity->GetValue(v) >= threshold; };
  if (crossings)
  {
    isovalues = Crossings(this->ScalarOpacity, threshold, range[0], range[1], &rising);
    if (isovalues.empty())
    {
      if (opaque(0.5 * (range[0] + range[1])))
      {
        // Opaque throughout: the volume shows its outer faces (the mesh's).
        vtkNew<vtkPolyDataNormals> normals;
        normals->SetInputData(OuterFaces(data,
          vtkImageData::SafeDownCast(data) ? std::vector<vtkTypeUInt64>() : this->SharedPoints));
        normals->SplittingOff();
        normals->Update();
        output->ShallowCopy(normals->GetOutput());
      }
      return 1;
    }
  }

  // Images: closed where the opaque region meets the whole extent's faces.
  vtkImageData* image = vtkImageData::SafeDownCast(data);
  vtkSmartPointer<vtkImageData> unpadded; // (kept: `data` moves on to the padded image)
  if (image && crossings)
  {
    vtkSmartPointer<vtkImageData> padded = this->PadToClose(image, values, range, inputVector);
    if (padded)
    {
      unpadded = image;
      data = padded;
      image = padded;
      double padRange[2];
      padded->GetPointData()->GetScalars()->GetRange(padRange, 0);
      isovalues = Crossings(this->ScalarOpacity, threshold, padRange[0], padRange[1], &rising);
    }
  }

  vtkSmartPointer<vtkPolyData> surface = this->Contour(data, image != nullptr, isovalues);
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->DeepCopy(surface);
  if (crossings)
  {
    OrientOutwards(result, isovalues, rising);
  }
  if (unpadded)
  {
    ColourCaps(result, unpadded, values);
  }
  // Other meshes: closed where the opaque region meets their outer faces.
  vtkSmartPointer<vtkPolyData> caps = !image && crossings
    ? BoundaryCaps(data, isovalues, rising, range, opaque, this->SharedPoints)
    : nullptr;
  if (caps && caps->GetNumberOfCells() > 0)
  {
    vtkNew<vtkAppendPolyData> both;
    both->AddInputData(result);
    both->AddInputData(caps);
    both->Update();
    result->ShallowCopy(both->GetOutput());
  }
  output->ShallowCopy(FiniteOnly(result));
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> vtkStylizeVolumeSurface::PadToClose(vtkImageData* image,
  vtkDataArray* values, const double range[2], vtkInformationVector** inputVector)
{
  // (padded with the most transparent value over the data's and the function's ranges)
  int whole[6];
  vtkInformation* info = inputVector[0]->GetInformationObject(0);
  const int* given = this->WholeExtent;
  if (given[0] <= given[1] && given[2] <= given[3] && given[4] <= given[5])
  {
    std::copy(given, given + 6, whole);
  }
  else if (info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  }
  else
  {
    image->GetExtent(whole);
  }
  vtkPiecewiseFunction* f = this->ScalarOpacity;
  const double low = std::min(range[0], f->GetRange()[0]);
  const double high = std::max(range[1], f->GetRange()[1]);
  double pad = low, least = f->GetValue(low);
  for (int i = 1; i <= Samples; ++i)
  {
    const double x = low + (high - low) * i / Samples;
    const double o = f->GetValue(x);
    if (o < least)
    {
      least = o;
      pad = x;
    }
  }
  const double threshold = this->OpacityThreshold;
  return least < threshold
    ? Padded(image, values, whole, pad, [&](double v) { return f->GetValue(v) >= threshold; })
    : nullptr;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkStylizeVolumeSurface::Contour(
  vtkDataSet* data, bool image, const std::vector<double>& isovalues)
{
  // Progress forwarded from the contour filter.
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(this);
  progress->SetCallback(
    [](vtkObject* caller, unsigned long, void* self, void*)
    {
      static_cast<vtkStylizeVolumeSurface*>(self)->UpdateProgress(
        0.9 * static_cast<vtkAlgorithm*>(caller)->GetProgress());
    });
  vtkSmartPointer<vtkPolyDataAlgorithm> contour;
  if (image)
  {
    auto edges = vtkSmartPointer<vtkFlyingEdges3D>::New();
    edges->ComputeNormalsOn();
    edges->ComputeScalarsOn();
    edges->ComputeGradientsOff();
    edges->SetNumberOfContours(static_cast<int>(isovalues.size()));
    for (size_t v = 0; v < isovalues.size(); ++v)
    {
      edges->SetValue(static_cast<int>(v), isovalues[v]);
    }
    contour = edges;
  }
  else
  {
    auto generic = vtkSmartPointer<vtkContourFilter>::New();
    generic->ComputeScalarsOn();
    generic->SetNumberOfContours(static_cast<int>(isovalues.size()));
    for (size_t v = 0; v < isovalues.size(); ++v)
    {
      generic->SetValue(static_cast<int>(v), isovalues[v]);
    }
    contour = generic;
  }
  contour->SetInputData(data);
  contour->AddObserver(vtkCommand::ProgressEvent, progress);
  contour->Update();
  vtkSmartPointer<vtkPolyData> surface = contour->GetOutput();
  if (!surface->GetPointData()->GetNormals() && surface->GetNumberOfCells() > 0)
  {
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(surface);
    normals->SplittingOff();
    normals->Update();
    surface = normals->GetOutput();
  }
  return surface;
}
