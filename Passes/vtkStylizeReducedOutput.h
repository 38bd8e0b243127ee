/**
 * @class   vtkStylizeReducedOutput
 * @brief   A style's output at a reduced image size, scaled up into the window.
 *
 * While the user drags, a style may render its whole picture at 1/k of the viewport's size in
 * each direction (vtkStylizeStylePass::InteractiveImageReduction). Begin() binds a framebuffer of
 * that size (colour RGBA8 and depth) in place of the window, so that every write of the style's
 * output lands there; End() binds the window again and, when something was written, draws the
 * picture over the viewport: the colour filtered linearly, the depth of the nearest pixel, so that
 * what follows (translucent geometry, volumes, the overlay) is drawn at the window's resolution
 * and depth-tested against the stylized scene. Private to the module.
 */

#ifndef vtkStylizeReducedOutput_h
#define vtkStylizeReducedOutput_h

#include "vtkStylizePassesModule.h"    // for export macro
#include "vtkStylizeShaderUtilities.h" // for vtkStylizeScreenQuad
#include "vtkType.h"

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class VTKSTYLIZEPASSES_NO_EXPORT vtkStylizeReducedOutput
{
public:
  vtkStylizeReducedOutput() = default;
  ~vtkStylizeReducedOutput();
  vtkStylizeReducedOutput(const vtkStylizeReducedOutput&) = delete;
  vtkStylizeReducedOutput& operator=(const vtkStylizeReducedOutput&) = delete;

  /**
   * Binds a w x h framebuffer as the output in place of the current one; `viewport` (x, y,
   * width, height, window pixels) is where End() draws it. Returns false (and binds nothing)
   * when the textures cannot be made.
   */
  bool Begin(vtkOpenGLRenderWindow* window, int w, int h, const int viewport[4]);
  /** Something was written to the reduced output (End() draws it only then). */
  void MarkWritten() { this->Written = true; }
  /** Between Begin() and End(). */
  bool IsActive() const { return this->Active; }
  /** Binds the previous framebuffer again and draws the picture over the viewport. */
  void End();
  /** Bytes of its textures on the device. */
  vtkIdType GetTextureBytes() const;
  /** Frees the textures, the framebuffer and the program. */
  void Release(vtkWindow* w);

private:
  vtkOpenGLRenderWindow* Window = nullptr;
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  vtkTextureObject* Color = nullptr;
  vtkTextureObject* Depth = nullptr;
  vtkStylizeScreenQuad Quad;
  int Viewport[4] = { 0, 0, 0, 0 };
  bool Active = false;
  bool Written = false;
};

#endif
