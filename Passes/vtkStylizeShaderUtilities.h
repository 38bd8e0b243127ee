/**
 * @class   vtkStylizeShaderUtilities
 * @brief   The one place for VTK Stylize's shader plumbing (private to the module).
 *
 * - InjectCommon() adds the shared GLSL helpers (vtkStylizeCommonFS.glsl) and the facet normal
 *   (vtkStylizeFaceNormal.glsl) to a polydata fragment shader, once, whichever pass asks first.
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
class vtkWindow;

class VTKSTYLIZEPASSES_NO_EXPORT vtkStylizeShaderUtilities
{
public:
  /** Adds the shared helpers and the facet normal to a polydata fragment shader (idempotent). */
  static void InjectCommon(std::string& fragmentShader);

  /** A full-screen quad whose fragment shader is `declarations` plus `body` in main(). */
  class ScreenQuad
  {
  public:
    ScreenQuad() = default;
    ~ScreenQuad();
    ScreenQuad(const ScreenQuad&) = delete;
    ScreenQuad& operator=(const ScreenQuad&) = delete;

    /**
     * Makes the program current, building it when the source differs from the last build.
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
    std::string Source;
  };
};

#endif
