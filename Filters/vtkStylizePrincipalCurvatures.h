/**
 * @class   vtkStylizePrincipalCurvatures
 * @brief   Per-point principal curvatures and principal directions of a triangle mesh, by a
 *          per-face curvature-tensor fit (in the manner of Rusinkiewicz, 2004).
 *
 * For every triangle the second fundamental form is fitted, by least squares, to the change of
 * the vertex normals along its three edges. Each face's tensor is rotated into the tangent frame
 * of its three vertices and accumulated with the vertex's Voronoi (mixed) area share of the
 * face. The eigen-decomposition of each vertex's 2x2 tensor gives the principal curvatures and
 * directions.
 *
 * Output: the input geometry and topology (shallow copies), plus these point-data arrays:
 * - "PrincipalCurvatureMax", "PrincipalCurvatureMin": k1 >= k2, in 1 / (world unit). The sign
 *   follows the normals: positive where the surface bends away from them (a sphere with
 *   outward normals has k1 = k2 = 1 / r).
 * - "PrincipalDirectionMax", "PrincipalDirectionMin": unit tangent vectors of k1 and k2. A
 *   direction is a line, so d and -d are the same.
 * - "PrincipalDirectionBisector": the unit bisector (d1 + d2) / sqrt(2) of the two directions.
 * - "PrincipalDirectionMinAbs", "PrincipalDirectionMaxAbs": unit tangent vectors of the
 *   principal curvature of the smaller and of the larger **absolute value**: along and around a
 *   cylinder, whether it is convex or concave (the signed k2 of a concave cylinder runs around
 *   it). This is the convention of vtkSketchPass' MINIMUM and MAXIMUM, in screen and in model
 *   mode. Zero vectors where there is no principal direction: planar points (the larger |k|
 *   times the input's diagonal below PlanarTolerance) and umbilic points (|k1 - k2|
 *   below UmbilicTolerance times |k1| + |k2|); the sketch pass estimates those in screen space.
 * - "MeanCurvature" (k1 + k2) / 2 and "GaussianCurvature" k1 k2.
 * The direction arrays are single-precision (vtkFloatArray: unit vectors, as the GPU reads them),
 * the curvatures double. One direction array is also the point data's active tangents
 * (TangentDirection): that is how a direction reaches the GPU through VTK's composite data mapper,
 * and so in ParaView (vtkSketchPass's model mode reads it there).
 *
 * Pieces: the filter asks its input for one more ghost level, so each point of a piece has its
 * whole ring of faces, and takes the object's size over all processes (Controller): a piece
 * gives the values the whole mesh gives, except that smoothing beyond the ghost ring is
 * one-sided at a piece's boundary.
 *
 * Scale: with a SmoothingRadius above 0, each point's tensor is the average of the tensors of
 * the points around it (reached through the mesh's edges, within the radius), transported into
 * its tangent frame and weighted by their areas and a Gaussian of the distance: the curvature
 * at the shape's scale rather than at the scan noise's.
 *
 * Point normals are taken from the input's point normals when it has them (and
 * UseInputNormals is on), otherwise computed (face normals weighted by the corner angle). Only
 * polygons and triangle strips are used (triangulated); points of no polygon get zeros.
 * Degenerate triangles are skipped. No output value is NaN or infinite.
 *
 * The estimate is exact for the quadratic part of the surface up to the normals' accuracy.
 * At umbilic points (k1 = k2, e.g. everywhere on a sphere) the directions are arbitrary.
 *
 * Reference: S. Rusinkiewicz, "Estimating Curvatures and Their Derivatives on Triangle Meshes",
 * 3DPVT 2004. This is an independent implementation under the project's licence.
 */

#ifndef vtkStylizePrincipalCurvatures_h
#define vtkStylizePrincipalCurvatures_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkStylizeFiltersModule.h" // for export macro

#include <array>  // for std::array
#include <vector> // for std::vector

class vtkMultiProcessController;

class VTKSTYLIZEFILTERS_EXPORT vtkStylizePrincipalCurvatures : public vtkPolyDataAlgorithm
{
public:
  static vtkStylizePrincipalCurvatures* New();
  vtkTypeMacro(vtkStylizePrincipalCurvatures, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Use the input's point normals when it has them. Default on. */
  vtkSetMacro(UseInputNormals, bool);
  vtkGetMacro(UseInputNormals, bool);
  vtkBooleanMacro(UseInputNormals, bool);
  ///@}

  ///@{
  /**
   * Radius of the neighbourhood whose curvature tensors are averaged at each point, as a
   * fraction of the input's bounding-box diagonal (dimensionless); 0 keeps each point's own
   * estimate (exact for the quadratic part of the surface). At most MaximumNeighbors points
   * are averaged. Range [0, 1], default 0.
   */
  vtkSetClampMacro(SmoothingRadius, double, 0.0, 1.0);
  vtkGetMacro(SmoothingRadius, double);
  ///@}

  ///@{
  /** Most points averaged into one point's tensor (SmoothingRadius). Range [1, 100000], default 2000. */
  vtkSetClampMacro(MaximumNeighbors, int, 1, 100000);
  vtkGetMacro(MaximumNeighbors, int);
  ///@}

  ///@{
  /**
   * A point whose larger |curvature| times the input's bounding-box diagonal (dimensionless:
   * the normal's turn, in radians, across the object's size) is below this is planar: no
   * principal direction in the MinAbs/MaxAbs arrays. 1 (default) counts a surface whose radius
   * of curvature exceeds the object's size as flat, at any mesh resolution (the fandisk's flat
   * faces have 0.01 to 0.5 from their tessellation; its fillets 3 and more). Range [0, 1000],
   * default 1.
   */
  vtkSetClampMacro(PlanarTolerance, double, 0.0, 1000.0);
  vtkGetMacro(PlanarTolerance, double);
  ///@}

  ///@{
  /**
   * A point whose |k1 - k2| is at most this times |k1| + |k2| is umbilic: no principal
   * direction in the MinAbs/MaxAbs arrays. Range [0, 1], default 0.05.
   */
  vtkSetClampMacro(UmbilicTolerance, double, 0.0, 1.0);
  vtkGetMacro(UmbilicTolerance, double);
  ///@}

  /** Principal direction arrays that can be the output's tangents (TangentDirection). */
  enum TangentDirections
  {
    NONE = 0,
    MIN_ABS = 1,
    MAX_ABS = 2,
    MIN = 3,
    MAX = 4,
    BISECTOR = 5
  };

  ///@{
  /**
   * Which direction array the output's point data also marks as its active tangents
   * (vtkDataSetAttributes::SetTangents): NONE, MIN_ABS ("PrincipalDirectionMinAbs"), MAX_ABS,
   * MIN, MAX or BISECTOR (the arrays of the same names). VTK's composite data mapper
   * (vtkCompositePolyDataMapper2, which every ParaView representation uses) sends a mesh's
   * tangents to the GPU but no other array, so vtkSketchPass's model mode (DirectionSource
   * MODEL) reads the tangents of composite data: with MIN_ABS the sketch's Direction MINIMUM
   * draws along the smaller |curvature| there. Default MIN_ABS.
   */
  vtkSetClampMacro(TangentDirection, int, NONE, BISECTOR);
  vtkGetMacro(TangentDirection, int);
  ///@}

  ///@{
  /**
   * The processes whose pieces make up the data (vtkMultiProcessController): the bounding box
   * that SmoothingRadius and PlanarTolerance are fractions of is the whole data's, so a piece
   * gives the values the whole mesh gives (with one ghost level requested, its boundary points
   * see their neighbours across it). Default the global controller (none outside MPI).
   */
  virtual void SetController(vtkMultiProcessController* controller);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkStylizePrincipalCurvatures();
  ~vtkStylizePrincipalCurvatures() override;

  /**
   * The bounding-box diagonal of the data on all processes (Controller), 0 for no points.
   * Collective: every process calls it once per execution.
   */
  double DataDiagonal(vtkPolyData* input);

  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /**
   * The tensors (per unit area, in each point's frame) averaged over each point's
   * neighbourhood of the given radius (world units), reached through the edges of the faces.
   */
  std::vector<std::array<double, 3>> SmoothTensors(const std::vector<std::array<double, 3>>& p,
    const std::vector<std::array<double, 3>>& normal,
    const std::vector<std::array<double, 3>>& frameU,
    const std::vector<std::array<double, 3>>& frameV,
    const std::vector<std::array<vtkIdType, 3>>& faces,
    const std::vector<std::array<double, 3>>& tensor, const std::vector<double>& area,
    double radius) const;

  bool UseInputNormals = true;
  double SmoothingRadius = 0.0;
  int MaximumNeighbors = 2000;
  double PlanarTolerance = 1.0;
  double UmbilicTolerance = 0.05;
  int TangentDirection = MIN_ABS;
  vtkMultiProcessController* Controller = nullptr;

private:
  vtkStylizePrincipalCurvatures(const vtkStylizePrincipalCurvatures&) = delete;
  void operator=(const vtkStylizePrincipalCurvatures&) = delete;
};

#endif
