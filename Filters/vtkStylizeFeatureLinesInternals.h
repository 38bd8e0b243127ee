/**
 * The stages of vtkStylizeFeatureLines (private): the welded triangle mesh, the view, line
 * segments per kind found inside triangles or along edges, and their chaining into polylines.
 */
#ifndef vtkStylizeFeatureLinesInternals_h
#define vtkStylizeFeatureLinesInternals_h

#include "vtkStylizeMeshGeometry.h"
#include <algorithm> // for std::equal

#include <cmath>
#include <cstdint>
#include <vector>

namespace vtkStylizeFeatureLinesInternals
{
using vtkStylizeMesh::Vec;
using Face = std::array<vtkIdType, 3>;

/** A triangle mesh with unit face and vertex normals (zero where undefined). */
struct Mesh
{
  std::vector<Vec> P;
  std::vector<Face> Faces;
  std::vector<Vec> FaceNormal;
  std::vector<double> FaceArea;
  std::vector<Vec> Normal;
  std::vector<char> OnCrease;    // the vertex is an end of a crease edge
  std::vector<vtkIdType> Source; // the input point each vertex stands for (iso-lines' values)
  /** The edges of two faces that touch a crease: (a, b, face, face). Their faces are flat
   * (a normal interpolated across a crease means nothing), so their contours are the edges
   * between a face toward the viewer and one away from it. */
  std::vector<std::array<vtkIdType, 4>> CreaseSideEdges;
  double Diagonal = 0.0; // of the points' bounding box

  /** Whether there are faces and a finite, non-zero size. */
  bool Usable() const
  {
    return !this->Faces.empty() && this->Diagonal > 0.0 && std::isfinite(this->Diagonal);
  }
};

/** Principal curvatures k1 >= k2 with their unit directions; EMaxAbs the direction of the
 * larger |k| (zero at planar and umbilic points). */
struct Curvature
{
  std::vector<double> K1, K2;
  std::vector<Vec> E1, E2, EMaxAbs;
};

/** The viewer in the mesh's coordinates. */
struct View
{
  bool Parallel = false;
  Vec Eye{ 0, 0, 0 };      // perspective: the camera's position
  Vec ToViewer{ 0, 0, 1 }; // parallel: the unit direction toward the viewer
  /** The unit vector from p toward the viewer. */
  Vec Toward(const Vec& p) const;
};

/** What the view-independent part of a run depends on: the input and the settings used. */
/** What the view-independent lines depend on (whether the curvature is needed is not part of
 * it: the curvature is added to a cache that lacks it, and kept when a frame needs none). */
struct CacheKey
{
  const void* Input = nullptr;
  unsigned long InputTime = 0;
  double CreaseAngle = 0.0, RidgeThreshold = 0.0, CurvatureSmoothing = 0.0;
  double ObjectBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  bool operator==(const CacheKey& o) const
  {
    return this->Input == o.Input && this->InputTime == o.InputTime &&
      this->CreaseAngle == o.CreaseAngle && this->RidgeThreshold == o.RidgeThreshold &&
      this->CurvatureSmoothing == o.CurvatureSmoothing &&
      std::equal(this->ObjectBounds, this->ObjectBounds + 6, o.ObjectBounds);
  }
};

/** One end of a segment: the mesh edge (or vertex) it lies on, where, and its strength. */
struct End
{
  std::uint64_t Key;
  Vec P;
  float Strength;
};
struct Segment
{
  End A, B;
};
using Segments = std::vector<Segment>;
using Chain = std::vector<End>;

/** The view-independent part of the last run (vtkStylizeFeatureLines keeps it). */
struct Cache
{
  bool Valid = false;
  CacheKey Key;
  vtkStylizeFeatureLinesInternals::Mesh Surface;
  double OwnDiagonal = 0.0;  // the welded mesh's own diagonal (Surface.Diagonal: the object's)
  bool HasCurvature = false; // Curvatures, Ridges and Valleys computed
  vtkStylizeFeatureLinesInternals::Curvature Curvatures;
  Segments Boundaries, Creases, Ridges, Valleys;
};

/** Fills the faces' normals and areas, the unit vertex normals and the diagonal. */
void FinishMesh(Mesh& mesh);

/** Boundary edges (one face) and creases (faces' normals more than creaseAngle degrees
 * apart, or more than two faces); marks the creases' vertices in mesh.OnCrease. */
void EdgeLines(Mesh& mesh, double creaseAngle, Segments& boundaries, Segments& creases);

/** Zero crossings of n.v inside the triangles; beside creases, the edges between a face toward
 * the viewer and one away from it. */
void Contours(const Mesh& mesh, const View& view, Segments& out);

/** Extremes of the larger-magnitude principal curvature along its direction. */
void RidgesAndValleys(const Mesh& mesh, const Curvature& curvature, double threshold,
  Segments& ridges, Segments& valleys);

/** Zero crossings of the radial curvature with a positive derivative toward the viewer. */
void SuggestiveContours(
  const Mesh& mesh, const Curvature& curvature, const View& view, double threshold, Segments& out);

/** Where `values` (one per vertex) crosses each of `levels` (increasing) inside the triangles;
 * each level's ends keyed apart from the others', so that chains never join two levels. */
void IsoLines(const Mesh& mesh, const std::vector<double>& values,
  const std::vector<double>& levels, Segments& out);

/** The segments joined through their shared ends into polylines; a junction (an end shared by
 * three or more segments) ends the chains that meet there. A closed chain repeats its first
 * end at its end. */
std::vector<Chain> ChainSegments(const Segments& segments);

/** The length of a chain. */
double ChainLength(const Chain& chain);
}

#endif
