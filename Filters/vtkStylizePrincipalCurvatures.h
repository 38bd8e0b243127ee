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
 * - "MeanCurvature" (k1 + k2) / 2 and "GaussianCurvature" k1 k2.
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

protected:
  vtkStylizePrincipalCurvatures() = default;
  ~vtkStylizePrincipalCurvatures() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool UseInputNormals = true;

private:
  vtkStylizePrincipalCurvatures(const vtkStylizePrincipalCurvatures&) = delete;
  void operator=(const vtkStylizePrincipalCurvatures&) = delete;
};

#endif
