/**
 * @class   vtkStylizeShaderUtilities
 * @brief   The one place for VTK Stylize's shader plumbing (private to the module).
 *
 * - InjectCommon() adds the shared GLSL helpers (vtkStylizeCommonFS.glsl) and the facet normal
 *   (vtkStylizeFaceNormal.glsl) to a polydata fragment shader, once, whichever pass asks first.
 * - EnsureScreenTexture() / FreeTexture() keep the screen-sized float textures of the G-buffer
 *   and the style passes (nearest filtering, clamped), recreated only when they must be.
 * - vtkStylizeScreenQuad builds a full-screen quad program from one of the
 *   project's GLSL files, rebuilds it only when its source changes, and frees it.
 * - vtkStylizeUniforms sets a screen pass's uniforms and textures where the
 *   program uses them, and releases the texture units it took.
 * - GetFullImage() and PixelWorldSize(): where a viewport lies in the full (possibly tiled,
 *   magnified) image, and the world size of its pixels, for resolution-free screen lengths.
 */

#ifndef vtkStylizeShaderUtilities_h
#define vtkStylizeShaderUtilities_h

#include "vtkOpenGLState.h"         // for vtkOpenGLState::Scoped*
#include "vtkStylizePassesModule.h" // for export macro
#include "vtkType.h"

#include <string> // for std::string
#include <vector> // for std::vector

class vtkCamera;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkRenderer;
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
   * float colour format (GL_R32F / GL_R16F: one channel; others: RGBA), GL_DEPTH_COMPONENT32F
   * or GL_DEPTH24_STENCIL8. An existing texture is resized; it is recreated when it belongs to
   * another context or when `recreate` is true (its format changed).
   */
  static void EnsureScreenTexture(vtkTextureObject*& tex, vtkOpenGLRenderWindow* renWin, int w,
    int h, int internalFormat, bool recreate = false);

  /** Releases (when w is given) and deletes a texture; sets the pointer to nullptr. */
  static void FreeTexture(vtkTextureObject*& tex, vtkWindow* w);

  /** Bytes a texture holds on the device (width x height x depth x texel size of its internal
   * format); 0 for none or an unallocated one. */
  static vtkIdType TextureBytes(vtkTextureObject* tex);

  /** The full image a renderer's viewport belongs to (vtkWindowToImageFilter tiles included). */
  struct FullImage
  {
    double Size[2];   ///< the renderer's size in the full image, pixels
    double Offset[2]; ///< the viewport's lower-left corner in the full image, whole pixels
    int TileScale[2]; ///< the magnification of a tiled screenshot (1 otherwise)
  };

  /** The full image of the viewport at (ox, oy) (from vtkRenderer::GetTiledSizeAndOrigin). */
  static FullImage GetFullImage(vtkRenderer* ren, int ox, int oy);

  /**
   * World size of one pixel of a w x h viewport: to be multiplied by the depth in perspective,
   * as is in parallel projection. The tile's own camera gives the full image's pixel
   * (vtkWindowToImageFilter narrows its angle and height). 1 when undefined.
   */
  static double PixelWorldSize(vtkCamera* camera, int w, int h);

  /**
   * The pixels of a size[0] x size[1] viewport that the renderer's visible props can cover: their
   * bounds projected by `cam` (then by `guard`, the guard band's NDC transform sx, sy, tx, ty),
   * padded by `margin` pixels, 2 more and half the largest point size or line width (times
   * `tileScale`), clipped to the viewport, as x0, y0, x1, y1 in `rect`. False when that is
   * the whole viewport or cannot be bounded (no props, a corner behind the eye).
   */
  static bool PropsScreenRectangle(vtkRenderer* ren, vtkCamera* cam, const double guard[4],
    const int size[2], int tileScale, int margin, int rect[4]);
};

/**
 * Sets uniforms and binds textures only where the program uses them; the texture units it
 * takes are released when it goes out of scope (after the quad is drawn).
 */
class VTKSTYLIZEPASSES_NO_EXPORT vtkStylizeUniforms
{
public:
  explicit vtkStylizeUniforms(vtkShaderProgram* program)
    : Program(program)
  {
  }
  ~vtkStylizeUniforms();
  vtkStylizeUniforms(const vtkStylizeUniforms&) = delete;
  vtkStylizeUniforms& operator=(const vtkStylizeUniforms&) = delete;

  vtkStylizeUniforms& Int(const char* name, int v);
  vtkStylizeUniforms& Float(const char* name, double v);
  vtkStylizeUniforms& Int2(const char* name, int x, int y);
  vtkStylizeUniforms& Float2(const char* name, double x, double y);
  vtkStylizeUniforms& Float3(const char* name, double x, double y, double z);
  vtkStylizeUniforms& Float4(const char* name, double x, double y, double z, double w);
  /** Binds tex (when not null) to a free unit and sets the sampler. */
  vtkStylizeUniforms& Texture(const char* name, vtkTextureObject* tex);
  vtkShaderProgram* GetProgram() const { return this->Program; }

private:
  vtkShaderProgram* Program;
  std::vector<vtkTextureObject*> Bound;
};

/** A full-screen quad whose fragment shader is `declarations` plus `body` in main(). */
class VTKSTYLIZEPASSES_NO_EXPORT vtkStylizeScreenQuad
{
public:
  vtkStylizeScreenQuad() = default;
  ~vtkStylizeScreenQuad();
  vtkStylizeScreenQuad(const vtkStylizeScreenQuad&) = delete;
  vtkStylizeScreenQuad& operator=(const vtkStylizeScreenQuad&) = delete;

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

/**
 * Saves the GL state a full-screen stage into the output changes (blending and its function,
 * the depth test, the scissor test and box, the viewport) and restores it when it goes.
 */
struct VTKSTYLIZEPASSES_NO_EXPORT vtkStylizeScopedOutputState
{
  explicit vtkStylizeScopedOutputState(vtkOpenGLState* state);
  vtkOpenGLState::ScopedglEnableDisable Blend;
  vtkOpenGLState::ScopedglEnableDisable DepthTest;
  vtkOpenGLState::ScopedglEnableDisable ScissorTest;
  vtkOpenGLState::ScopedglBlendFuncSeparate BlendFunc;
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglScissor Scissor;
};

#endif
