/**
 * @class   vtkSketchPass
 * @brief   Pencil sketch: strokes drawn by line integral convolution of solid noise along the
 *          surface's principal curvature directions, estimated per pixel in real time.
 *
 * The method of "real-time pencil sketch rendering along principal directions"
 * (docs/algorithms.md section 3) as one render pass: `renderer->SetPass(sketch)`; no delegate.
 * The opaque geometry is rendered once into the shared G-buffer (vtkStylizeGBufferPass), lit
 * by a vtkStylizeLightingPass (Standard model). Each surface pixel gets a principal direction,
 * estimated from its neighbours' normals by focal surfaces (DirectionSource SCREEN) or read
 * from a point-data array such as vtkStylizePrincipalCurvatures' (MODEL), then smoothed and
 * filled. Strokes follow it by perspective-correct line integral convolution of a noise fixed
 * to the surface; the pencil tone is the lit luminance with contrast against a blur of it, and
 * cross strokes darken the darkest zones.
 *
 * Lengths are in points (one pixel of an image ReferenceHeight pixels tall), so a magnified
 * screenshot shows the same picture at higher detail. While the window renders interactively
 * (InteractiveUpdateRate) a cheaper variant is drawn; the still frame is the full sketch.
 * Method, parameters and measured figures: docs/sketch.md.
 *
 * @sa vtkStylizeGBufferPass vtkStylizeLightingPass vtkStylizePrincipalCurvatures
 */

#ifndef vtkSketchPass_h
#define vtkSketchPass_h

#include "vtkStylizePassesModule.h" // for export macro
#include "vtkStylizeStylePass.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkFloatArray;

class VTKSTYLIZEPASSES_EXPORT vtkSketchPass : public vtkStylizeStylePass
{
public:
  static vtkSketchPass* New();
  vtkTypeMacro(vtkSketchPass, vtkStylizeStylePass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Where the principal directions come from. */
  enum DirectionSources
  {
    SCREEN = 0, ///< estimated per pixel from the G-buffer (focal surfaces)
    MODEL = 1   ///< a point-data direction array of the data (exact at render time)
  };

  /** The direction the strokes follow. */
  enum Directions
  {
    MINIMUM = 0, ///< the principal direction of the smaller |curvature| (along a cylinder)
    MAXIMUM = 1, ///< the principal direction of the larger |curvature| (around a cylinder)
    BISECTOR = 2 ///< halfway between the two (fewer visible turns)
  };

  /** Noise convolved along the strokes. */
  enum Noises
  {
    WHITE = 0,  ///< hard pencil
    PERLIN = 1, ///< medium
    WORLEY = 2, ///< soft
    SPARSE = 3  ///< separate strokes that hold still in animations
  };

  /** Where the noise is fixed. */
  enum NoiseSpaces
  {
    OBJECT = 0,      ///< the object-space position: strokes stick to the surface
    SCREEN_SPACE = 1 ///< the image: strokes swim when the camera moves
  };

  /** How a stroke is traced. */
  enum LicModes
  {
    PERSPECTIVE = 0, ///< steps in world space, reprojected each step (the paper's method)
    SCREEN_2D = 1    ///< the classic screen-space LIC (baseline for the accuracy study)
  };

  /** What the pass writes. */
  enum Layers
  {
    SKETCH = 0,     ///< the pencil sketch
    DIRECTIONS = 1, ///< the stroke direction's screen angle (mod 180 degrees) as a hue
    STROKES = 2,    ///< the LIC stroke texture alone (gray, 0.5 on average)
    TONE = 3        ///< the tone before strokes (bright faces and contrast applied)
  };

  ///@{
  /**
   * The layer written to the output: SKETCH (default), DIRECTIONS, STROKES or TONE. Values: SKETCH,
   * the pencil sketch; DIRECTIONS, the stroke direction's screen angle (mod 180 degrees) as a hue;
   * STROKES, the LIC stroke texture alone (gray, 0.5 on average); TONE, the tone before strokes
   * (bright faces and contrast applied).
   */
  vtkSetClampMacro(Layer, int, SKETCH, TONE);
  vtkGetMacro(Layer, int);

  /** Sets Layer and returns the one it had (vtkStylizeStylePass::SwapLayer()). */
  int SwapLayer(int layer) override;
  bool GetTinted() override { return this->Tint != BLACK_AND_WHITE; }
  /**
   * The tone of the light, darkened by a solid colour's lightness (not by a colour map's), on
   * paper of the data's hue as Tint says.
   */
  void ConfigureLightingColors(vtkStylizeLightingPass* lighting) override;
  ///@}

  ///@{
  /**
   * Where directions come from: SCREEN (default, the per-pixel estimate) or MODEL. Values: SCREEN,
   * estimated per pixel from the G-buffer (focal surfaces); MODEL, a point-data direction array of
   * the data (exact at render time).
   */
  vtkSetClampMacro(DirectionSource, int, SCREEN, MODEL);
  vtkGetMacro(DirectionSource, int);
  ///@}

  ///@{
  /**
   * The point-data array used in MODEL mode: a 3-component direction per point, taken as the
   * direction of the smaller |curvature| (Direction then picks it, its perpendicular or the
   * bisector), as in SCREEN mode: MINIMUM and MAXIMUM are by absolute value in both modes (along
   * and around a cylinder, convex or concave). Default "PrincipalDirectionMinAbs"
   * (vtkStylizePrincipalCurvatures: the direction of the smaller |curvature|, zero where the
   * surface is planar or umbilic; such pixels take the SCREEN estimate). The pass maps it on
   * each actor's vtkOpenGLPolyDataMapper that has it. Composite data (vtkCompositePolyDataMapper2,
   * every ParaView representation) gives its point data's tangents instead, whatever this name
   * (vtkStylizePrincipalCurvatures marks PrincipalDirectionMinAbs as the tangents). With no
   * visible data holding either, MODEL warns once and draws the SCREEN estimate.
   */
  vtkSetStringMacro(DirectionArrayName);
  vtkGetStringMacro(DirectionArrayName);
  ///@}

  ///@{
  /**
   * The direction drawn: MINIMUM, MAXIMUM (default) or BISECTOR. Values: MINIMUM, the principal
   * direction of the smaller |curvature| (along a cylinder); MAXIMUM, the principal direction of
   * the larger |curvature| (around a cylinder); BISECTOR, halfway between the two (fewer visible
   * turns).
   */
  vtkSetClampMacro(Direction, int, MINIMUM, BISECTOR);
  vtkGetMacro(Direction, int);
  ///@}

  ///@{
  /**
   * Neighbours of the focal-surface estimate: 2 (one pair, the earlier method), 4 (four pairs:
   * enough for smooth man-made shapes) or 8 (eight pairs: organic and coarse meshes; default).
   * Other values are rounded to the nearest of these.
   */
  virtual void SetNeighbors(int n);
  vtkGetMacro(Neighbors, int);
  ///@}

  ///@{
  /**
   * Smallest neighbour spacing, points at the focal distance, turned into a world length:
   * nearer the camera the pixel stride grows to keep it. This is the scale at which the
   * principal directions are estimated: a few points follow every bump of a scanned surface
   * (strokes swirl with the scan noise); 16 points follow the shape (measured on the real-data
   * set: local direction agreement 0.67 -> 0.80 on a scanned bunny, docs/sketch.md).
   * Range [0.5, 64], default 16.
   */
  vtkSetClampMacro(NeighborSpacing, double, 0.5, 64.0);
  vtkGetMacro(NeighborSpacing, double);
  ///@}

  ///@{
  /**
   * The object's share of the estimate's scale, dimensionless: the neighbour spacing is at
   * least this fraction of the scene's size (the diagonal of SceneBounds), and the smoothing
   * radius grows with it, so a close-up of a scanned surface follows its shape, not its scan
   * noise, while a view of the whole object keeps the screen scale (NeighborSpacing,
   * SmoothingRadius): the coarser of the two is used. 0 keeps the screen scale at any zoom.
   * Range [0, 1], default 0.01.
   */
  vtkSetClampMacro(ObjectScale, double, 0.0, 1.0);
  vtkGetMacro(ObjectScale, double);
  ///@}

  ///@{
  /**
   * The scene's bounds (world units; xmin, xmax, ymin, ymax, zmin, zmax) for ObjectScale. An
   * invalid box (xmin > xmax, the default) means the renderer's visible props' bounds; a
   * parallel renderer (ParaView's view) sets the bounds of all ranks' data so every rank
   * counts the same scale; a non-finite box counts as invalid. Range each [-1e300, 1e300],
   * default (1, -1, 1, -1, 1, -1).
   */
  vtkSetVector6Macro(SceneBounds, double);
  vtkGetVector6Macro(SceneBounds, double);
  ///@}

  ///@{
  /** Largest neighbour stride, points (at least NeighborSpacing to keep it). Range [1, 64],
   * default 32. */
  vtkSetClampMacro(MaxStride, double, 1.0, 64.0);
  vtkGetMacro(MaxStride, double);
  ///@}

  ///@{
  /**
   * A pair whose larger |curvature| times the neighbour distance (the normal's turn across
   * the pair, radians) is below this is planar and skipped. Range [0, 1], default 1e-3.
   */
  vtkSetClampMacro(PlanarTolerance, double, 0.0, 1.0);
  vtkGetMacro(PlanarTolerance, double);
  ///@}

  ///@{
  /**
   * A pixel whose fit confidence (the fitted points' alignment times their distance from the
   * umbilic case, 0..1) is not above this is undefined and filled. Range [0, 1], default 0.05.
   */
  vtkSetClampMacro(UmbilicTolerance, double, 0.0, 1.0);
  vtkGetMacro(UmbilicTolerance, double);
  ///@}

  ///@{
  /**
   * Distance (points) over which the direction field is averaged, sign-invariantly, weighted
   * by the estimates' confidence and only within a surface: 3x3 passes with taps 1, 2, 4, ...
   * points apart up to this distance (an "a trous" pyramid: the cost grows with the logarithm
   * of the radius). This is the scale of the strokes' flow: 0 follows every estimate; 16
   * points smooths a scanned mesh's noise away but keeps the shape's turns (measured on the
   * real-data set, docs/sketch.md). Range [0, 256], default 16.
   */
  vtkSetClampMacro(SmoothingRadius, double, 0.0, 256.0);
  vtkGetMacro(SmoothingRadius, double);
  ///@}

  ///@{
  /**
   * Size of a texel of the grid on which the directions are estimated and smoothed, points.
   * The field turns over SmoothingRadius (16 points), so a grid of a few points keeps what the
   * strokes show at a fraction of the cost (the estimate and smoothing run on 1/k^2 of the
   * pixels); the resolve upsamples it to the pixels within each surface (the four texels
   * around a pixel, those across a fold or silhouette left out). 1: one texel per point.
   * Range [1, 16], default 4 (docs/sketch.md, the speed trade).
   */
  vtkSetClampMacro(FieldTexelSize, double, 1.0, 16.0);
  vtkGetMacro(FieldTexelSize, double);
  ///@}
  ///@{
  /**
   * Further sign-invariant smoothing iterations over 3x3 neighbouring pixels after the
   * SmoothingRadius passes: each widens the averaging by about a pixel and evens out the
   * pyramid's taps. Range [0, 16], default 2.
   */
  vtkSetClampMacro(SmoothingIterations, int, 0, 16);
  vtkGetMacro(SmoothingIterations, int);
  ///@}

  ///@{
  /**
   * Farthest distance (points) from which an undefined pixel takes its surface's direction;
   * iterations at distances 1, 2, 4, ... up to it, those within the smoothing pyramid's reach
   * skipped (its passes already fill as they smooth). 0 disables filling. Range [0, 512],
   * default 16.
   */
  vtkSetClampMacro(FillRadius, double, 0.0, 512.0);
  vtkGetMacro(FillRadius, double);
  ///@}

  ///@{
  /**
   * Screen angle (degrees, counter-clockwise from +x) of the strokes on pixels with no
   * direction and no lighting gradient. Range [-180, 180], default 45.
   */
  vtkSetClampMacro(FallbackAngle, double, -180.0, 180.0);
  vtkGetMacro(FallbackAngle, double);
  ///@}

  ///@{
  /**
   * Stroke tracing: PERSPECTIVE (default) or SCREEN_2D (baseline). Values: PERSPECTIVE, steps in
   * world space, reprojected each step (the paper's method); SCREEN_2D, the classic screen-space
   * LIC (baseline for the accuracy study).
   */
  vtkSetClampMacro(LicMode, int, PERSPECTIVE, SCREEN_2D);
  vtkGetMacro(LicMode, int);
  ///@}

  ///@{
  /** LIC step length, points (long: soft pencil; short: hard). Range [0.1, 32], default 1.5. */
  vtkSetClampMacro(StepLength, double, 0.1, 32.0);
  vtkGetMacro(StepLength, double);
  ///@}

  ///@{
  /** LIC steps on each side of a pixel. Range [1, 256], default 10. */
  vtkSetClampMacro(Steps, int, 1, 256);
  vtkGetMacro(Steps, int);
  ///@}

  ///@{
  /**
   * The noise: WHITE (default), PERLIN, WORLEY or SPARSE. Values: WHITE, hard pencil; PERLIN,
   * medium; WORLEY, soft; SPARSE, separate strokes that hold still in animations (dark dots on
   * 5% of the texels, read at the object-space position interpolated between pixels and
   * prefiltered over the pixel's footprint on the surface (mipmapped); a texel spans at least
   * 1.7 pixels of the window, so that a stroke moves with the surface instead of being resampled
   * by the pixels: the default of orbit animations).
   */
  vtkSetClampMacro(Noise, int, WHITE, SPARSE);
  vtkGetMacro(Noise, int);
  ///@}

  ///@{
  /**
   * Where the noise is fixed: OBJECT (default) or SCREEN_SPACE. Values: OBJECT, the object-space
   * position: strokes stick to the surface; SCREEN_SPACE, the image: strokes swim when the camera
   * moves.
   */
  vtkSetClampMacro(NoiseSpace, int, OBJECT, SCREEN_SPACE);
  vtkGetMacro(NoiseSpace, int);
  ///@}

  ///@{
  /**
   * Size of a noise texel, points at the focal distance (a world length; the image's pixels
   * for SCREEN_SPACE). Range [0.1, 64], default 1.
   */
  vtkSetClampMacro(NoiseSize, double, 0.1, 64.0);
  vtkGetMacro(NoiseSize, double);
  ///@}

  ///@{
  /** Contrast of the stroke texture (0: flat tone). Range [0, 8], default 1.5. */
  vtkSetClampMacro(StrokeContrast, double, 0.0, 8.0);
  vtkGetMacro(StrokeContrast, double);
  ///@}

  ///@{
  /** Cross-hatching in dark zones. Default on. */
  vtkSetMacro(CrossHatching, bool);
  vtkGetMacro(CrossHatching, bool);
  vtkBooleanMacro(CrossHatching, bool);
  ///@}

  ///@{
  /** Tone below which the cross strokes start (full 0.2 lower). Range [0, 1], default 0.4. */
  vtkSetClampMacro(CrossThreshold, double, 0.0, 1.0);
  vtkGetMacro(CrossThreshold, double);
  ///@}

  ///@{
  /**
   * Contrast against the blurred image: o + c (o - b). 0 disables the blur. Range [0, 4],
   * default 0.5.
   */
  vtkSetClampMacro(Contrast, double, 0.0, 4.0);
  vtkGetMacro(Contrast, double);
  ///@}

  ///@{
  /** Radius of the large Gaussian (3 sigma), points. Range [1, 512], default 36 (73x73). */
  vtkSetClampMacro(BlurRadius, double, 1.0, 512.0);
  vtkGetMacro(BlurRadius, double);
  ///@}

  ///@{
  /**
   * Blur stride k: the blur runs at 1/k of the resolution with taps k pixels apart (the paper
   * uses 2, 4, 6). Range [1, 16], default 4.
   */
  vtkSetClampMacro(BlurStride, int, 1, 16);
  vtkGetMacro(BlurStride, int);
  ///@}

  ///@{
  /**
   * Bright faces (the seed's light face): tones (the lit luminance) above t1 are lifted
   * smoothly to white, reached at t2, so the lit side of a shape is left as paper; below t1
   * the strokes darken with the shadow (single strokes in the grey face, crossed below
   * CrossThreshold in the dark). Each in [0, 1]; t2 < t1 is raised to t1. Default
   * (0.45, 0.62): the brightest quarter of a lit scan is paper, its tone still followed
   * (docs/sketch.md; the seed's 0.8, 0.95 acted on 0.1-1.4% of real scans' pixels: VTK's
   * diffuse surfaces seldom pass 0.8).
   */
  virtual void SetBrightThresholds(double t1, double t2);
  vtkGetVector2Macro(BrightThresholds, double);
  ///@}

  ///@{
  /**
   * Feature lines: the lines an illustrator draws, found on the meshes as vtkLineArtPass finds
   * them (occluding contours, boundaries, creases, ridges, valleys and suggestive contours,
   * hidden lines removed), drawn in pencil: the eyes, nose and mouth of a face scan, the folds of a
   * part, which screen-space thresholds cannot tell from scan noise. The interactive variant
   * draws contours, boundaries and creases only; translucent layers draw none. Default on.
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
   * Vector figures (vtkStylizeFigureWriter, SVG and PDF) draw the pencil's strokes as vector
   * polylines, traced along the same direction field at the density and darkness of the same
   * tone, crossed in the same dark, so that the figure scales; the feature lines are traced
   * outlines and the paper regions. Off: the pencil is an embedded image. Default off.
   */
  vtkSetMacro(VectorFigureStrokes, bool);
  vtkGetMacro(VectorFigureStrokes, bool);
  vtkBooleanMacro(VectorFigureStrokes, bool);
  ///@}
  ///@{
  /** Pencil colour (RGB, each [0, 1]). Default (0.12, 0.12, 0.14), graphite. */
  virtual void SetPencilColor(double r, double g, double b);
  vtkGetVector3Macro(PencilColor, double);
  ///@}

  ///@{
  /** Paper colour under the strokes (RGB, each [0, 1]). Default white. */
  virtual void SetPaperColor(double r, double g, double b);
  vtkGetVector3Macro(PaperColor, double);
  ///@}

  ///@{
  /**
   * Which surfaces keep their colours: BLACK_AND_WHITE, DATA_COLORS (default) or ALL_COLORS.
   * Values: BLACK_AND_WHITE, none: the pencil on PaperColor; DATA_COLORS, surfaces coloured by an
   * array: the paper takes the hue and saturation of the colour map at full value (times
   * PaperColor), solid colours stay PaperColor; ALL_COLORS, every surface, solid colours
   * included. The strokes' tone comes from the light alone in all three.
   */
  vtkSetClampMacro(Tint, int, BLACK_AND_WHITE, ALL_COLORS);
  vtkGetMacro(Tint, int);
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
   * Reads the last frame's resolved direction field back: 4 floats per pixel (view-space unit
   * direction, then the linear depth; all 0 where there is no surface), rows bottom to top.
   * The window's context must be current, as it is right after a render.
   */
  bool DownloadDirections(vtkFloatArray* out);

  /**
   * The tileable noise texture of a kind, size^3 values in [0, 1] (x fastest): WHITE (uniform
   * per texel), PERLIN (gradient noise, lattice period 8 texels), WORLEY (distance to the
   * nearest feature point, one per 8^3 cell). size is clamped to [8, 128] and made a multiple
   * of 8. The pass uses size 64.
   */
  static void GenerateNoise(int kind, int size, vtkFloatArray* out);

protected:
  /**
   * The sketch of a scene (the opaque one, then each translucent layer): the scene into the
   * G-buffer (Standard lighting by default, FULL precision), the raw directions, smoothing and
   * fill, fallbacks, the tone's blur, then strokes and tone into the output.
   */
  bool RenderStyle(const vtkRenderState* s, const Frame& frame) override;
  double GetPointReferenceHeight() override;
  /** Patterns anchored to the surface: noise in object space, the SPARSE noise. */
  void AnchorToSurface(bool keepNoise) override;
  void RestoreAnchors() override;
  int SavedNoise = WHITE;
  int SavedNoiseSpace = OBJECT;
  /** Frees the direction field's textures. */
  void ReleaseStyleResources(vtkWindow* w) override;
  vtkIdType GetStyleTextureBytes() override;

  vtkSketchPass();
  ~vtkSketchPass() override;

  int Layer = SKETCH;
  int DirectionSource = SCREEN;
  char* DirectionArrayName = nullptr;
  int Direction = FieldSettings().Direction;
  int Neighbors = FieldSettings().Neighbors;
  double NeighborSpacing = FieldSettings().NeighborSpacing;
  double MaxStride = FieldSettings().MaxStride;
  double ObjectScale = FieldSettings().ObjectScale;
  double SceneBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  double PlanarTolerance = FieldSettings().PlanarTolerance;
  double UmbilicTolerance = FieldSettings().UmbilicTolerance;
  double SmoothingRadius = FieldSettings().SmoothingRadius;
  double FieldTexelSize = 4.0;
  bool VectorFigureStrokes = false;
  int SmoothingIterations = FieldSettings().SmoothingIterations;
  double FillRadius = FieldSettings().FillRadius;
  double FallbackAngle = FieldSettings().FallbackAngle;
  int LicMode = PERSPECTIVE;
  double StepLength = 1.5;
  int Steps = 10;
  int Noise = WHITE;
  int NoiseSpace = OBJECT;
  double NoiseSize = 1.0;
  double StrokeContrast = 1.5;
  bool CrossHatching = true;
  double CrossThreshold = 0.4;
  double Contrast = 0.5;
  double BlurRadius = 36.0;
  int BlurStride = 4;
  double BrightThresholds[2] = { 0.45, 0.62 };
  double PencilColor[3] = { 0.12, 0.12, 0.14 };
  double PaperColor[3] = { 1.0, 1.0, 1.0 };
  int Tint = DATA_COLORS;
  double ReferenceHeight = 1080.0;
  bool FeatureLines = true;
  double FeatureLineWidth = 1.5;

  /** What a frame computes: stages, channels, defines, and the settings' lengths in pixels. */
  struct Plan;
  Plan PlanFrame(const Frame& frame) const;
  /** The strokes' length on top of the field's reach, or the blur's, whichever is larger. */
  double GetReach(const Frame& frame) override;
  /** How far the feature lines' strokes reach from their lines, pixels. */
  double FeatureLineReach(double pointSize) const;
  /** The blur's grid: BlurStride. */
  int GetGuardAlignment(const Frame& frame) override;
  /** The noise texture of the current kind, made when the kind changes. */
  void UpdateNoise(const Frame& frame);
  // 1-3: the direction field (vtkStylizeDirectionField).
  /** 4. The strided blur of the lit luminance (the contrast's reference). */
  void RenderBlurStages(const Frame& frame, const Plan& plan);
  /** 5. Strokes and tone into the output framebuffer, with the scene's depth. */
  void RenderFinalStage(const Frame& frame, const Plan& plan);

private:
  vtkSketchPass(const vtkSketchPass&) = delete;
  void operator=(const vtkSketchPass&) = delete;

  void MapDirectionArrays(vtkRenderer* ren);

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
