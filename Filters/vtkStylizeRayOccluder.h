/**
 * @class   vtkStylizeRayOccluder
 * @brief   A surface that hides lines, for ray casting: its triangles in world coordinates under
 *          a bounding volume hierarchy, built once, queried from any number of threads.
 *
 * vtkStylizeLineVisibility's RAY_CAST method asks, for every sample of every line, whether the
 * segment from the sample toward the viewer crosses a surface. The occluder holds the surface's
 * triangles (polygons fanned, strips split) as indices into single-precision points relative to
 * the surface's centre, and a bounding volume hierarchy over them (median splits along the
 * longest axis, at most 4 triangles a leaf). Blocks() reads only: one occluder serves every
 * thread and every line filter of a scene (vtkStylizeFeatureStrokes builds one per surface for a
 * figure). Memory: about 40 bytes per triangle.
 *
 * @sa vtkStylizeLineVisibility
 */

#ifndef vtkStylizeRayOccluder_h
#define vtkStylizeRayOccluder_h

#include "vtkObject.h"
#include "vtkStylizeFiltersModule.h" // for export macro

#include <memory> // for std::unique_ptr

class vtkDataArray;
class vtkMatrix4x4;
class vtkPolyData;

class VTKSTYLIZEFILTERS_EXPORT vtkStylizeRayOccluder : public vtkObject
{
public:
  static vtkStylizeRayOccluder* New();
  vtkTypeMacro(vtkStylizeRayOccluder, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Builds the hierarchy over surface's polygons and triangle strips, through matrix (its model
   * matrix, may be null) into world coordinates. Triangles with a point that is not finite are
   * left out. A null or empty surface blocks nothing.
   */
  void SetSurface(vtkPolyData* surface, vtkMatrix4x4* matrix);

  /**
   * Whether the segment from a to b (world coordinates) crosses one of the triangles.
   * Thread-safe (reads only).
   */
  bool Blocks(const double a[3], const double b[3]) const;

  /**
   * A translucent surface's opacity (after SetSurface()): `opacity` in [0, 1], times, per point,
   * the fourth component of `rgba` over 255 (RGBA bytes, as direct colours; null: none). Default
   * 1 (opaque).
   */
  void SetOpacity(double opacity, vtkDataArray* rgba);

  /**
   * The share of light the triangles let through along the segment from a to b (world
   * coordinates): the product of 1 - the opacity of each triangle it crosses (a triangle's
   * opacity: the mean of its points'). 1 when it crosses none. Thread-safe (reads only).
   */
  double Transmittance(const double a[3], const double b[3]) const;

  /** The triangles' bounds in world coordinates (invalid, min > max, when there are none). */
  void GetBounds(double bounds[6]) const;

  /** The mean edge length of (up to 10000 of) the triangles, world units; 0 without any. */
  double GetMeanEdgeLength() const;

  /** The number of triangles. */
  vtkIdType GetNumberOfTriangles() const;

protected:
  vtkStylizeRayOccluder();
  ~vtkStylizeRayOccluder() override;

private:
  vtkStylizeRayOccluder(const vtkStylizeRayOccluder&) = delete;
  void operator=(const vtkStylizeRayOccluder&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
