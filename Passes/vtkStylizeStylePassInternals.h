// The style base's private state (vtkStylizeStylePass.cxx and vtkStylizeStylePassFrame.cxx).
#ifndef vtkStylizeStylePassInternals_h
#define vtkStylizeStylePassInternals_h

#include "vtkNew.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeReducedOutput.h"
#include "vtkStylizeShaderUtilities.h"
#include "vtkStylizeStageRunner.h"
#include "vtkStylizeStylePass.h"
#include "vtkStylizeVolumeSurfaces.h"

#include <memory>
#include <vector>

class vtkOpenGLFramebufferObject;
class vtkProp;
class vtkRenderState;
class vtkTextureObject;
class vtkWindow;

class vtkStylizeStylePass::vtkInternals
{
public:
  vtkNew<vtkStylizeLightingPass> Lighting;
  vtkNew<vtkStylizeGBufferPass> GBuffer;
  vtkNew<vtkStylizeStageRunner> Runner;
  // Translucent layers (RenderTranslucentLayers()): their G-buffer, the scene the stages read
  // (GBuffer, or LayerGBuffer while a layer is stylized), the layer's number (0: opaque), the
  // layers' composite (premultiplied, front to back) and its framebuffer and program.
  vtkNew<vtkStylizeGBufferPass> LayerGBuffer;
  vtkStylizeGBufferPass* Scene = nullptr;
  int Layer = 0;
  bool EmittedLayers = false; // (the layers hold emitted colours alone: a volume's fog)
  vtkTextureObject* LayerTexture = nullptr;
  vtkOpenGLFramebufferObject* LayerFramebuffer = nullptr;
  vtkStylizeScreenQuad LayerQuad;
  vtkStylizeScreenQuad BackgroundQuad;     // the background around the scene's rectangle
  std::vector<vtkTextureObject*> Textures; // the style's slots
  bool Culling = true;                     // BackgroundCullingOn()

  // This frame's stages' size and screen transform when they differ from the viewport's: a
  // guard band (PlanGuardBand()) or a reduced picture (PlanReduction(), Reduced).
  bool Guarded = false;
  int GuardSize[2] = { 0, 0 };
  double GuardTransform[4] = { 1.0, 1.0, 0.0, 0.0 };
  vtkStylizeReducedOutput Reduced;
  vtkStylizeVolumeSurfaces Volumes;  // volumes drawn as surfaces (StylizeVolumes)
  std::vector<vtkProp*> Annotations; // drawn plain after the frame (PlainAnnotations)
  std::vector<vtkProp*> SceneProps;  // the frame's props without them
  std::unique_ptr<vtkRenderState> SceneState;

  void FreeTextures(vtkWindow* w)
  {
    for (vtkTextureObject*& t : this->Textures)
    {
      vtkStylizeShaderUtilities::FreeTexture(t, w);
    }
    vtkStylizeShaderUtilities::FreeTexture(this->LayerTexture, w);
  }
};

#endif
