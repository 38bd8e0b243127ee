/**
 * @class   vtkStylizePrincipalCurvatures
 * @brief   Per-point principal curvatures and principal directions of a triangle mesh, by a
 *          per-face curvature-tensor fit (in the manner of Rusinkiewicz, 2004).
 *
 * For every triangle the second fundamental form is fitted to the change of the vertex normals
 * along its edges and accumulated at its vertices by their Voronoi area share; each vertex's
 * 2x2 tensor, averaged over SmoothingRadius when set, gives its principal curvatures and
 * directions. The output is the input (shallow copies) plus point-data arrays:
 * PrincipalCurvatureMax and Min (k1 >= k2), MeanCurvature, GaussianCurvature, the unit
 * directions PrincipalDirectionMax, Min and Bisector, and PrincipalDirectionMinAbs and MaxAbs
 * (by absolute curvature; zero vectors at planar and umbilic points). One direction is also
 * the active tangents (TangentDirection), which is how vtkSketchPass' model mode
 * (DirectionSource MODEL) reads it through VTK's composite data mapper and in ParaView.
 * Pieces with ghost cells give the values the whole mesh gives.
 *
 * The work is on vtkSMPTools' threads, with a result that does not depend on their number;
 * the smoothing reports progress (ProgressEvent, 0.2 to 0.9) and stops when AbortExecute is set
 * (the output is then the input without the arrays).
 *
 * Method and conventions (signs, tolerances, pieces, smoothing): docs/algorithms.md section 3.
 * Reference: S. Rusinkiewicz, "Estimating Curvatures and Their Derivatives on Triangle Meshes",
 * 3DPVT 2004. This is an independent implementation under the project's licence.
 *
 * @sa vtkSketchPass vtkCurvatures
 */

#ifndef vtkStylizePrincipalCurvatures_h
#define vtkStylizePrincipalCurvatures_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkStylizeFiltersModule.h" // for export macro

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
   * estimate (exact for the quadratic part of the surface). The neighbourhood is reached
   * through the mesh's edges and weighted by a Gaussian of sigma half the radius times each
   * point's area. Range [0, 1], default 0.
   */
  vtkSetClampMacro(SmoothingRadius, double, 0.0, 1.0);
  vtkGetMacro(SmoothingRadius, double);
  ///@}

  ///@{
  /**
   * Side of the grid cells in which neighbours are summed before they are averaged, as a
   * fraction of the smoothing radius (dimensionless): the sums are averaged with their
   * neighbours, then fitted to each point, instead of every point within the radius, so that the
   * cost is linear in the point count at any resolution. 0 averages every neighbour on its own
   * (exact, but the cost grows with the points per neighbourhood: quadratic in the point count
   * at a fixed radius). docs/algorithms.md section 3 gives the error and time against exact.
   * Range [0, 1], default 0.2.
   */
  vtkSetClampMacro(SmoothingCellSize, double, 0.0, 1.0);
  vtkGetMacro(SmoothingCellSize, double);
  ///@}

  ///@{
  /** Most neighbours averaged into one point's tensor: points when SmoothingCellSize is 0, cell
   * sums otherwise. Range [1, 100000], default 2000. */
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

  bool UseInputNormals = true;
  double SmoothingRadius = 0.0;
  double SmoothingCellSize = 0.2;
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
