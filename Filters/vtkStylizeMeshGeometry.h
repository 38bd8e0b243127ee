/**
 * Small vector algebra and triangle-mesh helpers shared by the Filters module's mesh
 * algorithms (principal curvatures, feature lines). Private: not installed.
 */
#ifndef vtkStylizeMeshGeometry_h
#define vtkStylizeMeshGeometry_h

#include "vtkType.h"

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

/** The triangles of the input's polygons and strips (the points are unchanged); triangles with
 * a repeated point id are left out. */
std::vector<std::array<vtkIdType, 3>> Triangles(vtkPolyData* input);

/** Point normals as the sum of each face's unit normal times its corner angle at the point;
 * not normalized (zero at points without a non-degenerate face). */
std::vector<Vec> AngleWeightedNormals(
  const std::vector<Vec>& p, const std::vector<std::array<vtkIdType, 3>>& faces);
}

#endif
