/**
 * @class   vtkLineArtPass
 * @brief   Line art: the lines an illustrator draws (occluding contours, boundaries, creases,
 *          ridges, valleys and suggestive contours), found on the meshes and drawn in ink on
 *          paper with their hidden parts removed, over an optional flat tone.
 *
 * Use it like any VTK pass: `renderer->SetPass(lines)`; it needs no delegate. Each frame the
 * scene is rendered once into the shared G-buffer (vtkStylizeGBufferPass); the lines of every
 * visible opaque actor whose mapper's input is a surface (vtkPolyData or composite data of
 * them) come from vtkStylizeFeatureLines through the actor's matrix, and each is cut where it
 * passes behind any surface of the scene (vtkStylizeLineVisibility against the G-buffer's
 * linear depth, sampled every quarter pixel). The visible runs are drawn as round-capped
 * strokes whose width is set per kind (0 leaves a kind out, and it is not computed), thinned
 * with depth across the scene (DepthTaper) and faded in with the line's strength
 * (StrengthTaper), so that lines appear gradually as the view turns. Under the ink the paper
 * is plain (Tone NONE) or the lit tone in a few flat shades (SHADES). Actors drawn as
 * wireframe or points, and line and vertex cells, are drawn in ink as they are. Vector figures
 * (vtkStylizeFigureWriter) draw the same strokes as paths, found by ray casting.
 *
 * What does not depend on the view (curvature, creases, ridges and valleys) is computed once per
 * mesh and kept; a new camera recomputes only the contours and suggestive contours. The
 * interactive variant (InteractiveUpdateRate) draws contours, boundaries and creases only.
 * A translucent surface (TranslucentLayers) is drawn as its paper or tone with its outline
 * (TranslucentOutlines), over the line art with its opacity.
 * Lengths are in points (one pixel of an image ReferenceHeight pixels tall). Method, measures
 * and costs: docs/algorithms.md ("Feature lines").
 * The pass invokes ProgressEvent (a double in [0, 1]) while a frame finds the lines of its
 * surfaces (seconds for the first frame of millions of triangles): the vtkstylize program's
 * progress bar and ParaView's. The comic and the sketch report their feature lines the same way.
 *
 * @sa vtkStylizeFeatureLines vtkStylizeLineVisibility vtkComicPass vtkSketchPass
 */

#ifndef vtkLineArtPass_h
#define vtkLineArtPass_h

#include "vtkStylizePassesModule.h" // for export macro
#include "vtkStylizeStylePass.h"

class vtkPolyData;
class vtkStylizeFeatureStrokes;

class VTKSTYLIZEPASSES_EXPORT vtkLineArtPass : public vtkStylizeStylePass
{
public:
  static vtkLineArtPass* New();
  vtkTypeMacro(vtkLineArtPass, vtkStylizeStylePass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Width of occluding contours and boundaries (the outline and the object's own edges), in
   * points. A rendered stroke (of every kind) is at least a pixel wide; a vector figure keeps
   * the exact widths. Range [0, 20], default 2.5.
   */
  vtkSetClampMacro(ContourWidth, double, 0.0, 20.0);
  vtkGetMacro(ContourWidth, double);
  ///@}

  ///@{
  /**
   * Width of creases (edges whose faces meet at more than CreaseAngle), in points; 0 leaves
   * them out. Range [0, 20], default 1.5.
   */
  vtkSetClampMacro(CreaseWidth, double, 0.0, 20.0);
  vtkGetMacro(CreaseWidth, double);
  ///@}

  ///@{
  /**
   * Width of ridges and of valleys (extremes of the principal curvature), in points; 0 leaves
   * them out. Range [0, 20], default 1 each.
   */
  vtkSetClampMacro(RidgeWidth, double, 0.0, 20.0);
  vtkGetMacro(RidgeWidth, double);
  vtkSetClampMacro(ValleyWidth, double, 0.0, 20.0);
  vtkGetMacro(ValleyWidth, double);
  ///@}

  ///@{
  /**
   * Width of suggestive contours (where a contour would appear from a nearby view), in points;
   * 0 leaves them out. Range [0, 20], default 1.2.
   */
  vtkSetClampMacro(SuggestiveWidth, double, 0.0, 20.0);
  vtkGetMacro(SuggestiveWidth, double);
  ///@}

  ///@{
  /**
   * Share of a stroke's width lost from the scene's nearest point to its farthest (the bounding
   * sphere of the visible props along the view direction): near lines read heavier. 0 keeps
   * every line at its width. Range [0, 1], default 0.5.
   */
  vtkSetClampMacro(DepthTaper, double, 0.0, 1.0);
  vtkGetMacro(DepthTaper, double);
  ///@}

  ///@{
  /**
   * Share of a stroke's width that follows the line's strength (vtkStylizeFeatureLines'
   * FeatureStrength, 1 for contours and creases, rising from 0 at the threshold for the
   * others): weak lines are thin, and lines grow in rather than pop as the view turns. 0 draws
   * every line at its full width. Range [0, 1], default 1.
   */
  vtkSetClampMacro(StrengthTaper, double, 0.0, 1.0);
  vtkGetMacro(StrengthTaper, double);
  ///@}

  ///@{
  /**
   * Creases: edges whose faces' normals differ by more than this angle
   * (vtkStylizeFeatureLines::CreaseAngle), in degrees. Range [0, 180], default 40.
   */
  vtkSetClampMacro(CreaseAngle, double, 0.0, 180.0);
  vtkGetMacro(CreaseAngle, double);
  ///@}

  ///@{
  /**
   * Ridges and valleys: the least |curvature| times the object's diagonal
   * (vtkStylizeFeatureLines::RidgeThreshold). Range [0, 1e6], default 40.
   */
  vtkSetClampMacro(RidgeThreshold, double, 0.0, 1.0e6);
  vtkGetMacro(RidgeThreshold, double);
  ///@}

  ///@{
  /**
   * Suggestive contours: the least derivative of the radial curvature toward the viewer, times
   * the object's diagonal squared (vtkStylizeFeatureLines::SuggestiveThreshold). Range
   * [0, 1e9], default 2000.
   */
  vtkSetClampMacro(SuggestiveThreshold, double, 0.0, 1.0e9);
  vtkGetMacro(SuggestiveThreshold, double);
  ///@}

  ///@{
  /**
   * Whether a translucent surface's outline is drawn: its contours and boundaries, in its
   * translucent layer (TranslucentLayers), hidden by the surfaces in front of it and seen through
   * the translucent ones as the layer is (a glass shell, a volume's haze: VolumeHaze). Off, a
   * translucent surface is its paper (or tone) alone. Default on.
   */
  vtkSetMacro(TranslucentOutlines, bool);
  vtkGetMacro(TranslucentOutlines, bool);
  vtkBooleanMacro(TranslucentOutlines, bool);
  ///@}

  /** The paper under the ink. */
  enum Tones
  {
    NONE = 0,   ///< plain paper
    SHADES = 1, ///< the lit tone in ToneLevels flat shades
    DOTS = 2    ///< the lit tone as the comic's halftone dots
  };

  ///@{
  /**
   * The paper under the ink: NONE (default), plain paper; SHADES, the lit tone in ToneLevels
   * flat shades from the paper down to ToneDarkest; DOTS, the lit tone as the comic's halftone
   * dots (vtkComicPass's, DotSpacing apart at 45 degrees, in the ink's colour).
   */
  vtkSetClampMacro(Tone, int, NONE, DOTS);
  vtkGetMacro(Tone, int);
  ///@}

  ///@{
  /** Number of flat shades of Tone SHADES, the paper included. Range [2, 8], default 3. */
  vtkSetClampMacro(ToneLevels, int, 2, 8);
  vtkGetMacro(ToneLevels, int);
  ///@}

  ///@{
  /**
   * The darkest shade of Tone SHADES, as a share of the paper's brightness. Range [0, 1],
   * default 0.6.
   */
  vtkSetClampMacro(ToneDarkest, double, 0.0, 1.0);
  vtkGetMacro(ToneDarkest, double);
  ///@}

  ///@{
  /** Tone DOTS: the dots' spacing (the screen period), in points. Range [2, 200], default 8. */
  vtkSetClampMacro(DotSpacing, double, 2.0, 200.0);
  vtkGetMacro(DotSpacing, double);
  ///@}

  ///@{
  /** Colour of the lines, RGB in [0, 1]. Default black (0, 0, 0). */
  virtual void SetInkColor(double r, double g, double b);
  vtkGetVector3Macro(InkColor, double);
  ///@}

  ///@{
  /** Colour of the paper under the lines, RGB in [0, 1]. Default white (1, 1, 1). */
  virtual void SetPaperColor(double r, double g, double b);
  vtkGetVector3Macro(PaperColor, double);
  ///@}

  ///@{
  /**
   * Height in pixels of the reference image in which one point is one pixel. A renderer of
   * height h (times the tile scale of a magnified screenshot) has h / ReferenceHeight pixels per
   * point. 0: one point is one window pixel (magnified screenshots still scale).
   * Range [0, 1e5], default 1080.
   */
  vtkSetClampMacro(ReferenceHeight, double, 0.0, 1.0e5);
  vtkGetMacro(ReferenceHeight, double);
  ///@}

  /** What the pass writes to the output (vector figures read the PAPER layer). */
  enum Layers
  {
    LINE_ART = 0, ///< the lines over the paper
    PAPER = 1     ///< the paper (and tone) alone, with the background
  };

  ///@{
  /** The layer written to the output: LINE_ART (default) or PAPER. */
  vtkSetClampMacro(Layer, int, LINE_ART, PAPER);
  vtkGetMacro(Layer, int);

  /** Sets Layer and returns the one it had (vtkStylizeStylePass::SwapLayer()). */
  int SwapLayer(int layer) override;
  /** Gray: the light's tone, darkened by a solid colour's lightness (not a colour map's). */
  void ConfigureLightingColors(vtkStylizeLightingPass* lighting) override;
  ///@}

  /**
   * The strokes of the last frame (or of the last ComputeFigureStrokes()): polylines with
   * points (x, y, 0) in the pixels the frame computed (row 0 at the bottom), point data
   * StrokeWidth (pixels) and cell data FeatureKind.
   */
  vtkPolyData* GetStrokes();

  /**
   * The strokes of the last rendered renderer's scene in an image `width` x `height` pixels
   * drawn in `tiles` x `tiles` tiles (a magnified figure; 1 otherwise), their hidden parts
   * removed by ray casting against the scene's surfaces (exact, slower than a frame): what a
   * vector figure draws. The result is GetStrokes(), until the next frame; empty before the
   * first frame.
   */
  vtkPolyData* ComputeFigureStrokes(int width, int height, int tiles);

protected:
  vtkLineArtPass();
  ~vtkLineArtPass() override;

  bool RenderStyle(const vtkRenderState* s, const Frame& frame) override;
  double GetPointReferenceHeight() override { return this->ReferenceHeight; }
  double GetReach(const Frame& frame) override;
  double GetVolumeOutlineWidth(vtkRenderer* ren) override;
  void ReleaseStyleResources(vtkWindow* w) override;
  vtkIdType GetStyleTextureBytes() override;

  double ContourWidth = 2.5;
  double CreaseWidth = 1.5;
  double RidgeWidth = 1.0;
  double ValleyWidth = 1.0;
  double SuggestiveWidth = 1.2;
  double DepthTaper = 0.5;
  double StrengthTaper = 1.0;
  double CreaseAngle = 40.0;
  double RidgeThreshold = 40.0;
  double SuggestiveThreshold = 2000.0;
  bool TranslucentOutlines = true;
  int Tone = NONE;
  int ToneLevels = 3;
  double ToneDarkest = 0.6;
  double DotSpacing = 8.0;
  double InkColor[3] = { 0.0, 0.0, 0.0 };
  double PaperColor[3] = { 1.0, 1.0, 1.0 };
  double ReferenceHeight = 1080.0;
  int Layer = LINE_ART;

private:
  vtkLineArtPass(const vtkLineArtPass&) = delete;
  void operator=(const vtkLineArtPass&) = delete;

  struct Internals;
  Internals* Internal;
};

#endif
