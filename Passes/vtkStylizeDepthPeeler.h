/**
 * @class   vtkStylizeDepthPeeler
 * @brief   Peels the translucent surfaces of a scene into G-buffer layers, front to back.
 *
 * Layer 0 holds, at each pixel, the nearest translucent surface in front of the opaque scene's
 * depth; each next layer the nearest behind the previous one. The peeler drives a
 * vtkStylizeGBufferPass through one layer at a time: it swaps the layer sequence into the
 * pass's camera pass, has translucent props write depth, adds the discard test to their
 * fragment shaders, and counts with an occlusion query whether the layer holds any surface.
 * Across several processes each layer is composited by depth to process 0 and its depth given
 * back to every process (vtkStylizeRankCompositor), so that all peel behind the whole scene.
 */

#ifndef vtkStylizeDepthPeeler_h
#define vtkStylizeDepthPeeler_h

#include "vtkNew.h" // for vtkNew
#include "vtkObject.h"
#include "vtkStylizePassesModule.h"   // for export macro
#include "vtkStylizeRankCompositor.h" // for vtkNew<vtkStylizeRankCompositor>

#include <string> // for std::string

class vtkCameraPass;
class vtkMultiProcessController;
class vtkOpenGLRenderWindow;
class vtkRenderPass;
class vtkRenderState;
class vtkSequencePass;
class vtkShaderProgram;
class vtkStylizeGBufferClearPass;
class vtkStylizeGBufferPass;
class vtkTextureObject;
class vtkWindow;

class VTKSTYLIZEPASSES_NO_EXPORT vtkStylizeDepthPeeler : public vtkObject
{
public:
  static vtkStylizeDepthPeeler* New();
  vtkTypeMacro(vtkStylizeDepthPeeler, vtkObject);

  /** The passes a layer renders: the lights and the translucent geometry. */
  void SetLayerPasses(vtkRenderPass* lights, vtkRenderPass* translucent);

  /**
   * Renders layer `index` (0 the nearest) of the translucent props of `s` into `gbuffer`,
   * in front of `opaque`'s depth. Returns whether the layer holds a surface (on every process).
   */
  bool RenderLayer(const vtkRenderState* s, vtkStylizeGBufferPass* gbuffer,
    vtkStylizeGBufferPass* opaque, int index);

  /** Whether any visible prop of `s` has translucent polygonal geometry. */
  static bool HasTranslucentGeometry(const vtkRenderState* s);

  /** The layer being rendered (-1: none) and the opaque G-buffer it lies in front of. */
  int GetLayerIndex() const { return this->LayerIndex; }
  vtkStylizeGBufferPass* GetOpaque() const { return this->Opaque; }

  /**
   * Before the layer's textures are allocated: the previous layer's depth becomes the one this
   * layer lies behind (swapped with `depth`), at w x h.
   */
  void SwapPeelDepth(vtkTextureObject*& depth);
  void AllocatePeelDepth(vtkOpenGLRenderWindow* renWin, int w, int h);

  /** Around the layer's geometry render: the layer's passes, state and occlusion query. */
  void Begin(const vtkRenderState* s, vtkCameraPass* camera);
  void End(const vtkRenderState* s, vtkCameraPass* camera, vtkRenderPass* geometry);

  /**
   * The fragment code that keeps only what lies in front of the opaque depth and, when
   * peeling, behind the previous layer's; `depth` is the expression of the fragment's depth.
   * Adds its uniforms' declarations to `fragmentShader`.
   */
  std::string FragmentCode(std::string& fragmentShader, const std::string& depth) const;

  /** The uniforms of FragmentCode(). */
  void SetShaderParameters(vtkShaderProgram* program);

  /** The G-buffer clear pass that starts a layer. */
  vtkStylizeGBufferClearPass* GetClearPass();

  void ReleaseGraphicsResources(vtkWindow* w);

protected:
  vtkStylizeDepthPeeler();
  ~vtkStylizeDepthPeeler() override;

  /**
   * The other processes' opaque G-buffers take process 0's depth (the depth composited over
   * the processes), which their translucent layers must lie in front of.
   */
  void ShareOpaqueDepth(vtkStylizeGBufferPass* opaque);
  /**
   * Process 0's layer becomes the nearest surface of all the processes' layers at each pixel,
   * and every process's layer depth that layer's depth. Returns whether any process's layer
   * holds a surface.
   */
  bool CompositeLayer(vtkStylizeGBufferPass* gbuffer, bool rendered);

  vtkNew<vtkStylizeRankCompositor> Compositor;
  vtkSequencePass* LayerSequence = nullptr;
  vtkStylizeGBufferClearPass* ClearPass = nullptr;
  int LayerIndex = -1;
  vtkStylizeGBufferPass* Opaque = nullptr;
  vtkTextureObject* OpaqueDepth = nullptr;
  vtkTextureObject* PeelDepthTexture = nullptr;
  unsigned int Query = 0;
  bool Blend = false;      // GL_BLEND before the layer's render
  bool HasSamples = false; // the last layer's query result

private:
  vtkStylizeDepthPeeler(const vtkStylizeDepthPeeler&) = delete;
  void operator=(const vtkStylizeDepthPeeler&) = delete;
};

#endif
