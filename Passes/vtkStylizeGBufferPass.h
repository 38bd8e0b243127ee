/**
 * @class   vtkStylizeGBufferPass
 * @brief   The shared G-buffer: renders the scene's opaque geometry once into the buffers a
 *          style needs, then composites it back with its depth.
 *
 * In the manner of vtkSSAOPass, the pass renders the opaque geometry, lit by its LightingPass,
 * into a framebuffer object whose attachments are only those asked for (SetChannels()): the lit
 * colour and the depth always; the view-space NORMAL, the view- or object-space POSITION, the
 * LINEAR_DEPTH (-z in view space) and the tangent DIRECTION of the vertex attribute
 * stylizeDirectionMC on request. A style calls RenderGeometry(), processes the textures, writes
 * its image and depth, then calls RenderAfterGeometry() for the translucent geometry, the
 * volumes and the 2D overlay; Render() alone writes the colour and depth back and draws those.
 *
 * With SceneImagePass set, the scene comes from that pass's image (lit colour and window depth,
 * as after ParaView's IceT compositing): the channels are rebuilt from it, or taken from the
 * processes' own G-buffers where a ChannelSource drew the same surface.
 *
 * Channels, formats, the image path and what is tested: docs/gbuffer.md.
 *
 * @sa vtkStylizeLightingPass vtkStylizeStylePass vtkSSAOPass
 */

#ifndef vtkStylizeGBufferPass_h
#define vtkStylizeGBufferPass_h

#include "vtkOpenGLRenderPass.h"
#include "vtkStylizePassesModule.h" // for export macro

#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

class vtkCameraPass;
class vtkFloatArray;
class vtkMultiProcessController;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkProp;
class vtkRenderPass;
class vtkSequencePass;
class vtkShaderProgram;
class vtkStylizeLightingPass;
class vtkTextureObject;

class VTKSTYLIZEPASSES_EXPORT vtkStylizeGBufferPass : public vtkOpenGLRenderPass
{
public:
  static vtkStylizeGBufferPass* New();
  vtkTypeMacro(vtkStylizeGBufferPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Optional channels (bit mask). Colour and depth are always allocated. */
  enum ChannelBits
  {
    NORMAL = 1,
    POSITION = 2,
    LINEAR_DEPTH = 4,
    DIRECTION = 8
  };

  /** Buffers that DownloadChannel() can read back. */
  enum Buffers
  {
    COLOR_BUFFER = 0,
    NORMAL_BUFFER = 1,
    POSITION_BUFFER = 2,
    DEPTH_BUFFER = 3,
    LINEAR_DEPTH_BUFFER = 4,
    DIRECTION_BUFFER = 5
  };

  /** Spaces for the POSITION channel. */
  enum PositionSpaces
  {
    VIEW = 0,
    OBJECT = 1
  };

  ///@{
  /**
   * Bit mask of the optional channels to allocate and write (NORMAL, POSITION, LINEAR_DEPTH,
   * DIRECTION). Only these are allocated. Default 0: colour and depth only.
   *
   * DIRECTION carries a per-vertex tangent direction field (for example a principal direction
   * of vtkStylizePrincipalCurvatures) to the screen. Map the point array to the vertex attribute
   * `stylizeDirectionMC` (vtkOpenGLPolyDataMapper::MapDataArrayToVertexAttribute); VTK's
   * composite data mapper (vtkCompositePolyDataMapper2, ParaView's) uploads no mapped array, so
   * for composite data the direction is the point data's tangents (vtkDataSetAttributes::
   * SetTangents, a vtkFloatArray: vtkStylizePrincipalCurvatures sets them). Directions are
   * unsigned (d and -d are the same), so the vertex shader interpolates the outer product d d^T,
   * not d; the fragment shader projects it onto the tangent plane and writes its principal
   * eigenvector and coherence (eigenvalue gap / trace, 0..1). Actors without the attribute
   * write coherence 0.
   */
  vtkSetClampMacro(Channels, int, 0, (NORMAL | POSITION | LINEAR_DEPTH | DIRECTION));
  vtkGetMacro(Channels, int);
  ///@}

  ///@{
  /**
   * Space of the POSITION channel: VIEW (camera coordinates, the default) or OBJECT (each
   * actor's model coordinates, for textures that stick to the surface).
   */
  vtkSetClampMacro(PositionSpace, int, VIEW, OBJECT);
  vtkGetMacro(PositionSpace, int);
  ///@}

  /** Precision of the colour, normal and direction channels. */
  enum Precisions
  {
    HALF = 0,
    FULL = 1
  };

  ///@{
  /**
   * Precision of the colour, normal and direction textures: HALF (RGBA16F, the default: about 3
   * decimal digits, enough for 8-bit output) or FULL (RGBA32F: for measurement and numeric
   * tests, at twice the memory traffic). A style may ask for more in the normal and direction
   * textures alone (NormalPrecision). Positions are always RGBA32F and depth DEPTH32F.
   */
  vtkSetClampMacro(Precision, int, HALF, FULL);
  vtkGetMacro(Precision, int);
  ///@}

  ///@{
  /**
   * The least precision of the normal and direction textures, per channel: they are FULL when
   * this or Precision is FULL, while the colour follows Precision alone. A style sets it at
   * every render (the sketch asks for FULL: its curvature estimate differentiates normals, and
   * its colour needs no more than HALF). HALF (default) or FULL.
   */
  vtkSetClampMacro(NormalPrecision, int, HALF, FULL);
  vtkGetMacro(NormalPrecision, int);
  ///@}

  ///@{
  /**
   * The lighting pass used for the geometry. Default nullptr: VTK's own lighting.
   * Only its lighting settings are used; its delegate is ignored.
   */
  vtkGetObjectMacro(LightingPass, vtkStylizeLightingPass);
  virtual void SetLightingPass(vtkStylizeLightingPass* pass);
  ///@}

  ///@{
  /**
   * A pass whose image (lit colour and window depth) replaces the geometry as the scene's
   * source; see the class description. Default nullptr: render the geometry.
   */
  vtkGetObjectMacro(SceneImagePass, vtkRenderPass);
  virtual void SetSceneImagePass(vtkRenderPass* pass);
  ///@}

  ///@{
  /**
   * The G-buffer pass that renders this process's geometry in the same frame, inside
   * SceneImagePass (see the class description). Before the image is rendered, the source is set
   * to this pass's NORMAL, POSITION, LINEAR_DEPTH and DIRECTION channels, position space and
   * normal precision; in the image path its channels replace the reconstruction where its depth
   * equals the image's. Ignored for a frame the source did not render, or rendered at another
   * size (an interactive image reduction). Default nullptr: everything is reconstructed from the
   * image.
   */
  vtkGetObjectMacro(ChannelSource, vtkStylizeGBufferPass);
  virtual void SetChannelSource(vtkStylizeGBufferPass* source);
  ///@}

  ///@{
  /**
   * The processes whose channel sources each hold part of the scene (ParaView's render ranks).
   * With more than one process, each sends its source's channels inside the rectangle where it
   * drew a surface to process 0 (a binary tree, log2(N) steps), which keeps the nearest by depth
   * at every pixel; every process must render each frame, as they do under IceT. Default
   * nullptr: this process alone.
   */
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  virtual void SetController(vtkMultiProcessController* controller);
  ///@}

  ///@{
  /**
   * The background the picture stands for when the image was rendered over another one:
   * ParaView renders the ranks, and a server's picture for its client, over transparent black
   * and blends the styled result over the view's background afterwards; a transparent-background
   * screenshot renders over white and over black and keeps what both show. With
   * UseImageBackground on, a frame of the image path whose renderer's background is not this
   * colour (the compositor replaced it) takes this colour in the colour channel where the image
   * has no surface (its alpha is kept), so that stages reading colour across a silhouette
   * (edges, tone blurs) see the background the picture stands for; on the background the styles
   * then give that background's share of each pixel back to the renderer's (stylizeOutput() in
   * vtkStylizeScreenFS: premultiplied under compositing). An RGB
   * colour, each component in [0, 1] (clamped; NaN gives 0). Default (0, 0, 0).
   */
  void SetImageBackground(double r, double g, double b);
  void SetImageBackground(const double rgb[3]) { this->SetImageBackground(rgb[0], rgb[1], rgb[2]); }
  vtkGetVector3Macro(ImageBackground, double);
  ///@}

  ///@{
  /**
   * Whether ImageBackground is used (ParaView's view sets it for a flat background). Default
   * off: the image's own colour.
   */
  vtkSetMacro(UseImageBackground, bool);
  vtkGetMacro(UseImageBackground, bool);
  vtkBooleanMacro(UseImageBackground, bool);
  ///@}

  /** Whether the last image-path frame replaced its background by ImageBackground. */
  vtkGetMacro(ImageBackgroundApplied, bool);

  /**
   * Whether the last image-path frame took its channels from ChannelSource (where its depth was
   * the image's depth) rather than reconstructing them all.
   */
  vtkGetMacro(ChannelSourceUsed, bool);

  /** Whether the last RenderGeometry() took the scene from SceneImagePass. */
  vtkGetMacro(SceneFromImage, bool);

  /** Geometry, composite, translucent geometry and volumes, overlay. */
  void Render(const vtkRenderState* s) override;

  /**
   * Renders the opaque geometry into the G-buffer. Returns false when nothing could be rendered
   * (zero-sized viewport). Leaves the output framebuffer bound as it was.
   */
  bool RenderGeometry(const vtkRenderState* s);

  /** Writes the G-buffer's colour and depth into the output framebuffer at the viewport. */
  void CompositeToOutput(const vtkRenderState* s);

  /**
   * Renders translucent geometry (unless DrawTranslucent is off) and volumes (lit by the lighting
   * pass, depth-tested against the composited depth), then the 2D overlay, into the output
   * framebuffer.
   */
  void RenderAfterGeometry(const vtkRenderState* s);

  /**
   * Renders the props a style leaves plain (SetAfterProps(): annotations, and volumes left out of
   * a channel source's picture) over the output, as VTK draws them, depth-tested against it
   * (RenderAfterGeometry() does, after the translucent geometry; over a scene from an image, the
   * only thing it draws).
   */
  void RenderAnnotations(const vtkRenderState* s);

#ifndef __VTK_WRAP__
  /**
   * Props RenderAfterGeometry() draws as VTK does (VTK's lighting, opaque, translucent and
   * volumetric, then their overlay), depth-tested against the stylized picture, after the
   * volumes: the annotations a style leaves plain (vtkStylizeStylePass::PlainAnnotations), and
   * the volumes a channel source left out of its picture (LeaveOutVolumes). Not owned: valid
   * until the frame ends. Default: none.
   */
  void SetAfterProps(const std::vector<vtkProp*>& props)
  {
    this->AfterProps = props;
  }
#endif

  /**
   * Renders one translucent layer of the scene into this G-buffer, for a style that draws
   * translucent surfaces itself (vtkStylizeStylePass::TranslucentLayers). The props with
   * translucent polygonal geometry are rendered lit by the lighting pass, with blending off and
   * the depth written, so that each pixel keeps one surface: the nearest that lies in front of
   * `opaque`'s depth (the opaque G-buffer of the same frame, rendered at the same size) and, for
   * `index` > 0, behind this G-buffer's previous layer (depth peeling: layer `index` - 1 must be
   * the last one rendered). The depth is stored in `opaque`'s mapping (window or logarithmic;
   * an opaque scene from an image has the image's window depth). The colour's alpha is that
   * surface's opacity, 0 where the layer has no surface; the other channels are as for opaque
   * geometry. Channels, precision, resolution and screen transform are this pass's own settings:
   * give them `opaque`'s. Returns false when the layer holds no surface (an occlusion query counts
   * its samples) or nothing could be rendered.
   *
   * When `opaque` has a Controller of several processes (each rendering its own props), this is
   * a collective call: every process gets process 0's opaque depth (at `index` 0), peels its
   * layer behind the whole scene's previous layer, and process 0's layer becomes the nearest
   * surface of all the processes' layers at each pixel (every channel, composited by depth as
   * the channel source's are); the result says whether any process's layer holds a surface.
   */
  bool RenderTranslucentLayer(const vtkRenderState* s, vtkStylizeGBufferPass* opaque, int index);

  /**
   * Whether any visible prop of the render state has translucent polygonal geometry (what
   * RenderTranslucentLayer() renders).
   */
  static bool HasTranslucentGeometry(const vtkRenderState* s);

  ///@{
  /**
   * Whether RenderAfterGeometry() draws the translucent geometry, plain (lit, blended over the
   * composited picture). A style that drew the translucent layers itself turns it off for the
   * frame. A hardware selection (picking) draws them regardless. Default on.
   */
  vtkSetMacro(DrawTranslucent, bool);
  vtkGetMacro(DrawTranslucent, bool);
  ///@}

  ///@{
  /**
   * Whether Render() leaves out the annotations (vtkStylizeStylePass::IsAnnotation(): axes and
   * 3D text), so that a style processing this pass's picture (ParaView's view, each rank's pass)
   * draws them plain over its own (vtkStylizeStylePass::PlainAnnotations). A hardware selection
   * (picking) draws them. Default off.
   */
  vtkSetMacro(LeaveOutAnnotations, bool);
  vtkGetMacro(LeaveOutAnnotations, bool);
  ///@}

  ///@{
  /**
   * Whether Render() leaves out the volumes still in the render state (those a style leaves to
   * VTK: StylizeVolumes off, or STYLIZE_VOLUME 0; the others stand in it as surfaces), so that a
   * style processing this pass's picture draws them over its own, as VTK draws them
   * (ParaView's view; on several processes each one's pieces, composited in visibility order:
   * vtkStylizePlainVolumes). A hardware selection (picking) draws them. Default off.
   */
  vtkSetMacro(LeaveOutVolumes, bool);
  vtkGetMacro(LeaveOutVolumes, bool);
  ///@}

  ///@{
  /** The G-buffer textures of the last frame (nullptr for channels not allocated). */
  vtkGetObjectMacro(ColorTexture, vtkTextureObject);
  vtkGetObjectMacro(NormalTexture, vtkTextureObject);
  vtkGetObjectMacro(PositionTexture, vtkTextureObject);
  vtkGetObjectMacro(LinearDepthTexture, vtkTextureObject);
  vtkGetObjectMacro(DepthTexture, vtkTextureObject);
  vtkGetObjectMacro(DirectionTexture, vtkTextureObject);

  /**
   * The colour the G-buffer clears a flat background to (the renderer's background snapped to
   * the 8-bit level the window shows, alpha 1), for a renderer that erases, is opaque and has
   * neither a gradient nor a textured background; false otherwise (the background is then
   * whatever the G-buffer's colour channel holds).
   */
  static bool GetFlatBackground(vtkRenderer* ren, float rgba[4]);

  /**
   * Bytes the G-buffer's textures hold on the device (channels, depth and, for a scene from an
   * image, the image's colour and depth), for memory reports.
   */
  vtkIdType GetTextureBytes();
  ///@}

  /**
   * Perspective near/far ratio above which the G-buffer stores a logarithmic depth
   * (log(z/near)/log(far/near)) instead of the window depth, so that the depth test keeps its
   * precision at extreme ratios (at 1e7 a window depth has a handful of distinct values across
   * the scene). Screen passes convert it back (stylizeWindowDepth() in vtkStylizeDepthFS.glsl,
   * uniforms from SetDepthMappingUniforms()). Lines drawn over surfaces lose VTK's polygon
   * offset in this mode. Range [1, 1e30], default 1e4.
   */
  vtkSetClampMacro(LogarithmicDepthRatio, double, 1.0, 1.0e30);
  vtkGetMacro(LogarithmicDepthRatio, double);

  /** Whether the last frame stored a logarithmic depth. */
  vtkGetMacro(LogarithmicDepth, bool);

  /** Sets stylizeDepthMapping (see vtkStylizeDepthFS.glsl) for the last frame. */
  void SetDepthMappingUniforms(vtkShaderProgram* program);

  /** Size (width, height) and origin (x, y) in the window of the last frame's viewport. */
  vtkGetVector4Macro(Viewport, int);

  ///@{
  /**
   * Resolution and screen transform of the geometry render, for styles that render the scene
   * at another resolution or shifted by a fraction of a pixel (vtkPixelArtPass):
   * - SetGeometryResolution(w, h): the opaque geometry is rendered into a w x h G-buffer
   *   instead of the viewport's size (0 x 0, the default). CompositeToOutput() then stretches it.
   * - SetGeometryScreenTransform(sx, sy, tx, ty): after the camera's projection (and its user
   *   transform), normalized device coordinates are mapped by x' = sx x + tx, y' = sy y + ty.
   *   Default (1, 1, 0, 0). Scales must be positive and finite; others are ignored.
   * - SetAfterScreenShift(tx, ty): the shift applied to translucent geometry and volumes in
   *   RenderAfterGeometry() (they are drawn at the viewport's resolution), in normalized device
   *   coordinates. Default (0, 0).
   * The camera's user transform is restored after each render.
   */
  void SetGeometryResolution(int w, int h);
  void SetGeometryScreenTransform(double sx, double sy, double tx, double ty);
  void SetAfterScreenShift(double tx, double ty);
  ///@}

  /** Size of the last geometry render: the G-buffer textures' width and height. */
  vtkGetVector2Macro(GeometrySize, int);

  /**
   * The texture of a buffer (Buffers: COLOR_BUFFER, ..., DIRECTION_BUFFER) of the last frame;
   * nullptr when it was not allocated.
   */
  vtkTextureObject* GetBufferTexture(int buffer);

  /** The G-buffer's framebuffer (nullptr before the first frame). */
  vtkGetObjectMacro(FrameBufferObject, vtkOpenGLFramebufferObject);

  /**
   * glReadPixels of a buffer of the last frame inside rect (x, y, width, height), as floats
   * (the components of DownloadChannel()); the context must be current.
   */
  void ReadBuffer(int buffer, const int rect[4], float* out);

  /**
   * Reads a buffer of the last frame back as floats (4 components per pixel for colour, normal,
   * position and direction, 1 for depth and linear depth), rows bottom to top. The window's context
   * must be current, as it is right after a render. Returns false when the channel was not
   * allocated.
   */
  bool DownloadChannel(int buffer, vtkFloatArray* out);

  /** Frees all textures, the framebuffer, the quad and the internal passes' resources. */
  void ReleaseGraphicsResources(vtkWindow* w) override;

  ///@{
  /** vtkOpenGLRenderPass shader hooks: write the requested channels after lighting. */
  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override;
  ///@}

protected:
  vtkStylizeGBufferPass();
  ~vtkStylizeGBufferPass() override;

  friend class vtkStylizeDepthPeeler;
  friend class vtkStylizeGBufferImagePath;

  void AllocateTextures(vtkOpenGLRenderWindow* renWin, int w, int h);
  void FreeTextures(vtkWindow* w);
  /**
   * RenderGeometry()'s steps: the viewport, depth mapping and shader state of the frame (false
   * for an empty viewport); the textures attached to the framebuffer as its draw buffers; the
   * props rendered into it.
   */
  bool BeginFrame(vtkRenderer* ren, int& w, int& h);
  void AttachTextures(int w, int h);
  void RenderProps(const vtkRenderState* s, vtkOpenGLFramebufferObject* fbo);
  /** The G-buffer lines of a fragment shader (PostReplaceShaderValues()). */
  std::string ChannelCode(
    std::string& vertexShader, std::string& geometryShader, std::string& fragmentShader);

  int Channels = 0;
  double LogarithmicDepthRatio = 1.0e4;
  bool LogarithmicDepth = false;
  bool BuiltLogarithmicDepth = false;
  double DepthRange[2] = { 0.0, 1.0 };
  int PositionSpace = VIEW;
  int Precision = HALF;
  int NormalPrecision = HALF;
  int AllocatedPrecision = -1;
  int AllocatedNormalPrecision = -1;
  int Viewport[4] = { 0, 0, 0, 0 };
  int GeometryResolution[2] = { 0, 0 };
  int GeometrySize[2] = { 0, 0 };
  double GeometryScreenTransform[4] = { 1.0, 1.0, 0.0, 0.0 };
  double AfterScreenShift[2] = { 0.0, 0.0 };
  double ImageBackground[3] = { 0.0, 0.0, 0.0 };
  bool UseImageBackground = false;
  bool ImageBackgroundApplied = false;
  unsigned int NumberOfAttachments = 1;
  vtkTimeStamp ShaderStageTime;
  int BuiltChannels = -1;
  int BuiltPositionSpace = -1;

  vtkStylizeLightingPass* LightingPass = nullptr;
  vtkRenderPass* SceneImagePass = nullptr;
  bool SceneFromImage = false; // the last RenderGeometry() used SceneImagePass
  vtkStylizeGBufferPass* ChannelSource = nullptr;
  vtkMultiProcessController* Controller = nullptr;
  bool ChannelSourceUsed = false;
  vtkTypeUInt64 GeometryRenders = 0; // RenderGeometry() calls that rendered geometry
  vtkCameraPass* GeometryCameraPass = nullptr;
  vtkSequencePass* GeometrySequence = nullptr;
  vtkSequencePass* AfterSequence = nullptr;
  vtkSequencePass* VolumeSequence = nullptr; // AfterSequence without the translucent geometry
  bool DrawTranslucent = true;
  bool LeaveOutAnnotations = false;
  bool LeaveOutVolumes = false;
  bool BuiltLayer = false; // the shaders test a translucent layer's depths
  vtkRenderPass* OverlayPass = nullptr;
  vtkSequencePass* AnnotationSequence = nullptr; // opaque and translucent, VTK's lighting
  std::vector<vtkProp*> AfterProps;

  vtkOpenGLFramebufferObject* FrameBufferObject = nullptr;
  vtkTextureObject* ColorTexture = nullptr;
  vtkTextureObject* NormalTexture = nullptr;
  vtkTextureObject* PositionTexture = nullptr;
  vtkTextureObject* LinearDepthTexture = nullptr;
  vtkTextureObject* DepthTexture = nullptr;
  vtkTextureObject* DirectionTexture = nullptr;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;

private:
  vtkStylizeGBufferPass(const vtkStylizeGBufferPass&) = delete;
  void operator=(const vtkStylizeGBufferPass&) = delete;
};

#endif
