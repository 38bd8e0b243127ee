#include "vtkStylizeTensorSmoothing.h"

#include "vtkMath.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>

namespace vtkStylizeTensorSmoothing
{
namespace
{
using namespace vtkStylizeMesh;

/** Tensor t of the frame (n0, u0, v0) in the frame (n1, u1, v1), after the smallest rotation
 * that takes n0 to n1 (n0 != -n1). */
Tensor Turn(const Vec& n0, const Vec& u0, const Vec& v0, const Tensor& t, const Vec& n1,
  const Vec& u1, const Vec& v1)
{
  // (Rotate(n0, n1, x) for x = u0 and v0, the axis and the cosine computed once)
  const double cosine = Dot(n0, n1);
  const Vec w = Cross(n0, n1);
  const double k = 1.0 / (1.0 + cosine);
  const Vec u = Add(Add(Scale(u0, cosine), Cross(w, u0)), Scale(w, Dot(w, u0) * k));
  const Vec v = Add(Add(Scale(v0, cosine), Cross(w, v0)), Scale(w, Dot(w, v0) * k));
  const double a = Dot(u1, u), b = Dot(u1, v);
  const double c = Dot(v1, u), d = Dot(v1, v);
  const double A = t[0], B = t[1], C = t[2];
  return { A * a * a + 2.0 * B * a * b + C * b * b, A * a * c + B * (a * d + b * c) + C * b * d,
    A * c * c + 2.0 * B * c * d + C * d * d };
}

/** Normals this close to opposite have no defined smallest rotation: such neighbours are left
 * out. */
constexpr double Opposite = -0.999999;

/**
 * fn(first, last) over [0, n) on vtkSMPTools' threads, in about 32 blocks with progress reported
 * between them (from `from` to `to`); false when progress asked to stop.
 */
template <typename Fn>
bool ForBlocks(size_t n, const Progress& progress, double from, double to, Fn&& fn)
{
  const size_t blocks = 32;
  const size_t step = std::max<size_t>(1, (n + blocks - 1) / blocks);
  for (size_t begin = 0; begin < n; begin += step)
  {
    const size_t end = std::min(n, begin + step);
    vtkSMPTools::For(static_cast<vtkIdType>(begin), static_cast<vtkIdType>(end), 256,
      [&](vtkIdType first, vtkIdType last)
      { fn(static_cast<size_t>(first), static_cast<size_t>(last)); });
    if (progress && !progress(from + (to - from) * static_cast<double>(end) / n))
    {
      return false;
    }
  }
  return true;
}

/** Compressed rows of the undirected edges of the faces: the neighbours of j are
 * second[start[j]] to second[start[j + 1] - 1], in increasing order. */
struct Adjacency
{
  std::vector<size_t> Start;
  std::vector<vtkIdType> Second;
};

Adjacency EdgeAdjacency(size_t np, const std::vector<std::array<vtkIdType, 3>>& faces)
{
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
  vtkSMPTools::Sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  Adjacency a;
  a.Start.assign(np + 1, 0);
  a.Second.resize(edges.size());
  for (size_t e = 0; e < edges.size(); ++e)
  {
    ++a.Start[static_cast<size_t>(edges[e].first) + 1];
    a.Second[e] = edges[e].second;
  }
  for (size_t i = 0; i < np; ++i)
  {
    a.Start[i + 1] += a.Start[i];
  }
  return a;
}

/** The smoothing weight of a neighbour at squared distance d2 (the Gaussian times the area). */
inline double Weight(double area, double d2, double sigma2)
{
  return area * std::exp(-0.5 * d2 / sigma2);
}

constexpr size_t None = std::numeric_limits<size_t>::max();
constexpr uint64_t NoKey = std::numeric_limits<uint64_t>::max();

/** A cluster: its points' tensors summed in its own frame (the area-weighted mean normal) at
 * its area-weighted centroid. */
struct Cluster
{
  Vec Centroid, Normal, U, V;
  Tensor T; // per unit area
  double Area;
};

/** The clusters, each point's cluster (None: no tensor) and the links between clusters
 * through the faces' edges (compressed rows: cluster c's are Link[LinkStart[c]] on). */
struct Clusters
{
  std::vector<size_t> Of;
  std::vector<Cluster> C;
  std::vector<size_t> LinkStart;
  std::vector<uint32_t> Link;
};

/**
 * Each point's key: its grid cell's Morton code (clusters near in space are then near in
 * memory) and the dominant axis of its normal with its sign; NoKey without a tensor. At most
 * 2^20 cells along an axis: `cell` grows when the radius is that small. Empty when no point
 * has a tensor.
 */
std::vector<uint64_t> CellKeys(const Surface& s, double& cell)
{
  const size_t np = s.P.size();
  double low[3] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
    std::numeric_limits<double>::max() };
  double high[3] = { -low[0], -low[0], -low[0] };
  for (size_t i = 0; i < np; ++i)
  {
    if (s.Area[i] > 0.0)
    {
      for (int a = 0; a < 3; ++a)
      {
        low[a] = std::min(low[a], s.P[i][a]);
        high[a] = std::max(high[a], s.P[i][a]);
      }
    }
  }
  if (!(low[0] <= high[0]))
  {
    return {};
  }
  const double axisCells = static_cast<double>((1 << 20) - 1);
  for (int a = 0; a < 3; ++a)
  {
    cell = std::max(cell, (high[a] - low[a]) / axisCells);
  }
  // The grid's lines at multiples of the cell in world coordinates, so that the pieces of a mesh
  // split over processes share them.
  for (int a = 0; a < 3; ++a)
  {
    low[a] = std::floor(low[a] / cell) * cell;
  }
  std::vector<uint64_t> key(np, NoKey);
  vtkSMPTools::For(0, static_cast<vtkIdType>(np),
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        if (!(s.Area[i] > 0.0))
        {
          continue;
        }
        uint64_t k = 0;
        for (int a = 0; a < 3; ++a)
        {
          const double g = std::floor((s.P[i][a] - low[a]) / cell);
          const uint64_t v =
            std::isfinite(g) ? static_cast<uint64_t>(std::min(std::max(g, 0.0), axisCells)) : 0;
          for (int bit = 0; bit < 20; ++bit)
          {
            k |= ((v >> bit) & 1u) << (3 * bit + a);
          }
        }
        const Vec& n = s.Normal[i];
        const int axis = std::abs(n[0]) >= std::abs(n[1])
          ? (std::abs(n[0]) >= std::abs(n[2]) ? 0 : 2)
          : (std::abs(n[1]) >= std::abs(n[2]) ? 1 : 2);
        key[i] = (k << 3) | static_cast<uint64_t>(2 * axis + (n[axis] < 0.0 ? 1 : 0));
      }
    });
  return key;
}

/**
 * Each point's cluster: the pieces of each key's points connected through the faces' edges
 * (union and find, the smaller index the root, in the faces' order), numbered in the order of
 * their keys, then roots (deterministic). Returns the number of clusters.
 */
size_t GroupClusters(const Surface& s, const std::vector<uint64_t>& key, std::vector<size_t>& of)
{
  const size_t np = s.P.size();
  std::vector<size_t> parent(np);
  std::iota(parent.begin(), parent.end(), size_t{ 0 });
  auto find = [&parent](size_t i)
  {
    while (parent[i] != i)
    {
      parent[i] = parent[parent[i]];
      i = parent[i];
    }
    return i;
  };
  for (const auto& f : s.Faces)
  {
    for (int k = 0; k < 3; ++k)
    {
      const size_t a = static_cast<size_t>(f[k]), b = static_cast<size_t>(f[(k + 1) % 3]);
      if (key[a] == key[b] && key[a] != NoKey)
      {
        const size_t ra = find(a), rb = find(b);
        parent[std::max(ra, rb)] = std::min(ra, rb);
      }
    }
  }
  std::vector<std::pair<uint64_t, size_t>> roots;
  for (size_t i = 0; i < np; ++i)
  {
    if (key[i] != NoKey && find(i) == i)
    {
      roots.emplace_back(key[i], i);
    }
  }
  vtkSMPTools::Sort(roots.begin(), roots.end());
  of.assign(np, None);
  for (size_t c = 0; c < roots.size(); ++c)
  {
    of[roots[c].second] = c;
  }
  for (size_t i = 0; i < np; ++i)
  {
    if (key[i] != NoKey)
    {
      of[i] = of[find(i)];
    }
  }
  return roots.size();
}

/** The clusters' sums (their points in increasing index: deterministic). */
std::vector<Cluster> SumClusters(const Surface& s, const std::vector<size_t>& of, size_t nc)
{
  const size_t np = s.P.size();
  std::vector<size_t> start(nc + 1, 0);
  for (size_t i = 0; i < np; ++i)
  {
    if (of[i] != None)
    {
      ++start[of[i] + 1];
    }
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<size_t> members(start[nc]);
  {
    std::vector<size_t> fill(start.begin(), start.end() - 1);
    for (size_t i = 0; i < np; ++i)
    {
      if (of[i] != None)
      {
        members[fill[of[i]]++] = i;
      }
    }
  }
  std::vector<Cluster> clusters(nc);
  vtkSMPTools::For(0, static_cast<vtkIdType>(nc),
    [&](vtkIdType first, vtkIdType last)
    {
      for (size_t c = static_cast<size_t>(first); c < static_cast<size_t>(last); ++c)
      {
        Cluster& q = clusters[c];
        Vec centroid{ 0, 0, 0 }, normal{ 0, 0, 0 };
        double area = 0.0;
        for (size_t m = start[c]; m < start[c + 1]; ++m)
        {
          const size_t j = members[m];
          centroid = Add(centroid, Scale(s.P[j], s.Area[j]));
          normal = Add(normal, Scale(s.Normal[j], s.Area[j]));
          area += s.Area[j];
        }
        if (!Normalize(normal))
        {
          normal = s.Normal[members[start[c]]];
        }
        q.Centroid = Scale(centroid, 1.0 / area);
        q.Normal = normal;
        q.U = Perpendicular(normal);
        q.V = Cross(normal, q.U);
        Tensor t{ 0, 0, 0 };
        for (size_t m = start[c]; m < start[c + 1]; ++m)
        {
          const size_t j = members[m];
          if (Dot(s.Normal[j], normal) > Opposite)
          {
            const Tensor tj =
              Turn(s.Normal[j], s.FrameU[j], s.FrameV[j], s.Tensors[j], normal, q.U, q.V);
            for (int k = 0; k < 3; ++k)
            {
              t[k] += s.Area[j] * tj[k];
            }
          }
        }
        q.T = { t[0] / area, t[1] / area, t[2] / area };
        q.Area = area;
      }
    });
  return clusters;
}

/** The links between clusters through the faces' edges (sorted: deterministic). */
void LinkClusters(const Surface& s, Clusters& c)
{
  std::vector<std::pair<uint32_t, uint32_t>> links;
  for (const auto& f : s.Faces)
  {
    for (int k = 0; k < 3; ++k)
    {
      const size_t a = c.Of[f[k]], b = c.Of[f[(k + 1) % 3]];
      if (a != b && a != None && b != None)
      {
        links.emplace_back(static_cast<uint32_t>(a), static_cast<uint32_t>(b));
        links.emplace_back(static_cast<uint32_t>(b), static_cast<uint32_t>(a));
      }
    }
  }
  vtkSMPTools::Sort(links.begin(), links.end());
  links.erase(std::unique(links.begin(), links.end()), links.end());
  c.LinkStart.assign(c.C.size() + 1, 0);
  c.Link.resize(links.size());
  for (size_t e = 0; e < links.size(); ++e)
  {
    ++c.LinkStart[links[e].first + 1];
    c.Link[e] = links[e].second;
  }
  std::partial_sum(c.LinkStart.begin(), c.LinkStart.end(), c.LinkStart.begin());
}

/**
 * Each cluster's smoothed tensor, at its centroid, in its frame: the clusters reached breadth
 * first through the links within `outer` of its centroid, weighted by their area, the Gaussian
 * (variance sigma2) of the distance between the centroids and a taper from 1 to 0 over the
 * last cell, at most `most` clusters.
 */
bool SmoothClusters(const Clusters& c, double outer, double cell, double sigma2, size_t most,
  const Progress& progress, std::vector<Tensor>& smooth)
{
  const size_t nc = c.C.size();
  smooth.resize(nc);
  std::vector<Vec> centroids(nc); // (compact: the walk reads many centroids for few clusters)
  for (size_t k = 0; k < nc; ++k)
  {
    centroids[k] = c.C[k].Centroid;
  }
  struct Scratch
  {
    std::vector<size_t> Stamp;
    std::vector<uint32_t> Queue;
  };
  vtkSMPThreadLocal<Scratch> scratch;
  return ForBlocks(nc, progress, 0.2, 0.8,
    [&](size_t first, size_t last)
    {
      Scratch& local = scratch.Local();
      std::vector<size_t>& stamp = local.Stamp;
      std::vector<uint32_t>& queue = local.Queue;
      if (stamp.size() != nc)
      {
        stamp.assign(nc, None);
      }
      for (size_t i = first; i < last; ++i)
      {
        const Cluster& q = c.C[i];
        double sum[3] = { 0, 0, 0 };
        double wsum = 0.0;
        queue.assign(1, static_cast<uint32_t>(i));
        stamp[i] = i;
        for (size_t head = 0; head < queue.size() && head < most; ++head)
        {
          const Cluster& k = c.C[queue[head]];
          const Vec d = Sub(k.Centroid, q.Centroid);
          const double d2 = Dot(d, d);
          if (Dot(k.Normal, q.Normal) > Opposite)
          {
            const double x = std::min(1.0, (outer - std::sqrt(d2)) / cell);
            const double w = Weight(k.Area, d2, sigma2) * x * x * (3.0 - 2.0 * x);
            const Tensor t = Turn(k.Normal, k.U, k.V, k.T, q.Normal, q.U, q.V);
            for (int m = 0; m < 3; ++m)
            {
              sum[m] += w * t[m];
            }
            wsum += w;
          }
          for (size_t e = c.LinkStart[queue[head]]; e < c.LinkStart[queue[head] + 1]; ++e)
          {
            const uint32_t n = c.Link[e];
            if (stamp[n] == i)
            {
              continue;
            }
            stamp[n] = i;
            const Vec dn = Sub(centroids[n], q.Centroid);
            if (Dot(dn, dn) < outer * outer)
            {
              queue.push_back(n);
            }
          }
        }
        smooth[i] = wsum > 0.0 && std::isfinite(sum[0] + sum[1] + sum[2])
          ? Tensor{ sum[0] / wsum, sum[1] / wsum, sum[2] / wsum }
          : q.T;
      }
    });
}

/**
 * Each point: its own and the linked clusters' smoothed tensors, turned onto its frame, fitted
 * by a linear function of the position on its tangent plane (least squares weighted by a
 * Gaussian, variance interpolation2, of the distance to their centroids), the fit's value at the
 * point: the field varies smoothly from point to point across the clusters, and a field that
 * varies linearly is kept exactly (a weighted mean alone tripled the difference from exact).
 */
bool Interpolate(const Surface& s, const Clusters& c, const std::vector<Tensor>& smooth,
  double interpolation2, const Progress& progress, std::vector<Tensor>& out)
{
  return ForBlocks(s.P.size(), progress, 0.8, 1.0,
    [&](size_t first, size_t last)
    {
      for (size_t i = first; i < last; ++i)
      {
        const size_t own = c.Of[i];
        if (own == None)
        {
          continue;
        }
        // Weighted least squares of a linear function on the tangent plane through the
        // clusters' values: m = sum w [1 x y]^T [1 x y], r = sum w [1 x y]^T t.
        double m[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
        double r[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } }; // [row][component]
        auto add = [&](size_t k)
        {
          const Cluster& q = c.C[k];
          if (!(Dot(q.Normal, s.Normal[i]) > Opposite))
          {
            return;
          }
          const Vec d = Sub(q.Centroid, s.P[i]);
          const double w = std::exp(-0.5 * Dot(d, d) / interpolation2);
          const Tensor t =
            Turn(q.Normal, q.U, q.V, smooth[k], s.Normal[i], s.FrameU[i], s.FrameV[i]);
          const double basis[3] = { 1.0, Dot(d, s.FrameU[i]), Dot(d, s.FrameV[i]) };
          for (int row = 0; row < 3; ++row)
          {
            for (int col = 0; col < 3; ++col)
            {
              m[row][col] += w * basis[row] * basis[col];
              r[row][col] += w * basis[row] * t[col];
            }
          }
        };
        add(own);
        for (size_t e = c.LinkStart[own]; e < c.LinkStart[own + 1]; ++e)
        {
          add(c.Link[e]);
        }
        if (!(m[0][0] > 0.0))
        {
          continue;
        }
        Tensor value{ r[0][0] / m[0][0], r[0][1] / m[0][0], r[0][2] / m[0][0] }; // the mean
        // The linear fit's value at the point where the system is well conditioned (the
        // clusters around it in two directions); else the weighted mean.
        const double det = vtkMath::Determinant3x3(m);
        const double scale = m[0][0] * (m[1][1] + m[2][2]) * (m[1][1] + m[2][2]);
        if (det > 1e-3 * scale)
        {
          double inverse[3][3];
          vtkMath::Invert3x3(m, inverse);
          for (int col = 0; col < 3; ++col)
          {
            value[col] =
              inverse[0][0] * r[0][col] + inverse[0][1] * r[1][col] + inverse[0][2] * r[2][col];
          }
        }
        if (std::isfinite(value[0] + value[1] + value[2]))
        {
          out[i] = value;
        }
      }
    });
}
}

//------------------------------------------------------------------------------
std::vector<Tensor> Exact(
  const Surface& s, double radius, size_t most, const Progress& progress, bool& stopped)
{
  const size_t np = s.P.size();
  const Adjacency adjacency = EdgeAdjacency(np, s.Faces);
  const double sigma2 = 0.25 * radius * radius; // a Gaussian of sigma radius / 2
  const double radius2 = radius * radius;
  std::vector<Tensor> out(s.Tensors);
  // Each point's sum is its own (out[i] alone is written): each thread has its own visit stamps
  // and queue, and the result does not depend on the thread count.
  struct Scratch
  {
    std::vector<size_t> Stamp;
    std::vector<size_t> Queue;
  };
  vtkSMPThreadLocal<Scratch> scratch;
  stopped = !ForBlocks(np, progress, 0.0, 1.0,
    [&](size_t first, size_t last)
    {
      Scratch& local = scratch.Local();
      if (local.Stamp.size() != np)
      {
        local.Stamp.assign(np, np);
      }
      std::vector<size_t>& stamp = local.Stamp;
      std::vector<size_t>& queue = local.Queue;
      for (size_t i = first; i < last; ++i)
      {
        if (!(s.Area[i] > 0.0))
        {
          continue;
        }
        double sum[3] = { 0, 0, 0 };
        double wsum = 0.0;
        queue.assign(1, i);
        stamp[i] = i;
        // Breadth first through the edges, within the radius, up to `most` points.
        for (size_t head = 0; head < queue.size() && head < most; ++head)
        {
          const size_t j = queue[head];
          if (s.Area[j] > 0.0 && Dot(s.Normal[j], s.Normal[i]) > Opposite)
          {
            const Vec dj = Sub(s.P[j], s.P[i]);
            const double w = Weight(s.Area[j], Dot(dj, dj), sigma2);
            const Tensor t = Turn(s.Normal[j], s.FrameU[j], s.FrameV[j], s.Tensors[j], s.Normal[i],
              s.FrameU[i], s.FrameV[i]);
            for (int c = 0; c < 3; ++c)
            {
              sum[c] += w * t[c];
            }
            wsum += w;
          }
          for (size_t e = adjacency.Start[j]; e < adjacency.Start[j + 1]; ++e)
          {
            const size_t k = static_cast<size_t>(adjacency.Second[e]);
            if (stamp[k] == i)
            {
              continue;
            }
            stamp[k] = i;
            const Vec dk = Sub(s.P[k], s.P[i]);
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
    });
  return stopped ? s.Tensors : out;
}

//------------------------------------------------------------------------------
std::vector<Tensor> Clustered(const Surface& s, double radius, double cell, size_t most,
  const Progress& progress, bool& stopped)
{
  stopped = false;
  Clusters c;
  {
    const std::vector<uint64_t> key = CellKeys(s, cell);
    if (key.empty())
    {
      return s.Tensors; // no point has a tensor
    }
    const size_t nc = GroupClusters(s, key, c.Of);
    if (nc >= std::numeric_limits<uint32_t>::max())
    {
      return Exact(s, radius, most, progress, stopped); // (cluster ids are 32-bit)
    }
    c.C = SumClusters(s, c.Of, nc);
  }
  LinkClusters(s, c);
  if (progress && !progress(0.2))
  {
    stopped = true;
    return s.Tensors;
  }
  // The clusters' Gaussian is narrowed by the interpolation's (sigma half a cell), so that the
  // two together are as wide as exact's (sigma half the radius).
  const double interpolation2 = 0.25 * cell * cell;
  const double sigma2 = std::max(0.25 * radius * radius - interpolation2, interpolation2);
  std::vector<Tensor> smooth;
  std::vector<Tensor> out(s.Tensors);
  stopped = !SmoothClusters(c, radius + 0.5 * cell, cell, sigma2, most, progress, smooth) ||
    !Interpolate(s, c, smooth, interpolation2, progress, out);
  return stopped ? s.Tensors : out;
}
}
