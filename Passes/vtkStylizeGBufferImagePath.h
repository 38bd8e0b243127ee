/**
 * @class   vtkStylizeGBufferImagePath
 * @brief   Builds a G-buffer from a rendered image instead of the geometry.
 *
 * Where another pass renders the scene (vtkStylizeGBufferPass::SceneImagePass: ParaView's
 * compositing, for one), its colour and depth are all there is. This path renders that pass
 * into an image at the viewport's size and reconstructs the G-buffer's channels from it: the
 * position from the depth and the inverse projection, the normal from the positions' slopes.
 * Where a channel source (a G-buffer that rendered this process's geometry inside the image,
 * composited by depth across processes when there are several) holds a surface, its exact
 * normals, positions and directions replace the reconstructed ones.
 */

#ifndef vtkStylizeGBufferImagePath_h
#define vtkStylizeGBufferImagePath_h

#include "vtkMatrix4x4.h" // for vtkNew<vtkMatrix4x4>
#include "vtkNew.h"       // for vtkNew
#include "vtkObject.h"
#include "vtkStylizePassesModule.h"   // for export macro
#include "vtkStylizeRankCompositor.h" // for vtkNew<vtkStylizeRankCompositor>

#include <memory> // for std::unique_ptr

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkRenderState;
class vtkStylizeGBufferPass;
class vtkTextureObject;
class vtkWindow;

class VTKSTYLIZEPASSES_NO_EXPORT vtkStylizeGBufferImagePath : public vtkObject
{
public:
  static vtkStylizeGBufferImagePath* New();
  vtkTypeMacro(vtkStylizeGBufferImagePath, vtkObject);

  /**
   * Renders `gbuffer`'s scene image pass and fills the G-buffer (its framebuffer bound, at
   * gw x gh) from it. `inverseView` is the camera's inverse view matrix.
   */
  void Render(const vtkRenderState* s, vtkStylizeGBufferPass* gbuffer,
    vtkOpenGLRenderWindow* renWin, int gw, int gh, vtkMatrix4x4* inverseView);

  /** Bytes of the textures it holds. */
  vtkIdType GetTextureBytes();

  void ReleaseGraphicsResources(vtkWindow* w);

protected:
  vtkStylizeGBufferImagePath();
  ~vtkStylizeGBufferImagePath() override;

  /** Step 1: the image, and the channel source's channels when it rendered into it. */
  void RenderImage(const vtkRenderState* s, vtkStylizeGBufferPass* gbuffer,
    vtkOpenGLRenderWindow* renWin, int w, int h);
  /**
   * The channel source's channels composited over the processes, kept on process 0. Returns
   * whether process 0 holds any.
   */
  bool CompositeChannelSource(
    vtkStylizeGBufferPass* gbuffer, vtkOpenGLRenderWindow* renWin, bool rendered, int w, int h);
  /** Step 2: the G-buffer's channels from the image. */
  void Reconstruct(const vtkRenderState* s, vtkStylizeGBufferPass* gbuffer,
    vtkOpenGLRenderWindow* renWin, int gw, int gh, vtkMatrix4x4* inverseView);
  void FreeTextures(vtkWindow* w);

  vtkOpenGLFramebufferObject* FrameBuffer = nullptr;
  vtkTextureObject* ColorTexture = nullptr;
  vtkTextureObject* DepthTexture = nullptr;
  int DepthFormat = 0; // DepthTexture's: the window's own (see RenderImage())
  // The channel source's channels composited over the processes (on process 0): stored depth,
  // normal, position, direction, linear depth, inside the rectangle SourceRect (x, y, width,
  // height).
  static constexpr int SourceSlots = 5;
  vtkTextureObject* Composited[SourceSlots] = { nullptr, nullptr, nullptr, nullptr, nullptr };
  int SourceRect[4] = { 0, 0, 0, 0 };
  // The textures the channels come from: the source's own (one process) or Composited.
  vtkTextureObject* SourceTextures[SourceSlots] = { nullptr, nullptr, nullptr, nullptr, nullptr };
  vtkNew<vtkStylizeRankCompositor> Compositor;
  vtkNew<vtkMatrix4x4> Upload; // a matrix on its way to a shader (transposed)
  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;

private:
  vtkStylizeGBufferImagePath(const vtkStylizeGBufferImagePath&) = delete;
  void operator=(const vtkStylizeGBufferImagePath&) = delete;
};

#endif
