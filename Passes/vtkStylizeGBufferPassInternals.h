/**
 * @file    vtkStylizeGBufferPassInternals.h
 * @brief   What vtkStylizeGBufferPass keeps besides its settings and textures: its clear pass,
 *          depth peeler, image path, composite quad and the matrices of the frame. Shared by
 *          the pass's two source files.
 */

#ifndef vtkStylizeGBufferPassInternals_h
#define vtkStylizeGBufferPassInternals_h

#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkStylizeDepthPeeler.h"
#include "vtkStylizeGBufferClearPass.h"
#include "vtkStylizeGBufferImagePath.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizePlainVolumes.h"
#include "vtkStylizeShaderUtilities.h"

class vtkStylizeGBufferPass::vtkInternals
{
public:
  vtkNew<vtkStylizeGBufferClearPass> ClearPass;
  vtkNew<vtkStylizeDepthPeeler> Peeler;
  vtkNew<vtkStylizeGBufferImagePath> ImagePath;
  vtkNew<vtkStylizePlainVolumes> PlainVolumes; // left out by a channel source, on several ranks
  vtkStylizeScreenQuad CompositeQuad;
  vtkNew<vtkMatrix4x4> InverseView;
  vtkNew<vtkMatrix4x4> View;
  double ClippingRange[2] = { 0.1, 1000.0 }; // (the camera's, for the frame's props)
  vtkNew<vtkMatrix4x4> InverseModel;
  vtkNew<vtkMatrix4x4> Product;
};

#endif
