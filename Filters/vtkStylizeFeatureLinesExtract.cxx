// The stages of vtkStylizeFeatureLines: segments per kind, and their chaining.
#include "vtkStylizeFeatureLinesInternals.h"

#include "vtkMath.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

namespace FL = vtkStylizeFeatureLinesInternals;
using namespace vtkStylizeMesh;

namespace
{
/** Faces per block of the threaded loops: blocks are concatenated in order, so the output does
 * not depend on the number of threads. */
constexpr vtkIdType BlockSize = 4096;

std::uint64_t EdgeKey(vtkIdType a, vtkIdType b, size_t np)
{
  if (a > b)
  {
    std::swap(a, b);
  }
  return static_cast<std::uint64_t>(a) * np + static_cast<std::uint64_t>(b);
}

/** The gradient of the linear interpolant of f over a face (zero for a degenerate face). */
Vec FaceGradient(const FL::Mesh& m, size_t face, const double f[3])
{
  const double area = m.FaceArea[face];
  if (!(area > 0.0))
  {
    return { 0, 0, 0 };
  }
  const FL::Face& t = m.Faces[face];
  const Vec& n = m.FaceNormal[face];
  const Vec& p0 = m.P[t[0]];
  const Vec& p1 = m.P[t[1]];
  const Vec& p2 = m.P[t[2]];
  const Vec g = Add(Add(Scale(Cross(n, Sub(p2, p1)), f[0]), Scale(Cross(n, Sub(p0, p2)), f[1])),
    Scale(Cross(n, Sub(p1, p0)), f[2]));
  return Scale(g, 0.5 / area);
}

/**
 * Where f (one value per corner of face) changes sign (f >= 0 counts as positive) on the face's
 * edges: true with the two crossings when there are two. Each crossing is computed from the
 * edge's ends in the order of their point ids, so the face on either side of an edge gives the
 * same point; aux is interpolated there.
 */
bool Crossing(const FL::Mesh& m, size_t face, const double f[3], const double aux[3], FL::End& a,
  double& auxA, FL::End& b, double& auxB)
{
  const FL::Face& t = m.Faces[face];
  int found = 0;
  for (int k = 0; k < 3; ++k)
  {
    int i = k, j = (k + 1) % 3;
    if ((f[i] >= 0.0) == (f[j] >= 0.0))
    {
      continue;
    }
    if (t[i] > t[j])
    {
      std::swap(i, j);
    }
    const double s = f[i] / (f[i] - f[j]);
    FL::End& e = found == 0 ? a : b;
    double& x = found == 0 ? auxA : auxB;
    e.Key = EdgeKey(t[i], t[j], m.P.size());
    e.P = Add(m.P[t[i]], Scale(Sub(m.P[t[j]], m.P[t[i]]), s));
    e.Strength = 1.0f;
    x = aux[i] + s * (aux[j] - aux[i]);
    ++found;
  }
  return found == 2;
}

/** Runs body(face, segments) over every face in blocks, and concatenates the blocks' segments
 * (and those of a second output, when given) in order. */
template <class Body>
void ForEachFace(const FL::Mesh& m, FL::Segments& out, FL::Segments* out2, Body body)
{
  const vtkIdType nf = static_cast<vtkIdType>(m.Faces.size());
  const vtkIdType blocks = (nf + BlockSize - 1) / BlockSize;
  std::vector<FL::Segments> parts(static_cast<size_t>(blocks));
  std::vector<FL::Segments> parts2(out2 ? static_cast<size_t>(blocks) : 0);
  vtkSMPTools::For(0, blocks,
    [&](vtkIdType b0, vtkIdType b1)
    {
      for (vtkIdType b = b0; b < b1; ++b)
      {
        FL::Segments* second = out2 ? &parts2[b] : nullptr;
        for (vtkIdType f = b * BlockSize; f < std::min(nf, (b + 1) * BlockSize); ++f)
        {
          body(static_cast<size_t>(f), parts[b], second);
        }
      }
    });
  for (vtkIdType b = 0; b < blocks; ++b)
  {
    out.insert(out.end(), parts[b].begin(), parts[b].end());
    if (out2)
    {
      out2->insert(out2->end(), parts2[b].begin(), parts2[b].end());
    }
  }
}

/** Per point: the area-weighted mean of its faces' gradients of field, in its tangent plane. */
std::vector<Vec> VertexGradients(const FL::Mesh& m, const std::vector<double>& field)
{
  std::vector<Vec> g(m.P.size(), Vec{ 0, 0, 0 });
  std::vector<double> w(m.P.size(), 0.0);
  for (size_t f = 0; f < m.Faces.size(); ++f)
  {
    const FL::Face& t = m.Faces[f];
    const double v[3] = { field[t[0]], field[t[1]], field[t[2]] };
    const Vec fg = Scale(FaceGradient(m, f, v), m.FaceArea[f]);
    for (vtkIdType i : t)
    {
      g[i] = Add(g[i], fg);
      w[i] += m.FaceArea[f];
    }
  }
  for (size_t i = 0; i < g.size(); ++i)
  {
    if (w[i] > 0.0)
    {
      const Vec& n = m.Normal[i];
      g[i] = Scale(g[i], 1.0 / w[i]);
      g[i] = Sub(g[i], Scale(n, Dot(g[i], n)));
    }
  }
  return g;
}

/** 0 at the threshold, 1 at twice the threshold (1 everywhere above a zero threshold). */
float Ramp(double measure, double threshold)
{
  if (!(threshold > 0.0))
  {
    return 1.0f;
  }
  return static_cast<float>(std::max(0.0, std::min(1.0, measure / threshold - 1.0)));
}
}

//------------------------------------------------------------------------------
FL::Vec FL::View::Toward(const Vec& p) const
{
  if (this->Parallel)
  {
    return this->ToViewer;
  }
  Vec v = Sub(this->Eye, p);
  return Normalize(v) ? v : this->ToViewer;
}

//------------------------------------------------------------------------------
void FL::FinishMesh(Mesh& m)
{
  const size_t nf = m.Faces.size();
  m.FaceNormal.assign(nf, Vec{ 0, 0, 0 });
  m.FaceArea.assign(nf, 0.0);
  for (size_t f = 0; f < nf; ++f)
  {
    const Face& t = m.Faces[f];
    Vec n = Cross(Sub(m.P[t[1]], m.P[t[0]]), Sub(m.P[t[2]], m.P[t[0]]));
    const double twice = Norm(n);
    if (Normalize(n))
    {
      m.FaceNormal[f] = n;
      m.FaceArea[f] = 0.5 * twice;
    }
  }
  m.Normal = AngleWeightedNormals(m.P, m.Faces);
  for (Vec& n : m.Normal)
  {
    if (!Normalize(n))
    {
      n = Vec{ 0, 0, 0 };
    }
  }
  m.OnCrease.assign(m.P.size(), 0);
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { VTK_DOUBLE_MIN, VTK_DOUBLE_MIN, VTK_DOUBLE_MIN };
  for (const Vec& p : m.P)
  {
    for (int c = 0; c < 3; ++c)
    {
      lo[c] = std::min(lo[c], p[c]);
      hi[c] = std::max(hi[c], p[c]);
    }
  }
  m.Diagonal = m.P.empty() ? 0.0 : std::sqrt(vtkMath::Distance2BetweenPoints(lo, hi));
}

//------------------------------------------------------------------------------
void FL::EdgeLines(Mesh& m, double creaseAngle, Segments& boundaries, Segments& creases)
{
  std::vector<std::tuple<std::uint64_t, size_t>> edges;
  edges.reserve(3 * m.Faces.size());
  for (size_t f = 0; f < m.Faces.size(); ++f)
  {
    const Face& t = m.Faces[f];
    for (int k = 0; k < 3; ++k)
    {
      edges.emplace_back(EdgeKey(t[k], t[(k + 1) % 3], m.P.size()), f);
    }
  }
  vtkSMPTools::Sort(edges.begin(), edges.end()); // (each entry distinct: deterministic)
  const double cosLimit = std::cos(vtkMath::RadiansFromDegrees(creaseAngle));
  for (size_t i = 0; i < edges.size();)
  {
    size_t j = i + 1;
    while (j < edges.size() && std::get<0>(edges[j]) == std::get<0>(edges[i]))
    {
      ++j;
    }
    const std::uint64_t key = std::get<0>(edges[i]);
    const vtkIdType a = static_cast<vtkIdType>(key / m.P.size());
    const vtkIdType b = static_cast<vtkIdType>(key % m.P.size());
    const Segment s{ { static_cast<std::uint64_t>(a), m.P[a], 1.0f },
      { static_cast<std::uint64_t>(b), m.P[b], 1.0f } };
    if (j - i == 1)
    {
      boundaries.push_back(s);
    }
    else if (j - i > 2 ||
      Dot(m.FaceNormal[std::get<1>(edges[i])], m.FaceNormal[std::get<1>(edges[i + 1])]) < cosLimit)
    {
      creases.push_back(s);
      m.OnCrease[a] = m.OnCrease[b] = 1;
    }
    i = j;
  }
  // The edges of two faces of which one touches a crease.
  m.CreaseSideEdges.clear();
  auto touches = [&m](size_t f)
  { return m.OnCrease[m.Faces[f][0]] || m.OnCrease[m.Faces[f][1]] || m.OnCrease[m.Faces[f][2]]; };
  for (size_t i = 0; i < edges.size();)
  {
    size_t j = i + 1;
    while (j < edges.size() && std::get<0>(edges[j]) == std::get<0>(edges[i]))
    {
      ++j;
    }
    const size_t f0 = std::get<1>(edges[i]);
    if (j - i == 2 && (touches(f0) || touches(std::get<1>(edges[i + 1]))))
    {
      const std::uint64_t key = std::get<0>(edges[i]);
      m.CreaseSideEdges.push_back(
        { static_cast<vtkIdType>(key / m.P.size()), static_cast<vtkIdType>(key % m.P.size()),
          static_cast<vtkIdType>(f0), static_cast<vtkIdType>(std::get<1>(edges[i + 1])) });
    }
    i = j;
  }
}

//------------------------------------------------------------------------------
void FL::Contours(const Mesh& m, const View& view, Segments& out)
{
  std::vector<double> g(m.P.size(), 0.0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(m.P.size()),
    [&](vtkIdType i0, vtkIdType i1)
    {
      for (vtkIdType i = i0; i < i1; ++i)
      {
        g[i] = Dot(m.Normal[i], view.Toward(m.P[i]));
      }
    });
  ForEachFace(m, out, nullptr,
    [&](size_t f, Segments& segments, Segments*)
    {
      const Face& t = m.Faces[f];
      if (m.OnCrease[t[0]] || m.OnCrease[t[1]] || m.OnCrease[t[2]])
      {
        return; // flat: its contour is on its edges (below)
      }
      const double v[3] = { g[t[0]], g[t[1]], g[t[2]] };
      const double none[3] = { 0, 0, 0 };
      Segment s;
      double x, y;
      if (Crossing(m, f, v, none, s.A, x, s.B, y))
      {
        segments.push_back(s);
      }
    });
  // Beside creases: the edges between a face toward the viewer and one away from it, ends keyed
  // apart from the edge points (np * np + point id).
  const std::uint64_t np = m.P.size();
  for (const auto& e : m.CreaseSideEdges)
  {
    const Vec mid = Scale(Add(m.P[e[0]], m.P[e[1]]), 0.5);
    const Vec v = view.Toward(mid);
    const bool toward0 = Dot(m.FaceNormal[e[2]], v) >= 0.0;
    const bool toward1 = Dot(m.FaceNormal[e[3]], v) >= 0.0;
    if (toward0 != toward1)
    {
      out.push_back({ { np * np + static_cast<std::uint64_t>(e[0]), m.P[e[0]], 1.0f },
        { np * np + static_cast<std::uint64_t>(e[1]), m.P[e[1]], 1.0f } });
    }
  }
}

//------------------------------------------------------------------------------
void FL::IsoLines(const Mesh& m, const std::vector<double>& values,
  const std::vector<double>& levels, Segments& out)
{
  if (levels.empty() || values.size() != m.P.size())
  {
    return;
  }
  // Ends keyed per level: level l's key is the edge's plus (l + 2) np^2 (the contours' crease
  // edges use np^2 + id); at most 1000 levels and 1e8 points stay below 2^64.
  const std::uint64_t np = m.P.size();
  const std::uint64_t fit = std::numeric_limits<std::uint64_t>::max() / (np * np);
  const auto end = levels.begin() +
    static_cast<std::ptrdiff_t>(std::min<std::uint64_t>(levels.size(), fit > 2 ? fit - 2 : 0));
  ForEachFace(m, out, nullptr,
    [&](size_t f, Segments& segments, Segments*)
    {
      const Face& t = m.Faces[f];
      const double v[3] = { values[t[0]], values[t[1]], values[t[2]] };
      if (!std::isfinite(v[0] + v[1] + v[2]))
      {
        return;
      }
      const double lo = std::min(v[0], std::min(v[1], v[2]));
      const double hi = std::max(v[0], std::max(v[1], v[2]));
      // the levels in (lo, hi]: a vertex at a level counts as above it (Crossing's f >= 0)
      auto l = std::upper_bound(levels.begin(), end, lo);
      for (; l != end && *l <= hi; ++l)
      {
        const double d[3] = { v[0] - *l, v[1] - *l, v[2] - *l };
        const double none[3] = { 0, 0, 0 };
        Segment s;
        double x, y;
        if (Crossing(m, f, d, none, s.A, x, s.B, y))
        {
          const std::uint64_t offset =
            (static_cast<std::uint64_t>(l - levels.begin()) + 2) * np * np;
          s.A.Key += offset;
          s.B.Key += offset;
          segments.push_back(s);
        }
      }
    });
}

//------------------------------------------------------------------------------
void FL::RidgesAndValleys(
  const Mesh& m, const Curvature& c, double threshold, Segments& ridges, Segments& valleys)
{
  const size_t np = m.P.size();
  // Per point: the larger-magnitude curvature k, its direction e and dk/de.
  const std::vector<Vec> g1 = VertexGradients(m, c.K1);
  const std::vector<Vec> g2 = VertexGradients(m, c.K2);
  std::vector<double> k(np), d(np);
  std::vector<char> family(np), valid(np);
  for (size_t i = 0; i < np; ++i)
  {
    const bool first = std::abs(c.K1[i]) >= std::abs(c.K2[i]);
    family[i] = first ? 1 : 2;
    k[i] = first ? c.K1[i] : c.K2[i];
    d[i] = Dot(first ? g1[i] : g2[i], c.EMaxAbs[i]);
    valid[i] = Dot(c.EMaxAbs[i], c.EMaxAbs[i]) > 0.5 && !m.OnCrease[i] && std::isfinite(d[i]);
  }
  const double scale = m.Diagonal;
  ForEachFace(m, ridges, &valleys,
    [&](size_t f, Segments& outRidges, Segments* outValleys)
    {
      const Face& t = m.Faces[f];
      for (vtkIdType i : t)
      {
        if (!valid[i] || family[i] != family[t[0]] || (k[i] > 0.0) != (k[t[0]] > 0.0))
        {
          return;
        }
      }
      // The directions turned to agree with the first corner's (a line has no sign); a face
      // where they cannot all agree holds a singular point of the direction field.
      const Vec& e0 = c.EMaxAbs[t[0]];
      const Vec& e1 = c.EMaxAbs[t[1]];
      const Vec& e2 = c.EMaxAbs[t[2]];
      const double s1 = Dot(e0, e1) < 0.0 ? -1.0 : 1.0;
      const double s2 = Dot(e0, e2) < 0.0 ? -1.0 : 1.0;
      if ((Dot(e1, e2) < 0.0 ? -1.0 : 1.0) != s1 * s2)
      {
        return;
      }
      const double dv[3] = { d[t[0]], s1 * d[t[1]], s2 * d[t[2]] };
      const double mag[3] = { std::abs(k[t[0]]) * scale, std::abs(k[t[1]]) * scale,
        std::abs(k[t[2]]) * scale };
      Segment s;
      double ma, mb;
      if (!Crossing(m, f, dv, mag, s.A, ma, s.B, mb) || std::max(ma, mb) < threshold)
      {
        return;
      }
      // A maximum of k along e where k > 0 (ridge), a minimum where k < 0 (valley).
      const Vec e = Add(Add(e0, Scale(e1, s1)), Scale(e2, s2));
      const double second = Dot(FaceGradient(m, f, dv), e);
      const bool convex = k[t[0]] > 0.0;
      if ((convex && second >= 0.0) || (!convex && second <= 0.0))
      {
        return;
      }
      // The curvature must change along e by at least its own size over the object's size: on
      // a cylinder or a tube (k constant along e) every point is an extreme, none a ridge.
      const double kc = (std::abs(k[t[0]]) + std::abs(k[t[1]]) + std::abs(k[t[2]])) / 3.0;
      if (std::abs(second) * m.Diagonal * m.Diagonal < kc * Norm(e))
      {
        return;
      }
      s.A.Strength = Ramp(ma, threshold);
      s.B.Strength = Ramp(mb, threshold);
      (convex ? outRidges : *outValleys).push_back(s);
    });
}

//------------------------------------------------------------------------------
void FL::SuggestiveContours(
  const Mesh& m, const Curvature& c, const View& view, double threshold, Segments& out)
{
  const size_t np = m.P.size();
  // Per point: n.v, w (v in the tangent plane) and the radial curvature times |w|^2, which has
  // the radial curvature's zeros and, at a zero, its derivative times |w|^2.
  std::vector<double> ndotv(np), kr(np);
  std::vector<Vec> w(np);
  vtkSMPTools::For(0, static_cast<vtkIdType>(np),
    [&](vtkIdType i0, vtkIdType i1)
    {
      for (vtkIdType i = i0; i < i1; ++i)
      {
        const Vec v = view.Toward(m.P[i]);
        ndotv[i] = Dot(m.Normal[i], v);
        w[i] = Sub(v, Scale(m.Normal[i], ndotv[i]));
        const double a = Dot(w[i], c.E1[i]), b = Dot(w[i], c.E2[i]);
        kr[i] = c.K1[i] * a * a + c.K2[i] * b * b;
      }
    });
  const double scale2 = m.Diagonal * m.Diagonal;
  ForEachFace(m, out, nullptr,
    [&](size_t f, Segments& segments, Segments*)
    {
      const Face& t = m.Faces[f];
      for (vtkIdType i : t)
      {
        if (!(ndotv[i] > 0.0) || m.OnCrease[i] || !std::isfinite(kr[i]))
        {
          return;
        }
      }
      const double v[3] = { kr[t[0]], kr[t[1]], kr[t[2]] };
      const double fade[3] = { ndotv[t[0]], ndotv[t[1]], ndotv[t[2]] };
      Segment s;
      double na, nb;
      if (!Crossing(m, f, v, fade, s.A, na, s.B, nb))
      {
        return;
      }
      const Vec wc = Scale(Add(Add(w[t[0]], w[t[1]]), w[t[2]]), 1.0 / 3.0);
      const double w2 = Dot(wc, wc);
      if (w2 < 1e-4)
      {
        return; // seen along the normal: the radial direction is undefined
      }
      // The derivative of the radial curvature along w / |w|.
      const double dwkr = Dot(FaceGradient(m, f, v), wc) / (std::sqrt(w2) * w2);
      const double measure = dwkr * scale2;
      if (!(measure >= threshold) || !(dwkr > 0.0))
      {
        return;
      }
      const float ramp = Ramp(measure, threshold);
      s.A.Strength = ramp * static_cast<float>(std::min(1.0, na / 0.3));
      s.B.Strength = ramp * static_cast<float>(std::min(1.0, nb / 0.3));
      segments.push_back(s);
    });
}

//------------------------------------------------------------------------------
std::vector<FL::Chain> FL::ChainSegments(const Segments& segments)
{
  const size_t ns = segments.size();
  // Ends sorted by key: each distinct key is a point, with the segments that end there.
  std::vector<std::pair<std::uint64_t, size_t>> ends(2 * ns);
  for (size_t i = 0; i < ns; ++i)
  {
    ends[2 * i] = { segments[i].A.Key, 2 * i };
    ends[2 * i + 1] = { segments[i].B.Key, 2 * i + 1 };
  }
  std::sort(ends.begin(), ends.end());
  std::vector<size_t> pointOf(2 * ns), first, count;
  for (size_t i = 0; i < ends.size(); ++i)
  {
    if (i == 0 || ends[i].first != ends[i - 1].first)
    {
      first.push_back(i);
      count.push_back(0);
    }
    pointOf[ends[i].second] = first.size() - 1;
    ++count.back();
  }
  auto endOf = [&](size_t end) { return end % 2 == 0 ? segments[end / 2].A : segments[end / 2].B; };

  std::vector<char> used(ns, 0);
  std::vector<Chain> chains;
  // From end `from` of a chain (a point), walks on through points of two segments.
  auto walk = [&](size_t point, size_t segment, Chain& out)
  {
    while (count[point] == 2)
    {
      const size_t e0 = ends[first[point]].second, e1 = ends[first[point] + 1].second;
      const size_t next = e0 / 2 == segment ? e1 : e0;
      if (used[next / 2])
      {
        break;
      }
      used[next / 2] = 1;
      const size_t far = next % 2 == 0 ? next + 1 : next - 1;
      out.push_back(endOf(far));
      point = pointOf[far];
      segment = next / 2;
    }
  };
  for (size_t i = 0; i < ns; ++i)
  {
    if (used[i])
    {
      continue;
    }
    used[i] = 1;
    Chain forward{ segments[i].A, segments[i].B };
    walk(pointOf[2 * i + 1], i, forward);
    Chain backward;
    walk(pointOf[2 * i], i, backward);
    Chain chain(backward.rbegin(), backward.rend());
    chain.insert(chain.end(), forward.begin(), forward.end());
    chains.push_back(std::move(chain));
  }
  return chains;
}

//------------------------------------------------------------------------------
double FL::ChainLength(const Chain& chain)
{
  double length = 0.0;
  for (size_t i = 1; i < chain.size(); ++i)
  {
    length += Norm(Sub(chain[i].P, chain[i - 1].P));
  }
  return length;
}
