/**
 * @class   vtkStylizeDirectionField
 * @brief   The principal direction field a style draws along, per pixel of the G-buffer.
 *
 * Three stages (vtkStylizeFieldFS, docs/algorithms.md section 3) over the G-buffer's linear
 * depth and normals: the estimate of each pixel's principal directions from its neighbours'
 * positions, smoothing and filling of undefined pixels, and the resolve into the requested
 * direction with its fallbacks. vtkComicPass (object-anchored hatching) and vtkSketchPass
 * (pencil strokes) each own one; its stages run through the style's stage runner.
 */

#ifndef vtkStylizeDirectionField_h
#define vtkStylizeDirectionField_h

#include "vtkObject.h"
#include "vtkStylizePassesModule.h" // for export macro
#include "vtkStylizeStylePass.h"    // for vtkStylizeStylePass::Frame

#include <string> // for std::string
#include <vector> // for std::vector

class vtkTextureObject;
class vtkWindow;

class VTKSTYLIZEPASSES_NO_EXPORT vtkStylizeDirectionField : public vtkObject
{
public:
  static vtkStylizeDirectionField* New();
  vtkTypeMacro(vtkStylizeDirectionField, vtkObject);

  using Frame = vtkStylizeStylePass::Frame;
  using Settings = vtkStylizeStylePass::FieldSettings;

  /**
   * Appends the field's stages to a style's: its GLSL before the style's (the style's stages
   * call its camera helpers), its three stages (their defines and names) after the style's,
   * main() running the field's function in those. Remembers the first stage's index.
   */
  void AddStages(std::string& source, std::string& mainCall, std::vector<vtkStylizeStage>& stages);

  /** The #defines of the field's stages for `s` (add them to the style's defines). */
  static std::string Defines(const Settings& s);

  /** World size of a pixel at the camera's focal distance (1 when it is not finite). */
  static double FocalPixelWorld(const Frame& frame);

  /**
   * How far the resolved field at a pixel depends on the G-buffer around it, pixels (the
   * estimate's neighbours, the smoothing and fill taps, the gradient fallback).
   */
  static double Reach(const Frame& frame, const Settings& s, double pointSize);

  /**
   * Runs the field's stages over `style`'s G-buffer of this frame, which must hold
   * LINEAR_DEPTH and NORMAL (and DIRECTION for `s.Model`); the style's defines must include
   * Defines(s). `pointSize`: pixels per point. Returns the resolved field: xyz the view-space
   * unit direction, w the linear depth (0: no surface).
   */
  vtkTextureObject* Render(
    vtkStylizeStylePass* style, const Frame& frame, const Settings& s, double pointSize);

  /** The resolved field of the last Render() (nullptr when none). */
  vtkTextureObject* GetTexture();

  /** Bytes of the field's textures. */
  vtkIdType GetTextureBytes();

  /** Frees the field's textures (a frame that does not use the field, or a release). */
  void Free(vtkWindow* w);

protected:
  vtkStylizeDirectionField() = default;
  ~vtkStylizeDirectionField() override;

  /** The field's stages for a frame: their tap distances and strides. */
  struct Plan
  {
    int Scale = 1;                // pixels per texel of the estimate's and smoothing's grid
    int GridOrigin[2] = { 0, 0 }; // the viewport's offset into its first texel, pixels
    int GridSize[2] = { 1, 1 };   // texels
    double SpacingWorld = 0.0;    // the estimate's neighbour spacing, world units
    int MaxStride = 1;            // the estimate's largest neighbour distance, pixels
    int GradientStride = 1;       // the lighting-gradient fallback's tap distance, pixels
    // The smoothing and fill passes: tap distance (texels), fill only.
    std::vector<std::pair<int, int>> Iterations;
  };
  static Plan MakePlan(const Frame& frame, const Settings& s, double pointSize);

  int FirstStage = -1;
  /**
   * The G-buffer's depth on the plan's grid (each texel the depth of its centre pixel, a
   * framebuffer blit): what the grid's stages cull the background against. nullptr (no
   * culling) when there is no depth or culling is off.
   */
  vtkTextureObject* GridDepth(vtkStylizeStylePass* style, const Frame& frame, const Plan& plan);

  // The raw field's ping-pong pair, the resolved field and the grid's depth.
  vtkTextureObject* Textures[4] = { nullptr, nullptr, nullptr, nullptr };
  int Resolved = -1; // index in Textures of the last resolved field
  vtkWindow* Window = nullptr;

private:
  vtkStylizeDirectionField(const vtkStylizeDirectionField&) = delete;
  void operator=(const vtkStylizeDirectionField&) = delete;
};

#endif
