/**
 * @class   vtkStylizeStylePass
 * @brief   Base of the style passes (vtkComicPass, vtkPixelArtPass, vtkSketchPass): a style
 *          is an image-processing pass over the shared G-buffer.
 *
 * A style renders the scene into its G-buffer (vtkStylizeGBufferPass), lit by its lighting
 * pass (vtkStylizeLightingPass), then runs its screen-space stages on the opaque scene and on
 * each translucent layer. Without a delegate (the default, and the accurate path) it renders
 * the geometry itself; with a delegate it stylizes the delegate's colour and depth, the path
 * for parallel rendering behind a compositor such as ParaView's IceT:
 * @code
 * vtkNew<vtkCameraPass> camera;
 * camera->SetDelegatePass(comic->GetLightingPass()); // lights the scene, comic model
 * comic->SetDelegatePass(camera);
 * @endcode
 *
 * A subclass holds only its settings and its stages: its RenderStyle() is the pipeline for one
 * scene, and the base owns the lighting pass, the G-buffer, shader assembly, stage running and
 * the GPU resources. Design, delegate path and translucent layers: docs/gbuffer.md.
 *
 * @sa vtkStylizeGBufferPass vtkStylizeLightingPass vtkImageProcessingPass
 */

#ifndef vtkStylizeStylePass_h
#define vtkStylizeStylePass_h

#include "vtkImageProcessingPass.h"
#include "vtkStylizePassesModule.h" // for export macro

#include <cstddef>          // for std::size_t
#include <functional>       // for std::function
#include <initializer_list> // for std::initializer_list
#include <memory>           // for std::unique_ptr
#include <string>           // for std::string
#include <vector>           // for std::vector

class vtkCamera;
class vtkInformationDoubleKey;
class vtkInformationIntegerKey;
class vtkFloatArray;
class vtkOpenGLRenderWindow;
class vtkProp;
class vtkRenderer;
class vtkStylizeGBufferPass;
class vtkStylizeLightingPass;
class vtkStylizeUniforms;
class vtkTextureObject;

#ifndef __VTK_WRAP__
/**
 * One stage of a style: its index (the style's enum of stages), the #define that selects it in
 * the style's GLSL ("" for none) and its name in stage timings. A style lists its stages in one
 * table, checked by vtkStylizeStagesInOrder() at compile time.
 */
struct vtkStylizeStage
{
  int Index;
  const char* Define;
  const char* Name;
};

/** Whether a table lists its stages in index order 0, 1, ... (for a static_assert). */
template <std::size_t N>
constexpr bool vtkStylizeStagesInOrder(const vtkStylizeStage (&stages)[N])
{
  for (std::size_t i = 0; i < N; ++i)
  {
    if (stages[i].Index != static_cast<int>(i))
    {
      return false;
    }
  }
  return true;
}
#endif

class VTKSTYLIZEPASSES_EXPORT vtkStylizeStylePass : public vtkImageProcessingPass
{
public:
  vtkTypeMacro(vtkStylizeStylePass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The lighting pass the style shades with (owned by the style; change its model and settings
   * freely). Its default model is the style's own (Comic, PixelArt, or Standard for sketch).
   */
  vtkStylizeLightingPass* GetLightingPass();

  /** Which surfaces keep their colours under a black-and-white style's ink (Tint). */
  enum Tints
  {
    BLACK_AND_WHITE = 0, ///< none: the paper is white
    DATA_COLORS = 1,     ///< surfaces coloured by an array (a colour map); solid colours white
    ALL_COLORS = 2       ///< every surface, solid colours included
  };

  /**
   * Sets what the lit colour must be made of for this style, from its settings, on `lighting`
   * (vtkStylizeLightingPass's ColorMode and SolidColorTones): the style does so on its own
   * lighting pass at every frame, and a view that lights the scene with a pass of its own
   * (ParaView's, before compositing) calls it for that one. The base: VTK's colours.
   */
  virtual void ConfigureLightingColors(vtkStylizeLightingPass* lighting);

  /**
   * The style's G-buffer (owned by the style), for reading the last frame back
   * (vtkStylizeGBufferPass::DownloadChannel()) and for its user settings (Precision,
   * LogarithmicDepthRatio). The style sets the per-frame configuration (channels, position
   * space, geometry resolution and screen transform, the scene's source) at every render from
   * its own settings: changes made to those here do not last.
   */
  vtkStylizeGBufferPass* GetGBufferPass();

  /** Frees the G-buffer, the stage programs, the intermediate textures and the framebuffer. */
  void ReleaseGraphicsResources(vtkWindow* w) override;

  ///@{
  /**
   * Interactive variant: while the render window's desired update rate is at least this many
   * frames per second (VTK's interactors ask for 15 while the user drags and 0.0001 when still;
   * ParaView's interactive renders for 5, its still renders for 0.002), the style renders its
   * cheaper interactive variant (each style's class documents it); the still frame after the
   * interaction is the full-quality image. 0 turns the interactive variant off: every frame is
   * full quality. In frames per second, from 0 to 1000; default 1.
   */
  vtkSetClampMacro(InteractiveUpdateRate, double, 0.0, 1000.0);
  vtkGetMacro(InteractiveUpdateRate, double);
  ///@}

  ///@{
  /**
   * Interactive image reduction: during the interactive variant's frames (InteractiveUpdateRate)
   * the style renders its picture at 1/k of the viewport's width and height, its lengths scaled
   * to match, and draws it scaled up (colour filtered linearly) over the viewport; translucent
   * geometry, volumes and the overlay are still drawn at the window's resolution. A cheap
   * preview while the user drags; still frames and screenshots are always at full size.
   * 1 renders interactive frames at full size. Not applied to the pixel art (it renders its scene
   * at its art resolution already), a tile of a magnified screenshot, several processes
   * (ParaView in parallel), a transparent (layered) renderer or one that does not erase. A factor
   * (dimensionless) in [1, 8]; each style sets its own: 1 for the comic and the pixel art, 2 for
   * the sketch and the line art (their still frames cost the most).
   */
  vtkSetClampMacro(InteractiveImageReduction, int, 1, 8);
  vtkGetMacro(InteractiveImageReduction, int);
  ///@}

  ///@{
  /**
   * Window scale (not a style setting: set by whoever renders a magnified image in one piece):
   * the lengths the style's settings give in window pixels (vtkPixelArtPass::PixelSize, comic's
   * points with ReferenceHeight 0) are multiplied by it, as a tile of a screenshot magnified
   * this many times multiplies them (vtkWindowToImageFilter), so that an image rendered at the
   * full size in one piece shows the magnified screenshot's picture. ParaView's view sets it
   * while it renders a large screenshot in one piece. In x and y, each from 1 to 64; default
   * (1, 1).
   */
  void SetWindowScale(int x, int y);
  vtkGetVector2Macro(WindowScale, int);
  ///@}

  ///@{
  /**
   * Translucent layers: how many layers of translucent surfaces (actors with an opacity below
   * 1) the style stylizes, nearest first. Each layer is one more run of the style's stages over
   * the nearest translucent surface not yet drawn (depth peeling; a layer that holds nothing
   * ends the peeling early), composited over the stylized opaque scene with the surface's
   * opacity, lines at full strength. Surfaces beyond the last layer are not drawn. 0 draws
   * translucent geometry unstylized: lit and blended over the stylized image (on several
   * ParaView ranks, composited by depth, it is left out). A closed translucent surface has two
   * layers (its front and its back). Range [0, 16] layers; default 4 (VTK's default number of
   * depth peels).
   */
  vtkSetClampMacro(TranslucentLayers, int, 0, 16);
  vtkGetMacro(TranslucentLayers, int);
  ///@}

  /** The number of translucent layers the last frame stylized (0 when none). */
  vtkGetMacro(LastTranslucentLayers, int);

  ///@{
  /**
   * Volumes in the style: each visible vtkVolume is drawn as the surface it shows, where its
   * scalar opacity reaches VolumeOpacityThreshold (vtkStylizeVolumeSurface: the isosurfaces at
   * the opacity's crossings, or at the volume's isovalues in the isosurface blend mode), with
   * the gradient as its normal, coloured by its colour transfer function and lit with its
   * lighting coefficients, so that the style's zones, edges, patterns, strokes and lines apply
   * to it as to any surface, in rendered frames and vector figures. The surface is recomputed
   * only when the data or the transfer functions change. What the volume holds below the
   * threshold (a faint haze) is drawn as VTK's fog (VolumeHaze, VolumeHazeMode). Off, and for a
   * volume whose STYLIZE_VOLUME key is 0, the volume is drawn by VTK over the stylized picture.
   * Volumes of composite data or of dependent components (RGBA) are always drawn by VTK. Behind a
   * compositor (a delegate pass: ParaView's view) each process draws the surfaces of its own pieces
   * of the volumes. Default on.
   */
  vtkSetMacro(StylizeVolumes, bool);
  vtkGetMacro(StylizeVolumes, bool);
  vtkBooleanMacro(StylizeVolumes, bool);
  ///@}

  ///@{
  /**
   * The opacity from which a volume's sample counts as solid (StylizeVolumes): the value of the
   * volume's scalar opacity function, i.e. the opacity of one ScalarOpacityUnitDistance of the
   * material, dimensionless. A volume's VOLUME_OPACITY_THRESHOLD key overrides it. Range
   * [0.001, 1], default 0.1.
   */
  vtkSetClampMacro(VolumeOpacityThreshold, double, 0.001, 1.0);
  vtkGetMacro(VolumeOpacityThreshold, double);
  ///@}

  ///@{
  /**
   * The opacity of a stylized volume's haze (StylizeVolumes): what the volume holds below
   * VolumeOpacityThreshold (soft tissue over a CT's bone, a faint shell of a field). 0 leaves
   * it out: the volume is its solid surface alone, drawn wherever its material reaches the
   * threshold (cheaper: nothing is computed per view, but thin or faint material looks unlike
   * VTK's picture). Above 0, a volume whose opacity function
   * holds values between a tenth of the threshold and the threshold is also drawn as a
   * translucent surface where its opacity first reaches a tenth of the threshold, coloured as
   * VolumeHazeMode says (HAZE_FOG: VTK's fog times this, so that 1 draws the volume's
   * translucent part as VTK does), which the style draws in its translucent layers
   * (TranslucentLayers: stylized, over the solid surface; the line art draws it as its paper,
   * with its outline). Not with the isosurface blend mode. Range [0, 1], default 1 (with
   * HAZE_FOG: the volume as VTK draws it, in the style).
   */
  vtkSetClampMacro(VolumeHaze, double, 0.0, 1.0);
  vtkGetMacro(VolumeHaze, double);
  ///@}

  /** How a volume's haze is coloured (VolumeHazeMode). */
  enum VolumeHazeModes
  {
    HAZE_SHELL = 0, ///< the colour map's colour at the haze, at the VolumeHaze opacity
    HAZE_FOG = 1    ///< VTK's accumulated colour and opacity, times VolumeHaze (default)
  };

  ///@{
  /**
   * How a volume's haze (VolumeHaze above 0) is coloured: HAZE_FOG (default), each point of the
   * haze takes the colour and opacity VTK's ray casting accumulates from it along the view ray
   * through the volume to its solid surface or out of it (opacity times VolumeHaze: 1 is VTK's
   * own; with the volume's Shade on, each sample lit as VTK's ray caster lights it: its lighting
   * coefficients, the gradient as the normal, the headlight; for an unstructured grid's mapper
   * (vtkUnstructuredGridVolumeMapper) unlit, the opacity taken as an attenuation coefficient,
   * as those mappers draw), recomputed when the view changes (while the camera moves, frames
   * of a window whose desired update rate is at least 1, as VTK's interactor styles and
   * ParaView's interactive renders set it, keep the last still frame's fog), so that a thick fog is
   * as dark as VTK draws it and the shell's back and its grazing parts as faint or as strong: the
   * layers of the shell, composited front to back, add up to the whole ray (the fog in front of the
   * shell included). The solid surface is drawn only where the volume looks solid from the eye
   * (the view ray's opacity, through the fog in front and the solid material, at least one
   * half); thinner solid material (a soft ball's rim, a wall that thins out) is part of the
   * fog, as VTK shows it. The style draws these colours as they are
   * (vtkStylizeLightingPass::EMITTED_COLORS: their lightness is the tone). The line art draws
   * the outline of where the volume looks solid (the whole ray's opacity one half) instead of
   * the shell's. Data that is not an image, or cell scalars, is sampled on an image of 64 points
   * along its longest side (again when it changes). On several processes (ParaView's ranks,
   * each holding a piece) each samples the whole volume, the pieces gathered onto the same
   * samples as one process takes (an image's own grid, up to 4M points; larger images on 128
   * points along their longest side), again when a piece changes.
   * HAZE_SHELL: a shell of the VolumeHaze opacity in the colour the colour map gives there.
   */
  vtkSetClampMacro(VolumeHazeMode, int, HAZE_SHELL, HAZE_FOG);
  vtkGetMacro(VolumeHazeMode, int);
  ///@}

  /**
   * Per-volume settings, as keys of the volume's vtkProp::GetPropertyKeys() information:
   * STYLIZE_VOLUME 0 leaves the volume to VTK (drawn as it is, over the stylized picture), 1
   * (the default) draws it in the style; VOLUME_OPACITY_THRESHOLD replaces the style's
   * VolumeOpacityThreshold for it.
   */
  static vtkInformationIntegerKey* STYLIZE_VOLUME();
  static vtkInformationDoubleKey* VOLUME_OPACITY_THRESHOLD();

  /** The number of volumes the last frame drew as surfaces (StylizeVolumes). */
  int GetNumberOfVolumeSurfaces();

  ///@{
  /**
   * Annotations drawn as VTK draws them: axes (vtkCubeAxesActor, vtkPolarAxesActor,
   * vtkGridAxesActor3D, vtkAxesActor, vtkAxisActor) and 3D text (vtkTextActor3D,
   * vtkBillboardTextActor3D, vtkAxisFollower) are left out of the stylized scene and drawn over
   * the stylized picture, depth-tested against it, so that labels stay readable in every style
   * (line art draws no lines on them, pixel art would pixelate them to blobs). Off stylizes them
   * with the rest of the scene. Applies when the style renders the geometry itself, and behind a
   * compositor whose per-process G-buffer pass leaves the annotations out
   * (vtkStylizeGBufferPass::LeaveOutAnnotations: ParaView's view, its data axes grid, on one
   * process and on several, where the first process's annotations are drawn). Default on.
   */
  vtkSetMacro(PlainAnnotations, bool);
  vtkGetMacro(PlainAnnotations, bool);
  vtkBooleanMacro(PlainAnnotations, bool);
  ///@}

  ///@{
  /**
   * Iso-lines of the coloured data: on every opaque surface coloured by a point-data array
   * through its mapper's colour map (a slice, a contour, a coloured mesh), lines where the
   * array crosses round levels of the colour map's range (IsoLineSpacing), drawn in ink with
   * the feature lines, hidden parts removed, and exact in vector figures: the contour plot of
   * the data made a drawing (vtkStylizeFeatureLines' ISOLINE kind). The comic, the sketch and
   * the line art draw them; the pixel art does not (its art pixels are coarser than the
   * lines). The most levels (ROUND), or their number (EVEN); 0 draws none. Range [0, 100],
   * default 0.
   */
  vtkSetClampMacro(IsoLines, int, 0, 100);
  vtkGetMacro(IsoLines, int);
  ///@}

  ///@{
  /** Width of the iso-lines (IsoLines), in points. Range [0.1, 20], default 1. */
  vtkSetClampMacro(IsoLineWidth, double, 0.1, 20.0);
  vtkGetMacro(IsoLineWidth, double);
  ///@}

  /** How the iso-line levels are placed (vtkStylizeFeatureLines::ComputeIsoLevels()). */
  enum IsoLineSpacings
  {
    ROUND, // round numbers, at most IsoLines of them, as a scalar bar's ticks
    EVEN,  // IsoLines levels splitting the colour map's range into equal parts
    BANDS  // the edges between a banded colour map's colours (else as ROUND)
  };

  ///@{
  /**
   * How the iso-line levels are placed in the colour map's range: ROUND (the default), EVEN, or
   * BANDS (a vtkLookupTable's NumberOfTableValues, a discretized colour transfer function's
   * NumberOfValues: one line between two colours). A colour map with a log scale places them on
   * a log scale.
   */
  vtkSetClampMacro(IsoLineSpacing, int, ROUND, BANDS);
  vtkGetMacro(IsoLineSpacing, int);
  ///@}

  /** Whether `prop` is an annotation (PlainAnnotations): axes and 3D text. */
  static bool IsAnnotation(vtkProp* prop);

  /** Renders the frame: the opaque scene and the translucent layers through the style. */
  void Render(const vtkRenderState* s) override;

  /**
   * Bytes of device memory the style's textures hold after the last frame: the G-buffer's
   * (vtkStylizeGBufferPass::GetTextureBytes()), the style's intermediate targets and the
   * direction field's. Divide by the viewport's pixels for bytes per pixel.
   */
  vtkIdType GetTextureBytes();

  ///@{
  /**
   * Background culling (not a style setting: the picture is the same either way): stages that
   * compute surface pixels only skip the background by an early depth test against the
   * G-buffer, and the final stage runs only within the scene's screen rectangle, the base
   * writing the background around it. On by default; off computes every pixel in every stage,
   * for comparisons and tests.
   */
  void BackgroundCullingOn();
  void BackgroundCullingOff();
  bool GetBackgroundCulling();
  ///@}

  ///@{
  /**
   * Stage timing, for benchmarks and profiling (not a style setting): while on, every stage of a
   * frame waits for the renderer to finish before and after it (glFinish), and its wall-clock
   * time is recorded. The waits make the frame slower than an untimed one. Off by default.
   */
  void StageTimingOn();
  void StageTimingOff();
  bool GetStageTiming();
  ///@}

  ///@{
  /**
   * Patterns fixed to the surface, for animations: AnchorPatternsToSurface() anchors the
   * style's pattern to the surface (comic dots and hatching in object space, pixel art in
   * texels, the sketch's noise in object space and, unless `keepNoise`, the SPARSE noise whose
   * strokes hold still), so that it does not swim over a turning surface; a pattern fixed to
   * the screen does. RestorePatternAnchors() gives back the settings the first call replaced.
   * vtkstylize --orbit, the Python package's orbit() and ParaView's SaveStylizedOrbit use them.
   */
  void AnchorPatternsToSurface(bool keepNoise = false);
  void RestorePatternAnchors();
  ///@}

  ///@{
  /**
   * What a vector figure (vtkStylizeFigureWriter) reads of the style, beside its settings:
   * - SwapLayer(layer): sets the layer the style writes to the output (the style's Layers
   *   enumeration; 0 is the style's own picture) and returns the one it had (-1 for a style
   *   without layers);
   * - GetPixelsPerPoint(height, tiles): pixels per point in an image `height` pixels tall
   *   rendered in `tiles` x `tiles` tiles (a magnified screenshot; 1 otherwise), with the
   *   style's ReferenceHeight and the WindowScale: what the style multiplies its lengths by;
   * - GetTinted(): whether the paper may keep the data's colours (Tint is not BLACK_AND_WHITE;
   *   false for a style without the setting).
   */
  virtual int SwapLayer(int) { return -1; }
  double GetPixelsPerPoint(int height, int tiles);
  virtual bool GetTinted() { return false; }
  ///@}

  ///@{
  /**
   * The last timed frame's stages, in the order they first ran: their number, their names (the
   * stage's #define, e.g. FIELD_STAGE_SMOOTH; SCENE for the lighting and G-buffer render of the
   * scene, AFTER for what follows the stylized image, OUTPUT for a final stage without a
   * #define), the milliseconds summed over the stage's runs in that frame, and its runs.
   */
  int GetNumberOfTimedStages();
  const char* GetTimedStageName(int i);
  double GetTimedStageMilliseconds(int i);
  int GetTimedStageRuns(int i);
  ///@}

protected:
  friend class vtkStylizeDirectionField;
  friend class vtkStylizeFeatureStrokes;

  /** `lightingModel`: the style's default lighting model (vtkStylizeLightingPass::Models). */
  explicit vtkStylizeStylePass(int lightingModel);

  /** The lighting colour mode of a Tint: LIGHT_TONE, DATA_HUES or ALL_HUES. */
  static int ColorModeForTint(int tint);
  ~vtkStylizeStylePass() override;

#ifndef __VTK_WRAP__
  /**
   * The style's stages (the constructor of a style calls it once): `source`, the style's GLSL
   * (declarations and `mainCall`'s function), assembled after the shared GLSL; `mainCall`, the
   * statement main() runs, e.g. "  comicMain();\n"; `stages`, in index order.
   */
  void SetStages(const std::string& source, const std::string& mainCall,
    const std::vector<vtkStylizeStage>& stages);
#endif

  /**
   * Makes `source`'s ProgressEvent (a double in [0, 1], e.g. while the strokes find the lines
   * of a large mesh) this pass's ProgressEvent, which the program's progress bar and ParaView's
   * progress bar observe. A style calls it once per source it owns.
   */
  void ForwardProgress(vtkObject* source);

  /** The frame being rendered, as the stages see it (filled by BeginFrame()). */
  struct Frame
  {
    vtkRenderer* Renderer = nullptr;
    vtkOpenGLRenderWindow* Window = nullptr;
    /** The stages' width and height, pixels: the viewport's, plus the guard band. */
    int Size[2] = { 0, 0 };
    /** The lower-left corner of the stages' pixels in the window (the guard band's corner). */
    int Origin[2] = { 0, 0 };
    /**
     * The guard band of a tile (left, bottom, right, top), pixels: how much of the neighbouring
     * tiles' picture the stages compute around the viewport, so that what a stage reads across
     * the tile's border is what a direct render at the full size would read. Zero on the full
     * image's own borders, and everywhere in an untiled render.
     */
    int Guard[4] = { 0, 0, 0, 0 };
    /**
     * The guard band's screen transform (sx, sy, tx, ty): the camera's normalized device
     * coordinates of the viewport mapped onto the stages' pixels (identity without a guard).
     */
    double GuardTransform[4] = { 1.0, 1.0, 0.0, 0.0 };
    /** The full (possibly tiled, magnified) image: the renderer's size in it, pixels. */
    double FullSize[2] = { 1.0, 1.0 };
    /** The lower-left corner of the stages' pixels in the full image, whole pixels. */
    double FullOffset[2] = { 0.0, 0.0 };
    /** The magnification of a tiled screenshot (1 otherwise), times the WindowScale. */
    int TileScale[2] = { 1, 1 };
    vtkCamera* Camera = nullptr;
    bool Parallel = false;
    /** World size of a pixel: times the depth in perspective, as is in parallel projection. */
    double PixelWorld = 1.0;
    /** The window renders at an interactive rate (InteractiveUpdateRate): a cheaper variant. */
    bool Interactive = false;
    /**
     * Window pixels per stage pixel: > 1 while the picture renders at a reduced size
     * (InteractiveImageReduction); the stages' Size, Origin and full image are then the
     * reduced picture's, and PointSize() is divided by it.
     */
    double Reduction = 1.0;
  };

  /**
   * What the G-buffer renders this frame. Applied whole at every frame: a field a style does
   * not set has its default.
   */
  struct SceneRequest
  {
    /** vtkStylizeGBufferPass::ChannelBits beyond colour and depth. */
    int Channels = 0;
    /** vtkStylizeGBufferPass::PositionSpaces of the POSITION channel. */
    int PositionSpace = 0;
    /** The least vtkStylizeGBufferPass::Precisions of the normal and direction channels. */
    int NormalPrecision = 0;
    /** Geometry render resolution; 0 x 0: the viewport's. */
    int Resolution[2] = { 0, 0 };
    /** Screen transform of the geometry, x' = sx x + tx, y' = sy y + ty (NDC). */
    double ScreenTransform[4] = { 1.0, 1.0, 0.0, 0.0 };
    /** Shift of translucent geometry and volumes (NDC). */
    double AfterShift[2] = { 0.0, 0.0 };
  };

  /**
   * Starts a frame: clears GL errors and fills `frame`. Returns false when there is nothing to
   * stylize (no OpenGL window, or a zero-sized viewport: the rest of the scene is then drawn and
   * the frame is done). In a tile of a magnified screenshot (vtkWindowToImageFilter) whose
   * scene comes from the geometry, the frame gets a guard band of GetReach() pixels on each
   * side that borders another tile: RenderScene() renders the geometry over it, every stage
   * computes it, and RenderStageToOutput() writes the viewport alone.
   */
  bool BeginFrame(const vtkRenderState* s, Frame& frame);

  /**
   * Height in pixels of the image in which one point of the style's lengths is one pixel (the
   * style's ReferenceHeight); 0, the default: one point is one window pixel, times the tile
   * scale of a magnified screenshot.
   */
  virtual double GetPointReferenceHeight()
  {
    return 0.0;
  }

  /** Pixels per point in this frame's full (possibly tiled, magnified) image. */
  double PointSize(const Frame& frame);

  ///@{
  /**
   * The style's part of AnchorPatternsToSurface(): saves the anchor settings and sets them to
   * the surface; and of RestorePatternAnchors(): sets the saved ones back.
   */
  virtual void AnchorToSurface(bool) {}
  virtual void RestoreAnchors() {}
  ///@}

  /**
   * How far the style's result at a pixel depends on the G-buffer around it, pixels of this
   * frame's image (through all its stages: a stage that reads another stage's result at a
   * distance adds that stage's reach). A tile of a magnified screenshot renders this much of
   * its neighbours around it (Frame::Guard). 0 (the default): the style reads no neighbours, or
   * plans its own margin (the G-buffer render at a custom resolution, as pixel art's blocks).
   */
  virtual double GetReach(const Frame&)
  {
    return 0.0;
  }

  /**
   * The guard band's lower-left corner falls on a multiple of this many pixels of the full
   * image, so that a stage computed on a coarser grid (every k-th pixel) uses the grid of a
   * render at the full size. Default 1.
   */
  virtual int GetGuardAlignment(const Frame&)
  {
    return 1;
  }

  /**
   * The width (pixels) of the line drawn where a volume's fog (HAZE_FOG) looks solid, its whole
   * view ray's opacity one half, in place of the haze's own outline; 0 (the default): none.
   */
  virtual double GetVolumeOutlineWidth(vtkRenderer*)
  {
    return 0.0;
  }

  /** Whether InteractiveImageReduction applies to the style (default true). */
  virtual bool AcceptsImageReduction()
  {
    return true;
  }

  /**
   * Renders the scene into the G-buffer (from the geometry, or from the delegate's image when a
   * delegate is set) as `request` says. Returns false when there is nothing to stylize; the rest
   * of the scene has then been drawn and the frame is done. While a translucent layer is being
   * stylized, renders that layer instead (same request) and returns false when it is empty.
   */
  bool RenderScene(const vtkRenderState* s, const SceneRequest& request);

  /** The translucent layer RenderStyle() is stylizing: 0 for the opaque scene, 1 the nearest. */
  int GetTranslucentLayer() const;

  /**
   * Whether RenderStyle() is stylizing a translucent layer of emitted colours alone (every
   * translucent prop's vtkStylizeLightingPass::EMITTED_COLORS set: a volume's fog, a glow, on
   * every process): light without a surface, which a style draws without outlines (the comic
   * screens its opacity with dots, the pixel art leaves its outline pixels out).
   */
  bool GetTranslucentLayerEmitted() const;

  /** Whether every visible translucent prop of `s` has emitted colours (none: true). */
  static bool EmittedLayers(const vtkRenderState* s);

  /** The G-buffer RenderStyle() is stylizing: GetGBufferPass(), or the translucent layer's. */
  vtkStylizeGBufferPass* GetSceneGBufferPass();

  /** Ends a frame: draws what follows the stylized image (translucent geometry, volumes, the
   * overlay), then checks GL errors. */
  void EndFrame(const vtkRenderState* s);

  /** The stages' #defines for this frame; the programs are rebuilt only when they change. */
  void SetShaderDefines(const std::string& defines);

  /**
   * Sets `target` to (r, g, b), each clamped to [0, 1] (a value that is not finite keeps the
   * old one); true when it changed. For the styles' colour setters.
   */
  static bool SetClampedColor(double target[3], double r, double g, double b);

  /** Appends "#define name" to `defines` when `on`. */
  static void AddDefine(std::string& defines, bool on, const std::string& name);

  /** The uniforms a stage sets (textures, numbers), given the program's binder. */
  using StageUniforms = std::function<void(vtkStylizeUniforms&)>;

  /** Which pixels a stage computes (RenderStage()). */
  enum StageCoverage
  {
    /** every pixel */
    ALL_PIXELS = 0,
    /**
     * The pixels the G-buffer's depth covers (surfaces, lines, points); the others keep zero in
     * every target. Applies when the stage runs at the G-buffer's resolution (else: every
     * pixel). The stage must not sample the G-buffer's window depth (stylizeDepthTexture),
     * which is then its framebuffer's depth attachment; the linear depth is free to read.
     */
    SURFACE_PIXELS = 1
  };

  /**
   * Runs stage `stage` into `targets` (colour attachments 0, 1, ... of the style's framebuffer),
   * over w x h pixels, without blending, for the pixels `coverage` (StageCoverage) names.
   * `cullDepth`: for SURFACE_PIXELS, a depth texture of the stage's size to cull against in
   * place of the G-buffer's (a stage on a coarser grid). Returns false when its program does
   * not build (reported once per frame by EndFrame()).
   */
  bool RenderStage(int stage, std::initializer_list<vtkTextureObject*> targets, int w, int h,
    const StageUniforms& uniforms, int coverage = ALL_PIXELS,
    vtkTextureObject* cullDepth = nullptr);

  /**
   * Runs stage `stage` into the output framebuffer over the frame's viewport. `writeDepth`:
   * the stage writes gl_FragDepth (depth test always passes); otherwise the viewport's depth is
   * cleared to the far plane and not tested. `margin` >= 0 (with `writeDepth`): the stage writes
   * nothing but the background (stylizeBackgroundMain() in vtkStylizeScreenFS: the saturated
   * colour, the background's alpha and depth, discarded in layered renderers) farther than
   * `margin` pixels from the scene (SceneRectangle()); the base then writes the background
   * there itself with that cheap program and runs the stage inside the rectangle only.
   * < 0: the stage runs over the whole viewport.
   */
  bool RenderStageToOutput(
    const Frame& frame, int stage, bool writeDepth, const StageUniforms& uniforms, int margin = -1);

  /**
   * Whether BlitToOutput() can write this frame: an opaque renderer (not a translucent layer,
   * not a transparent renderer that keeps the layer below), a single-sampled output framebuffer
   * with one draw buffer. Asked before the stages run, with the output framebuffer bound.
   */
  bool CanBlitToOutput(const Frame& frame) const;

  /**
   * Copies `source` into the output framebuffer, nearest-neighbour scaled onto `rect` (x0, y0,
   * x1, y1 in the frame's stage pixels, guard band included; it may reach past the viewport),
   * inside the viewport, with the viewport's depth cleared to the far plane: the final write of
   * an image that is constant over blocks of pixels (pixel art's art pixels, already in output
   * colours), as a blit instead of a full-size stage. Only where CanBlitToOutput().
   */
  bool BlitToOutput(const Frame& frame, vtkTextureObject* source, const int rect[4]);

  /**
   * The viewport's pixels where the scene can be: the screen rectangle of the visible props'
   * bounds, grown by `margin` pixels plus the largest point size and line width, clipped to the
   * viewport; rect = x0, y0, x1, y1 (x1, y1 exclusive; may be empty). False when it cannot be
   * bounded (a scene from an image, no bounds, a corner behind the eye) or covers the viewport.
   */
  bool SceneRectangle(const Frame& frame, int margin, int rect[4]);

  /** Binds the G-buffer's textures of the last frame under their shared sampler names. */
  void BindSceneTextures(vtkStylizeUniforms& u);

  /**
   * How a final stage writes the scene's background and depth: stylizeDiscardBackground
   * (layered renderers), stylizeSceneFromImage (keep an image's background alpha) and the depth
   * mapping (vtkStylizeDepthFS).
   */
  void SetSceneOutputUniforms(vtkStylizeUniforms& u, vtkRenderer* ren);

  /** The depth mapping of the last frame (vtkStylizeDepthFS) alone. */
  void SetDepthMappingUniforms(vtkStylizeUniforms& u);

  /** A G-buffer texture of the last frame (vtkStylizeGBufferPass::Buffers); nullptr if absent. */
  vtkTextureObject* GetSceneTexture(int buffer);

  /**
   * An intermediate texture of the style, by the style's own slot number: made w x h with
   * nearest filtering and `internalFormat` (see vtkStylizeShaderUtilities::EnsureScreenTexture),
   * resized or recreated as needed. Freed by FreeTexture() and ReleaseGraphicsResources().
   */
  vtkTextureObject* EnsureTexture(int slot, int w, int h, int internalFormat);

  /** The texture in `slot` (nullptr when none), for textures a style makes itself. */
  vtkTextureObject*& TextureSlot(int slot);

  /** Frees the texture in `slot`. */
  void FreeTexture(int slot);

  /**
   * Reads an RGBA float texture of the last frame back (rows bottom to top) through the style's
   * framebuffer. The window's context must be current. False when there is none.
   */
  bool DownloadTexture(vtkTextureObject* tex, vtkFloatArray* out);

  /**
   * Settings of the principal direction field (vtkStylizeDirectionField),
   * as vtkSketchPass exposes them (its comments give each one's meaning); lengths in points.
   * The member initializers are the settings' defaults. Finite values are expected.
   */
  struct FieldSettings
  {
    int Neighbors = 8;                                           ///< 2, 4 or 8
    double NeighborSpacing = 16.0;                               ///< points at the focal distance
    double MaxStride = 32.0;                                     ///< points
    double ObjectScale = 0.01;                                   ///< share of the scene's diagonal
    double SceneBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 }; ///< invalid: the props'
    double PlanarTolerance = 1.0e-3;
    double UmbilicTolerance = 0.05;
    double SmoothingRadius = 16.0; ///< points
    int SmoothingIterations = 2;
    double FillRadius = 16.0;    ///< points; 0: no fill
    double FallbackAngle = 45.0; ///< degrees
    int Direction = 1;           ///< 0 smaller, 1 larger |curvature|, 2 their bisector
    bool Model = false;          ///< the G-buffer's DIRECTION channel where it is defined
    double TexelSize = 0.0;      ///< points per texel of the estimate's grid; 0: a pixel
  };

  /**
   * The uniforms of vtkStylizeFieldFS' camera helpers (fieldSize, fieldProjection, ...), the
   * G-buffer textures and the depth mapping: what a stage that calls the helpers needs.
   */
  void SetFieldUniforms(vtkStylizeUniforms& u, const Frame& frame);

  /**
   * The output state of RenderStageToOutput() (blending, viewport, scissor, depth, the culled
   * background strips), then `write` draws into it.
   */
  bool WriteOutput(
    const Frame& frame, bool writeDepth, int margin, const std::function<bool()>& write);

  /** Frees everything a style made for its stages (ReleaseGraphicsResources() calls it). */
  virtual void ReleaseStyleResources(vtkWindow*) {}

  /** Bytes of the textures a style holds itself (its direction field), for GetTextureBytes(). */
  virtual vtkIdType GetStyleTextureBytes()
  {
    return 0;
  }

  /**
   * The style's pipeline for one scene (the opaque scene, or a translucent layer): RenderScene(),
   * the stages, the final stage into the output (RenderStageToOutput()). Returns false when
   * RenderScene() did (nothing to stylize).
   */
  virtual bool RenderStyle(const vtkRenderState* s, const Frame& frame) = 0;

  /**
   * Stylizes the translucent layers (TranslucentLayers) after the opaque scene and lays them
   * over the output; tells the G-buffer whether translucent geometry is still to be drawn plain.
   */
  void RenderTranslucentLayers(const vtkRenderState* s, const Frame& frame);

  bool PatternsAnchored = false; // AnchorPatternsToSurface() without a restore yet
  double InteractiveUpdateRate = 1.0;
  int InteractiveImageReduction = 1;
  int WindowScale[2] = { 1, 1 };
  int TranslucentLayers = 4;
  int LastTranslucentLayers = 0;
  bool StylizeVolumes = true;
  bool PlainAnnotations = true;
  int IsoLines = 0;
  double IsoLineWidth = 1.0;
  int IsoLineSpacing = ROUND;

  /** Whether the frame being rendered leaves annotations plain (PlainAnnotations): they are
   * drawn after the stylized picture, which must then write its depth. */
  bool HasPlainAnnotations();
  double VolumeOpacityThreshold = 0.1;
  double VolumeHaze = 1.0;
  int VolumeHazeMode = HAZE_FOG;

  /**
   * For a figure built after the frame (vtkLineArtPass::ComputeFigureStrokes()): puts the
   * surfaces of the volumes the last frame drew as surfaces into `ren`'s props, until
   * RemoveVolumeSurfaces().
   */
  void AddVolumeSurfaces(vtkRenderer* ren);
  void RemoveVolumeSurfaces();

private:
  vtkStylizeStylePass(const vtkStylizeStylePass&) = delete;
  void operator=(const vtkStylizeStylePass&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;

  /**
   * The state without its annotations (PlainAnnotations), which are handed to the G-buffer to
   * draw after the picture; `s` itself when there are none.
   */
  const vtkRenderState* SeparateAnnotations(const vtkRenderState* s);

  /** Gives `frame` its guard band (BeginFrame()). */
  void PlanGuardBand(Frame& frame);

  /** Reduces `frame` to InteractiveImageReduction's size where it applies (BeginFrame()). */
  void PlanReduction(Frame& frame);

  /**
   * The background around the scene's rectangle `rect` of the stages' pixels, as the final
   * stage would write it (RenderStageToOutput()); `scissor` clips a box to the viewport.
   */
  bool RenderBackgroundStrips(const Frame& frame, const int rect[4], bool layer,
    const std::function<void(int, int, int, int)>& scissor);
};

#endif
