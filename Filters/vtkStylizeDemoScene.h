/**
 * @class   vtkStylizeDemoScene
 * @brief   The built-in scene with scientific content, as a multiblock dataset.
 *
 * Three blocks of vtkPolyData, each with point normals:
 * - block 0 "isosurface": an isosurface of vtkRTAnalyticSource (the wavelet) at IsoValue,
 *   with the point array "RTData";
 * - block 1 "parametric": a parametric surface (a torus, vtkParametricTorus) beside it, with the
 *   point array "Height" (its z coordinate);
 * - block 2 "streamlines": tubes around streamlines of a swirling flow (rotation about the z axis
 *   with an upward drift) that wind around the isosurface, with the point array "Speed", for
 *   colouring by a scalar.
 *
 * Resolution scales every part (1 gives about 60k triangles). The output is deterministic.
 */

#ifndef vtkStylizeDemoScene_h
#define vtkStylizeDemoScene_h

#include "vtkMultiBlockDataSetAlgorithm.h"
#include "vtkStylizeFiltersModule.h" // for export macro

class VTKSTYLIZEFILTERS_EXPORT vtkStylizeDemoScene : public vtkMultiBlockDataSetAlgorithm
{
public:
  static vtkStylizeDemoScene* New();
  vtkTypeMacro(vtkStylizeDemoScene, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Detail factor, in [0.25, 8]: sampling of the wavelet and the surfaces. Default 1. */
  vtkSetClampMacro(Resolution, double, 0.25, 8.0);
  vtkGetMacro(Resolution, double);
  ///@}

  ///@{
  /** Isovalue of the wavelet surface, in [40, 270]. Default 190. */
  vtkSetClampMacro(IsoValue, double, 40.0, 270.0);
  vtkGetMacro(IsoValue, double);
  ///@}

  ///@{
  /** Number of streamlines, in [0, 200]. Default 12. */
  vtkSetClampMacro(NumberOfStreamlines, int, 0, 200);
  vtkGetMacro(NumberOfStreamlines, int);
  ///@}

protected:
  vtkStylizeDemoScene();
  ~vtkStylizeDemoScene() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Resolution = 1.0;
  double IsoValue = 190.0;
  int NumberOfStreamlines = 12;

private:
  vtkStylizeDemoScene(const vtkStylizeDemoScene&) = delete;
  void operator=(const vtkStylizeDemoScene&) = delete;
};

#endif
