/**
 * @class   vtkPVStylizeView
 * @brief   A ParaView render view that draws the scene in one of the VTK Stylize styles.
 *
 * The view is ParaView's render view (everything it does, it still does) plus a Style: None,
 * Comic, Pixel art or Sketch. It follows the design ParaView's eye-dome-lighting view uses, in
 * two stages, so that it works the same in the GUI, in pvbatch and under MPI with IceT:
 *
 * 1. **Per process, before compositing:** under a style, a vtkStylizeGBufferPass lit by the
 *    lighting model (vtkStylizeLightingPass, the style's model unless LightingModel says
 *    otherwise) is the render pass: each rank lights its own part of the data, including
 *    per-representation settings (vtkStylizeSurfaceRepresentation: the comic subject factor,
 *    gray levels, specular gain), writes colour and depth for IceT and keeps the normals,
 *    positions and directions the style reads. With the style None and a lighting model, the
 *    lighting pass alone is the render pass.
 * 2. **After compositing:** the style pass (a vtkStylizeStylePass) is the image-processing pass.
 *    It receives the composited colour and depth and takes the other channels from the ranks'
 *    G-buffers (vtkStylizeGBufferPass::SetChannelSource), composited by depth across the ranks
 *    over the global controller; where none covers a pixel they are rebuilt from the depth.
 *    With one process the same path is taken, so the image does not depend on the number of
 *    ranks beyond what compositing itself changes.
 * 3. **Translucent surfaces** (TranslucentLayers above 0): the ranks leave them out of their
 *    images, and the style renders them layer by layer from each rank's props, each layer
 *    composited by depth across the ranks (vtkStylizeGBufferPass::RenderTranslucentLayer()).
 *    Under a style the ranks are always composited by depth: ParaView's ordered compositing
 *    (which translucent data on several ranks asks for) carries no depth.
 *
 * The passes are the view's sub-proxies (ComicPass, PixelArtPass, SketchPass, LightingPass);
 * their settings appear in the view's properties panel (generated from the pass headers by
 * scripts/parameters.py). FXAA is kept off while a style is shown (it would blur the style's
 * pixels); the user's FXAA setting applies again with the style None.
 */

#ifndef vtkPVStylizeView_h
#define vtkPVStylizeView_h

#include "vtkPVRenderView.h"
#include "vtkSmartPointer.h"              // for vtkSmartPointer
#include "vtkStylizeLightingPass.h"       // for vtkStylizeLightingPass::Models
#include "vtkStylizeParaViewViewModule.h" // for export macro
#include "vtkWeakPointer.h"               // for vtkWeakPointer

#include <string> // for std::string
#include <vector> // for std::vector

class vtkAlgorithm;
class vtkCommand;
class vtkComicPass;
class vtkImageData;
class vtkPixelArtPass;
class vtkPVDataRepresentation;
class vtkProp;
class vtkSketchPass;
class vtkLineArtPass;
class vtkStylizeGBufferPass;
class vtkStylizeLightingPass;
class vtkStylizeStylePass;
class vtkRenderPass;
class vtkVolumeRepresentation;

class VTKSTYLIZEPARAVIEWVIEW_EXPORT vtkPVStylizeView : public vtkPVRenderView
{
public:
  static vtkPVStylizeView* New();
  vtkTypeMacro(vtkPVStylizeView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The styles. */
  enum Styles
  {
    NONE = 0,
    COMIC = 1,
    PIXEL_ART = 2,
    SKETCH = 3,
    LINE_ART = 4
  };

  ///@{
  /**
   * The style drawn: NONE (ParaView's rendering), COMIC, PIXEL_ART, SKETCH or LINE_ART. Default
   * NONE.
   */
  vtkSetClampMacro(Style, int, NONE, LINE_ART);
  vtkGetMacro(Style, int);
  ///@}

  /**
   * Lighting model choices: the style's own, or one of vtkStylizeLightingPass's models (the
   * same values as vtkStylizeLightingPass::Models).
   */
  enum LightingModels
  {
    STYLE_DEFAULT = -1,
    STANDARD = vtkStylizeLightingPass::STANDARD,
    COMIC_LIGHTING = vtkStylizeLightingPass::COMIC,
    PIXEL_ART_LIGHTING = vtkStylizeLightingPass::PIXEL_ART
  };

  ///@{
  /**
   * The lighting model: STYLE_DEFAULT (Comic for comic, PixelArt for pixel art, Standard for
   * sketch, ParaView's own lighting for the style None), or STANDARD, COMIC_LIGHTING or
   * PIXEL_ART_LIGHTING for any style (with None this shows the lighting model alone).
   */
  vtkSetClampMacro(LightingModel, int, STYLE_DEFAULT, PIXEL_ART_LIGHTING);
  vtkGetMacro(LightingModel, int);
  ///@}

  ///@{
  /** The passes (the view's sub-proxies' objects; the view creates its own when not set). */
  void SetComicPass(vtkComicPass* pass);
  void SetPixelArtPass(vtkPixelArtPass* pass);
  void SetSketchPass(vtkSketchPass* pass);
  void SetLineArtPass(vtkLineArtPass* pass);
  void SetLightingPass(vtkStylizeLightingPass* pass);
  vtkComicPass* GetComicPass();
  vtkPixelArtPass* GetPixelArtPass();
  vtkSketchPass* GetSketchPass();
  vtkLineArtPass* GetLineArtPass();
  vtkStylizeLightingPass* GetLightingPass();
  ///@}

  /** FXAA as the user asked; applied only while the style is None. */
  void SetUseFXAA(bool use) override;

  /**
   * The background mode as vtkPVRenderView takes it, remembered (vtkPVRenderView keeps it
   * private): the styles are told the flat background ParaView paints under a composited image.
   */
  void SetBackgroundColorMode(int mode) override;

  /**
   * While on, the styles take the background the view had when it was switched on as the one
   * the picture stands for (vtkStylizeGBufferPass::SetImageBackground), whatever the view
   * renders over meanwhile. vtkSMStylizeViewProxy switches it on for the two renders of a
   * transparent-background screenshot (over white, then over black), so that the style's ink
   * is the same in both and only the true background becomes transparent. Default off.
   */
  void SetFreezeBackground(int freeze);

  /**
   * The styles' window scale (vtkStylizeStylePass::SetWindowScale): vtkSMStylizeViewProxy sets
   * it to the magnification while it renders a screenshot larger than the view in one piece,
   * so that the picture is the magnified one. In x and y (the passes clamp each to [1, 64]);
   * default (1, 1).
   */
  vtkSetVector2Macro(WindowScale, int);
  vtkGetVector2Macro(WindowScale, int);

  /** The style pass in use (nullptr for the style None). */
  vtkStylizeStylePass* GetActiveStylePass();

  /**
   * 1: the active style's pattern is anchored to the surface for an animation
   * (vtkStylizeStylePass::AnchorPatternsToSurface()); 0: its settings are given back. The
   * view's PatternsAnchored property calls it (SaveStylizedOrbit() in the stylize Python
   * module).
   */
  void SetPatternsAnchored(int anchored);

  /**
   * Writes the view as a vector figure with vtkStylizeFigureWriter (SVG or PDF, from the name's
   * extension; the view's size, no magnification): the style's layers are rendered as the view
   * renders (on every rank, composited), and the first rank writes the file. An empty name does
   * nothing. The view's FigureFileName property calls it (the stylize Python module's
   * SaveStylizedFigure() sets it); GetFigureResult() is "" after a success, the failure's line
   * otherwise.
   */
  void WriteFigure(const char* fileName);
  const char* GetFigureResult() { return this->FigureResult.c_str(); }

  /**
   * Encodes numbered PNG frames into a .gif or .mp4 animation with ffmpeg, on the first rank
   * (vtkStylizeAnimationEncoder::Encode(): `pattern` is ffmpeg's printf-style frame name,
   * `fps` frames per second). An empty output does nothing. The view's AnimationEncoding
   * property calls it (the stylize Python module's SaveStylizedOrbit() sets it);
   * GetFigureResult() is "" after a success, the failure's line otherwise.
   */
  void EncodeAnimation(const char* pattern, int fps, const char* output);

  ///@{
  /**
   * The volumes each style leaves to ParaView. A display added here (ParaView's composite
   * representation, or a volume representation itself) has, while its active representation
   * is a Volume, that volume's vtkStylizeStylePass::STYLIZE_VOLUME key set to 0 at each render
   * (drawn as ParaView draws it, over the stylized picture); the key comes off when it leaves
   * the list. The view's internal PlainVolumeDisplays property calls them: vtkSMStylizeViewProxy
   * lists there, before each render, the displays whose StylizeVolume is off.
   */
  void AddPlainVolumeDisplay(vtkPVDataRepresentation* display);
  void RemoveAllPlainVolumeDisplays();
  ///@}

protected:
  friend class vtkPVStylizeViewFigureSource;

  vtkPVStylizeView();
  ~vtkPVStylizeView() override;

  /** Configures the passes for the current settings, then renders as vtkPVRenderView. */
  void Render(bool interactive, bool skip_rendering) override;

  /**
   * As vtkPVRenderView, and keeps whether the data asked for ordered compositing: under a style
   * it is not used (see Render()).
   */
  void Update() override;

  /** Puts the lighting pass and the style pass into ParaView's render and image slots. */
  void ConfigurePasses();

  /**
   * Whether the colour legends are drawn: only where the style shows the colours they explain
   * (as vtkstylize does), not over black and white (comic or sketch with Tint BLACK_AND_WHITE,
   * line art); the view's renders and its vector figures leave them out there.
   */
  bool ShowsColorLegends();

  /** Hides the visible scalar bars of the view's renderers, returned to be shown again. */
  std::vector<vtkProp*> HideColorLegends();

  /**
   * The view's background as ParaView will paint it (vtkPVRenderView::UpdateBackground()), when
   * it is one flat colour: false for a gradient, a texture or a skybox.
   */
  bool GetFlatBackground(double rgb[3]);

  /** Frees the graphics resources of the style passes other than keep (all when nullptr). */
  void ReleasePassResources(vtkStylizeStylePass* keep);

  /**
   * Passes the style's ProgressEvent (finding the lines of large meshes) to ParaView's progress
   * bar for one frame; returns the observer's tag on the style.
   */
  unsigned long ReportProgressOf(vtkStylizeStylePass* style);

  int Style = NONE;
  int LightingModel = STYLE_DEFAULT;
  bool RequestedFXAA = false;
  int ColorMode = DEFAULT;
  bool BackgroundFrozen = false;
  int WindowScale[2] = { 1, 1 };
  bool FrozenFlat = false;
  double FrozenBackground[3] = { 0.0, 0.0, 0.0 };
  bool DataNeedsOrderedCompositing = false; // what the representations asked at Update()
  bool WarnedUnlayered = false; // warned once: several ranks, translucent data, no layers
  vtkStylizeStylePass* LastStylePass = nullptr;
  vtkSmartPointer<vtkComicPass> ComicPass;
  vtkSmartPointer<vtkPixelArtPass> PixelArtPass;
  vtkSmartPointer<vtkSketchPass> SketchPass;
  vtkSmartPointer<vtkLineArtPass> LineArtPass;
  vtkSmartPointer<vtkStylizeLightingPass> LightingPass;
  vtkSmartPointer<vtkRenderPass> LightingDelegate;
  vtkSmartPointer<vtkStylizeGBufferPass> RankGBuffer;
  std::string FigureResult;
  vtkSmartPointer<vtkAlgorithm> ProgressReporter; // what the session's progress handler observes
  vtkSmartPointer<vtkCommand> ProgressForward;    // the style's progress to the reporter
  bool ProgressRegistered = false;
  bool ProgressReported = false; // this frame passed on progress below 1
  /** Sets the STYLIZE_VOLUME key of the plain displays' active volumes, takes it off others. */
  void MarkPlainVolumes();

  std::vector<vtkWeakPointer<vtkPVDataRepresentation>> PlainVolumeDisplays;
  std::vector<vtkWeakPointer<vtkVolumeRepresentation>> PlainVolumes; // keyed by the last frame

private:
  vtkPVStylizeView(const vtkPVStylizeView&) = delete;
  void operator=(const vtkPVStylizeView&) = delete;
};

#endif
