/**
 * Small vector algebra and triangle-mesh helpers shared by the Filters module's mesh
 * algorithms (principal curvatures, feature lines). Private: not installed.
 */
#ifndef vtkStylizeMeshGeometry_h
#define vtkStylizeMeshGeometry_h

#include "vtkSMPTools.h"
#include "vtkType.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

class vtkPolyData;

namespace vtkStylizeMesh
{
using Vec = std::array<double, 3>;

inline Vec Sub(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
inline double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec Cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
inline Vec Scale(const Vec& a, double s)
{
  return { a[0] * s, a[1] * s, a[2] * s };
}
inline Vec Add(const Vec& a, const Vec& b)
{
  return { a[0] + b[0], a[1] + b[1], a[2] + b[2] };
}
inline double Norm(const Vec& a)
{
  return std::sqrt(Dot(a, a));
}
/** a / |a|, or false when |a| is zero or not finite. */
inline bool Normalize(Vec& a)
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
inline Vec Perpendicular(const Vec& n)
{
  Vec axis = std::abs(n[0]) < 0.9 ? Vec{ 1, 0, 0 } : Vec{ 0, 1, 0 };
  Vec p = Cross(n, axis);
  Normalize(p);
  return p;
}
/** The rotation that takes unit vector a to unit vector b, applied to x (a != -b). */
inline Vec Rotate(const Vec& a, const Vec& b, const Vec& x)
{
  const double c = Dot(a, b);
  const Vec v = Cross(a, b);
  return Add(Add(Scale(x, c), Cross(v, x)), Scale(v, Dot(v, x) / (1.0 + c)));
}

/**
 * Per-face work on vtkSMPTools' threads, summed in face order on the calling thread: for each
 * face f of [0, n), compute(f, values) fills `values` (K doubles) on some thread, then
 * add(f, values) runs for f in increasing order, in blocks of 2^18 faces (bounded memory). The
 * sums are those of a serial loop, whatever the thread count.
 */
template <size_t K, typename Compute, typename Add>
void ForFacesInOrder(size_t n, Compute&& compute, Add&& add)
{
  const size_t block = size_t{ 1 } << 18;
  std::vector<std::array<double, K>> values(std::min(n, block));
  for (size_t begin = 0; begin < n; begin += block)
  {
    const size_t end = std::min(n, begin + block);
    vtkSMPTools::For(static_cast<vtkIdType>(begin), static_cast<vtkIdType>(end),
      [&](vtkIdType first, vtkIdType last)
      {
        for (vtkIdType f = first; f < last; ++f)
        {
          compute(static_cast<size_t>(f), values[static_cast<size_t>(f) - begin]);
        }
      });
    for (size_t f = begin; f < end; ++f)
    {
      add(f, values[f - begin]);
    }
  }
}

/**
 * Points within `tolerance` (world units, >= 0) of each other, transitively, merged: for each
 * point its representative, the smallest index of its group; -1 where use[i] is 0 (such
 * points are not merged). The points used must be finite. Deterministic. Identical points merge
 * however many there are; a point is compared with at most 256 distinct points within the
 * tolerance along x in each grid cell of 1024 tolerances it may reach (only a cloud of more
 * points than that within a tolerance could keep two of them apart).
 */
std::vector<vtkIdType> MergeCoincidentPoints(
  const std::vector<Vec>& p, const std::vector<char>& use, double tolerance);

/** The triangles of the input's polygons and strips (the points are unchanged); triangles with
 * a repeated point id are left out. */
std::vector<std::array<vtkIdType, 3>> Triangles(vtkPolyData* input);

/** Point normals as the sum of each face's unit normal times its corner angle at the point;
 * not normalized (zero at points without a non-degenerate face). */
std::vector<Vec> AngleWeightedNormals(
  const std::vector<Vec>& p, const std::vector<std::array<vtkIdType, 3>>& faces);
}

#endif
