/**
 * @class   vtkStylizeViewFilter
 * @brief   Base of the filters whose output depends on a view (vtkStylizeFeatureLines,
 *          vtkStylizeLineVisibility): a camera and the matrix from the input's coordinates to
 *          the camera's world, both part of the filter's modification time.
 *
 * @sa vtkStylizeFeatureLines vtkStylizeLineVisibility
 */
#ifndef vtkStylizeViewFilter_h
#define vtkStylizeViewFilter_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkStylizeFiltersModule.h" // for export macro

class vtkCamera;
class vtkMatrix4x4;

class VTKSTYLIZEFILTERS_EXPORT vtkStylizeViewFilter : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkStylizeViewFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The view: the camera's position (perspective) or direction of projection (parallel). */
  virtual void SetCamera(vtkCamera* camera);
  vtkGetObjectMacro(Camera, vtkCamera);
  ///@}

  ///@{
  /**
   * The matrix from the input's coordinates to the camera's world (an actor's matrix). None
   * (default): the identity.
   */
  virtual void SetModelMatrix(vtkMatrix4x4* matrix);
  vtkGetObjectMacro(ModelMatrix, vtkMatrix4x4);
  ///@}

  /** Includes the camera's and the model matrix's modification times. */
  vtkMTimeType GetMTime() override;

protected:
  vtkStylizeViewFilter();
  ~vtkStylizeViewFilter() override;

  /** The input: vtkPolyData. */
  int FillInputPortInformation(int port, vtkInformation* info) override;

  vtkCamera* Camera = nullptr;
  vtkMatrix4x4* ModelMatrix = nullptr;

private:
  vtkStylizeViewFilter(const vtkStylizeViewFilter&) = delete;
  void operator=(const vtkStylizeViewFilter&) = delete;
};

#endif
