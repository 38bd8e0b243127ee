#include "vtkStylizePrincipalCurvatures.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkCommunicator.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkStylizePrincipalCurvatures);

namespace
{
using Vec = std::array<double, 3>;

Vec Sub(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec Cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
Vec Scale(const Vec& a, double s)
{
  return { a[0] * s, a[1] * s, a[2] * s };
}
Vec Add(const Vec& a, const Vec& b)
{
  return { a[0] + b[0], a[1] + b[1], a[2] + b[2] };
}
double Norm(const Vec& a)
{
  return std::sqrt(Dot(a, a));
}
/** a / |a|, or false when |a| is zero or not finite. */
bool Normalize(Vec& a)
{
  const double n = Norm(a);
  if (!(n > 0.0) || !std::isfinite(n))
  {
    return false;
  }
  a = Scale(a, 1.0 / n);
  return true;
}
/** Any unit vector perpendicular to the unit vector n. */
Vec Perpendicular(const Vec& n)
{
  Vec axis = std::abs(n[0]) < 0.9 ? Vec{ 1, 0, 0 } : Vec{ 0, 1, 0 };
  Vec p = Cross(n, axis);
  Normalize(p);
  return p;
}
/** The rotation that takes unit vector a to unit vector b, applied to x (a != -b). */
Vec Rotate(const Vec& a, const Vec& b, const Vec& x)
{
  const double c = Dot(a, b);
  const Vec v = Cross(a, b);
  return Add(Add(Scale(x, c), Cross(v, x)), Scale(v, Dot(v, x) / (1.0 + c)));
}
}

//------------------------------------------------------------------------------
void vtkStylizePrincipalCurvatures::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UseInputNormals: " << this->UseInputNormals << "\n";
  os << indent << "SmoothingRadius: " << this->SmoothingRadius << "\n";
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

  // Triangles of the polygons and strips (the points are unchanged).
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(input->GetPoints());
  surface->SetPolys(input->GetPolys());
  surface->SetStrips(input->GetStrips());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(surface);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  if (np > 0 && (input->GetNumberOfPolys() > 0 || input->GetNumberOfStrips() > 0))
  {
    triangles->Update();
  }
  vtkPolyData* tri = triangles->GetOutput();
  std::vector<std::array<vtkIdType, 3>> faces;
  if (tri && tri->GetPolys())
  {
    vtkCellArray* polys = tri->GetPolys();
    vtkIdType n;
    const vtkIdType* ids;
    for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
    {
      if (n == 3 && ids[0] != ids[1] && ids[1] != ids[2] && ids[0] != ids[2])
      {
        faces.push_back({ ids[0], ids[1], ids[2] });
      }
    }
  }

  std::vector<Vec> p(static_cast<size_t>(np));
  for (vtkIdType i = 0; i < np; ++i)
  {
    input->GetPoint(i, p[i].data());
  }

  // Point normals: the input's, or corner-angle weighted face normals.
  std::vector<Vec> normal(static_cast<size_t>(np), Vec{ 0, 0, 0 });
  vtkDataArray* inNormals = input->GetPointData()->GetNormals();
  const bool useInput =
    this->UseInputNormals && inNormals && inNormals->GetNumberOfComponents() == 3;
  if (useInput)
  {
    for (vtkIdType i = 0; i < np; ++i)
    {
      inNormals->GetTuple(i, normal[i].data());
    }
  }
  else
  {
    for (const auto& f : faces)
    {
      Vec fn = Cross(Sub(p[f[1]], p[f[0]]), Sub(p[f[2]], p[f[0]]));
      if (!Normalize(fn))
      {
        continue;
      }
      for (int k = 0; k < 3; ++k)
      {
        Vec a = Sub(p[f[(k + 1) % 3]], p[f[k]]);
        Vec b = Sub(p[f[(k + 2) % 3]], p[f[k]]);
        if (!Normalize(a) || !Normalize(b))
        {
          continue;
        }
        const double angle = std::acos(std::max(-1.0, std::min(1.0, Dot(a, b))));
        normal[f[k]] = Add(normal[f[k]], Scale(fn, angle));
      }
    }
  }
  std::vector<bool> valid(static_cast<size_t>(np), false);
  for (vtkIdType i = 0; i < np; ++i)
  {
    valid[i] = Normalize(normal[i]);
  }

  // Each vertex's tangent frame (u, v, normal).
  std::vector<Vec> frameU(static_cast<size_t>(np)), frameV(static_cast<size_t>(np));
  std::vector<bool> framed(static_cast<size_t>(np), false);
  for (const auto& f : faces)
  {
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType i = f[k];
      if (framed[i] || !valid[i])
      {
        continue;
      }
      Vec e = Sub(p[f[(k + 1) % 3]], p[i]);
      e = Sub(e, Scale(normal[i], Dot(e, normal[i])));
      if (!Normalize(e))
      {
        e = Perpendicular(normal[i]);
      }
      frameU[i] = e;
      frameV[i] = Cross(normal[i], e);
      framed[i] = true;
    }
  }

  // Per face: the second fundamental form fitted to the normals' change along the edges, then
  // rotated into each vertex's frame and accumulated with the vertex's mixed Voronoi area.
  std::vector<std::array<double, 3>> tensor(static_cast<size_t>(np), { 0, 0, 0 });
  std::vector<double> weight(static_cast<size_t>(np), 0.0);
  for (const auto& f : faces)
  {
    if (!valid[f[0]] || !valid[f[1]] || !valid[f[2]])
    {
      continue;
    }
    const Vec e[3] = { Sub(p[f[2]], p[f[1]]), Sub(p[f[0]], p[f[2]]), Sub(p[f[1]], p[f[0]]) };
    Vec t = e[0];
    Vec n = Cross(e[0], e[1]);
    const double twiceArea = Norm(n);
    if (!Normalize(t) || !Normalize(n))
    {
      continue;
    }
    const Vec b = Cross(n, t);
    // Least squares for (e, f, g): [u v 0; 0 u v] x = [dn.t; dn.b] over the three edges.
    double m[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
    double r[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      const Vec dn = Sub(normal[f[(k + 2) % 3]], normal[f[(k + 1) % 3]]);
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
    // it), and a degenerate face (a singular system, as where a parametric surface closes on
    // itself) skipped here, before vtkMath warns about it.
    const double trace = m[0][0] + m[1][1] + m[2][2];
    if (!(trace > 0.0) || !std::isfinite(trace))
    {
      continue;
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
      continue;
    }
    double* rows[3] = { m[0], m[1], m[2] };
    if (!vtkMath::SolveLinearSystem(rows, r, 3))
    {
      continue;
    }
    const double fe = r[0], ff = r[1], fg = r[2];
    if (!std::isfinite(fe) || !std::isfinite(ff) || !std::isfinite(fg))
    {
      continue;
    }

    // Mixed Voronoi areas of the three corners (Meyer et al. 2003).
    const double l[3] = { Dot(e[0], e[0]), Dot(e[1], e[1]), Dot(e[2], e[2]) };
    const double area = 0.5 * twiceArea;
    double corner[3];
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
        cotangent[j] = -Dot(e[(j + 1) % 3], e[(j + 2) % 3]) / twiceArea;
      }
      for (int k = 0; k < 3; ++k)
      {
        const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        corner[k] = 0.125 * (l[k1] * cotangent[k1] + l[k2] * cotangent[k2]);
      }
    }

    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType i = f[k];
      const double c = Dot(normal[i], n);
      if (c <= -0.999999)
      {
        continue; // the vertex faces away from the face: no defined rotation
      }
      const Vec a1 = Rotate(normal[i], n, frameU[i]);
      const Vec a2 = Rotate(normal[i], n, frameV[i]);
      const double au = Dot(a1, t), av = Dot(a1, b);
      const double bu = Dot(a2, t), bv = Dot(a2, b);
      const double w = corner[k];
      tensor[i][0] += w * (au * au * fe + 2.0 * au * av * ff + av * av * fg);
      tensor[i][1] += w * (au * bu * fe + (au * bv + av * bu) * ff + av * bv * fg);
      tensor[i][2] += w * (bu * bu * fe + 2.0 * bu * bv * ff + bv * bv * fg);
      weight[i] += w;
    }
  }

  // The tensors per unit area, in each point's frame.
  for (vtkIdType i = 0; i < np; ++i)
  {
    const bool ok = weight[i] > 0.0 && framed[i] &&
      std::all_of(tensor[i].begin(), tensor[i].end(),
        [&](double v) { return std::isfinite(v / weight[i]); });
    for (double& v : tensor[i])
    {
      v = ok ? v / weight[i] : 0.0;
    }
    weight[i] = ok ? weight[i] : 0.0;
  }

  const double smoothing =
    np > 0 && std::isfinite(diagonal) ? this->SmoothingRadius * diagonal : 0.0;
  if (smoothing > 0.0)
  {
    tensor = this->SmoothTensors(p, normal, frameU, frameV, faces, tensor, weight, smoothing);
  }

  auto makeArray = [np](const char* name, int comps) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(comps);
    a->SetNumberOfTuples(np);
    a->Fill(0.0);
    return a;
  };
  auto makeDirections = [np](const char* name) {
    vtkNew<vtkFloatArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(3);
    a->SetNumberOfTuples(np);
    a->Fill(0.0);
    return a;
  };
  auto kMax = makeArray("PrincipalCurvatureMax", 1);
  auto kMin = makeArray("PrincipalCurvatureMin", 1);
  auto dMax = makeDirections("PrincipalDirectionMax");
  auto dMin = makeDirections("PrincipalDirectionMin");
  auto bisector = makeDirections("PrincipalDirectionBisector");
  auto dMinAbs = makeDirections("PrincipalDirectionMinAbs");
  auto dMaxAbs = makeDirections("PrincipalDirectionMaxAbs");
  auto mean = makeArray("MeanCurvature", 1);
  auto gauss = makeArray("GaussianCurvature", 1);
  for (vtkIdType i = 0; i < np; ++i)
  {
    if (!(weight[i] > 0.0) || !framed[i])
    {
      continue;
    }
    const double A = tensor[i][0];
    const double B = tensor[i][1];
    const double C = tensor[i][2];
    if (!std::isfinite(A) || !std::isfinite(B) || !std::isfinite(C))
    {
      continue;
    }
    const double half = 0.5 * (A + C);
    const double radius = std::hypot(0.5 * (A - C), B);
    const double k1 = half + radius, k2 = half - radius;
    const double theta = 0.5 * std::atan2(2.0 * B, A - C);
    const double ct = std::cos(theta), st = std::sin(theta);
    const Vec d1 = Add(Scale(frameU[i], ct), Scale(frameV[i], st));
    const Vec d2 = Add(Scale(frameU[i], -st), Scale(frameV[i], ct));
    const Vec bis = Scale(Add(d1, d2), 1.0 / std::sqrt(2.0));
    kMax->SetValue(i, k1);
    kMin->SetValue(i, k2);
    dMax->SetTuple(i, d1.data());
    dMin->SetTuple(i, d2.data());
    bisector->SetTuple(i, bis.data());
    mean->SetValue(i, half);
    gauss->SetValue(i, k1 * k2);
    const double larger = std::max(std::abs(k1), std::abs(k2));
    const bool planar = !(larger * diagonal > this->PlanarTolerance);
    const bool umbilic = !(k1 - k2 > this->UmbilicTolerance * (std::abs(k1) + std::abs(k2)));
    if (!planar && !umbilic)
    {
      const bool maxIsLarger = std::abs(k1) >= std::abs(k2);
      dMinAbs->SetTuple(i, (maxIsLarger ? d2 : d1).data());
      dMaxAbs->SetTuple(i, (maxIsLarger ? d1 : d2).data());
    }
  }
  vtkPointData* pd = output->GetPointData();
  for (vtkDataArray* a : { static_cast<vtkDataArray*>(kMax), static_cast<vtkDataArray*>(kMin),
         static_cast<vtkDataArray*>(dMax), static_cast<vtkDataArray*>(dMin),
         static_cast<vtkDataArray*>(bisector), static_cast<vtkDataArray*>(dMinAbs),
         static_cast<vtkDataArray*>(dMaxAbs), static_cast<vtkDataArray*>(mean),
         static_cast<vtkDataArray*>(gauss) })
  {
    pd->AddArray(a);
  }
  vtkFloatArray* const tangents[] = { nullptr, dMinAbs, dMaxAbs, dMin, dMax, bisector };
  if (tangents[this->TangentDirection])
  {
    pd->SetTangents(tangents[this->TangentDirection]);
  }
  return 1;
}

//------------------------------------------------------------------------------
std::vector<std::array<double, 3>> vtkStylizePrincipalCurvatures::SmoothTensors(
  const std::vector<std::array<double, 3>>& p, const std::vector<std::array<double, 3>>& normal,
  const std::vector<std::array<double, 3>>& frameU,
  const std::vector<std::array<double, 3>>& frameV,
  const std::vector<std::array<vtkIdType, 3>>& faces,
  const std::vector<std::array<double, 3>>& tensor, const std::vector<double>& area,
  double radius) const
{
  const size_t np = p.size();
  // Edge adjacency (compressed rows).
  std::vector<std::pair<vtkIdType, vtkIdType>> edges;
  edges.reserve(faces.size() * 6);
  for (const auto& f : faces)
  {
    for (int k = 0; k < 3; ++k)
    {
      edges.emplace_back(f[k], f[(k + 1) % 3]);
      edges.emplace_back(f[(k + 1) % 3], f[k]);
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<size_t> start(np + 1, 0);
  for (const auto& e : edges)
  {
    ++start[static_cast<size_t>(e.first) + 1];
  }
  for (size_t i = 0; i < np; ++i)
  {
    start[i + 1] += start[i];
  }

  const double sigma2 = 0.25 * radius * radius; // a Gaussian of sigma radius / 2
  const double radius2 = radius * radius;
  const size_t most = static_cast<size_t>(this->MaximumNeighbors);
  std::vector<std::array<double, 3>> out(tensor);
  std::vector<size_t> stamp(np, np);
  std::vector<size_t> queue;
  for (size_t i = 0; i < np; ++i)
  {
    if (!(area[i] > 0.0))
    {
      continue;
    }
    double sum[3] = { 0, 0, 0 };
    double wsum = 0.0;
    queue.assign(1, i);
    stamp[i] = i;
    // Breadth first through the edges, within the radius, up to MaximumNeighbors points.
    for (size_t head = 0; head < queue.size() && head < most; ++head)
    {
      const size_t j = queue[head];
      const Vec dj = Sub(p[j], p[i]);
      if (area[j] > 0.0 && Dot(normal[j], normal[i]) > -0.999999)
      {
        // j's frame turned onto i's tangent plane, then j's tensor in i's frame.
        const Vec u = Rotate(normal[j], normal[i], frameU[j]);
        const Vec v = Rotate(normal[j], normal[i], frameV[j]);
        const double a = Dot(frameU[i], u), b = Dot(frameU[i], v);
        const double c = Dot(frameV[i], u), d = Dot(frameV[i], v);
        const double A = tensor[j][0], B = tensor[j][1], C = tensor[j][2];
        const double w = area[j] * std::exp(-0.5 * Dot(dj, dj) / sigma2);
        sum[0] += w * (A * a * a + 2.0 * B * a * b + C * b * b);
        sum[1] += w * (A * a * c + B * (a * d + b * c) + C * b * d);
        sum[2] += w * (A * c * c + 2.0 * B * c * d + C * d * d);
        wsum += w;
      }
      for (size_t e = start[j]; e < start[j + 1]; ++e)
      {
        const size_t k = static_cast<size_t>(edges[e].second);
        if (stamp[k] == i)
        {
          continue;
        }
        stamp[k] = i;
        const Vec dk = Sub(p[k], p[i]);
        if (Dot(dk, dk) <= radius2)
        {
          queue.push_back(k);
        }
      }
    }
    if (wsum > 0.0 && std::isfinite(sum[0] + sum[1] + sum[2]))
    {
      out[i] = { sum[0] / wsum, sum[1] / wsum, sum[2] / wsum };
    }
  }
  return out;
}
