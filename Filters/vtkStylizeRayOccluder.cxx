#include "vtkStylizeRayOccluder.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkStylizeRayOccluder);

namespace
{
constexpr int LeafSize = 4;

/** A node: its box; an inner node's children are First and First + 1, a leaf's triangles
 * Order[First, First + Count). */
struct Node
{
  float Low[3];
  float High[3];
  std::uint32_t First;
  std::uint32_t Count; // 0: inner node
};
}

struct vtkStylizeRayOccluder::Internals
{
  double Centre[3] = { 0, 0, 0 };   // world = Centre + stored point
  std::vector<float> Points;        // 3 per point, relative to Centre
  std::vector<std::uint32_t> Tris;  // 3 point indices per triangle
  std::vector<std::uint32_t> Order; // triangles in the leaves' order
  std::vector<Node> Nodes;          // Nodes[0]: the root
  double MeanEdge = 0.0;
  double Bounds[6] = { 1, -1, 1, -1, 1, -1 };
  std::vector<float> Alpha; // per triangle, its opacity (SetOpacity(); empty: opaque)
  vtkIdType SurfacePoints = 0;

  void Build();
  std::uint32_t Split(std::uint32_t first, std::uint32_t count, std::vector<float>& centroids);
  bool Hit(std::uint32_t t, const double o[3], const double d[3]) const;
  /** Calls visit(t) for every triangle the segment o + s d, s in [0, 1], crosses, until it
   * returns false. */
  template <typename Visit>
  void Cross(const double o[3], const double d[3], Visit visit) const;
};

//------------------------------------------------------------------------------
vtkStylizeRayOccluder::vtkStylizeRayOccluder()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkStylizeRayOccluder::~vtkStylizeRayOccluder() = default;

//------------------------------------------------------------------------------
void vtkStylizeRayOccluder::SetSurface(vtkPolyData* surface, vtkMatrix4x4* matrix)
{
  Internals& in = *this->Internal;
  in = Internals();
  vtkPoints* points = surface ? surface->GetPoints() : nullptr;
  const vtkIdType np = points ? points->GetNumberOfPoints() : 0;
  in.SurfacePoints = np;
  if (np == 0 || np >= static_cast<vtkIdType>(std::numeric_limits<std::uint32_t>::max()))
  {
    this->Modified();
    return;
  }
  // World points (double), their bounds and centre.
  std::vector<double> world(static_cast<size_t>(3 * np));
  std::vector<char> finite(static_cast<size_t>(np), 0);
  double m[16];
  if (matrix)
  {
    vtkMatrix4x4::DeepCopy(m, matrix);
  }
  double low[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double high[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3], w[3];
    points->GetPoint(i, p);
    if (matrix)
    {
      const double h = m[12] * p[0] + m[13] * p[1] + m[14] * p[2] + m[15];
      for (int r = 0; r < 3; ++r)
      {
        w[r] = (m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3]) /
          (h != 0.0 ? h : 1.0);
      }
    }
    else
    {
      std::copy(p, p + 3, w);
    }
    if (!std::isfinite(w[0] + w[1] + w[2]))
    {
      continue;
    }
    finite[static_cast<size_t>(i)] = 1;
    for (int r = 0; r < 3; ++r)
    {
      world[static_cast<size_t>(3 * i + r)] = w[r];
      low[r] = std::min(low[r], w[r]);
      high[r] = std::max(high[r], w[r]);
    }
  }
  if (low[0] > high[0])
  {
    this->Modified();
    return;
  }
  for (int r = 0; r < 3; ++r)
  {
    in.Centre[r] = 0.5 * (low[r] + high[r]);
    in.Bounds[2 * r] = low[r];
    in.Bounds[2 * r + 1] = high[r];
  }
  in.Points.resize(world.size());
  for (size_t i = 0; i < world.size(); ++i)
  {
    in.Points[i] = static_cast<float>(world[i] - in.Centre[i % 3]);
  }
  // Triangles: polygons as fans, strips split.
  auto add = [&](vtkIdType a, vtkIdType b, vtkIdType c)
  {
    if (a >= 0 && b >= 0 && c >= 0 && a < np && b < np && c < np &&
      finite[static_cast<size_t>(a)] && finite[static_cast<size_t>(b)] &&
      finite[static_cast<size_t>(c)] && a != b && b != c && a != c)
    {
      in.Tris.push_back(static_cast<std::uint32_t>(a));
      in.Tris.push_back(static_cast<std::uint32_t>(b));
      in.Tris.push_back(static_cast<std::uint32_t>(c));
    }
  };
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = surface->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    for (vtkIdType k = 1; k + 1 < n; ++k)
    {
      add(ids[0], ids[k], ids[k + 1]);
    }
  }
  vtkCellArray* strips = surface->GetStrips();
  for (strips->InitTraversal(); strips->GetNextCell(n, ids);)
  {
    for (vtkIdType k = 0; k + 2 < n; ++k)
    {
      add(ids[k], ids[k + 1], ids[k + 2]);
    }
  }
  // The mean edge length of up to 10000 triangles.
  const size_t count = in.Tris.size() / 3;
  const size_t stride = std::max<size_t>(1, count / 10000);
  double sum = 0.0;
  size_t edges = 0;
  for (size_t t = 0; t < count; t += stride)
  {
    for (int k = 0; k < 3; ++k)
    {
      const double* a = &world[3 * in.Tris[3 * t + k]];
      const double* b = &world[3 * in.Tris[3 * t + (k + 1) % 3]];
      sum += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
        (a[2] - b[2]) * (a[2] - b[2]));
      ++edges;
    }
  }
  in.MeanEdge = edges ? sum / edges : 0.0;
  in.Build();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkStylizeRayOccluder::Internals::Build()
{
  const std::uint32_t count = static_cast<std::uint32_t>(this->Tris.size() / 3);
  this->Order.resize(count);
  std::vector<float> centroids(3 * static_cast<size_t>(count));
  for (std::uint32_t t = 0; t < count; ++t)
  {
    this->Order[t] = t;
    for (int r = 0; r < 3; ++r)
    {
      centroids[3 * t + r] =
        (this->Points[3 * this->Tris[3 * t] + r] + this->Points[3 * this->Tris[3 * t + 1] + r] +
          this->Points[3 * this->Tris[3 * t + 2] + r]) /
        3.0f;
    }
  }
  this->Nodes.clear();
  if (count == 0)
  {
    return;
  }
  this->Nodes.reserve(2 * (count / LeafSize + 1));
  this->Nodes.push_back(Node());
  // Depth first with an explicit stack: (node, first, count).
  struct Task
  {
    std::uint32_t NodeIndex, First, Count;
  };
  std::vector<Task> tasks{ { 0, 0, count } };
  while (!tasks.empty())
  {
    const Task task = tasks.back();
    tasks.pop_back();
    // The node's box.
    float low[3] = { std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
      std::numeric_limits<float>::max() };
    float high[3] = { -low[0], -low[1], -low[2] };
    float clow[3] = { low[0], low[1], low[2] }, chigh[3] = { high[0], high[1], high[2] };
    for (std::uint32_t i = task.First; i < task.First + task.Count; ++i)
    {
      const std::uint32_t t = this->Order[i];
      for (int k = 0; k < 3; ++k)
      {
        const float* p = &this->Points[3 * static_cast<size_t>(this->Tris[3 * t + k])];
        for (int r = 0; r < 3; ++r)
        {
          low[r] = std::min(low[r], p[r]);
          high[r] = std::max(high[r], p[r]);
        }
      }
      for (int r = 0; r < 3; ++r)
      {
        clow[r] = std::min(clow[r], centroids[3 * t + r]);
        chigh[r] = std::max(chigh[r], centroids[3 * t + r]);
      }
    }
    Node& node = this->Nodes[task.NodeIndex];
    std::copy(low, low + 3, node.Low);
    std::copy(high, high + 3, node.High);
    int axis = 0;
    for (int r = 1; r < 3; ++r)
    {
      axis = chigh[r] - clow[r] > chigh[axis] - clow[axis] ? r : axis;
    }
    if (task.Count <= LeafSize || !(chigh[axis] > clow[axis]))
    {
      node.First = task.First;
      node.Count = task.Count;
      continue;
    }
    // The median along the longest axis of the centroids.
    const std::uint32_t half = task.Count / 2;
    auto begin = this->Order.begin() + task.First;
    std::nth_element(begin, begin + half, begin + task.Count,
      [&](std::uint32_t a, std::uint32_t b)
      { return centroids[3 * a + axis] < centroids[3 * b + axis]; });
    const std::uint32_t left = static_cast<std::uint32_t>(this->Nodes.size());
    this->Nodes[task.NodeIndex].First = left;
    this->Nodes[task.NodeIndex].Count = 0;
    this->Nodes.push_back(Node());
    this->Nodes.push_back(Node());
    tasks.push_back({ left + 1, task.First + half, task.Count - half });
    tasks.push_back({ left, task.First, half });
  }
}

//------------------------------------------------------------------------------
bool vtkStylizeRayOccluder::Internals::Hit(
  std::uint32_t t, const double o[3], const double d[3]) const
{
  // Moller-Trumbore, the segment o + s d for s in [0, 1].
  const float* p0 = &this->Points[3 * static_cast<size_t>(this->Tris[3 * t])];
  const float* p1 = &this->Points[3 * static_cast<size_t>(this->Tris[3 * t + 1])];
  const float* p2 = &this->Points[3 * static_cast<size_t>(this->Tris[3 * t + 2])];
  const double e1[3] = { p1[0] - double(p0[0]), p1[1] - double(p0[1]), p1[2] - double(p0[2]) };
  const double e2[3] = { p2[0] - double(p0[0]), p2[1] - double(p0[1]), p2[2] - double(p0[2]) };
  const double q[3] = { d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2],
    d[0] * e2[1] - d[1] * e2[0] };
  const double det = e1[0] * q[0] + e1[1] * q[1] + e1[2] * q[2];
  if (det == 0.0)
  {
    return false;
  }
  const double inv = 1.0 / det;
  const double s[3] = { o[0] - p0[0], o[1] - p0[1], o[2] - p0[2] };
  const double u = (s[0] * q[0] + s[1] * q[1] + s[2] * q[2]) * inv;
  if (u < 0.0 || u > 1.0)
  {
    return false;
  }
  const double r[3] = { s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2],
    s[0] * e1[1] - s[1] * e1[0] };
  const double v = (d[0] * r[0] + d[1] * r[1] + d[2] * r[2]) * inv;
  if (v < 0.0 || u + v > 1.0)
  {
    return false;
  }
  const double along = (e2[0] * r[0] + e2[1] * r[1] + e2[2] * r[2]) * inv;
  return along >= 0.0 && along <= 1.0;
}

//------------------------------------------------------------------------------
template <typename Visit>
void vtkStylizeRayOccluder::Internals::Cross(
  const double o[3], const double d[3], Visit visit) const
{
  if (this->Nodes.empty())
  {
    return;
  }
  double inv[3];
  for (int r = 0; r < 3; ++r)
  {
    inv[r] = d[r] != 0.0 ? 1.0 / d[r] : std::numeric_limits<double>::infinity();
  }
  // The box test: the segment's parameter range inside the box meets [0, 1].
  auto crosses = [&](const Node& node)
  {
    double t0 = 0.0, t1 = 1.0;
    for (int r = 0; r < 3; ++r)
    {
      if (d[r] == 0.0)
      {
        if (o[r] < node.Low[r] || o[r] > node.High[r])
        {
          return false;
        }
        continue;
      }
      double enter = (node.Low[r] - o[r]) * inv[r], leave = (node.High[r] - o[r]) * inv[r];
      if (enter > leave)
      {
        std::swap(enter, leave);
      }
      t0 = std::max(t0, enter);
      t1 = std::min(t1, leave);
      if (t0 > t1)
      {
        return false;
      }
    }
    return true;
  };
  std::uint32_t stack[128]; // (the tree is balanced: depth 2 log2 of the triangles at most)
  int top = 0;
  stack[top++] = 0;
  while (top > 0)
  {
    const Node& node = this->Nodes[stack[--top]];
    if (!crosses(node))
    {
      continue;
    }
    if (node.Count > 0)
    {
      for (std::uint32_t i = node.First; i < node.First + node.Count; ++i)
      {
        if (this->Hit(this->Order[i], o, d) && !visit(this->Order[i]))
        {
          return;
        }
      }
    }
    else if (top + 2 <= 128)
    {
      stack[top++] = node.First + 1;
      stack[top++] = node.First;
    }
  }
}

//------------------------------------------------------------------------------
bool vtkStylizeRayOccluder::Blocks(const double a[3], const double b[3]) const
{
  const Internals& in = *this->Internal;
  const double o[3] = { a[0] - in.Centre[0], a[1] - in.Centre[1], a[2] - in.Centre[2] };
  const double d[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  bool blocked = false;
  in.Cross(o, d,
    [&](std::uint32_t)
    {
      blocked = true;
      return false;
    });
  return blocked;
}

//------------------------------------------------------------------------------
double vtkStylizeRayOccluder::Transmittance(const double a[3], const double b[3]) const
{
  const Internals& in = *this->Internal;
  const double o[3] = { a[0] - in.Centre[0], a[1] - in.Centre[1], a[2] - in.Centre[2] };
  const double d[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  double through = 1.0;
  in.Cross(o, d,
    [&](std::uint32_t t)
    {
      through *= 1.0 - (in.Alpha.empty() ? 1.0 : in.Alpha[t]);
      return through > 1e-4;
    });
  return through > 1e-4 ? through : 0.0;
}

//------------------------------------------------------------------------------
void vtkStylizeRayOccluder::SetOpacity(double opacity, vtkDataArray* rgba)
{
  Internals& in = *this->Internal;
  const double k = std::isfinite(opacity) ? std::min(1.0, std::max(0.0, opacity)) : 1.0;
  const bool perPoint =
    rgba && rgba->GetNumberOfComponents() == 4 && rgba->GetNumberOfTuples() == in.SurfacePoints;
  const size_t count = in.Tris.size() / 3;
  in.Alpha.assign(count, static_cast<float>(k));
  for (size_t t = 0; perPoint && t < count; ++t)
  {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      const double value = rgba->GetComponent(in.Tris[3 * t + c], 3) / 255.0;
      sum += std::isfinite(value) ? std::min(1.0, std::max(0.0, value)) : 1.0;
    }
    in.Alpha[t] = static_cast<float>(k * sum / 3.0);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkStylizeRayOccluder::GetBounds(double bounds[6]) const
{
  std::copy(this->Internal->Bounds, this->Internal->Bounds + 6, bounds);
}

//------------------------------------------------------------------------------
double vtkStylizeRayOccluder::GetMeanEdgeLength() const
{
  return this->Internal->MeanEdge;
}

//------------------------------------------------------------------------------
vtkIdType vtkStylizeRayOccluder::GetNumberOfTriangles() const
{
  return static_cast<vtkIdType>(this->Internal->Tris.size() / 3);
}

//------------------------------------------------------------------------------
void vtkStylizeRayOccluder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Triangles: " << this->GetNumberOfTriangles() << "\n";
  os << indent << "Nodes: " << this->Internal->Nodes.size() << "\n";
  os << indent << "MeanEdgeLength: " << this->Internal->MeanEdge << "\n";
}
