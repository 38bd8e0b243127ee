/**
 * @class   vtkStylizeStylePass
 * @brief   Base of the style passes (vtkComicPass, vtkPixelArtPass, vtkSketchPass): a style
 *          is an image-processing pass over the shared G-buffer.
 *
 * A style renders the scene into its G-buffer (vtkStylizeGBufferPass), lit by its lighting
 * pass (vtkStylizeLightingPass), then runs its screen-space stages. Where the scene comes from
 * depends on the delegate, as for VTK's other image-processing passes:
 *
 * - **No delegate** (the default): the style renders the renderer's opaque geometry itself,
 *   with every G-buffer channel it needs taken from the geometry (shading normals, object
 *   positions, direction attributes), then draws translucent geometry, volumes and the 2D
 *   overlay on top. This is the accurate path; use it whenever the style sees the geometry.
 * - **A delegate** (SetDelegatePass()): the style stylizes the delegate's image, its lit colour
 *   and window depth. Normals are reconstructed from the depth and positions are in world
 *   space (see vtkStylizeGBufferPass, SceneImagePass). The delegate lights the scene: give it
 *   GetLightingPass() (its own delegate renders the props) to keep the style's lighting model.
 *   This is the path for parallel rendering, where a compositor (ParaView's IceT) hands over
 *   only colour and depth: per-process lighting runs before compositing, the style after.
 *
 * @code
 * vtkNew<vtkComicPass> comic;
 * renderer->SetPass(comic);                 // stylize the geometry
 * // or stylize an image:
 * vtkNew<vtkCameraPass> camera;
 * camera->SetDelegatePass(comic->GetLightingPass()); // lights the scene, comic model
 * comic->SetDelegatePass(camera);
 * @endcode
 *
 * @sa vtkStylizeGBufferPass vtkStylizeLightingPass vtkImageProcessingPass
 */

#ifndef vtkStylizeStylePass_h
#define vtkStylizeStylePass_h

#include "vtkImageProcessingPass.h"
#include "vtkStylizePassesModule.h" // for export macro

class vtkStylizeGBufferPass;
class vtkStylizeLightingPass;

class VTKSTYLIZEPASSES_EXPORT vtkStylizeStylePass : public vtkImageProcessingPass
{
public:
  vtkTypeMacro(vtkStylizeStylePass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The lighting pass the style shades with (owned by the style; change its settings freely). */
  virtual vtkStylizeLightingPass* GetLightingPass() = 0;

  /** The style's G-buffer (owned by the style). */
  virtual vtkStylizeGBufferPass* GetGBufferPass() = 0;

protected:
  vtkStylizeStylePass();
  ~vtkStylizeStylePass() override;

  /**
   * Renders the scene into the G-buffer (from the geometry, or from the delegate's image when a
   * delegate is set) with the channels given. Returns false when there is nothing to stylize
   * (zero-sized viewport); the rest of the scene has then been drawn and the frame is done.
   */
  bool RenderScene(const vtkRenderState* s, int channels);

  /** Draws what follows the stylized image (translucent geometry, volumes, the overlay). */
  void FinishScene(const vtkRenderState* s);

private:
  vtkStylizeStylePass(const vtkStylizeStylePass&) = delete;
  void operator=(const vtkStylizeStylePass&) = delete;
};

#endif
