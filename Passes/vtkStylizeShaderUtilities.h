/**
 * @class   vtkStylizeShaderUtilities
 * @brief   The one place for VTK Stylize's shader plumbing (private to the module).
 *
 * - InjectCommon() adds the shared GLSL helpers (vtkStylizeCommonFS.glsl) and the facet normal
 *   (vtkStylizeFaceNormal.glsl) to a polydata fragment shader, once, whichever pass asks first.
 * - EnsureScreenTexture() / FreeTexture() keep the screen-sized float textures of the G-buffer
 *   and the style passes (nearest filtering, clamped), recreated only when they must be.
 * - vtkStylizeShaderUtilities::ScreenQuad builds a full-screen quad program from one of the
 *   project's GLSL files, rebuilds it only when its source changes, and frees it.
 */

#ifndef vtkStylizeShaderUtilities_h
#define vtkStylizeShaderUtilities_h

#include "vtkStylizePassesModule.h" // for export macro
#include "vtkType.h"

#include <string> // for std::string

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class VTKSTYLIZEPASSES_NO_EXPORT vtkStylizeShaderUtilities
{
public:
  /** Adds the shared helpers and the facet normal to a polydata fragment shader (idempotent). */
  static void InjectCommon(std::string& fragmentShader);

  /**
   * Makes `tex` a w x h texture with nearest filtering and clamped edges. internalFormat is a
   * float colour format (GL_R32F / GL_R16F: one channel; others: RGBA) or
   * GL_DEPTH_COMPONENT32F. An existing texture is resized; it is recreated when it belongs to
   * another context or when `recreate` is true (its format changed).
   */
  static void EnsureScreenTexture(vtkTextureObject*& tex, vtkOpenGLRenderWindow* renWin, int w,
    int h, int internalFormat, bool recreate = false);

  /** Releases (when w is given) and deletes a texture; sets the pointer to nullptr. */
  static void FreeTexture(vtkTextureObject*& tex, vtkWindow* w);

  /** A full-screen quad whose fragment shader is `declarations` plus `body` in main(). */
  class ScreenQuad
  {
  public:
    ScreenQuad() = default;
    ~ScreenQuad();
    ScreenQuad(const ScreenQuad&) = delete;
    ScreenQuad& operator=(const ScreenQuad&) = delete;

    /**
     * Makes the program current, building it when the inputs differ from the last build.
     * Returns nullptr (after reporting the compiler's message) when it does not compile.
     */
    vtkShaderProgram* Prepare(
      vtkOpenGLRenderWindow* renWin, const std::string& declarations, const std::string& body);
    /** Draws the quad over the current viewport. */
    void Render();
    /** Frees the program and the vertex arrays. */
    void Release(vtkWindow* w);

  private:
    vtkOpenGLQuadHelper* Helper = nullptr;
    vtkOpenGLRenderWindow* Window = nullptr;
    std::string Declarations;
    std::string Body;
  };
};

#endif
