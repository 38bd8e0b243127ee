/**
 * @class   vtkPixelArtPass
 * @brief   Pixel-art rendering: the pixel-art lighting model, pixelation to a grid of art
 *          pixels, Canny outlines, and 8x8 ordered dithering to a small palette.
 *
 * The method of "real-time pixel-art rendering" (docs/algorithms.md section 1) as one render
 * pass. Use it like any VTK pass: `renderer->SetPass(pixelArt)`; it needs no delegate.
 * The opaque geometry is rendered into the shared G-buffer (vtkStylizeGBufferPass) with the
 * PixelArt lighting model (vtkStylizeLightingPass), either directly at the art-pixel resolution
 * (FAST) or at full resolution with each block of PixelSize x PixelSize pixels reduced to its
 * mean (FAITHFUL). Outlines are found on the art-pixel image (Canny or Sobel, optionally depth
 * and normal edges), then the paper's 8x8 matrix dithers each art pixel to K levels, grays,
 * DawnBringer's 16 colours, a user list or a palette from the data's colormap.
 *
 * With parallel projection SnapToGrid keeps the grid fixed to the world, so a pan moves the
 * picture by whole art pixels; DitherAnchor SURFACE fixes the art pixels to the surface for
 * animations. Sizes are window pixels, multiplied by the scale of a magnified screenshot. The
 * interactive variant (InteractiveUpdateRate) is FAST.
 * Method, parameters and measured figures: docs/pixel-art.md.
 *
 * @sa vtkStylizeGBufferPass vtkStylizeLightingPass vtkComicPass
 */

#ifndef vtkPixelArtPass_h
#define vtkPixelArtPass_h

#include "vtkStylizePassesModule.h" // for export macro
#include "vtkStylizeStylePass.h"
#include "vtkWrappingHints.h" // for VTK_SIZEHINT

#include <memory> // for std::unique_ptr

class vtkScalarsToColors;

class VTKSTYLIZEPASSES_EXPORT vtkPixelArtPass : public vtkStylizeStylePass
{
public:
  static vtkPixelArtPass* New();
  vtkTypeMacro(vtkPixelArtPass, vtkStylizeStylePass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** How the colour of an art pixel is obtained. */
  enum Modes
  {
    FAST = 0,    ///< render the scene at the art-pixel resolution (one sample per art pixel)
    FAITHFUL = 1 ///< render at full resolution and average each block
  };

  /** The edge detector run on the art-pixel image. */
  enum EdgeDetectors
  {
    NO_EDGES = 0, ///< no image edges (depth and normal edges may still be on)
    SOBEL = 1,    ///< Gaussian, Sobel, magnitude above HighThreshold
    CANNY = 2     ///< Gaussian, Sobel, non-maximum suppression, double threshold, hysteresis
  };

  /** The colours art pixels are reduced to. */
  enum Palettes
  {
    LEVELS = 0,    ///< Levels values per channel (Levels^3 colours)
    GRAYS = 1,     ///< Levels grays (Levels = 2: 1-bit black and white)
    PALETTE16 = 2, ///< the 16-colour DawnBringer palette
    CUSTOM = 3,    ///< the user's list (AddPaletteColor); empty list: LEVELS
    COLORMAP = 4   ///< the data's colormap at ColormapColors values x ColormapShades shades
  };

  /** What the dither pattern is attached to. */
  enum DitherAnchors
  {
    SCREEN = 0, ///< the window's art-pixel grid
    GRID = 1,   ///< the art-pixel grid aligned to the world origin (moves with a pan)
    SURFACE = 2 ///< the surface: the art pixel's object-space position (triplanar)
  };

  /** What the pass writes (for figures and tests). */
  enum Layers
  {
    PIXEL_ART = 0, ///< the final image
    PIXELATED = 1, ///< the art-pixel colours before edges and dither
    EDGES = 2      ///< black edge art pixels on white
  };

  ///@{
  /**
   * FAST or FAITHFUL (default) pixelation. Values: FAST, render the scene at the art-pixel
   * resolution (one sample per art pixel); FAITHFUL, render at full resolution and average each
   * block.
   */
  vtkSetClampMacro(Mode, int, FAST, FAITHFUL);
  vtkGetMacro(Mode, int);
  void SetModeToFast() { this->SetMode(FAST); }
  void SetModeToFaithful() { this->SetMode(FAITHFUL); }
  ///@}

  ///@{
  /**
   * Size of an art pixel in screen pixels of the window (times the tile scale of a magnified
   * screenshot). 1 keeps the full resolution; sizes as large as the window or larger give one
   * art pixel. Range [1, 8192], default 4. Ignored when ArtPixelsAcross is set.
   */
  vtkSetClampMacro(PixelSize, int, 1, 8192);
  vtkGetMacro(PixelSize, int);
  ///@}

  ///@{
  /**
   * Number of art pixels across the image's width: the pixel size becomes the image width
   * divided by it, rounded (at least 1 screen pixel). 0 (default) uses PixelSize.
   * Range [0, 16384].
   */
  vtkSetClampMacro(ArtPixelsAcross, int, 0, 16384);
  vtkGetMacro(ArtPixelsAcross, int);
  ///@}

  ///@{
  /**
   * The edge detector: NO_EDGES, SOBEL or CANNY (default). Values: NO_EDGES, no image edges (depth
   * and normal edges may still be on); SOBEL, Gaussian, Sobel, magnitude above HighThreshold;
   * CANNY, Gaussian, Sobel, non-maximum suppression, double threshold, hysteresis.
   */
  vtkSetClampMacro(EdgeDetector, int, NO_EDGES, CANNY);
  vtkGetMacro(EdgeDetector, int);
  ///@}

  ///@{
  /**
   * Canny's thresholds on the Sobel magnitude of the smoothed gray image (gray in [0, 1]; a
   * step of height g gives a magnitude of about 2.9 g after the Gaussian). Art pixels above
   * HighThreshold are edges, those between the two are edges when connected to one (hysteresis).
   * SOBEL uses HighThreshold alone. Range [0, 8], defaults 0.25 and 0.5. The low threshold is
   * used as min(Low, High).
   */
  vtkSetClampMacro(LowThreshold, double, 0.0, 8.0);
  vtkGetMacro(LowThreshold, double);
  vtkSetClampMacro(HighThreshold, double, 0.0, 8.0);
  vtkGetMacro(HighThreshold, double);
  ///@}

  ///@{
  /**
   * Hysteresis steps: a weak art pixel becomes an edge when a chain of weak art pixels at most
   * this long connects it to a strong one (one full-screen pass per step, at the art-pixel
   * resolution, about 1.2 ms each at 1920x1080 with 4 px art pixels on llvmpipe). 0: strong
   * edges only. Range [0, 256], default 4.
   */
  vtkSetClampMacro(HysteresisIterations, int, 0, 256);
  vtkGetMacro(HysteresisIterations, int);
  ///@}

  ///@{
  /** Outline the depth discontinuities (silhouettes), on the nearer art pixel. Default on. */
  vtkSetMacro(DepthEdges, bool);
  vtkGetMacro(DepthEdges, bool);
  vtkBooleanMacro(DepthEdges, bool);
  ///@}

  ///@{
  /**
   * Depth-edge threshold, dimensionless: the slope of the linear depth against the screen, in
   * world units per world unit, between neighbouring art pixels. Scale-free (the same at any
   * scene size). Range [0.01, 1e4], default 4.
   */
  vtkSetClampMacro(DepthThreshold, double, 0.01, 1.0e4);
  vtkGetMacro(DepthThreshold, double);
  ///@}

  ///@{
  /** Outline creases: the normal changes by more than NormalThreshold to the next art pixel. */
  vtkSetMacro(NormalEdges, bool);
  vtkGetMacro(NormalEdges, bool);
  vtkBooleanMacro(NormalEdges, bool);
  ///@}

  ///@{
  /**
   * Normal-edge threshold: the length of the difference of unit normals between neighbouring
   * art pixels (0.5 is about 29 degrees). Range [0.001, 2], default 0.5.
   */
  vtkSetClampMacro(NormalThreshold, double, 0.001, 2.0);
  vtkGetMacro(NormalThreshold, double);
  ///@}

  ///@{
  /** Colour of the outline art pixels, RGB in [0, 1]. Default black. */
  virtual void SetOutlineColor(double r, double g, double b);
  virtual void SetOutlineColor(const double c[3]) { this->SetOutlineColor(c[0], c[1], c[2]); }
  vtkGetVector3Macro(OutlineColor, double);
  ///@}

  ///@{
  /**
   * The palette: LEVELS (default), GRAYS, PALETTE16, CUSTOM or COLORMAP. Values: LEVELS, Levels
   * values per channel (Levels^3 colours); GRAYS, Levels grays (Levels = 2: 1-bit black and white);
   * PALETTE16, the 16-colour DawnBringer palette; CUSTOM, the user's list (AddPaletteColor); empty
   * list: LEVELS; COLORMAP, the data's colormap at ColormapColors values x ColormapShades shades.
   */
  vtkSetClampMacro(Palette, int, LEVELS, COLORMAP);
  vtkGetMacro(Palette, int);
  /** GRAYS with 2 levels: black and white. */
  void SetPaletteToOneBit()
  {
    this->SetPalette(GRAYS);
    this->SetLevels(2);
  }
  /** GRAYS with 4 levels. */
  void SetPaletteToFourGrays()
  {
    this->SetPalette(GRAYS);
    this->SetLevels(4);
  }
  ///@}

  ///@{
  /** K, the levels per channel (LEVELS) or of gray (GRAYS). Range [2, 256], default 4. */
  vtkSetClampMacro(Levels, int, 2, 256);
  vtkGetMacro(Levels, int);
  ///@}

  ///@{
  /**
   * The CUSTOM palette: RGB colours in [0, 1] (clamped; NaN becomes 0), at most 256.
   */
  void AddPaletteColor(double r, double g, double b);
  void RemoveAllPaletteColors();
  int GetNumberOfPaletteColors() const;
  /** Copies colour i into rgb; returns false when i is out of range. */
  bool GetPaletteColor(int i, double rgb[3]) const;
  ///@}

  ///@{
  /**
   * The colormap for the COLORMAP palette. nullptr (default): the lookup table of the first
   * visible actor that colours by scalars (one component, or a vector mapped by its magnitude or
   * a component). Without one, COLORMAP falls back to LEVELS.
   */
  virtual void SetLookupTable(vtkScalarsToColors* lut);
  vtkGetObjectMacro(LookupTable, vtkScalarsToColors);
  ///@}

  ///@{
  /**
   * COLORMAP palette size: ColormapColors evenly spaced values of the colormap's range, each at
   * ColormapShades brightness levels (k / ColormapShades, k = 1 .. ColormapShades), plus black.
   * Ranges [2, 64] (default 8) and [1, 8] (default 4).
   */
  vtkSetClampMacro(ColormapColors, int, 2, 64);
  vtkGetMacro(ColormapColors, int);
  vtkSetClampMacro(ColormapShades, int, 1, 8);
  vtkGetMacro(ColormapShades, int);
  ///@}

  ///@{
  /**
   * Dither strength in [0, 1]: 1 uses the full threshold range of the matrix (the paper's
   * ordered dither), 0 plain rounding to the nearest level or colour. Default 1.
   */
  vtkSetClampMacro(DitherStrength, double, 0.0, 1.0);
  vtkGetMacro(DitherStrength, double);
  ///@}

  ///@{
  /**
   * Dither size: art pixels per cell of the 8x8 matrix (the pattern repeats every 8 x DitherSize
   * art pixels). Range [1, 64], default 1.
   */
  vtkSetClampMacro(DitherSize, int, 1, 64);
  vtkGetMacro(DitherSize, int);
  ///@}

  ///@{
  /**
   * SCREEN, GRID (default) or SURFACE. Values: SCREEN, the window's art-pixel grid; GRID, the
   * art-pixel grid aligned to the world origin (moves with a pan); SURFACE, the surface: in
   * FAITHFUL mode the surface is drawn in texels fixed to it (art pixels of the object-space
   * position, triplanar, their colour, dither and outlines moving with the surface: for
   * animations), in FAST mode the dither follows the art pixel's object-space position. Where
   * the surface turns away and a texel or dither cell would be under a pixel on the screen, it
   * merges with its neighbours, in powers of two along each of its axes.
   */
  vtkSetClampMacro(DitherAnchor, int, SCREEN, SURFACE);
  vtkGetMacro(DitherAnchor, int);
  ///@}

  ///@{
  /**
   * With parallel projection, shift the image by less than an art pixel so the world origin lies
   * on the art-pixel grid: a pan moves the picture by whole art pixels. Default on. No effect in
   * perspective (where no shift can align every depth).
   */
  vtkSetMacro(SnapToGrid, bool);
  vtkGetMacro(SnapToGrid, bool);
  vtkBooleanMacro(SnapToGrid, bool);
  ///@}

  ///@{
  /** Dither and quantize the background too. Default off: it is only pixelated. */
  vtkSetMacro(StylizeBackground, bool);
  vtkGetMacro(StylizeBackground, bool);
  vtkBooleanMacro(StylizeBackground, bool);
  ///@}

  ///@{
  /**
   * Light with the lights' own colours. Off (default): the lights shade by their luminance
   * alone, so a gray or white surface stays gray under a coloured light kit (ParaView's warm key
   * and cool fill lights), where the lights' faint tint would dither into coloured dots the data
   * does not have; coloured surfaces keep their colours. On: VTK's coloured lights.
   */
  vtkSetMacro(ColoredLights, bool);
  vtkGetMacro(ColoredLights, bool);
  vtkBooleanMacro(ColoredLights, bool);
  ///@}

  /** When the pass writes the scene's depth into the output's depth buffer. */
  enum DepthOutputs
  {
    DEPTH_AUTO = 0, ///< when translucent geometry, volumes or annotations follow; else far
    DEPTH_ALWAYS =
      1 ///< always (for readers of the depth buffer: vtkRenderer::GetZ, z-buffer capture)
  };

  ///@{
  /**
   * DEPTH_AUTO (default) writes the depth only when the scene has translucent geometry, volumes
   * or plain annotations (drawn afterwards and depth-tested against the pixel art); otherwise the
   * depth buffer is cleared, which saves a full-resolution depth write (about 4 ms per frame at
   * 1920x1080 on llvmpipe). DEPTH_ALWAYS writes it every frame. Values: DEPTH_AUTO, when
   * translucent geometry, volumes or annotations follow; else far; DEPTH_ALWAYS, always (for
   * readers of the depth buffer: vtkRenderer::GetZ, z-buffer capture).
   */
  vtkSetClampMacro(DepthOutput, int, DEPTH_AUTO, DEPTH_ALWAYS);
  vtkGetMacro(DepthOutput, int);
  ///@}

  ///@{
  /**
   * The layer written to the output: PIXEL_ART (default), PIXELATED or EDGES. Values: PIXEL_ART,
   * the final image; PIXELATED, the art-pixel colours before edges and dither; EDGES, black edge
   * art pixels on white.
   */
  vtkSetClampMacro(Layer, int, PIXEL_ART, EDGES);
  vtkGetMacro(Layer, int);

  /** Sets Layer and returns the one it had (vtkStylizeStylePass::SwapLayer()). */
  int SwapLayer(int layer) override;
  /** The surface's colours under neutral lights, or the lights' colours (ColoredLights). */
  void ConfigureLightingColors(vtkStylizeLightingPass* lighting) override;
  ///@}

  /**
   * The art pixel size (x, y) in screen pixels and the art-pixel grid size of the last frame.
   * For tests and measurement.
   */
  void GetLastGrid(int blockSize[2], int gridSize[2]) const;

  /** The 8x8 dither matrix of eq. 10 (values 1..64), row-major: entry (y mod 8) * 8 + x mod 8. */
  static const int* GetDitherMatrix() VTK_SIZEHINT(64);

  /** The 16-colour DawnBringer palette, RGB in [0, 1], 48 values. */
  static const double* GetPalette16() VTK_SIZEHINT(48);

protected:
  /**
   * The pixel-art image of a scene (the opaque one, then each translucent layer): the scene into
   * the G-buffer at the art resolution (FAST) or at full resolution then reduced per block
   * (FAITHFUL), the edges, the art pixels, then the upsample into the output. The lighting
   * pass's default model is PixelArt.
   */
  bool RenderStyle(const vtkRenderState* s, const Frame& frame) override;

  vtkPixelArtPass();
  ~vtkPixelArtPass() override;
  /** Patterns anchored to the surface: the SURFACE dither anchor (texels). */
  void AnchorToSurface(bool) override;
  void RestoreAnchors() override;
  /** The scene renders at the art resolution already: no InteractiveImageReduction. */
  bool AcceptsImageReduction() override { return false; }
  int SavedDitherAnchor = GRID;

  int Mode = FAITHFUL;
  int PixelSize = 4;
  int ArtPixelsAcross = 0;
  int EdgeDetector = CANNY;
  double LowThreshold = 0.25;
  double HighThreshold = 0.5;
  int HysteresisIterations = 4;
  bool DepthEdges = true;
  double DepthThreshold = 4.0;
  bool NormalEdges = false;
  double NormalThreshold = 0.5;
  double OutlineColor[3] = { 0.0, 0.0, 0.0 };
  int Palette = LEVELS;
  int Levels = 4;
  vtkScalarsToColors* LookupTable = nullptr;
  int ColormapColors = 8;
  int ColormapShades = 4;
  double DitherStrength = 1.0;
  int DitherSize = 1;
  int DitherAnchor = GRID;
  bool SnapToGrid = true;
  bool StylizeBackground = false;
  bool ColoredLights = false;
  int Layer = PIXEL_ART;
  int DepthOutput = DEPTH_AUTO;

  /** What a frame computes: the grid, the enabled stages, their channels and defines. */
  struct Plan;
  /** The textures the art-resolution stages read. */
  struct Inputs;
  Plan PlanFrame(const vtkRenderState* s, const Frame& frame);
  /** The art-pixel grid of this viewport in the full image, the snap shift, the dither origin. */
  void PlanGrid(const Frame& frame, Plan& plan) const;
  /** The list palette's colours (PALETTE16, CUSTOM, COLORMAP), RGBA. */
  void PlanPalette(const vtkRenderState* s, Plan& plan) const;
  /** Uploads the list palette when it changed. */
  void UpdatePalette(const Frame& frame, const Plan& plan);
  /** The uniforms every stage reads; `input` is the stage's own input, `art` the art pixels. */
  void SetStageUniforms(vtkStylizeUniforms& u, const Frame& frame, const Plan& plan,
    const Inputs& inputs, vtkTextureObject* input, vtkTextureObject* art);
  /** FAITHFUL: averages each block of the G-buffer; `inputs` become the averages. */
  void RenderReduceStage(const Frame& frame, const Plan& plan, Inputs& inputs);
  /** Gaussian, Sobel, classification and hysteresis; returns the edge image. */
  vtkTextureObject* RenderEdgeStages(const Frame& frame, const Plan& plan, const Inputs& inputs);
  /** The art pixels: palette, dither and outlines. */
  void RenderArtStage(
    const Frame& frame, const Plan& plan, const Inputs& inputs, vtkTextureObject* edges);
  /** The art pixels into the output framebuffer (with the depth when needed). */
  void RenderUpsampleStage(
    const Frame& frame, const Plan& plan, const Inputs& inputs, vtkTextureObject* gray);

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;

private:
  vtkPixelArtPass(const vtkPixelArtPass&) = delete;
  void operator=(const vtkPixelArtPass&) = delete;
};

#endif
