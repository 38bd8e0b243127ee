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
 * - Iso-lines: where a point-data array (IsoLineArrayName) crosses the levels IsoLineCount and
 *   IsoLineSpacing place in IsoLineRange, its linear interpolant cut inside each triangle: the
 *   contour plot of the array, drawn on the surface. Levels and how they are chosen:
 *   ComputeIsoLevels().
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
#include <string> // for std::string
#include <vector> // for std::vector

namespace vtkStylizeFeatureLinesInternals
{
struct Cache;
struct Mesh;
struct Segment;
}
class vtkPolyData;

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
    ISOLINE,
    NUMBER_OF_KINDS
  };
  /** The name of a kind ("contour", "boundary", "crease", "ridge", "valley", "suggestive",
   * "isoline"). */
  static const char* GetKindName(int kind);

  ///@{
  /**
   * The kinds extracted, a bit mask: bit (1 << kind) for each Kinds value. Range [0, 127],
   * default 127 (all; iso-lines need IsoLineCount > 0 too).
   */
  vtkSetClampMacro(KindMask, int, 0, 127);
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
   * The point-data array whose iso-lines are drawn; empty (the default): the active scalars.
   * Cell data has no iso-lines (its colours are constant per cell).
   */
  vtkSetStdStringFromCharMacro(IsoLineArrayName);
  vtkGetCharFromStdStringMacro(IsoLineArrayName);
  ///@}

  ///@{
  /**
   * The array's component whose iso-lines are drawn, -1 for the magnitude (the value itself for
   * one component). A component the array lacks draws nothing. Range [-1, 1023], default -1.
   */
  vtkSetClampMacro(IsoLineComponent, int, -1, 1023);
  vtkGetMacro(IsoLineComponent, int);
  ///@}

  ///@{
  /**
   * How many iso-lines: the most levels (ROUND), the number of levels (EVEN), or ignored
   * (BANDS, the colour map's own); 0 draws none. Range [0, 1000], default 0.
   */
  vtkSetClampMacro(IsoLineCount, int, 0, 1000);
  vtkGetMacro(IsoLineCount, int);
  ///@}

  /** How the levels are placed in IsoLineRange (ComputeIsoLevels()). */
  enum IsoLineSpacings
  {
    ROUND, // round numbers: a step of 1, 2, 2.5 or 5 times a power of ten
    EVEN,  // IsoLineCount levels that split the range into equal parts
    BANDS  // the edges between the IsoLineBands colours of a banded colour map
  };

  ///@{
  /** How the levels are placed: ROUND (the default), EVEN or BANDS. */
  vtkSetClampMacro(IsoLineSpacing, int, ROUND, BANDS);
  vtkGetMacro(IsoLineSpacing, int);
  ///@}

  ///@{
  /**
   * BANDS spacing: the number of colours of the banded colour map (a vtkLookupTable's
   * NumberOfTableValues, a discretized colour transfer function's NumberOfValues). Range
   * [1, 1000], default 10.
   */
  vtkSetClampMacro(IsoLineBands, int, 1, 1000);
  vtkGetMacro(IsoLineBands, int);
  ///@}

  ///@{
  /**
   * The range of values the levels are placed in, in the array's units (the colour map's
   * range); invalid (low > high, the default): the array's own range.
   */
  vtkSetVector2Macro(IsoLineRange, double);
  vtkGetVector2Macro(IsoLineRange, double);
  ///@}

  ///@{
  /**
   * Levels placed on a logarithmic scale (a colour map with a log scale): ROUND gives 1, 2 and 5
   * times powers of ten (or powers of ten alone, or every few of them), EVEN and BANDS split the
   * logarithm of the range. A range that is not positive draws nothing. Default off.
   */
  vtkSetMacro(IsoLineLogScale, bool);
  vtkGetMacro(IsoLineLogScale, bool);
  vtkBooleanMacro(IsoLineLogScale, bool);
  ///@}

  /**
   * The iso-line levels of a range [low, high] (excluded: the extremes of the colour map draw
   * no line), in increasing order:
   * - ROUND: the multiples of the smallest round step (1, 2, 2.5 or 5 times a power of ten)
   *   that gives at most `count` levels inside the range, as a scalar bar's ticks;
   * - EVEN: `count` levels that split the range into count + 1 equal parts;
   * - BANDS: the bands - 1 edges between `bands` equal bands (count ignored).
   * With `logScale`, EVEN and BANDS split log10 of the range, and ROUND takes 1 to 9, or 1, 2
   * and 5, times each power of ten, or the powers of ten alone, or every k-th: the densest that
   * gives at most `count` (a range too narrow for any: the linear round levels). Empty for a
   * range that is empty, not finite, or (logScale) not positive.
   */
  static std::vector<double> ComputeIsoLevels(
    double low, double high, int count, int spacing, int bands, bool logScale);

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

  int KindMask = 127;
  std::string IsoLineArrayName;
  int IsoLineComponent = -1;
  int IsoLineCount = 0;
  int IsoLineSpacing = ROUND;
  int IsoLineBands = 10;
  double IsoLineRange[2] = { 1.0, -1.0 };
  bool IsoLineLogScale = false;
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

  /** The iso-lines of the input's array on its welded mesh. */
  void IsoLineSegments(vtkPolyData* input, const vtkStylizeFeatureLinesInternals::Mesh& mesh,
    std::vector<vtkStylizeFeatureLinesInternals::Segment>& out);

  /** The welded mesh, its curvature and the view-independent lines of the last input. */
  std::unique_ptr<vtkStylizeFeatureLinesInternals::Cache> ViewIndependent;
};

#endif
