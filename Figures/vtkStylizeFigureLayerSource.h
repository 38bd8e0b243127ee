/**
 * @class   vtkStylizeFigureLayerSource
 * @brief   Where vtkStylizeFigureWriter gets a style's layers from: a render window, or a view.
 *
 * A figure is drawn from the layers the style renders (vtkStylizeStylePass::SwapLayer()). By
 * default they come from the writer's render window: its first renderer's style, rendered and
 * read back with vtkWindowToImageFilter. An application that renders otherwise (ParaView's
 * stylized view renders through its own compositing) hands the writer a source of its own
 * (vtkStylizeFigureWriter::SetLayerSource()) that overrides these methods.
 */

#ifndef vtkStylizeFigureLayerSource_h
#define vtkStylizeFigureLayerSource_h

#include "vtkObject.h"
#include "vtkStylizeFiguresModule.h" // for export macro

class vtkContext2D;
class vtkImageData;
class vtkProp;
class vtkRenderWindow;
class vtkRenderer;
class vtkStylizeStylePass;
class vtkViewport;

class VTKSTYLIZEFIGURES_EXPORT vtkStylizeFigureLayerSource : public vtkObject
{
public:
  static vtkStylizeFigureLayerSource* New();
  vtkTypeMacro(vtkStylizeFigureLayerSource, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The render window the layers come from (the writer's RenderWindow by default). */
  virtual void SetRenderWindow(vtkRenderWindow* window);
  vtkGetObjectMacro(RenderWindow, vtkRenderWindow);
  ///@}

  /** The style pass to draw: the first renderer's of the window that renders with one. */
  virtual vtkStylizeStylePass* FindStylePass();

  /**
   * The renderer the style draws: the one whose pass it is. The window's other renderers (an
   * orientation marker's, ParaView's annotation renderer) render over it unstylized: a figure
   * leaves them out of the style's layers and draws what their 3D props show as an image.
   */
  virtual vtkRenderer* FindStyleRenderer();

  /**
   * Renders the window once as it is, so that the 2D actors lay themselves out before they are
   * drawn as vectors.
   */
  virtual void RenderFrame();

  /**
   * Renders the frame with the style's layer set to `layer` (restored afterwards) and reads it
   * back, RGB, `magnification` times the window's size, row 0 at the bottom. With `key` set,
   * the background is that flat colour for this frame: what differs from it is the scene.
   * Returns false when nothing could be read.
   */
  virtual bool CaptureLayer(int layer, const double* key, int magnification, vtkImageData* out);

  /**
   * Paints a 2D actor that draws through vtkContext2D into `painter`, whose device writes the
   * figure's vector shapes (its coordinates are the viewport's pixels, as on the screen).
   * Returns true when it painted the actor: a vtkContextActor's scene here; a source for an
   * application with 2D actors of its own kind (ParaView's vtkContext2DScalarBarActor) paints
   * those too.
   */
  virtual bool PaintContextOverlay(vtkProp* actor, vtkViewport* viewport, vtkContext2D* painter);

protected:
  vtkStylizeFigureLayerSource() = default;
  ~vtkStylizeFigureLayerSource() override;

  vtkRenderWindow* RenderWindow = nullptr;

private:
  vtkStylizeFigureLayerSource(const vtkStylizeFigureLayerSource&) = delete;
  void operator=(const vtkStylizeFigureLayerSource&) = delete;
};

#endif
