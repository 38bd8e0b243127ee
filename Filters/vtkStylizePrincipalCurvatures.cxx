#include "vtkStylizePrincipalCurvatures.h"

#include "vtkSMPTools.h"
#include "vtkStylizeMeshGeometry.h"
#include "vtkStylizeTensorSmoothing.h"

#include "vtkCellArray.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkStylizePrincipalCurvatures);

namespace
{
using namespace vtkStylizeMesh;

/** The triangulated surface with each vertex's normal and tangent frame (u, v, normal). */
struct Surface
{
  std::vector<std::array<vtkIdType, 3>> Faces; // non-degenerate triangles (distinct ids)
  std::vector<Vec> P;                          // the points
  std::vector<Vec> Normal;                     // unit where Valid
  std::vector<bool> Valid;                     // the normal is defined
  std::vector<Vec> FrameU, FrameV;             // unit tangents where Framed
  std::vector<bool> Framed;                    // the vertex has a face and a valid normal
};

/**
 * The points and unit point normals of s: the input's normals (useInput and the input has
 * 3-component point normals), or corner-angle weighted face normals. Valid marks the points
 * whose normal could be normalized.
 */
void ComputeNormals(vtkPolyData* input, bool useInput, Surface& s)
{
  const vtkIdType np = input->GetNumberOfPoints();
  s.P.assign(static_cast<size_t>(np), Vec{ 0, 0, 0 });
  s.Normal.assign(static_cast<size_t>(np), Vec{ 0, 0, 0 });
  vtkDataArray* inNormals = input->GetPointData()->GetNormals();
  const bool given = useInput && inNormals && inNormals->GetNumberOfComponents() == 3;
  vtkDataArray* points = np > 0 ? input->GetPoints()->GetData() : nullptr;
  vtkSMPTools::For(0, np,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        points->GetTuple(i, s.P[i].data());
        if (given)
        {
          inNormals->GetTuple(i, s.Normal[i].data());
        }
      }
    });
  if (!given)
  {
    s.Normal = vtkStylizeMesh::AngleWeightedNormals(s.P, s.Faces);
  }
  s.Valid.assign(static_cast<size_t>(np), false);
  for (vtkIdType i = 0; i < np; ++i)
  {
    s.Valid[i] = Normalize(s.Normal[i]);
  }
}

/**
 * Each vertex's tangent frame: u along the first edge of its first face, projected onto the
 * tangent plane (any tangent when that edge is along the normal), v = normal x u.
 */
void ComputeFrames(Surface& s)
{
  const size_t np = s.P.size();
  s.FrameU.assign(np, Vec{ 0, 0, 0 });
  s.FrameV.assign(np, Vec{ 0, 0, 0 });
  s.Framed.assign(np, false);
  for (const auto& f : s.Faces)
  {
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType i = f[k];
      if (s.Framed[i] || !s.Valid[i])
      {
        continue;
      }
      Vec e = Sub(s.P[f[(k + 1) % 3]], s.P[i]);
      e = Sub(e, Scale(s.Normal[i], Dot(e, s.Normal[i])));
      if (!Normalize(e))
      {
        e = Perpendicular(s.Normal[i]);
      }
      s.FrameU[i] = e;
      s.FrameV[i] = Cross(s.Normal[i], e);
      s.Framed[i] = true;
    }
  }
}

/** One face's second fundamental form (FE, FF, FG) in its own frame (T, B, N). */
struct FaceForm
{
  Vec E[3];         // edge k, opposite corner k: E[0] = p2 - p1, E[1] = p0 - p2, E[2] = p1 - p0
  Vec T, B, N;      // unit: along E[0], in-plane normal to it, the face normal
  double TwiceArea; // |E[0] x E[1]|, in world units squared
  double FE, FF, FG;
};

/**
 * Fits the face's second fundamental form, by least squares, to the change of the vertex
 * normals along its three edges. False for a degenerate face (no area, or a singular system,
 * as where a parametric surface closes on itself) or a non-finite result.
 */
bool FitFaceForm(const Surface& s, const std::array<vtkIdType, 3>& f, FaceForm& form)
{
  const std::vector<Vec>& p = s.P;
  form.E[0] = Sub(p[f[2]], p[f[1]]);
  form.E[1] = Sub(p[f[0]], p[f[2]]);
  form.E[2] = Sub(p[f[1]], p[f[0]]);
  const Vec* e = form.E;
  form.T = e[0];
  form.N = Cross(e[0], e[1]);
  form.TwiceArea = Norm(form.N);
  if (!Normalize(form.T) || !Normalize(form.N))
  {
    return false;
  }
  const Vec& t = form.T;
  form.B = Cross(form.N, t);
  const Vec& b = form.B;
  // Least squares for (e, f, g): [u v 0; 0 u v] x = [dn.t; dn.b] over the three edges.
  double m[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
  double r[3] = { 0, 0, 0 };
  for (int k = 0; k < 3; ++k)
  {
    const Vec dn = Sub(s.Normal[f[(k + 2) % 3]], s.Normal[f[(k + 1) % 3]]);
    const double u = Dot(e[k], t), v = Dot(e[k], b);
    const double du = Dot(dn, t), dv = Dot(dn, b);
    m[0][0] += u * u;
    m[0][1] += u * v;
    m[1][1] += u * u + v * v;
    m[1][2] += u * v;
    m[2][2] += v * v;
    r[0] += u * du;
    r[1] += v * du + u * dv;
    r[2] += v * dv;
  }
  m[1][0] = m[0][1];
  m[2][1] = m[1][2];
  // The system scaled to unit trace (vtkMath's pivot test is absolute: a tiny face would fail
  // it), and a singular system skipped here, before vtkMath warns about it.
  const double trace = m[0][0] + m[1][1] + m[2][2];
  if (!(trace > 0.0) || !std::isfinite(trace))
  {
    return false;
  }
  for (int i = 0; i < 3; ++i)
  {
    r[i] /= trace;
    for (int j = 0; j < 3; ++j)
    {
      m[i][j] /= trace;
    }
  }
  if (!(std::abs(vtkMath::Determinant3x3(m)) > 1e-9))
  {
    return false;
  }
  double* rows[3] = { m[0], m[1], m[2] };
  if (!vtkMath::SolveLinearSystem(rows, r, 3))
  {
    return false;
  }
  form.FE = r[0];
  form.FF = r[1];
  form.FG = r[2];
  return std::isfinite(form.FE) && std::isfinite(form.FF) && std::isfinite(form.FG);
}

/** The mixed Voronoi areas of the face's three corners (Meyer et al. 2003), world units^2. */
void CornerAreas(const FaceForm& form, double corner[3])
{
  const Vec* e = form.E;
  const double l[3] = { Dot(e[0], e[0]), Dot(e[1], e[1]), Dot(e[2], e[2]) };
  const double area = 0.5 * form.TwiceArea;
  const double ew[3] = { l[0] * (l[1] + l[2] - l[0]), l[1] * (l[2] + l[0] - l[1]),
    l[2] * (l[0] + l[1] - l[2]) };
  if (ew[0] <= 0.0)
  {
    corner[0] = 0.5 * area;
    corner[1] = corner[2] = 0.25 * area;
  }
  else if (ew[1] <= 0.0)
  {
    corner[1] = 0.5 * area;
    corner[0] = corner[2] = 0.25 * area;
  }
  else if (ew[2] <= 0.0)
  {
    corner[2] = 0.5 * area;
    corner[0] = corner[1] = 0.25 * area;
  }
  else
  {
    // Voronoi areas: corner k gets (|e_{k+1}|^2 cot(angle k+1) + |e_{k+2}|^2 cot(angle k+2))/8,
    // the cotangent of the angle at corner j being -(e_{j+1} . e_{j+2}) / (2 area).
    double cotangent[3];
    for (int j = 0; j < 3; ++j)
    {
      cotangent[j] = -Dot(e[(j + 1) % 3], e[(j + 2) % 3]) / form.TwiceArea;
    }
    for (int k = 0; k < 3; ++k)
    {
      const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      corner[k] = 0.125 * (l[k1] * cotangent[k1] + l[k2] * cotangent[k2]);
    }
  }
}

/**
 * Per face: the fitted form rotated into each vertex's frame and accumulated with the vertex's
 * mixed Voronoi area (tensor: the sums of area times (A, B, C), weight: the sums of the areas).
 */
void AccumulateTensors(
  const Surface& s, std::vector<std::array<double, 3>>& tensor, std::vector<double>& weight)
{
  tensor.assign(s.P.size(), { 0, 0, 0 });
  weight.assign(s.P.size(), 0.0);
  // Per face, on threads: each corner's (area times (A, B, C), area), zeros where undefined;
  // summed at the vertices in face order.
  ForFacesInOrder<12>(
    s.Faces.size(),
    [&](size_t index, std::array<double, 12>& out)
    {
      out.fill(0.0);
      const auto& f = s.Faces[index];
      FaceForm form;
      if (!s.Valid[f[0]] || !s.Valid[f[1]] || !s.Valid[f[2]] || !FitFaceForm(s, f, form))
      {
        return;
      }
      double corner[3];
      CornerAreas(form, corner);
      const Vec &t = form.T, &b = form.B, &n = form.N;
      for (int k = 0; k < 3; ++k)
      {
        const vtkIdType i = f[k];
        const double c = Dot(s.Normal[i], n);
        if (c <= -0.999999)
        {
          continue; // the vertex faces away from the face: no defined rotation
        }
        const Vec a1 = Rotate(s.Normal[i], n, s.FrameU[i]);
        const Vec a2 = Rotate(s.Normal[i], n, s.FrameV[i]);
        const double au = Dot(a1, t), av = Dot(a1, b);
        const double bu = Dot(a2, t), bv = Dot(a2, b);
        const double w = corner[k];
        double* o = out.data() + 4 * k;
        o[0] = w * (au * au * form.FE + 2.0 * au * av * form.FF + av * av * form.FG);
        o[1] = w * (au * bu * form.FE + (au * bv + av * bu) * form.FF + av * bv * form.FG);
        o[2] = w * (bu * bu * form.FE + 2.0 * bu * bv * form.FF + bv * bv * form.FG);
        o[3] = w;
      }
    },
    [&](size_t index, const std::array<double, 12>& v)
    {
      for (int k = 0; k < 3; ++k)
      {
        const vtkIdType i = s.Faces[index][k];
        for (int c = 0; c < 3; ++c)
        {
          tensor[i][c] += v[4 * k + c];
        }
        weight[i] += v[4 * k + 3];
      }
    });
  // The tensors per unit area, in each point's frame; zero (and no weight) where undefined.
  for (size_t i = 0; i < s.P.size(); ++i)
  {
    const bool ok = weight[i] > 0.0 && s.Framed[i] &&
      std::all_of(
        tensor[i].begin(), tensor[i].end(), [&](double v) { return std::isfinite(v / weight[i]); });
    for (double& v : tensor[i])
    {
      v = ok ? v / weight[i] : 0.0;
    }
    weight[i] = ok ? weight[i] : 0.0;
  }
}

/** What the eigen decomposition of the tensors writes: the output's point-data arrays. */
struct CurvatureArrays
{
  vtkSmartPointer<vtkDoubleArray> KMax, KMin, Mean, Gauss;
  vtkSmartPointer<vtkFloatArray> DMax, DMin, Bisector, DMinAbs, DMaxAbs;

  /** Every array named, with np zero tuples. */
  explicit CurvatureArrays(vtkIdType np)
  {
    auto makeArray = [np](const char* name, int comps)
    {
      vtkNew<vtkDoubleArray> a;
      a->SetName(name);
      a->SetNumberOfComponents(comps);
      a->SetNumberOfTuples(np);
      a->Fill(0.0);
      return vtkSmartPointer<vtkDoubleArray>(a);
    };
    auto makeDirections = [np](const char* name)
    {
      vtkNew<vtkFloatArray> a;
      a->SetName(name);
      a->SetNumberOfComponents(3);
      a->SetNumberOfTuples(np);
      a->Fill(0.0);
      return vtkSmartPointer<vtkFloatArray>(a);
    };
    this->KMax = makeArray("PrincipalCurvatureMax", 1);
    this->KMin = makeArray("PrincipalCurvatureMin", 1);
    this->DMax = makeDirections("PrincipalDirectionMax");
    this->DMin = makeDirections("PrincipalDirectionMin");
    this->Bisector = makeDirections("PrincipalDirectionBisector");
    this->DMinAbs = makeDirections("PrincipalDirectionMinAbs");
    this->DMaxAbs = makeDirections("PrincipalDirectionMaxAbs");
    this->Mean = makeArray("MeanCurvature", 1);
    this->Gauss = makeArray("GaussianCurvature", 1);
  }

  /** Adds the arrays to pd, and marks the one of tangentDirection as its tangents. */
  void AddTo(vtkPointData* pd, int tangentDirection) const
  {
    for (vtkDataArray* a : { static_cast<vtkDataArray*>(this->KMax),
           static_cast<vtkDataArray*>(this->KMin), static_cast<vtkDataArray*>(this->DMax),
           static_cast<vtkDataArray*>(this->DMin), static_cast<vtkDataArray*>(this->Bisector),
           static_cast<vtkDataArray*>(this->DMinAbs), static_cast<vtkDataArray*>(this->DMaxAbs),
           static_cast<vtkDataArray*>(this->Mean), static_cast<vtkDataArray*>(this->Gauss) })
    {
      pd->AddArray(a);
    }
    vtkFloatArray* const tangents[] = { nullptr, this->DMinAbs, this->DMaxAbs, this->DMin,
      this->DMax, this->Bisector };
    if (tangents[tangentDirection])
    {
      pd->SetTangents(tangents[tangentDirection]);
    }
  }
};

/**
 * The principal curvatures and directions of point i's 2x2 tensor (A, B, C) in its frame,
 * written to the arrays' tuple i. The MinAbs/MaxAbs directions stay zero at planar points (the
 * larger |k| times diagonal not above planarTolerance) and umbilic points (k1 - k2 not above
 * umbilicTolerance times |k1| + |k2|).
 */
void DecomposePoint(const Surface& s, const std::array<double, 3>& tensor, double weight,
  double diagonal, double planarTolerance, double umbilicTolerance, size_t i, CurvatureArrays& out)
{
  const double A = tensor[0], B = tensor[1], C = tensor[2];
  if (!(weight > 0.0) || !s.Framed[i] || !std::isfinite(A) || !std::isfinite(B) ||
    !std::isfinite(C))
  {
    return;
  }
  const double half = 0.5 * (A + C);
  const double radius = std::hypot(0.5 * (A - C), B);
  const double k1 = half + radius, k2 = half - radius;
  const double theta = 0.5 * std::atan2(2.0 * B, A - C);
  const double ct = std::cos(theta), st = std::sin(theta);
  const Vec d1 = Add(Scale(s.FrameU[i], ct), Scale(s.FrameV[i], st));
  const Vec d2 = Add(Scale(s.FrameU[i], -st), Scale(s.FrameV[i], ct));
  const Vec bis = Scale(Add(d1, d2), 1.0 / std::sqrt(2.0));
  const vtkIdType id = static_cast<vtkIdType>(i);
  out.KMax->SetValue(id, k1);
  out.KMin->SetValue(id, k2);
  out.DMax->SetTuple(id, d1.data());
  out.DMin->SetTuple(id, d2.data());
  out.Bisector->SetTuple(id, bis.data());
  out.Mean->SetValue(id, half);
  out.Gauss->SetValue(id, k1 * k2);
  const double larger = std::max(std::abs(k1), std::abs(k2));
  const bool planar = !(larger * diagonal > planarTolerance);
  const bool umbilic = !(k1 - k2 > umbilicTolerance * (std::abs(k1) + std::abs(k2)));
  if (!planar && !umbilic)
  {
    const bool maxIsLarger = std::abs(k1) >= std::abs(k2);
    out.DMinAbs->SetTuple(id, (maxIsLarger ? d2 : d1).data());
    out.DMaxAbs->SetTuple(id, (maxIsLarger ? d1 : d2).data());
  }
}

/** DecomposePoint() for every point, on vtkSMPTools' threads (each writes its own tuples). */
void Decompose(const Surface& s, const std::vector<std::array<double, 3>>& tensor,
  const std::vector<double>& weight, double diagonal, double planarTolerance,
  double umbilicTolerance, CurvatureArrays& out)
{
  vtkSMPTools::For(0, static_cast<vtkIdType>(s.P.size()),
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType p = first; p < last; ++p)
      {
        DecomposePoint(s, tensor[p], weight[p], diagonal, planarTolerance, umbilicTolerance,
          static_cast<size_t>(p), out);
      }
    });
}
}

//------------------------------------------------------------------------------
void vtkStylizePrincipalCurvatures::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UseInputNormals: " << this->UseInputNormals << "\n";
  os << indent << "SmoothingRadius: " << this->SmoothingRadius << "\n";
  os << indent << "SmoothingCellSize: " << this->SmoothingCellSize << "\n";
  os << indent << "MaximumNeighbors: " << this->MaximumNeighbors << "\n";
  os << indent << "PlanarTolerance: " << this->PlanarTolerance << "\n";
  os << indent << "UmbilicTolerance: " << this->UmbilicTolerance << "\n";
  os << indent << "TangentDirection: " << this->TangentDirection << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
}

//------------------------------------------------------------------------------
vtkCxxSetObjectMacro(vtkStylizePrincipalCurvatures, Controller, vtkMultiProcessController);

//------------------------------------------------------------------------------
vtkStylizePrincipalCurvatures::vtkStylizePrincipalCurvatures()
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

//------------------------------------------------------------------------------
vtkStylizePrincipalCurvatures::~vtkStylizePrincipalCurvatures()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
double vtkStylizePrincipalCurvatures::DataDiagonal(vtkPolyData* input)
{
  // Low corner and the negated high corner, so that one minimum reduces both.
  double corners[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  if (input->GetNumberOfPoints() > 0)
  {
    double b[6];
    input->GetBounds(b);
    for (int i = 0; i < 3; ++i)
    {
      corners[i] = b[2 * i];
      corners[3 + i] = -b[2 * i + 1];
    }
  }
  if (this->Controller && this->Controller->GetNumberOfProcesses() > 1)
  {
    double all[6];
    this->Controller->AllReduce(corners, all, 6, vtkCommunicator::MIN_OP);
    std::copy(all, all + 6, corners);
  }
  if (corners[0] == VTK_DOUBLE_MAX)
  {
    return 0.0;
  }
  double squared = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    const double side = -corners[3 + i] - corners[i];
    squared += side * side;
  }
  return std::sqrt(squared);
}

//------------------------------------------------------------------------------
int vtkStylizePrincipalCurvatures::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* in = inputVector[0]->GetInformationObject(0);
  vtkInformation* out = outputVector->GetInformationObject(0);
  const int ghosts = out->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS());
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), ghosts + 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkStylizePrincipalCurvatures::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!input || !output)
  {
    return 0;
  }
  output->ShallowCopy(input);
  const vtkIdType np = input->GetNumberOfPoints();
  // The object's size, over every process's piece (a collective call: before any return), so
  // that the smoothing radius and the planar test do not depend on how the data is split.
  const double diagonal = this->DataDiagonal(input);

  Surface s;
  s.Faces = Triangles(input);
  ComputeNormals(input, this->UseInputNormals, s);
  ComputeFrames(s);
  std::vector<std::array<double, 3>> tensor;
  std::vector<double> weight;
  AccumulateTensors(s, tensor, weight);
  this->UpdateProgress(0.2);

  const double smoothing =
    np > 0 && std::isfinite(diagonal) ? this->SmoothingRadius * diagonal : 0.0;
  if (smoothing > 0.0)
  {
    // The smoothing is the long part on large meshes: progress from 0.2 to 0.9, and an abort
    // (AbortExecute: ParaView's abort button, or an owner's) leaves the output without arrays.
    const vtkStylizeTensorSmoothing::Surface surface{ s.P, s.Normal, s.FrameU, s.FrameV, s.Faces,
      tensor, weight };
    auto progress = [this](double done)
    {
      this->UpdateProgress(0.2 + 0.7 * done);
      return !this->GetAbortExecute();
    };
    bool stopped = false;
    const size_t most = static_cast<size_t>(this->MaximumNeighbors);
    tensor = this->SmoothingCellSize > 0.0
      ? vtkStylizeTensorSmoothing::Clustered(
          surface, smoothing, this->SmoothingCellSize * smoothing, most, progress, stopped)
      : vtkStylizeTensorSmoothing::Exact(surface, smoothing, most, progress, stopped);
    if (stopped)
    {
      return 1;
    }
  }
  this->UpdateProgress(0.9);

  CurvatureArrays arrays(np);
  Decompose(s, tensor, weight, diagonal, this->PlanarTolerance, this->UmbilicTolerance, arrays);
  arrays.AddTo(output->GetPointData(), this->TangentDirection);
  return 1;
}
