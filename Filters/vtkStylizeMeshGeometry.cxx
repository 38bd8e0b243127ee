#include "vtkStylizeMeshGeometry.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <cstdint>
#include <utility>

//------------------------------------------------------------------------------
std::vector<std::array<vtkIdType, 3>> vtkStylizeMesh::Triangles(vtkPolyData* input)
{
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(input->GetPoints());
  surface->SetPolys(input->GetPolys());
  surface->SetStrips(input->GetStrips());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(surface);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  if (input->GetNumberOfPoints() > 0 &&
    (input->GetNumberOfPolys() > 0 || input->GetNumberOfStrips() > 0))
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
  return faces;
}

//------------------------------------------------------------------------------
std::vector<vtkStylizeMesh::Vec> vtkStylizeMesh::AngleWeightedNormals(
  const std::vector<Vec>& p, const std::vector<std::array<vtkIdType, 3>>& faces)
{
  std::vector<Vec> normal(p.size(), Vec{ 0, 0, 0 });
  // Per face: its unit normal times each corner's angle (zeros where undefined).
  ForFacesInOrder<9>(
    faces.size(),
    [&](size_t i, std::array<double, 9>& out)
    {
      out.fill(0.0);
      const auto& f = faces[i];
      Vec fn = Cross(Sub(p[f[1]], p[f[0]]), Sub(p[f[2]], p[f[0]]));
      if (!Normalize(fn))
      {
        return;
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
        for (int c = 0; c < 3; ++c)
        {
          out[3 * k + c] = fn[c] * angle;
        }
      }
    },
    [&](size_t i, const std::array<double, 9>& v)
    {
      for (int k = 0; k < 3; ++k)
      {
        Vec& n = normal[faces[i][k]];
        n = Add(n, Vec{ v[3 * k], v[3 * k + 1], v[3 * k + 2] });
      }
    });
  return normal;
}

//------------------------------------------------------------------------------
std::vector<vtkIdType> vtkStylizeMesh::MergeCoincidentPoints(
  const std::vector<Vec>& p, const std::vector<char>& use, double tolerance)
{
  const size_t np = p.size();
  std::vector<vtkIdType> parent(np, -1);
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (size_t i = 0; i < np; ++i)
  {
    if (use[i])
    {
      parent[i] = static_cast<vtkIdType>(i);
      for (int a = 0; a < 3; ++a)
      {
        lo[a] = std::min(lo[a], p[i][a]);
        hi[a] = std::max(hi[a], p[i][a]);
      }
    }
  }
  if (!(lo[0] <= hi[0]))
  {
    return parent;
  }
  // Grid cells of 1024 tolerances (at most 2^21 along an axis): a point's partners lie in its
  // own cell or, when it is within the tolerance of a side, in the cells across that side.
  tolerance = std::max(tolerance, 0.0);
  const double axisCells = static_cast<double>((1 << 21) - 4);
  double side = tolerance > 0.0 ? 1024.0 * tolerance : 1.0;
  for (int a = 0; a < 3; ++a)
  {
    side = std::max(side, (hi[a] - lo[a]) / axisCells);
  }
  auto cellOf = [&](const Vec& x, int a) { return std::floor((x[a] - lo[a]) / side) + 1.0; };
  auto keyOf = [](const double g[3])
  {
    return (static_cast<uint64_t>(g[0]) << 42) | (static_cast<uint64_t>(g[1]) << 21) |
      static_cast<uint64_t>(g[2]);
  };
  // The used points sorted by cell, then coordinates (identical points are next to each other),
  // then index: deterministic.
  struct Entry
  {
    uint64_t Key;
    Vec X;
    vtkIdType Id;
    bool operator<(const Entry& o) const
    {
      return Key != o.Key ? Key < o.Key : X != o.X ? X < o.X : Id < o.Id;
    }
  };
  std::vector<Entry> sorted;
  sorted.reserve(np);
  for (size_t i = 0; i < np; ++i)
  {
    if (use[i])
    {
      const double g[3] = { cellOf(p[i], 0), cellOf(p[i], 1), cellOf(p[i], 2) };
      sorted.push_back({ keyOf(g), p[i], static_cast<vtkIdType>(i) });
    }
  }
  vtkSMPTools::Sort(sorted.begin(), sorted.end());
  auto find = [&parent](vtkIdType i)
  {
    while (parent[i] != i)
    {
      parent[i] = parent[parent[i]];
      i = parent[i];
    }
    return i;
  };
  auto unite = [&](vtkIdType a, vtkIdType b)
  {
    const vtkIdType ra = find(a), rb = find(b);
    parent[std::max(ra, rb)] = std::min(ra, rb);
  };
  const double t2 = tolerance * tolerance;
  auto join = [&](const Entry& a, const Entry& b)
  {
    const Vec d = Sub(a.X, b.X);
    if (Dot(d, d) <= t2)
    {
      unite(a.Id, b.Id);
    }
  };
  // Identical points: each joined to the one before it, and left out of the search below (it is
  // found through that one).
  const size_t n = sorted.size();
  std::vector<char> repeated(n, 0);
  for (size_t e = 1; e < n; ++e)
  {
    if (sorted[e].Key == sorted[e - 1].Key && sorted[e].X == sorted[e - 1].X)
    {
      repeated[e] = 1;
      unite(sorted[e].Id, sorted[e - 1].Id);
    }
  }
  // Distinct points within the tolerance: in its cell, the points before it with x within the
  // tolerance; in the cells across the sides it is within the tolerance of, the points with x
  // within the tolerance of its own. At most 256 comparisons each way (only a cloud of more
  // points than that within a tolerance, not in real meshes, could miss a merge).
  const size_t most = 256;
  for (size_t e = 0; e < n; ++e)
  {
    if (repeated[e])
    {
      continue;
    }
    const Entry& me = sorted[e];
    size_t compared = 0;
    for (size_t b = e; b > 0 && sorted[b - 1].Key == me.Key &&
         me.X[0] - sorted[b - 1].X[0] <= tolerance && compared < most;
         --b)
    {
      if (!repeated[b - 1])
      {
        join(me, sorted[b - 1]);
        ++compared;
      }
    }
    int low[3], high[3];
    double g[3];
    for (int a = 0; a < 3; ++a)
    {
      g[a] = cellOf(me.X, a);
      const double x = (me.X[a] - lo[a]) / side - (g[a] - 1.0); // in [0, 1): its place in the cell
      low[a] = x * side <= tolerance ? -1 : 0;
      high[a] = (1.0 - x) * side <= tolerance ? 1 : 0;
    }
    for (int dx = low[0]; dx <= high[0]; ++dx)
    {
      for (int dy = low[1]; dy <= high[1]; ++dy)
      {
        for (int dz = low[2]; dz <= high[2]; ++dz)
        {
          if (dx == 0 && dy == 0 && dz == 0)
          {
            continue;
          }
          const double h[3] = { g[0] + dx, g[1] + dy, g[2] + dz };
          const Entry from{ keyOf(h), Vec{ me.X[0] - tolerance, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX },
            VTK_ID_MIN };
          compared = 0;
          for (auto it = std::lower_bound(sorted.begin(), sorted.end(), from); it != sorted.end() &&
               it->Key == from.Key && it->X[0] <= me.X[0] + tolerance && compared < most;
               ++it)
          {
            if (!repeated[it - sorted.begin()])
            {
              join(me, *it);
              ++compared;
            }
          }
        }
      }
    }
  }
  for (size_t i = 0; i < np; ++i)
  {
    if (parent[i] >= 0)
    {
      parent[i] = find(static_cast<vtkIdType>(i));
    }
  }
  return parent;
}
