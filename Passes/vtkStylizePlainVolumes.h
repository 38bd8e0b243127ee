/**
 * @class   vtkStylizePlainVolumes
 * @brief   Draws the volumes a style leaves to VTK over the style's picture, across processes.
 *
 * On one process the style draws such volumes (vtkStylizeStylePass::STYLIZE_VOLUME 0, or
 * StylizeVolumes off) over its picture as VTK draws them. Behind a compositor of several
 * processes (ParaView's view on several ranks) each holds a piece of such a volume and the
 * picture is on process 0; depth compositing would keep none of a volume, which writes no
 * depth. Render() does, on every process at once (collective):
 *
 * 1. process 0's depth (the composited scene's) to every process;
 * 2. each process draws its pieces with VTK's mapper into a layer of its own, premultiplied
 *    colour over transparent black, against that depth (in the window's depth format, which
 *    VTK's GPU ray caster copies the depth from);
 * 3. the layers go to process 0, which puts them over each other in visibility order (the
 *    pieces' bounding boxes seen from the camera, vtkStylizeRankCompositor::InFront(): each
 *    process's pieces are one box of a partition such as a reader's extents or a k-d split)
 *    and blends the result over its picture.
 */

#ifndef vtkStylizePlainVolumes_h
#define vtkStylizePlainVolumes_h

#include "vtkNew.h" // for vtkNew
#include "vtkObject.h"
#include "vtkStylizePassesModule.h"    // for export macro
#include "vtkStylizeRankCompositor.h"  // for vtkNew<vtkStylizeRankCompositor>
#include "vtkStylizeShaderUtilities.h" // for vtkStylizeScreenQuad

#include <array>  // for std::array
#include <vector> // for std::vector

class vtkMultiProcessController;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkProp;
class vtkRenderPass;
class vtkRenderState;
class vtkRenderer;
class vtkTextureObject;
class vtkWindow;

class VTKSTYLIZEPASSES_NO_EXPORT vtkStylizePlainVolumes : public vtkObject
{
public:
  static vtkStylizePlainVolumes* New();
  vtkTypeMacro(vtkStylizePlainVolumes, vtkObject);

  /**
   * Draws `volumes` (this process's) with `volumePass` (VTK's volumetric pass) over the
   * picture in the bound framebuffer of process 0, as described above. Every process of
   * `controller` calls it for the same frame, with or without volumes of its own; it does
   * nothing when no process has any.
   */
  void Render(const vtkRenderState* s, const std::vector<vtkProp*>& volumes,
    vtkRenderPass* volumePass, vtkMultiProcessController* controller);

  /** Frees the layer's textures, framebuffer and quad. */
  void ReleaseGraphicsResources(vtkWindow* w);

protected:
  vtkStylizePlainVolumes() = default;
  ~vtkStylizePlainVolumes() override;

private:
  vtkStylizePlainVolumes(const vtkStylizePlainVolumes&) = delete;
  void operator=(const vtkStylizePlainVolumes&) = delete;

  /** A process's layer: its rectangle inside the viewport, RGBA inside it, its pieces' box. */
  struct VolumeLayer
  {
    vtkStylizeRankCompositor::Part Pixels;
    std::array<double, 6> Box = { { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 } };
  };

  /** Step 1: process 0's depth over the viewport into Depths, on every process. */
  void ShareDepth(vtkOpenGLRenderWindow* renWin, vtkMultiProcessController* c);
  /** Step 2: this process's volumes against Depths, read back into Pixels (RGBA). */
  void DrawLayer(
    const vtkRenderState* s, const std::vector<vtkProp*>& volumes, vtkRenderPass* volumePass);
  /**
   * Step 3: the layers to process 0, over each other in visibility order into Over. Returns
   * whether Over holds any (false on the other processes).
   */
  bool CompositeLayers(vtkRenderer* ren, VolumeLayer& own, vtkMultiProcessController* controller);
  /** Step 4: Over blended over the bound framebuffer (premultiplied). */
  void BlendOver(vtkOpenGLRenderWindow* renWin);

  int Viewport[4] = { 0, 0, 0, 0 }; // the renderer's, this frame (x, y, width, height)
  // (kept from frame to frame, so that a frame allocates nothing at the same size)
  vtkStylizeRankCompositor::Part Shared; // process 0's depth as broadcast
  std::vector<float> Depths;             // that depth over the viewport, rows bottom to top
  std::vector<unsigned int> Packed;      // the same as 24-bit depth and 8-bit stencil
  std::vector<float> Pixels;             // this process's layer over the viewport (RGBA)
  std::vector<float> Over;               // the layers composited, on process 0 (RGBA)

  vtkNew<vtkStylizeRankCompositor> Compositor;
  vtkOpenGLFramebufferObject* FrameBuffer = nullptr;
  vtkTextureObject* Color = nullptr; // the process's layer (premultiplied colour)
  vtkTextureObject* Depth = nullptr; // process 0's depth, in the window's format
  int DepthFormat = 0;
  vtkTextureObject* Layer = nullptr; // the layers composited, on process 0
  vtkStylizeScreenQuad Quad;
};

#endif
