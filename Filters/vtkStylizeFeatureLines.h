/**
 * @class   vtkStylizeFeatureLines
 * @brief   The lines an illustrator draws on a surface, found on the mesh: occluding contours,
 *          boundaries, creases, ridges, valleys and suggestive contours, as polylines.
 *
 * The input is a surface (polygons and strips, triangulated; coincident points are merged);
 * the output is polylines with the point-data arrays FeatureKind (unsigned char, a Kinds value),
 * FeatureStrength (float in [0, 1]: 1 for contours, boundaries and creases; for the other kinds
 * how far the line is above its threshold, so that lines fade in instead of popping) and the
 * cell-data array FeatureKind. The lines are in the input's coordinates.
 *
 * - Contours: zero crossings of n.v inside triangles (v toward the Camera, vertex normals
 *   interpolated), smooth curves rather than mesh-edge zig-zags.
 * - Boundaries: edges of one face. Creases: edges whose faces meet at more than CreaseAngle.
 * - Ridges and valleys: where the principal curvature of larger magnitude is extreme along its
 *   own direction (vtkStylizePrincipalCurvatures), positive for ridges, negative for valleys,
 *   with |k| times the object's diagonal above RidgeThreshold.
 * - Suggestive contours (DeCarlo et al. 2003): zero crossings of the radial curvature on front
 *   faces where its derivative toward the viewer is positive, above SuggestiveThreshold, faded
 *   near contours.
 *
 * Every threshold is relative to the object (its bounding-box diagonal), so the same mesh at
 * any scale gives the same lines. Segments are chained into polylines through the mesh edges
 * they cross; interior lines (ridges, valleys, suggestive contours) shorter than MinimumLength
 * are dropped. Contours and suggestive contours need a Camera (vtkStylizeViewFilter, with the
 * ModelMatrix from the input's coordinates to the camera's world); without one they are
 * skipped.
 * What does not depend on the view (the welded mesh, its curvature, boundaries, creases, ridges
 * and valleys) is kept while the input and those settings stay the same: a new camera
 * recomputes only the contours and the suggestive contours, and a kind mask without the
 * curvature's kinds keeps the curvature computed for an earlier one.
 * Progress (ProgressEvent) runs through the weld (to 0.05), the curvature (to 0.8) and the
 * ridges and valleys (to 0.9); AbortExecute set during the curvature stops it: no lines, and
 * nothing kept (the next execution, after Modified(), starts over). The work is on vtkSMPTools'
 * threads with a result that does not depend on their number. Method, thresholds and their tuning
 * on real data: docs/algorithms.md ("Feature lines").
 *
 * @sa vtkStylizePrincipalCurvatures vtkFeatureEdges vtkPolyDataSilhouette
 */
#ifndef vtkStylizeFeatureLines_h
#define vtkStylizeFeatureLines_h

#include "vtkStylizeFiltersModule.h" // for export macro
#include "vtkStylizeViewFilter.h"

#include <memory> // for std::unique_ptr

namespace vtkStylizeFeatureLinesInternals
{
struct Cache;
}

class VTKSTYLIZEFILTERS_EXPORT vtkStylizeFeatureLines : public vtkStylizeViewFilter
{
public:
  static vtkStylizeFeatureLines* New();
  vtkTypeMacro(vtkStylizeFeatureLines, vtkStylizeViewFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The kinds of line: the values of the output's FeatureKind arrays. */
  enum Kinds
  {
    CONTOUR, // 0
    BOUNDARY,
    CREASE,
    RIDGE,
    VALLEY,
    SUGGESTIVE_CONTOUR, // 5
    NUMBER_OF_KINDS
  };
  /** The name of a kind ("contour", "boundary", "crease", "ridge", "valley", "suggestive"). */
  static const char* GetKindName(int kind);

  ///@{
  /**
   * The kinds extracted, a bit mask: bit (1 << kind) for each Kinds value. Range [0, 63],
   * default 63 (all).
   */
  vtkSetClampMacro(KindMask, int, 0, 63);
  vtkGetMacro(KindMask, int);
  void EnableKind(int kind, bool enabled);
  bool IsKindEnabled(int kind) const;
  ///@}

  ///@{
  /**
   * Edges whose two faces' normals differ by more than this angle are creases, in degrees.
   * Range [0, 180], default 40.
   */
  vtkSetClampMacro(CreaseAngle, double, 0.0, 180.0);
  vtkGetMacro(CreaseAngle, double);
  ///@}

  ///@{
  /**
   * A ridge or valley point is drawn where |k| times the object's bounding-box diagonal (the
   * normal's turn, in radians, across the object's size) exceeds this; its strength grows from
   * 0 at the threshold to 1 at twice the threshold. Range [0, 1e6], default 40.
   */
  vtkSetClampMacro(RidgeThreshold, double, 0.0, 1e6);
  vtkGetMacro(RidgeThreshold, double);
  ///@}

  ///@{
  /**
   * A suggestive contour point is drawn where the radial curvature's derivative toward the
   * viewer times the squared diagonal exceeds this (dimensionless); strength as for ridges,
   * times a fade from 0 where the surface is seen edge-on to 1 where n.v >= 0.3. Range
   * [0, 1e9], default 2000.
   */
  vtkSetClampMacro(SuggestiveThreshold, double, 0.0, 1e9);
  vtkGetMacro(SuggestiveThreshold, double);
  ///@}

  ///@{
  /**
   * Ridges, valleys and suggestive contours shorter than this fraction of the diagonal
   * (dimensionless) are dropped (scan noise makes many short pieces). Range [0, 1], default
   * 0.03.
   */
  vtkSetClampMacro(MinimumLength, double, 0.0, 1.0);
  vtkGetMacro(MinimumLength, double);
  ///@}

  ///@{
  /**
   * The curvature estimate's smoothing radius, a fraction of the diagonal (dimensionless;
   * vtkStylizePrincipalCurvatures::SmoothingRadius): larger values keep scan noise out of
   * ridges, valleys and suggestive contours. Range [0, 1], default 0.01.
   */
  vtkSetClampMacro(CurvatureSmoothing, double, 0.0, 1.0);
  vtkGetMacro(CurvatureSmoothing, double);
  ///@}

  ///@{
  /**
   * The bounds (in the input's coordinates) of the object whose diagonal the thresholds, the
   * smoothing and the minimum length are fractions of. Invalid (xmin > xmax, the default): the
   * input's own. A piece of a larger dataset (a rank's piece in ParaView) given the whole's
   * bounds gets the lines the whole would have there.
   */
  void SetObjectBounds(const double bounds[6]);
  void SetObjectBounds(double x0, double x1, double y0, double y1, double z0, double z1)
  {
    const double b[6] = { x0, x1, y0, y1, z0, z1 };
    this->SetObjectBounds(b);
  }
  vtkGetVector6Macro(ObjectBounds, double);
  ///@}

  ///@{
  /**
   * How many times this filter built the view-independent part (the welded mesh, boundaries and
   * creases), and how many times its curvature (for ridges, valleys and suggestive contours):
   * once per change of the input or of the settings above, not per camera and not when the kind
   * mask goes from kinds without curvature to kinds with it and back (a drag's interactive
   * frames and the still frames between them). Counts, for tests and measurements.
   */
  vtkGetMacro(ViewIndependentBuilds, int);
  vtkGetMacro(CurvatureBuilds, int);
  ///@}

protected:
  vtkStylizeFeatureLines();
  ~vtkStylizeFeatureLines() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int KindMask = 63;
  double CreaseAngle = 40.0;
  double RidgeThreshold = 40.0;
  double SuggestiveThreshold = 2000.0;
  double MinimumLength = 0.03;
  double CurvatureSmoothing = 0.01;
  double ObjectBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  int ViewIndependentBuilds = 0;
  int CurvatureBuilds = 0;

private:
  vtkStylizeFeatureLines(const vtkStylizeFeatureLines&) = delete;
  void operator=(const vtkStylizeFeatureLines&) = delete;

  /** The welded mesh, its curvature and the view-independent lines of the last input. */
  std::unique_ptr<vtkStylizeFeatureLinesInternals::Cache> ViewIndependent;
};

#endif
