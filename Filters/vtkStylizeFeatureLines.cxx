#include "vtkStylizeFeatureLines.h"
#include "vtkStylizeFeatureLinesInternals.h"
#include "vtkStylizePrincipalCurvatures.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>

vtkStandardNewMacro(vtkStylizeFeatureLines);

namespace FL = vtkStylizeFeatureLinesInternals;
using namespace vtkStylizeMesh;

namespace
{
/** The input's surface, points within 1e-7 of its diagonal merged (so that split normals and
 * seams make no boundary), in the order of their first input point; points of no face left
 * out. Empty when a point of a face is not finite. */
FL::Mesh WeldedMesh(vtkPolyData* input)
{
  FL::Mesh m;
  vtkPoints* points = input->GetPoints();
  if (!points || input->GetNumberOfPoints() == 0)
  {
    return m;
  }
  const std::vector<FL::Face> faces = Triangles(input);
  const size_t np = static_cast<size_t>(input->GetNumberOfPoints());
  std::vector<Vec> p(np);
  std::vector<char> use(np, 0);
  vtkDataArray* coordinates = points->GetData();
  vtkSMPTools::For(0, static_cast<vtkIdType>(np),
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        coordinates->GetTuple(i, p[i].data());
      }
    });
  for (const FL::Face& f : faces)
  {
    for (const vtkIdType i : f)
    {
      use[i] = 1;
    }
  }
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (size_t i = 0; i < np; ++i)
  {
    if (use[i])
    {
      if (!std::isfinite(p[i][0] + p[i][1] + p[i][2]))
      {
        return m; // non-finite points would poison the diagonal
      }
      for (int a = 0; a < 3; ++a)
      {
        lo[a] = std::min(lo[a], p[i][a]);
        hi[a] = std::max(hi[a], p[i][a]);
      }
    }
  }
  const double diagonal = lo[0] <= hi[0]
    ? std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
        (hi[2] - lo[2]) * (hi[2] - lo[2]))
    : 0.0;
  // 1e-7 of the diagonal: seams of parametric and CAD surfaces.
  const std::vector<vtkIdType> representative = MergeCoincidentPoints(p, use, 1e-7 * diagonal);
  std::vector<vtkIdType> id(np, -1);
  for (size_t i = 0; i < np; ++i)
  {
    if (representative[i] == static_cast<vtkIdType>(i))
    {
      id[i] = static_cast<vtkIdType>(m.P.size());
      m.P.push_back(p[i]);
      m.Source.push_back(static_cast<vtkIdType>(i));
    }
  }
  m.Faces.reserve(faces.size());
  for (const FL::Face& f : faces)
  {
    const FL::Face g{ id[representative[f[0]]], id[representative[f[1]]],
      id[representative[f[2]]] };
    if (g[0] != g[1] && g[1] != g[2] && g[0] != g[2])
    {
      m.Faces.push_back(g);
    }
  }
  FL::FinishMesh(m);
  return m;
}

/** Forwards an inner filter's progress to its owner's range [From, To], and the owner's abort
 * to the inner filter. */
struct ForwardProgress
{
  vtkAlgorithm* Owner;
  double From, To;

  static void Call(vtkObject* caller, unsigned long, void* self, void* data)
  {
    const auto* f = static_cast<ForwardProgress*>(self);
    f->Owner->UpdateProgress(f->From + (f->To - f->From) * *static_cast<double*>(data));
    if (f->Owner->GetAbortExecute())
    {
      static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
    }
  }
};

/**
 * The principal curvatures of the mesh, smoothed over `smoothing` times its diagonal; the
 * filter's progress is owner's from 0.1 to 0.8, and owner's abort stops it (empty arrays).
 */
FL::Curvature Curvatures(const FL::Mesh& m, double smoothing, vtkAlgorithm* owner)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(m.P.size()));
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(static_cast<vtkIdType>(m.P.size()));
  for (size_t i = 0; i < m.P.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), m.P[i].data());
    normals->SetTuple(static_cast<vtkIdType>(i), m.Normal[i].data());
  }
  vtkNew<vtkCellArray> polys;
  for (const FL::Face& f : m.Faces)
  {
    polys->InsertNextCell(3, f.data());
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  mesh->GetPointData()->SetNormals(normals);
  vtkNew<vtkStylizePrincipalCurvatures> filter;
  filter->SetController(nullptr); // thresholds are relative to this mesh
  filter->SetInputData(mesh);
  filter->UseInputNormalsOn();
  filter->SetSmoothingRadius(smoothing);
  ForwardProgress forward{ owner, 0.1, 0.8 };
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(&forward);
  progress->SetCallback(&ForwardProgress::Call);
  filter->AddObserver(vtkCommand::ProgressEvent, progress);
  filter->Update();
  vtkPointData* pd = filter->GetOutput()->GetPointData();
  FL::Curvature c;
  const size_t np = m.P.size();
  auto scalars = [&](const char* name, std::vector<double>& out)
  {
    vtkDataArray* a = pd->GetArray(name);
    out.assign(np, 0.0);
    for (size_t i = 0; a && i < np; ++i)
    {
      out[i] = a->GetComponent(static_cast<vtkIdType>(i), 0);
    }
  };
  auto vectors = [&](const char* name, std::vector<Vec>& out)
  {
    vtkDataArray* a = pd->GetArray(name);
    out.assign(np, Vec{ 0, 0, 0 });
    for (size_t i = 0; a && i < np; ++i)
    {
      a->GetTuple(static_cast<vtkIdType>(i), out[i].data());
    }
  };
  scalars("PrincipalCurvatureMax", c.K1);
  scalars("PrincipalCurvatureMin", c.K2);
  vectors("PrincipalDirectionMax", c.E1);
  vectors("PrincipalDirectionMin", c.E2);
  vectors("PrincipalDirectionMaxAbs", c.EMaxAbs);
  return c;
}

/** The camera in the mesh's coordinates (through the inverse of the model matrix). */
FL::View MakeView(vtkCamera* camera, vtkMatrix4x4* model)
{
  FL::View view;
  vtkNew<vtkMatrix4x4> inverse;
  if (model)
  {
    vtkMatrix4x4::Invert(model, inverse);
  }
  view.Parallel = camera->GetParallelProjection() != 0;
  double eye[4] = { 0, 0, 0, 1 }, dir[4] = { 0, 0, 0, 0 };
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(dir);
  double e[4], d[4];
  inverse->MultiplyPoint(eye, e);
  inverse->MultiplyPoint(dir, d);
  view.Eye = { e[0] / e[3], e[1] / e[3], e[2] / e[3] };
  view.ToViewer = { -d[0], -d[1], -d[2] };
  if (!Normalize(view.ToViewer))
  {
    view.ToViewer = { 0, 0, 1 };
  }
  return view;
}
}

//------------------------------------------------------------------------------
vtkStylizeFeatureLines::vtkStylizeFeatureLines()
  : ViewIndependent(new vtkStylizeFeatureLinesInternals::Cache)
{
}

//------------------------------------------------------------------------------
vtkStylizeFeatureLines::~vtkStylizeFeatureLines() = default;

//------------------------------------------------------------------------------
const char* vtkStylizeFeatureLines::GetKindName(int kind)
{
  static const char* const names[] = { "contour", "boundary", "crease", "ridge", "valley",
    "suggestive", "isoline" };
  return kind >= 0 && kind < NUMBER_OF_KINDS ? names[kind] : "unknown";
}

//------------------------------------------------------------------------------
void vtkStylizeFeatureLines::EnableKind(int kind, bool enabled)
{
  if (kind >= 0 && kind < NUMBER_OF_KINDS)
  {
    this->SetKindMask(enabled ? (this->KindMask | (1 << kind)) : (this->KindMask & ~(1 << kind)));
  }
}

//------------------------------------------------------------------------------
bool vtkStylizeFeatureLines::IsKindEnabled(int kind) const
{
  return kind >= 0 && kind < NUMBER_OF_KINDS && (this->KindMask & (1 << kind)) != 0;
}

//------------------------------------------------------------------------------
void vtkStylizeFeatureLines::SetObjectBounds(const double bounds[6])
{
  double b[6];
  for (int i = 0; i < 6; ++i)
  {
    b[i] = bounds && std::isfinite(bounds[i]) ? bounds[i] : (i % 2 ? -1.0 : 1.0);
  }
  if (!std::equal(b, b + 6, this->ObjectBounds))
  {
    std::copy(b, b + 6, this->ObjectBounds);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkStylizeFeatureLines::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!input || !output)
  {
    return 0;
  }
  // What does not depend on the view is kept while the input and its settings stay: a new
  // camera recomputes only the contours and the suggestive contours. The curvature (the
  // costliest part) is computed the first time a frame needs it and kept: a still frame needs it
  // for ridges, valleys and suggestive contours, the interactive variant does not, and a drag
  // alternates the two (issue 52: each switch rebuilt the whole cache, seconds on 400k faces).
  FL::Cache& cache = *this->ViewIndependent;
  const bool curvature = this->IsKindEnabled(RIDGE) || this->IsKindEnabled(VALLEY) ||
    (this->Camera && this->IsKindEnabled(SUGGESTIVE_CONTOUR));
  FL::CacheKey key{ input, input->GetMTime(), this->CreaseAngle, this->RidgeThreshold,
    this->CurvatureSmoothing };
  std::copy(this->ObjectBounds, this->ObjectBounds + 6, key.ObjectBounds);
  if (!cache.Valid || !(cache.Key == key))
  {
    cache = FL::Cache();
    cache.Key = key;
    cache.Valid = true;
    cache.Surface = WeldedMesh(input);
    cache.OwnDiagonal = cache.Surface.Diagonal;
    ++this->ViewIndependentBuilds;
    // The thresholds' diagonal: the object's when given (a piece's lines as the whole's).
    const double* b = this->ObjectBounds;
    if (b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5])
    {
      const double d = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
        (b[5] - b[4]) * (b[5] - b[4]));
      if (d > 0.0 && std::isfinite(d))
      {
        cache.Surface.Diagonal = d;
      }
    }
    this->UpdateProgress(0.05);
    if (cache.Surface.Usable())
    {
      // Creases are found for the interior kinds too: they keep those off the creases.
      FL::EdgeLines(cache.Surface, this->CreaseAngle, cache.Boundaries, cache.Creases);
    }
  }
  if (curvature && !cache.HasCurvature && cache.Surface.Usable())
  {
    // (the curvature filter's radius is a fraction of the piece's own diagonal)
    const double own = cache.OwnDiagonal;
    cache.Curvatures = Curvatures(cache.Surface,
      own > 0.0 ? this->CurvatureSmoothing * cache.Surface.Diagonal / own : 0.0, this);
    if (this->GetAbortExecute())
    {
      cache.Curvatures = FL::Curvature();
      return 1; // interrupted: no lines; nothing is kept, the next execution starts over
    }
    FL::RidgesAndValleys(
      cache.Surface, cache.Curvatures, this->RidgeThreshold, cache.Ridges, cache.Valleys);
    cache.HasCurvature = true;
    ++this->CurvatureBuilds;
    this->UpdateProgress(0.9);
  }
  const FL::Mesh& mesh = cache.Surface;
  std::vector<FL::Segments> viewSegments(NUMBER_OF_KINDS);
  const FL::Segments* segments[NUMBER_OF_KINDS] = { &viewSegments[CONTOUR], &cache.Boundaries,
    &cache.Creases, &cache.Ridges, &cache.Valleys, &viewSegments[SUGGESTIVE_CONTOUR],
    &viewSegments[ISOLINE] };
  if (mesh.Usable() && this->IsKindEnabled(ISOLINE) && this->IsoLineCount > 0)
  {
    this->IsoLineSegments(input, mesh, viewSegments[ISOLINE]);
  }
  if (mesh.Usable() && this->Camera)
  {
    const FL::View v = MakeView(this->Camera, this->ModelMatrix);
    if (this->IsKindEnabled(CONTOUR))
    {
      FL::Contours(mesh, v, viewSegments[CONTOUR]);
    }
    if (this->IsKindEnabled(SUGGESTIVE_CONTOUR))
    {
      FL::SuggestiveContours(
        mesh, cache.Curvatures, v, this->SuggestiveThreshold, viewSegments[SUGGESTIVE_CONTOUR]);
    }
  }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> pointKind, cellKind;
  pointKind->SetName("FeatureKind");
  cellKind->SetName("FeatureKind");
  vtkNew<vtkFloatArray> strength;
  strength->SetName("FeatureStrength");
  const double minimum = this->MinimumLength * mesh.Diagonal;
  for (int kind = 0; kind < NUMBER_OF_KINDS; ++kind)
  {
    if (!this->IsKindEnabled(kind))
    {
      continue;
    }
    const bool interior = kind == RIDGE || kind == VALLEY || kind == SUGGESTIVE_CONTOUR;
    for (const FL::Chain& chain : FL::ChainSegments(*segments[kind]))
    {
      if (chain.size() < 2 || (interior && FL::ChainLength(chain) < minimum))
      {
        continue;
      }
      lines->InsertNextCell(static_cast<vtkIdType>(chain.size()));
      for (const FL::End& e : chain)
      {
        lines->InsertCellPoint(points->InsertNextPoint(e.P.data()));
        pointKind->InsertNextValue(static_cast<unsigned char>(kind));
        strength->InsertNextValue(e.Strength);
      }
      cellKind->InsertNextValue(static_cast<unsigned char>(kind));
    }
  }
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetPointData()->AddArray(pointKind);
  output->GetPointData()->AddArray(strength);
  output->GetCellData()->AddArray(cellKind);
  return 1;
}

//------------------------------------------------------------------------------
void vtkStylizeFeatureLines::IsoLineSegments(
  vtkPolyData* input, const FL::Mesh& mesh, FL::Segments& out)
{
  vtkPointData* pd = input->GetPointData();
  vtkDataArray* array = this->IsoLineArrayName.empty()
    ? pd->GetScalars()
    : pd->GetArray(this->IsoLineArrayName.c_str());
  const int components = array ? array->GetNumberOfComponents() : 0;
  const int component = components == 1 ? 0 : this->IsoLineComponent;
  if (!array || component >= components || array->GetNumberOfTuples() < input->GetNumberOfPoints())
  {
    return;
  }
  // The values at the welded mesh's vertices (each stands for its first input point).
  std::vector<double> values(mesh.P.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(values.size()),
    [&](vtkIdType first, vtkIdType last)
    {
      std::vector<double> tuple(components);
      for (vtkIdType i = first; i < last; ++i)
      {
        if (component >= 0)
        {
          values[i] = array->GetComponent(mesh.Source[i], component);
          continue;
        }
        array->GetTuple(mesh.Source[i], tuple.data());
        double sum = 0.0;
        for (const double c : tuple)
        {
          sum += c * c;
        }
        values[i] = std::sqrt(sum);
      }
    });
  double range[2] = { this->IsoLineRange[0], this->IsoLineRange[1] };
  if (!(range[0] <= range[1]))
  {
    range[0] = VTK_DOUBLE_MAX;
    range[1] = -VTK_DOUBLE_MAX;
    for (const double v : values)
    {
      if (std::isfinite(v) && (!this->IsoLineLogScale || v > 0.0))
      {
        range[0] = std::min(range[0], v);
        range[1] = std::max(range[1], v);
      }
    }
  }
  FL::IsoLines(mesh, values,
    ComputeIsoLevels(range[0], range[1], this->IsoLineCount, this->IsoLineSpacing,
      this->IsoLineBands, this->IsoLineLogScale),
    out);
}

//------------------------------------------------------------------------------
namespace
{
/** Round levels in (low, high): multiples of the smallest step of 1, 2, 2.5 or 5 times a power
 * of ten that gives at most `count` of them. */
std::vector<double> RoundLevels(double low, double high, int count)
{
  std::vector<double> levels;
  const double span = high - low;
  if (!(span > 0.0) || !std::isfinite(span) || count < 1)
  {
    return levels;
  }
  double power = std::pow(10.0, std::floor(std::log10(span / (count + 1))));
  for (int tries = 0; tries < 8 && levels.empty(); ++tries, power *= 10.0)
  {
    for (const double m : { 1.0, 2.0, 2.5, 5.0 })
    {
      const double step = m * power;
      const double first = std::floor(low / step) + 1.0;
      const double last = std::ceil(high / step) - 1.0;
      if (last - first + 1.0 <= count)
      {
        // (counted: beyond 2^53 a double's k + 1 is k again)
        const int n = static_cast<int>(last - first) + 1;
        for (int k = 0; k < n; ++k)
        {
          levels.push_back((first + k) * step);
        }
        break;
      }
    }
  }
  return levels;
}

/** Round levels in (low, high), low > 0, on a log scale: every power of ten, or every k-th,
 * when there are at least `count` of them; else 1 to 9, 1, 2 and 5, or 1 times each, the densest
 * that gives at most `count`; a range too narrow for those: linear round levels. */
std::vector<double> RoundLogLevels(double low, double high, int count)
{
  std::vector<double> levels;
  const double a = std::log10(low), b = std::log10(high);
  if (!(b > a) || !std::isfinite(a) || !std::isfinite(b) || count < 1)
  {
    return levels;
  }
  const int e0 = static_cast<int>(std::floor(a)), e1 = static_cast<int>(std::ceil(b));
  auto take = [&](const std::vector<double>& mantissas, int every)
  {
    levels.clear();
    for (int e = e0; e <= e1; ++e)
    {
      for (const double m : mantissas)
      {
        const double v = m * std::pow(10.0, e);
        if (v > low && v < high && (e % every) == 0)
        {
          levels.push_back(v);
        }
      }
    }
    return levels.size() <= static_cast<size_t>(count);
  };
  if (take({ 1, 2, 3, 4, 5, 6, 7, 8, 9 }, 1) || take({ 1, 2, 5 }, 1))
  {
    return levels;
  }
  for (int every = 1; every <= e1 - e0 + 1; ++every)
  {
    if (take({ 1 }, every))
    {
      return levels;
    }
  }
  return levels;
}
}

//------------------------------------------------------------------------------
std::vector<double> vtkStylizeFeatureLines::ComputeIsoLevels(
  double low, double high, int count, int spacing, int bands, bool logScale)
{
  std::vector<double> levels;
  if (!(low < high) || !std::isfinite(low) || !std::isfinite(high) || (logScale && !(low > 0.0)))
  {
    return levels;
  }
  count = std::max(0, std::min(1000, count));
  if (spacing == ROUND)
  {
    levels = logScale ? RoundLogLevels(low, high, count) : RoundLevels(low, high, count);
    return !levels.empty() || !logScale ? levels : RoundLevels(low, high, count);
  }
  const int parts = spacing == BANDS ? std::max(1, std::min(1000, bands)) : count + 1;
  const double a = logScale ? std::log10(low) : low;
  const double b = logScale ? std::log10(high) : high;
  for (int i = 1; i < parts; ++i)
  {
    const double v = a + (b - a) * i / parts;
    levels.push_back(logScale ? std::pow(10.0, v) : v);
  }
  return levels;
}

//------------------------------------------------------------------------------
void vtkStylizeFeatureLines::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "KindMask: " << this->KindMask << "\n";
  os << indent << "CreaseAngle: " << this->CreaseAngle << "\n";
  os << indent << "IsoLineArrayName: " << this->IsoLineArrayName << "\n";
  os << indent << "IsoLineComponent: " << this->IsoLineComponent << "\n";
  os << indent << "IsoLineCount: " << this->IsoLineCount << "\n";
  os << indent << "IsoLineSpacing: " << this->IsoLineSpacing << "\n";
  os << indent << "IsoLineBands: " << this->IsoLineBands << "\n";
  os << indent << "IsoLineRange: " << this->IsoLineRange[0] << " " << this->IsoLineRange[1] << "\n";
  os << indent << "IsoLineLogScale: " << this->IsoLineLogScale << "\n";
  os << indent << "RidgeThreshold: " << this->RidgeThreshold << "\n";
  os << indent << "SuggestiveThreshold: " << this->SuggestiveThreshold << "\n";
  os << indent << "MinimumLength: " << this->MinimumLength << "\n";
  os << indent << "CurvatureSmoothing: " << this->CurvatureSmoothing << "\n";
  os << indent << "ObjectBounds: " << this->ObjectBounds[0] << " " << this->ObjectBounds[1] << " "
     << this->ObjectBounds[2] << " " << this->ObjectBounds[3] << " " << this->ObjectBounds[4] << " "
     << this->ObjectBounds[5] << "\n";
}
