/**
 * @class   vtkStylizeGBufferClearPass
 * @brief   Clears what vtkRenderer::Clear() leaves alone in a G-buffer.
 *
 * The first step inside the G-buffer's camera pass: clears the extra attachments, the colour of
 * layered renderers, and everything when the renderer does not erase, so that no value of an
 * earlier frame survives. For a translucent layer it clears to "no surface yet" (alpha 0, the
 * colour of the flat background the stages read across a silhouette).
 */

#ifndef vtkStylizeGBufferClearPass_h
#define vtkStylizeGBufferClearPass_h

#include "vtkRenderPass.h"
#include "vtkStylizePassesModule.h" // for export macro

class VTKSTYLIZEPASSES_NO_EXPORT vtkStylizeGBufferClearPass : public vtkRenderPass
{
public:
  static vtkStylizeGBufferClearPass* New();
  vtkTypeMacro(vtkStylizeGBufferClearPass, vtkRenderPass);
  void Render(const vtkRenderState* s) override;

  unsigned int Attachments = 1;    ///< colour attachments of the G-buffer (1 to 5)
  bool Layer = false;              ///< clears for a translucent layer
  bool UseImageBackground = false; ///< a layer's background colour is ImageBackground
  float ImageBackground[3] = { 0.f, 0.f, 0.f };

protected:
  vtkStylizeGBufferClearPass() = default;
  ~vtkStylizeGBufferClearPass() override = default;

private:
  vtkStylizeGBufferClearPass(const vtkStylizeGBufferClearPass&) = delete;
  void operator=(const vtkStylizeGBufferClearPass&) = delete;
};

#endif
