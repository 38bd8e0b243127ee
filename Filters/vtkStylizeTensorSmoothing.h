/**
 * The neighbourhood average of per-point curvature tensors behind
 * vtkStylizePrincipalCurvatures' SmoothingRadius. Private: not installed.
 *
 * Each point's 2x2 tensor (per unit area, in its own tangent frame) is replaced by the Gaussian
 * (sigma = radius / 2) and area weighted mean of the tensors of the points within the radius
 * that are reached through the mesh's edges, each turned onto the point's tangent plane by the
 * smallest rotation. Two ways, both threaded with a result that does not depend on the thread
 * count:
 * - Exact: every neighbour on its own; the cost grows with the points per neighbourhood, so
 *   with the square of the point count at a fixed radius.
 * - Clustered: the neighbours are first gathered into clusters (the connected pieces of the
 *   mesh within one grid cell of the given size, split by the normal's dominant axis), each
 *   summed once in its own frame at its area-weighted centroid; each cluster averages the
 *   clusters within the radius (a taper of one cell lets a cluster enter gradually), and each
 *   point takes a linear fit through its own and its linked clusters' averages. The cost is
 *   linear in the point count: about 3 (radius / cell)^2 cluster pairs per cluster, 9 per point.
 *   docs/algorithms.md section 3 gives the accuracy against the exact way.
 */
#ifndef vtkStylizeTensorSmoothing_h
#define vtkStylizeTensorSmoothing_h

#include "vtkStylizeMeshGeometry.h"

#include <array>
#include <functional>
#include <vector>

namespace vtkStylizeTensorSmoothing
{
using Tensor = std::array<double, 3>; // (A, B, C): [A B; B C] in a point's frame (u, v)

/** The surface the tensors live on; Area[i] > 0 marks the points with a tensor and a frame. */
struct Surface
{
  const std::vector<vtkStylizeMesh::Vec>& P;
  const std::vector<vtkStylizeMesh::Vec>& Normal;
  const std::vector<vtkStylizeMesh::Vec>& FrameU;
  const std::vector<vtkStylizeMesh::Vec>& FrameV;
  const std::vector<std::array<vtkIdType, 3>>& Faces;
  const std::vector<Tensor>& Tensors;
  const std::vector<double>& Area;
};

/**
 * Called on the calling thread between blocks of work with the share done (0 to 1); returns
 * false to stop (the result is then the unsmoothed tensors).
 */
using Progress = std::function<bool(double)>;

/** Exact: each point's neighbours one by one (breadth first, at most `most` points). */
std::vector<Tensor> Exact(
  const Surface& s, double radius, size_t most, const Progress& progress, bool& stopped);

/**
 * Clustered, with grid cells of side `cell` (world units, > 0); at most `most` clusters per
 * neighbourhood.
 */
std::vector<Tensor> Clustered(const Surface& s, double radius, double cell, size_t most,
  const Progress& progress, bool& stopped);
}

#endif
