/**
 * @class   vtkComicPass
 * @brief   Black-and-white comic rendering: toon lighting, three-phase edges, halftone dots where
 *          the tone is bright and hatch lines where it is dark.
 *
 * The comic method of "real-time comic-style rendering" (docs/algorithms.md section 2) as one
 * render pass. Use it like any VTK pass: `renderer->SetPass(comic)`; it needs no delegate.
 * The opaque geometry is rendered once into the shared G-buffer (vtkStylizeGBufferPass) with
 * the Comic lighting model (vtkStylizeLightingPass). Edges come from Sobel filters on the
 * linear depth (scale-free), the normals and the colour; the light's tone is drawn as halftone
 * dots above BrightThreshold and hatch lines below DarkThreshold, in black ink, on white paper
 * or, where the data is coloured by an array, on paper of the colour map's hue (Tint).
 *
 * Lengths are in points (one pixel of an image ReferenceHeight pixels tall), so the picture is
 * the same at any resolution and in a magnified screenshot. Patterns are anchored to the screen
 * or to the surface (Anchor). While the window renders interactively (InteractiveUpdateRate) a
 * cheaper variant is drawn; the still frame is the full comic.
 * Method, parameters and measured figures: docs/comic.md.
 *
 * @sa vtkStylizeGBufferPass vtkStylizeLightingPass
 */

#ifndef vtkComicPass_h
#define vtkComicPass_h

#include "vtkNew.h"                 // for vtkNew
#include "vtkPolyData.h"            // for vtkNew<vtkPolyData>
#include "vtkStylizePassesModule.h" // for export macro
#include "vtkStylizeStylePass.h"

class vtkStylizeDirectionField;
class vtkStylizeFeatureStrokes;

class VTKSTYLIZEPASSES_EXPORT vtkComicPass : public vtkStylizeStylePass
{
public:
  static vtkComicPass* New();
  vtkTypeMacro(vtkComicPass, vtkStylizeStylePass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Where the dots and hatch lines are anchored. */
  enum Anchors
  {
    SCREEN = 0, ///< to the image: the classic look; the pattern stays while the scene moves
    OBJECT = 1  ///< to the surface (object-space position): moves with the data
  };

  /** What orients the hatch lines. */
  enum HatchOrientations
  {
    FIXED = 0,    ///< HatchAngle, or the screen-space normal in HatchDirections steps (eq. 12)
    PRINCIPAL = 1 ///< around the form: the surface's direction of larger |curvature|
  };

  /** What the pass writes: the comic image, or one of its layers (for figures and tests). */
  enum Layers
  {
    COMIC = 0,         ///< the pattern times the edges (the comic image)
    EDGES = 1,         ///< the edge factor e alone (white = no edge, black = full edge), gray
    PATTERN = 2,       ///< the dots and hatching alone, without edges
    FIGURE_INPUTS = 3, ///< red the tone, green the hatch direction's step / 255, blue the surface
    PAPER = 4          ///< the paper under the ink (tint or white), lines and points; background
  };

  ///@{
  /**
   * The layer written to the output: COMIC (default), EDGES, PATTERN, FIGURE_INPUTS or PAPER.
   * Values: COMIC, the pattern times the edges (the comic image); EDGES, the edge factor e alone
   * (white = no edge, black = full edge), gray, without the feature lines and iso-lines (a vector
   * figure draws them as paths: ComputeFigureStrokes()); PATTERN, the dots and hatching alone,
   * without edges; FIGURE_INPUTS, red the tone, green the hatch direction's step / 255, blue the
   * surface; PAPER, the paper under the ink: the tint (Tint) or white; lines and points as drawn;
   * the background.
   */
  vtkSetClampMacro(Layer, int, COMIC, PAPER);
  vtkGetMacro(Layer, int);
  ///@}

  ///@{
  /** Draw the three-phase edges. Default on. */
  vtkSetMacro(Edges, bool);
  vtkGetMacro(Edges, bool);
  vtkBooleanMacro(Edges, bool);
  ///@}

  ///@{
  /**
   * Feature lines: the lines an illustrator draws, found on the meshes as vtkLineArtPass finds
   * them (occluding contours, boundaries, creases, ridges, valleys and suggestive contours,
   * hidden lines removed), drawn in ink with the edges: the eyes, nose and mouth of a face scan,
   * the folds of a part, which screen-space thresholds cannot tell from scan noise. The interactive
   * variant draws contours, boundaries and creases only; translucent layers draw none. Default
   * off: the comic's own normal edges already draw the folds of scans and parts, and on a
   * faceted isosurface (ParaView's contours) the creases add clutter (docs/comic.md).
   */
  vtkSetMacro(FeatureLines, bool);
  vtkGetMacro(FeatureLines, bool);
  vtkBooleanMacro(FeatureLines, bool);
  ///@}

  ///@{
  /**
   * Width of the feature lines' contours and boundaries, in points; creases, ridges, valleys and
   * suggestive contours are thinner, in vtkLineArtPass's default proportions (0.6, 0.4, 0.4
   * and 0.48 of it). Range [0, 20], default 1.5.
   */
  vtkSetClampMacro(FeatureLineWidth, double, 0.0, 20.0);
  vtkGetMacro(FeatureLineWidth, double);
  ///@}

  ///@{
  /**
   * Weights a1 (depth), a2 (normal), a3 (colour) of the edge phases, each in [0, 1]; the pass
   * divides by their sum, so a1 + a2 + a3 = 1 as in eq. 9. A zero weight switches its phase off
   * (no Sobel is computed for it). All zero: no edges. Default (1/2, 1/2, 0): in black and
   * white the colour phase sees only the lighting's bands and the darkening the normal phase
   * has just drawn, whose lines it doubles (measured on the real-data set: ink that lowers the
   * tone's fidelity, docs/comic.md); (1/3, 1/3, 1/3) is the paper's three phases, for
   * tinted colour data. Default (0.5, 0.5, 0).
   */
  virtual void SetEdgeWeights(double depth, double normal, double color);
  virtual void SetEdgeWeights(const double w[3]) { this->SetEdgeWeights(w[0], w[1], w[2]); }
  vtkGetVector3Macro(EdgeWeights, double);
  ///@}

  ///@{
  /**
   * Depth-edge threshold, dimensionless: the slope |dz/dx| of the linear depth against the
   * screen, in world units per world unit, where a depth edge starts (full strength at twice
   * it). 10 marks surfaces within about 6 degrees of grazing and every depth jump between
   * surfaces. Range [0.01, 1e4], default 10.
   */
  vtkSetClampMacro(DepthThreshold, double, 0.01, 1.0e4);
  vtkGetMacro(DepthThreshold, double);
  ///@}

  ///@{
  /**
   * Normal-edge threshold: the Sobel change of the unit normal per tap where an edge starts
   * (full at twice it). 0.15 is a crease of about 17 degrees. Range [0.001, 2], default 0.15.
   */
  vtkSetClampMacro(NormalThreshold, double, 0.001, 2.0);
  vtkGetMacro(NormalThreshold, double);
  ///@}

  ///@{
  /**
   * Colour-edge threshold: the Sobel change of the normal-edged colour (RGB in [0, 1]) per tap
   * where an edge starts (full at twice it). Range [0.001, 2], default 0.1.
   */
  vtkSetClampMacro(ColorThreshold, double, 0.001, 2.0);
  vtkGetMacro(ColorThreshold, double);
  ///@}

  ///@{
  /**
   * Edge width in points: the Sobel taps are this far apart (rounded to whole pixels, at least
   * 1), so lines are about twice as wide. Range [0.25, 20], default 1.
   */
  vtkSetClampMacro(EdgeWidth, double, 0.25, 20.0);
  vtkGetMacro(EdgeWidth, double);
  ///@}

  ///@{
  /** Halftone dots in the bright zone. Off: the bright zone shows the lit tone. Default on. */
  vtkSetMacro(Dots, bool);
  vtkGetMacro(Dots, bool);
  vtkBooleanMacro(Dots, bool);
  ///@}

  ///@{
  /**
   * Dot spacing (the screen period) in points. Where the cells are under three pixels on the
   * screen (a window much smaller than ReferenceHeight, a surface turned away under the OBJECT
   * anchor) the dots fade to the tone, fully at two. Range [2, 200], default 8.
   */
  vtkSetClampMacro(DotSpacing, double, 2.0, 200.0);
  vtkGetMacro(DotSpacing, double);
  ///@}

  ///@{
  /** Screen angle of the dot grid in degrees (45 is the print convention). Range [-180, 180]. */
  vtkSetClampMacro(DotAngle, double, -180.0, 180.0);
  vtkGetMacro(DotAngle, double);
  ///@}

  ///@{
  /** Hatch lines in the dark zone. Off: the dark zone shows the lit tone. Default on. */
  vtkSetMacro(Hatching, bool);
  vtkGetMacro(Hatching, bool);
  vtkBooleanMacro(Hatching, bool);
  ///@}

  ///@{
  /**
   * Distance between hatch lines in points. Where the lines are under three pixels apart on the
   * screen they fade to their mean, fully at two (as the dots). Range [2, 200], default 8.
   */
  vtkSetClampMacro(HatchSpacing, double, 2.0, 200.0);
  vtkGetMacro(HatchSpacing, double);
  ///@}

  ///@{
  /**
   * Hatch line width in points (at most the spacing), constant as in eq. 11 of the paper. 0
   * (default): the width follows the tone, as the dots' radius does, so the ink covers 1 - I
   * of the dark zone (crossed lines each cover 1 - sqrt(I)) and a darker surface never prints
   * lighter; a constant width covers the same share at any tone, so the hatched shadow can print
   * lighter than the dotted mid-tones next to it. Range [0, 200], default 0.
   */
  vtkSetClampMacro(HatchWidth, double, 0.0, 200.0);
  vtkGetMacro(HatchWidth, double);
  ///@}

  ///@{
  /**
   * Direction of the hatch lines in degrees from the image's x axis (any angle, vertical
   * included). Range [-180, 180], default 135.
   */
  vtkSetClampMacro(HatchAngle, double, -180.0, 180.0);
  vtkGetMacro(HatchAngle, double);
  ///@}

  ///@{
  /**
   * Eq. 12: the hatch direction follows the screen-space normal, quantized to this many steps
   * over 180 degrees so each face keeps straight lines. 0: every line at HatchAngle, one
   * coherent direction over the whole image (on scanned meshes the normal-dependent variant
   * changes direction from facet to facet). Range [0, 16], default 0.
   */
  vtkSetClampMacro(HatchDirections, int, 0, 16);
  vtkGetMacro(HatchDirections, int);
  ///@}

  ///@{
  /**
   * What orients the hatch lines: FIXED (default) or PRINCIPAL. Values: FIXED, HatchAngle, or
   * the screen-space normal in HatchDirections steps (eq. 12); PRINCIPAL, around the form: the
   * surface's direction of larger |curvature|, from the per-pixel principal direction field
   * that the sketch style draws along (vtkStylizeDirectionField, at its
   * default settings), quantized to HatchDirections steps over 180 degrees (8 when
   * HatchDirections is 0) so that each region keeps straight lines. It costs the field's
   * full-screen passes (about a dozen), and only when hatching is on.
   */
  vtkSetClampMacro(HatchOrientation, int, FIXED, PRINCIPAL);
  vtkGetMacro(HatchOrientation, int);
  ///@}

  ///@{
  /** Cross the hatching with a second direction (+90 degrees) in the darkest zone. Default on. */
  vtkSetMacro(CrossHatching, bool);
  vtkGetMacro(CrossHatching, bool);
  vtkBooleanMacro(CrossHatching, bool);
  ///@}

  ///@{
  /** Tone below which hatching is crossed. Range [0, 1], default 0.12. */
  vtkSetClampMacro(CrossThreshold, double, 0.0, 1.0);
  vtkGetMacro(CrossThreshold, double);
  ///@}

  ///@{
  /** a1 of eq. 13: tones above it get dots only. Range [0, 1], default 0.5. */
  vtkSetClampMacro(BrightThreshold, double, 0.0, 1.0);
  vtkGetMacro(BrightThreshold, double);
  ///@}

  ///@{
  /**
   * a2 of eq. 13: tones below it get hatching only; between a2 and a1 the two blend linearly.
   * When a2 >= a1 the zones meet at a2 without a blend. Default 0.4: the shadow band of the
   * default comic lighting (the ambient term alone, tone 0.35) is hatched. Range [0, 1],
   * default 0.4.
   */
  vtkSetClampMacro(DarkThreshold, double, 0.0, 1.0);
  vtkGetMacro(DarkThreshold, double);
  ///@}

  ///@{
  /**
   * Which surfaces keep their colours: BLACK_AND_WHITE, DATA_COLORS (default) or ALL_COLORS.
   * Values: BLACK_AND_WHITE, none: black ink on white paper; DATA_COLORS, surfaces coloured by an
   * array: the paper takes the hue and saturation of the colour map at full value, so the data
   * reads under the ink, solid colours stay white; ALL_COLORS, every surface, solid colours
   * included. The tone (dots, hatching) comes from the light in all three: a surface coloured by a
   * dark or mid-luminance map is not hatched all over; a dark solid colour (luminance below 0.75)
   * darkens it in proportion, so black glyphs are hatched and a white or light gray part is not.
   */
  vtkSetClampMacro(Tint, int, BLACK_AND_WHITE, ALL_COLORS);
  vtkGetMacro(Tint, int);
  ///@}

  ///@{
  /**
   * Pattern anchoring: SCREEN (default) or OBJECT. Values: SCREEN, to the image: the classic look;
   * the pattern stays while the scene moves; OBJECT, to the surface (object-space position): moves
   * with the data (where the surface turns away and its cells shrink below three pixels, the
   * pattern fades to the tone rather than alias, fully at two).
   */
  vtkSetClampMacro(Anchor, int, SCREEN, OBJECT);
  vtkGetMacro(Anchor, int);
  void SetAnchorToScreen() { this->SetAnchor(SCREEN); }
  void SetAnchorToObject() { this->SetAnchor(OBJECT); }
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

  /**
   * The feature lines' and iso-lines' strokes of the last rendered renderer's scene in an image
   * `width` x `height` pixels drawn in `tiles` x `tiles` tiles, hidden parts removed by ray
   * casting (exact): what a vector figure draws, as vtkLineArtPass::ComputeFigureStrokes();
   * polylines with point data StrokeWidth (pixels) and cell data FeatureKind. Empty when the
   * comic draws neither (FeatureLines off and IsoLines 0) or before the first frame.
   */
  vtkPolyData* ComputeFigureStrokes(int width, int height, int tiles);

  /** Sets Layer and returns the one it had (vtkStylizeStylePass::SwapLayer()). */
  int SwapLayer(int layer) override;
  bool GetTinted() override { return this->Tint != BLACK_AND_WHITE; }
  /** The tone of the light alone, on paper of the data's hue as Tint says. */
  void ConfigureLightingColors(vtkStylizeLightingPass* lighting) override;

protected:
  /**
   * The comic image of a scene (the opaque one, then each translucent layer): the scene into the
   * G-buffer, the colour edges (when their weight is not 0), then edges, pattern and ink into
   * the output.
   */
  bool RenderStyle(const vtkRenderState* s, const Frame& frame) override;
  /** Frees the direction field's textures. */
  void ReleaseStyleResources(vtkWindow* w) override;
  vtkIdType GetStyleTextureBytes() override;

  vtkComicPass();
  ~vtkComicPass() override;

  bool Edges = true;
  bool FeatureLines = false;
  double FeatureLineWidth = 1.5;
  double EdgeWeights[3] = { 0.5, 0.5, 0.0 };
  double DepthThreshold = 10.0;
  double NormalThreshold = 0.15;
  double ColorThreshold = 0.1;
  double EdgeWidth = 1.0;
  bool Dots = true;
  double DotSpacing = 8.0;
  double DotAngle = 45.0;
  bool Hatching = true;
  double HatchSpacing = 8.0;
  double HatchWidth = 0.0;
  double HatchAngle = 135.0;
  int HatchDirections = 0;
  int HatchOrientation = FIXED;
  bool CrossHatching = true;
  double CrossThreshold = 0.12;
  double BrightThreshold = 0.5;
  double DarkThreshold = 0.4;
  int Tint = DATA_COLORS;
  int Anchor = SCREEN;
  int Layer = COMIC;
  double ReferenceHeight = 1080.0;
  /** The principal direction field of PRINCIPAL hatching. */
  vtkStylizeDirectionField* Field = nullptr;
  /** The feature lines' strokes. */
  vtkStylizeFeatureStrokes* Strokes = nullptr;
  /** An empty result of ComputeFigureStrokes(). */
  vtkNew<vtkPolyData> NoStrokes;

  /** What a frame computes (the enabled stages, their channels and defines). */
  struct Plan;
  Plan PlanFrame(bool interactive) const;
  /** The uniforms both stages read. */
  void SetStageUniforms(vtkStylizeUniforms& u, const Frame& frame, const Plan& plan);
  double GetPointReferenceHeight() override { return this->ReferenceHeight; }
  /** Patterns anchored to the surface: the OBJECT anchor. */
  void AnchorToSurface(bool) override;
  void RestoreAnchors() override;
  int SavedAnchor = SCREEN;
  /** The edge taps (twice the stride for colour edges) and the principal field's reach. */
  double GetReach(const Frame& frame) override;
  /** Stage 1 (colour edges only): luminance of f_normal, k1 and k2 into the edge texture. */
  void RenderEdgeStage(const Frame& frame, const Plan& plan);
  /** Stage 2: edges, pattern and ink into the output framebuffer, with the scene's depth. */
  void RenderCompositeStage(const Frame& frame, const Plan& plan);

private:
  vtkComicPass(const vtkComicPass&) = delete;
  void operator=(const vtkComicPass&) = delete;
};

#endif
