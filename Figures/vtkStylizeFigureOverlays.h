/**
 * @file    vtkStylizeFigureOverlays.h
 * @brief   The overlay drawer of vtkStylizeFigureWriter (private to the module): the window's
 *          2D actors as vectors over the style's drawing.
 *
 * Text actors become vector text fitted to the box VTK laid them out in; 2D actors that paint
 * through vtkContext2D are painted into a cairo context device; a vtkScalarBarActor nothing
 * painted is drawn from its layout (swatches as filled shapes, title and labels as text). The
 * others are left out and named in the canvas's warning.
 */

#ifndef vtkStylizeFigureOverlays_h
#define vtkStylizeFigureOverlays_h

#include "vtkStylizeFigureCanvas.h"

#include <functional> // for std::function
#include <utility>    // for std::pair
#include <vector>     // for std::vector

class vtkContext2D;
class vtkProp;
class vtkRenderWindow;
class vtkRenderer;
class vtkViewport;

namespace vtkStylizeFigure
{
/** A 2D actor to draw and the renderer it belongs to. */
struct Overlay
{
  vtkProp* Actor;
  vtkRenderer* Renderer;
};

/** Paints a 2D actor through vtkContext2D; true when it did (the writer's PaintContextOverlay). */
using PaintFunction =
  std::function<bool(vtkProp* actor, vtkViewport* viewport, vtkContext2D* painter)>;

/**
 * The visible 2D actors of `window`'s visible props (text, scalar bars, vtkContextActor),
 * hidden so that the layers render without them; each is appended to `hidden` with the
 * visibility to restore.
 */
std::vector<Overlay> HideOverlays(
  vtkRenderWindow* window, std::vector<std::pair<vtkProp*, int>>& hidden);

/**
 * The renderers of `window` other than `styleRenderer` that draw visible 3D props (an
 * orientation marker's axes, ParaView's orientation axes): they render unstylized over the
 * style's renderer, so the layers are captured without them and their pixels drawn apart.
 */
std::vector<vtkRenderer*> SceneOverlayRenderers(
  vtkRenderWindow* window, vtkRenderer* styleRenderer);

/**
 * Draws the pixels of `with` (the frame with the scene overlays' renderers) that differ from
 * `without` (the frame without them) as one image clipped to those pixels: 3D overlays as the
 * screen shows them (an image: they are geometry the figure has no vector drawer for).
 */
void DrawOverlayPixels(Canvas& c, const Image& with, const Image& without);

/**
 * Draws `overlays` on `c` in their order, each shown only while it is drawn; `paint` paints
 * those that draw through vtkContext2D.
 */
void DrawOverlays(Canvas& c, const std::vector<Overlay>& overlays, const PaintFunction& paint);
}

#endif
