#include "vtkStylizeFeatureLines.h"
#include "vtkStylizeFeatureLinesInternals.h"
#include "vtkStylizePrincipalCurvatures.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>

vtkStandardNewMacro(vtkStylizeFeatureLines);

namespace FL = vtkStylizeFeatureLinesInternals;
using namespace vtkStylizeMesh;

namespace
{
/** The input's surface, points within 1e-7 of its diagonal merged (so that split normals and
 * seams make no boundary). */
FL::Mesh WeldedMesh(vtkPolyData* input)
{
  FL::Mesh m;
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(input->GetPoints());
  surface->SetPolys(input->GetPolys());
  surface->SetStrips(input->GetStrips());
  if (!input->GetPoints() || input->GetNumberOfPoints() == 0)
  {
    return m;
  }
  // (vtkCleanPolyData, not the threaded vtkStaticCleanPolyData, whose merging within a
  // tolerance differs from run to run in VTK 9.1)
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputData(surface);
  clean->SetTolerance(1e-7); // of the diagonal: seams of parametric and CAD surfaces
  clean->ConvertLinesToPointsOff();
  clean->ConvertPolysToLinesOff();
  clean->ConvertStripsToPolysOff();
  clean->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  clean->Update();
  vtkPolyData* welded = clean->GetOutput();
  m.Faces = Triangles(welded);
  m.P.resize(static_cast<size_t>(welded->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < welded->GetNumberOfPoints(); ++i)
  {
    welded->GetPoint(i, m.P[i].data());
  }
  // Points of no face play no part; non-finite points would poison the diagonal.
  for (const Vec& p : m.P)
  {
    if (!std::isfinite(p[0] + p[1] + p[2]))
    {
      m.Faces.clear();
      m.P.clear();
      return m;
    }
  }
  FL::FinishMesh(m);
  return m;
}

/** The principal curvatures of the mesh, smoothed over `smoothing` times its diagonal. */
FL::Curvature Curvatures(const FL::Mesh& m, double smoothing)
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
    "suggestive" };
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
    cache.Curvatures = Curvatures(
      cache.Surface, own > 0.0 ? this->CurvatureSmoothing * cache.Surface.Diagonal / own : 0.0);
    FL::RidgesAndValleys(
      cache.Surface, cache.Curvatures, this->RidgeThreshold, cache.Ridges, cache.Valleys);
    cache.HasCurvature = true;
    ++this->CurvatureBuilds;
  }
  const FL::Mesh& mesh = cache.Surface;
  std::vector<FL::Segments> viewSegments(NUMBER_OF_KINDS);
  const FL::Segments* segments[NUMBER_OF_KINDS] = { &viewSegments[CONTOUR], &cache.Boundaries,
    &cache.Creases, &cache.Ridges, &cache.Valleys, &viewSegments[SUGGESTIVE_CONTOUR] };
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
void vtkStylizeFeatureLines::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "KindMask: " << this->KindMask << "\n";
  os << indent << "CreaseAngle: " << this->CreaseAngle << "\n";
  os << indent << "RidgeThreshold: " << this->RidgeThreshold << "\n";
  os << indent << "SuggestiveThreshold: " << this->SuggestiveThreshold << "\n";
  os << indent << "MinimumLength: " << this->MinimumLength << "\n";
  os << indent << "CurvatureSmoothing: " << this->CurvatureSmoothing << "\n";
  os << indent << "ObjectBounds: " << this->ObjectBounds[0] << " " << this->ObjectBounds[1] << " "
     << this->ObjectBounds[2] << " " << this->ObjectBounds[3] << " " << this->ObjectBounds[4] << " "
     << this->ObjectBounds[5] << "\n";
}
