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

namespace
{
using namespace vtkStylizeMesh;

/**
 * MergeCoincidentPoints()'s state: the used points in grid cells of 1024 tolerances (at most
 * 2^21 along an axis), sorted by cell, then coordinates (identical points are next to each
 * other), then index (deterministic), and the union-find forest (the smaller index the root).
 */
class Weld
{
public:
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

  Weld(const std::vector<Vec>& p, const std::vector<char>& use, double tolerance,
    const double lo[3], const double hi[3])
    : Tolerance(std::max(tolerance, 0.0))
    , Parent(p.size(), -1)
  {
    const double axisCells = static_cast<double>((1 << 21) - 4);
    this->Side = this->Tolerance > 0.0 ? 1024.0 * this->Tolerance : 1.0;
    for (int a = 0; a < 3; ++a)
    {
      this->Low[a] = lo[a];
      this->Side = std::max(this->Side, (hi[a] - lo[a]) / axisCells);
    }
    for (size_t i = 0; i < p.size(); ++i)
    {
      if (use[i])
      {
        this->Parent[i] = static_cast<vtkIdType>(i);
        const double g[3] = { this->CellOf(p[i], 0), this->CellOf(p[i], 1), this->CellOf(p[i], 2) };
        this->Sorted.push_back({ KeyOf(g), p[i], static_cast<vtkIdType>(i) });
      }
    }
    vtkSMPTools::Sort(this->Sorted.begin(), this->Sorted.end());
    // Identical points: each joined to the one before it, and left out of the search (it is
    // found through that one).
    this->Repeated.assign(this->Sorted.size(), 0);
    for (size_t e = 1; e < this->Sorted.size(); ++e)
    {
      if (this->Sorted[e].Key == this->Sorted[e - 1].Key &&
        this->Sorted[e].X == this->Sorted[e - 1].X)
      {
        this->Repeated[e] = 1;
        this->Unite(this->Sorted[e].Id, this->Sorted[e - 1].Id);
      }
    }
  }

  /** Joins each distinct point with the distinct points within the tolerance: in its cell, the
   * points before it with x within the tolerance; in the cells across the sides it is within the
   * tolerance of, the points with x within the tolerance of its own. */
  void Search()
  {
    for (size_t e = 0; e < this->Sorted.size(); ++e)
    {
      if (this->Repeated[e])
      {
        continue;
      }
      const Entry& me = this->Sorted[e];
      size_t compared = 0;
      for (size_t b = e; b > 0 && this->Sorted[b - 1].Key == me.Key &&
           me.X[0] - this->Sorted[b - 1].X[0] <= this->Tolerance && compared < Most;
           --b)
      {
        if (!this->Repeated[b - 1])
        {
          this->Join(me, this->Sorted[b - 1]);
          ++compared;
        }
      }
      this->SearchAcross(me);
    }
  }

  /** Each point's representative (-1: not used). */
  std::vector<vtkIdType> Representatives()
  {
    for (size_t i = 0; i < this->Parent.size(); ++i)
    {
      if (this->Parent[i] >= 0)
      {
        this->Parent[i] = this->Find(static_cast<vtkIdType>(i));
      }
    }
    return this->Parent;
  }

private:
  /** At most this many comparisons each way (only a cloud of more points than that within a
   * tolerance, not in real meshes, could miss a merge). */
  static constexpr size_t Most = 256;

  double CellOf(const Vec& x, int a) const
  {
    return std::floor((x[a] - this->Low[a]) / this->Side) + 1.0;
  }
  static uint64_t KeyOf(const double g[3])
  {
    return (static_cast<uint64_t>(g[0]) << 42) | (static_cast<uint64_t>(g[1]) << 21) |
      static_cast<uint64_t>(g[2]);
  }
  vtkIdType Find(vtkIdType i)
  {
    while (this->Parent[i] != i)
    {
      this->Parent[i] = this->Parent[this->Parent[i]];
      i = this->Parent[i];
    }
    return i;
  }
  void Unite(vtkIdType a, vtkIdType b)
  {
    const vtkIdType ra = this->Find(a), rb = this->Find(b);
    this->Parent[std::max(ra, rb)] = std::min(ra, rb);
  }
  void Join(const Entry& a, const Entry& b)
  {
    const Vec d = Sub(a.X, b.X);
    if (Dot(d, d) <= this->Tolerance * this->Tolerance)
    {
      this->Unite(a.Id, b.Id);
    }
  }

  /** The cells across the sides `me` is within the tolerance of. */
  void SearchAcross(const Entry& me)
  {
    int low[3], high[3];
    double g[3];
    for (int a = 0; a < 3; ++a)
    {
      g[a] = this->CellOf(me.X, a);
      const double x = (me.X[a] - this->Low[a]) / this->Side - (g[a] - 1.0); // its place: [0, 1)
      low[a] = x * this->Side <= this->Tolerance ? -1 : 0;
      high[a] = (1.0 - x) * this->Side <= this->Tolerance ? 1 : 0;
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
          const Entry from{ KeyOf(h),
            Vec{ me.X[0] - this->Tolerance, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX }, VTK_ID_MIN };
          size_t compared = 0;
          for (auto it = std::lower_bound(this->Sorted.begin(), this->Sorted.end(), from);
               it != this->Sorted.end() && it->Key == from.Key &&
               it->X[0] <= me.X[0] + this->Tolerance && compared < Most;
               ++it)
          {
            if (!this->Repeated[it - this->Sorted.begin()])
            {
              this->Join(me, *it);
              ++compared;
            }
          }
        }
      }
    }
  }

  double Tolerance;
  double Side = 1.0;
  double Low[3] = { 0, 0, 0 };
  std::vector<Entry> Sorted;
  std::vector<char> Repeated;
  std::vector<vtkIdType> Parent;
};
}

//------------------------------------------------------------------------------
std::vector<vtkIdType> vtkStylizeMesh::MergeCoincidentPoints(
  const std::vector<Vec>& p, const std::vector<char>& use, double tolerance)
{
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (size_t i = 0; i < p.size(); ++i)
  {
    if (use[i])
    {
      for (int a = 0; a < 3; ++a)
      {
        lo[a] = std::min(lo[a], p[i][a]);
        hi[a] = std::max(hi[a], p[i][a]);
      }
    }
  }
  if (!(lo[0] <= hi[0]))
  {
    return std::vector<vtkIdType>(p.size(), -1);
  }
  Weld weld(p, use, tolerance, lo, hi);
  weld.Search();
  return weld.Representatives();
}
