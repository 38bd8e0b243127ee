#include "vtkStylizeStylePass.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkCommunicator.h"
#include "vtkFloatArray.h"
#include "vtkMultiProcessController.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeShaderUtilities.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkStylizeCommonFS.h"
#include "vtkStylizeDepthFS.h"
#include "vtkStylizeFieldFS.h"
#include "vtkStylizeScreenFS.h"

#include "vtkMath.h"
#include "vtkMatrix4x4.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <utility>

class vtkStylizeStylePass::vtkInternals
{
public:
  vtkNew<vtkStylizeLightingPass> Lighting;
  vtkNew<vtkStylizeGBufferPass> GBuffer;
  // Translucent layers (RenderTranslucentLayers()): their G-buffer, the scene the stages read
  // (GBuffer, or LayerGBuffer while a layer is stylized), the layer's number (0: opaque), the
  // layers' composite (premultiplied, front to back) and its framebuffer and program.
  vtkNew<vtkStylizeGBufferPass> LayerGBuffer;
  vtkStylizeGBufferPass* Scene = nullptr;
  int Layer = 0;
  vtkTextureObject* LayerTexture = nullptr;
  vtkOpenGLFramebufferObject* LayerFramebuffer = nullptr;
  vtkStylizeScreenQuad LayerQuad;

  // Shader assembly: the style's source, its stages and the last frame's defines.
  std::string StyleSource;
  std::string MainCall;
  std::vector<std::string> StageDefines;
  std::string Defines;
  std::vector<std::string> Declarations; // one per stage
  std::vector<std::unique_ptr<vtkStylizeScreenQuad>> Quads;
  vtkStylizeScreenQuad BackgroundQuad; // the background around the scene's rectangle

  vtkOpenGLRenderWindow* Window = nullptr; // of the frame being rendered
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  std::vector<vtkTextureObject*> Textures; // the style's slots
  bool StageFailed = false;

  // The direction field: its first stage's index (-1: the style has none) and its textures
  // (the raw field's ping-pong pair and the resolved field).
  int FieldStage = -1;
  vtkTextureObject* FieldTextures[3] = { nullptr, nullptr, nullptr };
  int FieldResolved = -1; // index in FieldTextures of the last resolved field

  // The stages' framebuffer and the layers' (a layer's stages bind theirs inside it).
  void FreeFramebuffer(vtkWindow* w)
  {
    for (vtkOpenGLFramebufferObject** fbo : { &this->Framebuffer, &this->LayerFramebuffer })
    {
      if (*fbo)
      {
        if (w)
        {
          (*fbo)->ReleaseGraphicsResources(w);
        }
        (*fbo)->Delete();
        *fbo = nullptr;
      }
    }
  }

  // Makes `fbo` (created on first use) the draw framebuffer, the current bindings saved for
  // RestorePreviousBindingsAndBuffers().
  static vtkOpenGLFramebufferObject* BindFramebuffer(
    vtkOpenGLFramebufferObject*& fbo, vtkOpenGLRenderWindow* window)
  {
    if (!fbo)
    {
      fbo = vtkOpenGLFramebufferObject::New();
      fbo->SetContext(window);
    }
    fbo->SaveCurrentBindingsAndBuffers();
    fbo->Bind();
    return fbo;
  }

  void FreeTextures(vtkWindow* w)
  {
    for (vtkTextureObject*& t : this->Textures)
    {
      vtkStylizeShaderUtilities::FreeTexture(t, w);
    }
    vtkStylizeShaderUtilities::FreeTexture(this->LayerTexture, w);
    this->FreeField(w);
  }

  void FreeField(vtkWindow* w)
  {
    for (vtkTextureObject*& t : this->FieldTextures)
    {
      vtkStylizeShaderUtilities::FreeTexture(t, w);
    }
    this->FieldResolved = -1;
  }

  // Stage timing (StageTimingOn()): the last frame's stages as (name, milliseconds, runs).
  struct StageTime
  {
    std::string Name;
    double Milliseconds = 0.0;
    int Runs = 0;
  };
  bool Timing = false;
  bool Culling = true; // BackgroundCullingOn()

  // This frame's guard band (PlanGuardBand()): the stages' size and the screen transform.
  bool Guarded = false;
  int GuardSize[2] = { 0, 0 };
  double GuardTransform[4] = { 1.0, 1.0, 0.0, 0.0 };
  std::vector<StageTime> Times;
  std::chrono::steady_clock::time_point TimingStart;

  void TimeBegin()
  {
    if (this->Timing)
    {
      glFinish();
      this->TimingStart = std::chrono::steady_clock::now();
    }
  }

  void TimeEnd(const std::string& name) // no copy of the name when timing is off
  {
    if (!this->Timing)
    {
      return;
    }
    glFinish();
    const double ms = std::chrono::duration<double, std::milli>(
      std::chrono::steady_clock::now() - this->TimingStart)
                        .count();
    auto it = std::find_if(this->Times.begin(), this->Times.end(),
      [&](const StageTime& t) { return t.Name == name; });
    if (it == this->Times.end())
    {
      this->Times.push_back(StageTime{ name, 0.0, 0 });
      it = this->Times.end() - 1;
    }
    it->Milliseconds += ms;
    it->Runs++;
  }

  const std::string& StageName(int stage) const
  {
    static const std::string output = "OUTPUT";
    const std::string& d = this->StageDefines[stage];
    return d.empty() ? output : d;
  }

  // Makes stage `stage`'s program current; nullptr (and StageFailed) when it does not build.
  vtkShaderProgram* Prepare(int stage)
  {
    vtkShaderProgram* program =
      this->Quads[stage]->Prepare(this->Window, this->Declarations[stage], this->MainCall);
    this->StageFailed = this->StageFailed || !program;
    return program;
  }
};

//------------------------------------------------------------------------------
vtkStylizeStylePass::vtkStylizeStylePass(int lightingModel, const char* styleSource,
  std::vector<std::string> stageDefines, const char* mainCall, bool directionField)
  : Internals(new vtkInternals)
{
  vtkInternals& in = *this->Internals;
  in.Lighting->SetModel(lightingModel);
  in.GBuffer->SetLightingPass(in.Lighting);
  in.LayerGBuffer->SetLightingPass(in.Lighting);
  in.Scene = in.GBuffer;
  in.StyleSource = styleSource;
  in.MainCall = mainCall;
  in.StageDefines = std::move(stageDefines);
  if (directionField)
  {
    // The field's GLSL before the style's (the style's stages call its camera helpers), its
    // stages after the style's, and main() runs the field's function in those.
    in.StyleSource = std::string(vtkStylizeFieldFS) + in.StyleSource;
    in.MainCall = "#ifdef STYLIZE_FIELD_STAGE\n  stylizeFieldMain();\n#else\n" + in.MainCall +
      "#endif\n";
    in.FieldStage = static_cast<int>(in.StageDefines.size());
    in.StageDefines.insert(in.StageDefines.end(),
      { "FIELD_STAGE_ESTIMATE", "FIELD_STAGE_SMOOTH", "FIELD_STAGE_RESOLVE" });
  }
  in.Declarations.resize(in.StageDefines.size());
  for (size_t i = 0; i < in.StageDefines.size(); ++i)
  {
    in.Quads.emplace_back(new vtkStylizeScreenQuad);
  }
}

//------------------------------------------------------------------------------
vtkStylizeStylePass::~vtkStylizeStylePass()
{
  this->Internals->FreeTextures(nullptr);
  this->Internals->FreeFramebuffer(nullptr);
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scene: "
     << (this->DelegatePass ? "the delegate's image (colour and depth)" : "the geometry") << "\n";
  os << indent << "InteractiveUpdateRate: " << this->InteractiveUpdateRate << "\n";
  os << indent << "WindowScale: " << this->WindowScale[0] << " " << this->WindowScale[1] << "\n";
  os << indent << "BackgroundCulling: " << (this->Internals->Culling ? "on" : "off") << "\n";
  os << indent << "StageTiming: " << (this->Internals->Timing ? "on" : "off") << "\n";
  os << indent << "LightingPass:\n";
  this->Internals->Lighting->PrintSelf(os, indent.GetNextIndent());
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::SetWindowScale(int x, int y)
{
  x = std::max(1, std::min(64, x));
  y = std::max(1, std::min(64, y));
  if (x != this->WindowScale[0] || y != this->WindowScale[1])
  {
    this->WindowScale[0] = x;
    this->WindowScale[1] = y;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkStylizeLightingPass* vtkStylizeStylePass::GetLightingPass()
{
  return this->Internals->Lighting;
}

//------------------------------------------------------------------------------
vtkStylizeGBufferPass* vtkStylizeStylePass::GetGBufferPass()
{
  return this->Internals->GBuffer;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::StageTimingOn()
{
  this->Internals->Timing = true;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::StageTimingOff()
{
  this->Internals->Timing = false;
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::GetStageTiming()
{
  return this->Internals->Timing;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::BackgroundCullingOn()
{
  this->Internals->Culling = true;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::BackgroundCullingOff()
{
  this->Internals->Culling = false;
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::GetBackgroundCulling()
{
  return this->Internals->Culling;
}

//------------------------------------------------------------------------------
vtkIdType vtkStylizeStylePass::GetTextureBytes()
{
  vtkInternals& in = *this->Internals;
  vtkIdType total = in.GBuffer->GetTextureBytes() + in.LayerGBuffer->GetTextureBytes() +
    vtkStylizeShaderUtilities::TextureBytes(in.LayerTexture);
  for (vtkTextureObject* t : in.Textures)
  {
    total += vtkStylizeShaderUtilities::TextureBytes(t);
  }
  for (vtkTextureObject* t : in.FieldTextures)
  {
    total += vtkStylizeShaderUtilities::TextureBytes(t);
  }
  return total;
}

//------------------------------------------------------------------------------
int vtkStylizeStylePass::GetNumberOfTimedStages()
{
  return static_cast<int>(this->Internals->Times.size());
}

//------------------------------------------------------------------------------
const char* vtkStylizeStylePass::GetTimedStageName(int i)
{
  const auto& t = this->Internals->Times;
  return i >= 0 && i < static_cast<int>(t.size()) ? t[i].Name.c_str() : nullptr;
}

//------------------------------------------------------------------------------
double vtkStylizeStylePass::GetTimedStageMilliseconds(int i)
{
  const auto& t = this->Internals->Times;
  return i >= 0 && i < static_cast<int>(t.size()) ? t[i].Milliseconds : 0.0;
}

//------------------------------------------------------------------------------
int vtkStylizeStylePass::GetTimedStageRuns(int i)
{
  const auto& t = this->Internals->Times;
  return i >= 0 && i < static_cast<int>(t.size()) ? t[i].Runs : 0;
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::BeginFrame(const vtkRenderState* s, Frame& frame)
{
  vtkOpenGLClearErrorMacro();
  if (this->Internals->Timing)
  {
    this->Internals->Times.clear();
  }
  this->NumberOfRenderedProps = 0;
  this->Internals->StageFailed = false;
  vtkRenderer* ren = s->GetRenderer();
  frame.Renderer = ren;
  frame.Window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  this->Internals->Window = frame.Window;
  if (!frame.Window)
  {
    return false;
  }
  ren->GetTiledSizeAndOrigin(&frame.Size[0], &frame.Size[1], &frame.Origin[0], &frame.Origin[1]);
  if (frame.Size[0] < 1 || frame.Size[1] < 1)
  {
    this->RenderScene(s, SceneRequest()); // draws the rest of the scene and finishes
    return false;
  }
  const vtkStylizeShaderUtilities::FullImage full =
    vtkStylizeShaderUtilities::GetFullImage(ren, frame.Origin[0], frame.Origin[1]);
  for (int a = 0; a < 2; ++a)
  {
    frame.FullSize[a] = full.Size[a];
    frame.FullOffset[a] = full.Offset[a];
    frame.TileScale[a] = full.TileScale[a] * this->WindowScale[a];
  }
  frame.Camera = ren->GetActiveCamera();
  frame.Parallel = frame.Camera->GetParallelProjection() != 0;
  frame.PixelWorld =
    vtkStylizeShaderUtilities::PixelWorldSize(frame.Camera, frame.Size[0], frame.Size[1]);
  const double rate = frame.Window->GetDesiredUpdateRate();
  frame.Interactive = this->InteractiveUpdateRate > 0.0 && std::isfinite(rate) &&
    rate >= this->InteractiveUpdateRate;
  this->PlanGuardBand(frame);
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::PlanGuardBand(Frame& frame)
{
  vtkInternals& in = *this->Internals;
  in.Guarded = false;
  // A tile's borders inside the full image (an untiled render has none); a scene from an
  // image (IceT's tile) holds nothing beyond the tile.
  const double before[2] = { frame.FullOffset[0], frame.FullOffset[1] };
  const double after[2] = { frame.FullSize[0] - frame.FullOffset[0] - frame.Size[0],
    frame.FullSize[1] - frame.FullOffset[1] - frame.Size[1] };
  const bool tile = before[0] >= 1.0 || before[1] >= 1.0 || after[0] >= 1.0 || after[1] >= 1.0;
  if (this->DelegatePass || !tile)
  {
    return;
  }
  const double reach = this->GetReach(frame);
  if (!(reach > 0.0))
  {
    return;
  }
  const int align = std::max(1, this->GetGuardAlignment(frame));
  // At most this many pixels per side in all (a larger reach leaves a seam possible rather
  // than render textures many times the tile's size).
  constexpr double MaxSize = 8192.0;
  const int band = static_cast<int>(std::ceil(std::min(reach, MaxSize)));
  int guard[4], size[2];
  for (int a = 0; a < 2; ++a)
  {
    // The band stays inside the full image; its lower corner on the alignment grid.
    const long long offset = std::llround(before[a]);
    long long lo = std::min<long long>(band, offset);
    lo = offset - (offset - lo) / align * align;
    const long long hi = std::max(0LL, std::min<long long>(band, std::llround(after[a])));
    const long long total = frame.Size[a] + lo + hi;
    if (total > MaxSize)
    {
      return;
    }
    guard[a] = static_cast<int>(lo);
    guard[a + 2] = static_cast<int>(hi);
    size[a] = static_cast<int>(total);
  }
  for (int a = 0; a < 2; ++a)
  {
    // The viewport's NDC [-1, 1] onto its pixels inside the band.
    const double lo = guard[a], hi = guard[a + 2];
    frame.Guard[a] = guard[a];
    frame.Guard[a + 2] = guard[a + 2];
    frame.GuardTransform[a] = frame.Size[a] / static_cast<double>(size[a]);
    frame.GuardTransform[a + 2] = (lo - hi) / size[a];
    frame.Origin[a] -= frame.Guard[a];
    frame.FullOffset[a] -= frame.Guard[a];
    frame.Size[a] = size[a];
    in.GuardSize[a] = size[a];
  }
  std::copy(frame.GuardTransform, frame.GuardTransform + 4, in.GuardTransform);
  in.Guarded = true;
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::RenderScene(const vtkRenderState* s, const SceneRequest& request)
{
  vtkStylizeGBufferPass* gbuffer = this->Internals->Scene;
  const int layer = this->Internals->Layer;
  if (layer > 0)
  {
    // A translucent layer: the opaque G-buffer's user settings too, and the lighting of the
    // opaque scene (for a scene from an image, the one that lit the processes' own G-buffers).
    vtkStylizeGBufferPass* opaque = this->Internals->GBuffer;
    gbuffer->SetPrecision(opaque->GetPrecision());
    vtkStylizeGBufferPass* source = opaque->GetChannelSource();
    gbuffer->SetLightingPass(this->DelegatePass && source && source->GetLightingPass()
        ? source->GetLightingPass()
        : this->Internals->Lighting.Get());
  }
  else
  {
    gbuffer->SetSceneImagePass(this->DelegatePass);
  }
  gbuffer->SetChannels(request.Channels);
  gbuffer->SetNormalPrecision(request.NormalPrecision);
  if (request.Channels & vtkStylizeGBufferPass::POSITION)
  {
    gbuffer->SetPositionSpace(request.PositionSpace);
  }
  const double* t = request.ScreenTransform;
  vtkInternals& in = *this->Internals;
  if (in.Guarded && request.Resolution[0] <= 0)
  {
    // The guard band: the viewport's geometry, and its neighbours', on the stages' pixels.
    const double* g = in.GuardTransform;
    gbuffer->SetGeometryResolution(in.GuardSize[0], in.GuardSize[1]);
    gbuffer->SetGeometryScreenTransform(
      g[0] * t[0], g[1] * t[1], g[0] * t[2] + g[2], g[1] * t[3] + g[3]);
  }
  else
  {
    gbuffer->SetGeometryResolution(request.Resolution[0], request.Resolution[1]);
    gbuffer->SetGeometryScreenTransform(t[0], t[1], t[2], t[3]);
  }
  gbuffer->SetAfterScreenShift(request.AfterShift[0], request.AfterShift[1]);
  this->Internals->TimeBegin();
  const bool rendered = layer > 0
    ? gbuffer->RenderTranslucentLayer(s, this->Internals->GBuffer, layer - 1)
    : gbuffer->RenderGeometry(s);
  this->Internals->TimeEnd(layer > 0 ? "LAYER_SCENE" : "SCENE");
  if (!rendered && layer == 0)
  {
    this->EndFrame(s);
  }
  return rendered;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::Render(const vtkRenderState* s)
{
  Frame frame;
  if (!this->BeginFrame(s, frame) || !this->RenderStyle(s, frame))
  {
    return; // the frame was ended
  }
  this->RenderTranslucentLayers(s, frame);
  this->EndFrame(s);
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::RenderTranslucentLayers(const vtkRenderState* s, const Frame& frame)
{
  vtkInternals& in = *this->Internals;
  this->LastTranslucentLayers = 0;
  // A scene from an image holds its translucent geometry already, unless the processes' own
  // G-buffers (the channel source: ParaView's per-rank pass) left it out for the style to draw
  // from the props here; a selection renders ids.
  vtkStylizeGBufferPass* source = in.GBuffer->GetChannelSource();
  const bool fromProps = !this->DelegatePass || (source && !source->GetDrawTranslucent());
  bool layers = this->TranslucentLayers > 0 && fromProps && !frame.Renderer->GetSelector();
  int translucent = layers && vtkStylizeGBufferPass::HasTranslucentGeometry(s) ? 1 : 0;
  vtkMultiProcessController* controller = in.GBuffer->GetController();
  if (layers && controller && controller->GetNumberOfProcesses() > 1)
  {
    // Several processes, each with its props: the layers are composited across them (a
    // collective call per layer), so all of them draw layers when any has translucent geometry.
    int local = translucent;
    controller->AllReduce(&local, &translucent, 1, vtkCommunicator::MAX_OP);
  }
  layers = layers && translucent != 0;
  in.GBuffer->SetDrawTranslucent(!layers);
  if (!layers)
  {
    return;
  }
  // The layers are stylized into a texture of the stages' size (the frame's viewport at the
  // origin), composited front to back: each adds what the layers in front let through.
  vtkOpenGLRenderWindow* win = frame.Window;
  vtkOpenGLState* ostate = win->GetState();
  vtkStylizeShaderUtilities::EnsureScreenTexture(
    in.LayerTexture, win, frame.Size[0], frame.Size[1], GL_RGBA16F, false);
  vtkOpenGLFramebufferObject* fbo = vtkInternals::BindFramebuffer(in.LayerFramebuffer, win);
  fbo->AddColorAttachment(0, in.LayerTexture);
  fbo->ActivateDrawBuffers(1);
  {
    vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(ostate, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglClearColor clearColorSaver(ostate);
    ostate->vtkglDisable(GL_SCISSOR_TEST);
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
  }
  Frame layerFrame = frame;
  layerFrame.Origin[0] = 0;
  layerFrame.Origin[1] = 0;
  in.Scene = in.LayerGBuffer;
  for (int layer = 1; layer <= this->TranslucentLayers; ++layer)
  {
    in.Layer = layer;
    if (!this->RenderStyle(s, layerFrame))
    {
      break;
    }
    this->LastTranslucentLayers = layer;
  }
  in.Layer = 0;
  in.Scene = in.GBuffer;
  fbo->RemoveColorAttachments(1);
  fbo->UnBind();
  fbo->RestorePreviousBindingsAndBuffers();
  if (this->LastTranslucentLayers == 0)
  {
    return;
  }

  // The layers over the stylized opaque scene, within the viewport (not its guard band).
  static const std::string layersSource = std::string("#define STYLIZE_STAGE_LAYERS\n") +
    vtkStylizeCommonFS + vtkStylizeDepthFS + vtkStylizeScreenFS;
  vtkShaderProgram* program = in.LayerQuad.Prepare(win, layersSource, "  stylizeLayersMain();\n");
  in.StageFailed = in.StageFailed || !program;
  if (!program)
  {
    return;
  }
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(ostate, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  ostate->vtkglViewport(frame.Origin[0], frame.Origin[1], frame.Size[0], frame.Size[1]);
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  ostate->vtkglScissor(frame.Origin[0] + frame.Guard[0], frame.Origin[1] + frame.Guard[1],
    frame.Size[0] - frame.Guard[0] - frame.Guard[2], frame.Size[1] - frame.Guard[1] - frame.Guard[3]);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  vtkStylizeUniforms u(program);
  u.Texture("stylizeLayersTexture", in.LayerTexture);
  in.TimeBegin();
  in.LayerQuad.Render();
  in.TimeEnd("LAYERS");
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::EndFrame(const vtkRenderState* s)
{
  vtkStylizeGBufferPass* gbuffer = this->Internals->GBuffer;
  this->Internals->TimeBegin();
  gbuffer->RenderAfterGeometry(s);
  this->Internals->TimeEnd("AFTER");
  this->NumberOfRenderedProps = gbuffer->GetNumberOfRenderedProps();
  if (this->Internals->StageFailed)
  {
    vtkErrorMacro("Could not build a " << this->GetClassName() << " shader.");
  }
  vtkOpenGLCheckErrorMacro("failed after " << this->GetClassName() << "::Render");
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::SetShaderDefines(const std::string& defines)
{
  vtkInternals& in = *this->Internals;
  if (defines == in.Defines && !in.Declarations.empty() && !in.Declarations[0].empty())
  {
    return;
  }
  in.Defines = defines;
  const std::string shared = defines + vtkStylizeCommonFS + vtkStylizeDepthFS +
    vtkStylizeScreenFS + in.StyleSource;
  for (size_t i = 0; i < in.StageDefines.size(); ++i)
  {
    const std::string& stage = in.StageDefines[i];
    in.Declarations[i] = stage.empty() ? shared : "#define " + stage + "\n" + shared;
  }
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::AddDefine(std::string& defines, bool on, const std::string& name)
{
  if (on)
  {
    defines += "#define " + name + "\n";
  }
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::RenderStage(int stage,
  std::initializer_list<vtkTextureObject*> targets, int w, int h, const StageUniforms& uniforms,
  int coverage)
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLRenderWindow* renWin = in.Window;
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  vtkOpenGLFramebufferObject* fbo = vtkInternals::BindFramebuffer(in.Framebuffer, renWin);
  unsigned int n = 0;
  for (vtkTextureObject* t : targets)
  {
    fbo->AddColorAttachment(n++, t);
  }
  fbo->ActivateDrawBuffers(n);
  ostate->vtkglViewport(0, 0, w, h);
  ostate->vtkglScissor(0, 0, w, h);
  // Surface-only stages: the targets are cleared to zero, then an early depth test against the
  // G-buffer's depth (the quad at the far plane, GL_GREATER, no depth writes) leaves the
  // background's fragments unshaded. A renderer that shades in blocks (llvmpipe, GPUs) skips a
  // block with no surface pixel instead of running the stage's branches masked.
  vtkTextureObject* depth = in.Scene->GetDepthTexture();
  const bool skipBackground = in.Culling && coverage == SURFACE_PIXELS && depth &&
    static_cast<int>(depth->GetWidth()) == w && static_cast<int>(depth->GetHeight()) == h;
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglClearColor clearColorSaver(ostate);
  GLdouble depthRange[2] = { 0.0, 1.0 };
  in.TimeBegin();
  if (skipBackground)
  {
    ostate->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
    fbo->AddDepthAttachment(depth);
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_GREATER);
    ostate->vtkglDepthMask(GL_FALSE);
    glGetDoublev(GL_DEPTH_RANGE, depthRange);
    glDepthRange(1.0, 1.0);
  }
  vtkShaderProgram* program = in.Prepare(stage);
  if (program)
  {
    vtkStylizeUniforms u(program);
    uniforms(u);
    in.Quads[stage]->Render();
  }
  in.TimeEnd(in.StageName(stage));
  if (skipBackground)
  {
    glDepthRange(depthRange[0], depthRange[1]);
    fbo->RemoveDepthAttachment();
  }
  fbo->RemoveColorAttachments(n);
  fbo->UnBind();
  fbo->RestorePreviousBindingsAndBuffers();
  return program != nullptr;
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::RenderStageToOutput(const Frame& frame, int stage, bool writeDepth,
  const StageUniforms& uniforms, int margin)
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLState* ostate = in.Window->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(ostate, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
  const bool layer = in.Layer > 0;
  if (layer)
  {
    // A translucent layer (premultiplied) under the layers in front of it.
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglBlendFuncSeparate(GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ONE_MINUS_DST_ALPHA, GL_ONE);
  }
  else
  {
    ostate->vtkglDisable(GL_BLEND);
  }
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  // The quad covers the stages' pixels (the guard band included); the scissor keeps the
  // viewport's. `scissor` clips a box of the stages' pixels to the viewport.
  const int* g = frame.Guard;
  const int view[4] = { g[0], g[1], frame.Size[0] - g[2], frame.Size[1] - g[3] };
  auto scissor = [&](int x0, int y0, int x1, int y1) {
    x0 = std::max(x0, view[0]);
    y0 = std::max(y0, view[1]);
    x1 = std::min(x1, view[2]);
    y1 = std::min(y1, view[3]);
    ostate->vtkglScissor(frame.Origin[0] + x0, frame.Origin[1] + y0, std::max(0, x1 - x0),
      std::max(0, y1 - y0));
  };
  ostate->vtkglViewport(frame.Origin[0], frame.Origin[1], frame.Size[0], frame.Size[1]);
  scissor(view[0], view[1], view[2], view[3]);
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  ostate->vtkglDepthMask(GL_TRUE);
  if (writeDepth)
  {
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_ALWAYS);
  }
  else
  {
    ostate->vtkglClearDepth(1.0);
    ostate->vtkglClear(GL_DEPTH_BUFFER_BIT);
    ostate->vtkglDisable(GL_DEPTH_TEST);
  }

  // Outside the scene's rectangle the background program writes the background (four strips
  // around it); the stage runs inside it only.
  int rect[4] = { 0, 0, frame.Size[0], frame.Size[1] };
  const bool split = in.Culling && writeDepth && margin >= 0 && this->SceneRectangle(frame, margin, rect);
  if (split)
  {
    in.TimeBegin();
    const int strips[4][4] = { { 0, 0, frame.Size[0], rect[1] },
      { 0, rect[3], frame.Size[0], frame.Size[1] }, { 0, rect[1], rect[0], rect[3] },
      { rect[2], rect[1], frame.Size[0], rect[3] } };
    // The background as the stage would write it: nothing in a layered renderer (discarded), a
    // clear for a flat one (its snapped colour, alpha 1, the far plane), else the program.
    float flat[4];
    // (a translucent layer adds nothing there either)
    const bool layered = frame.Renderer->Transparent() != 0 || layer;
    const bool clear = !layered && vtkStylizeGBufferPass::GetFlatBackground(frame.Renderer, flat);
    vtkShaderProgram* background = nullptr;
    if (!layered && !clear)
    {
      static const std::string source = std::string("#define STYLIZE_STAGE_BACKGROUND\n") +
        vtkStylizeCommonFS + vtkStylizeDepthFS + vtkStylizeScreenFS; // assembled once
      background = in.BackgroundQuad.Prepare(in.Window, source, "  stylizeBackgroundMain();\n");
      in.StageFailed = in.StageFailed || !background;
    }
    vtkOpenGLState::ScopedglClearColor clearColorSaver(ostate);
    vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
    std::unique_ptr<vtkStylizeUniforms> u;
    if (background)
    {
      u.reset(new vtkStylizeUniforms(background));
      this->BindSceneTextures(*u);
      this->SetSceneOutputUniforms(*u, frame.Renderer);
    }
    if (clear)
    {
      ostate->vtkglClearColor(flat[0], flat[1], flat[2], flat[3]);
      ostate->vtkglClearDepth(1.0);
    }
    for (const auto& b : strips)
    {
      if (layered || b[2] <= b[0] || b[3] <= b[1])
      {
        continue;
      }
      scissor(b[0], b[1], b[2], b[3]);
      if (clear)
      {
        ostate->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      }
      else if (background)
      {
        in.BackgroundQuad.Render();
      }
    }
    u.reset(); // releases the texture units
    in.TimeEnd("BACKGROUND");
    if (rect[2] <= rect[0] || rect[3] <= rect[1])
    {
      return layered || clear || background; // nothing of the scene is in view
    }
    scissor(rect[0], rect[1], rect[2], rect[3]);
  }
  vtkShaderProgram* program = in.Prepare(stage);
  if (program)
  {
    vtkStylizeUniforms u(program);
    uniforms(u);
    in.TimeBegin();
    in.Quads[stage]->Render();
    in.TimeEnd(in.StageName(stage));
  }
  return program != nullptr;
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::SceneRectangle(const Frame& frame, int margin, int rect[4])
{
  // A scene from an image (IceT's composited picture) holds more than the local props.
  if (this->Internals->GBuffer->GetSceneFromImage() || !frame.Camera)
  {
    return false;
  }
  double b[6];
  frame.Renderer->ComputeVisiblePropBounds(b);
  if (!vtkMath::AreBoundsInitialized(b) ||
    !std::all_of(b, b + 6, [](double v) { return std::isfinite(v); }))
  {
    return false;
  }
  // Points and lines reach half their size beyond their vertices.
  double extent = 0.0;
  vtkActorCollection* actors = frame.Renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    if (actor->GetVisibility() && actor->GetProperty())
    {
      extent = std::max(extent,
        static_cast<double>(
          std::max(actor->GetProperty()->GetPointSize(), actor->GetProperty()->GetLineWidth())));
    }
  }
  const double pad = margin + 2.0 +
    std::ceil(extent * std::max(frame.TileScale[0], frame.TileScale[1]));
  vtkMatrix4x4* m = frame.Camera->GetCompositeProjectionTransformMatrix(
    frame.Renderer->GetTiledAspectRatio(), -1.0, 1.0);
  double lo[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX }, hi[2] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (int corner = 0; corner < 8; ++corner)
  {
    const double x[4] = { b[corner & 1], b[2 + ((corner >> 1) & 1)], b[4 + ((corner >> 2) & 1)],
      1.0 };
    double c[4];
    m->MultiplyPoint(x, c);
    if (!(c[3] > 1e-6 * (std::abs(c[0]) + std::abs(c[1]) + std::abs(c[2]))) ||
      !std::isfinite(c[3]))
    {
      return false; // a corner behind the eye: the projection does not bound the scene
    }
    for (int a = 0; a < 2; ++a)
    {
      const double ndc = frame.GuardTransform[a] * c[a] / c[3] + frame.GuardTransform[a + 2];
      const double pixel = (ndc + 1.0) * 0.5 * frame.Size[a];
      lo[a] = std::min(lo[a], pixel);
      hi[a] = std::max(hi[a], pixel);
    }
  }
  for (int a = 0; a < 2; ++a)
  {
    const double l = std::floor(lo[a] - pad), h = std::ceil(hi[a] + pad);
    if (!std::isfinite(l) || !std::isfinite(h))
    {
      return false;
    }
    rect[a] = static_cast<int>(std::max(0.0, std::min(l, static_cast<double>(frame.Size[a]))));
    rect[a + 2] =
      static_cast<int>(std::max(0.0, std::min(h, static_cast<double>(frame.Size[a]))));
  }
  // Worth it only when the rectangle leaves a part of the viewport out.
  return rect[0] > 0 || rect[1] > 0 || rect[2] < frame.Size[0] || rect[3] < frame.Size[1];
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::BindSceneTextures(vtkStylizeUniforms& u)
{
  vtkStylizeGBufferPass* g = this->Internals->Scene;
  u.Texture("stylizeColorTexture", g->GetColorTexture())
    .Texture("stylizeDepthTexture", g->GetDepthTexture())
    .Texture("stylizeLinearDepthTexture", g->GetLinearDepthTexture())
    .Texture("stylizeNormalTexture", g->GetNormalTexture())
    .Texture("stylizePositionTexture", g->GetPositionTexture())
    .Texture("stylizeDirectionTexture", g->GetDirectionTexture());
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::SetSceneOutputUniforms(vtkStylizeUniforms& u, vtkRenderer* ren)
{
  vtkStylizeGBufferPass* gbuffer = this->Internals->Scene;
  const double* bg = gbuffer->GetImageBackground();
  const bool layer = this->Internals->Layer > 0;
  u.Int("stylizeDiscardBackground", ren->Transparent() || layer ? 1 : 0)
    .Int("stylizeTranslucentLayer", layer ? 1 : 0)
    .Int("stylizeSceneFromImage", gbuffer->GetSceneFromImage() ? 1 : 0)
    .Float4("stylizeImageBackground", bg[0], bg[1], bg[2], gbuffer->GetImageBackgroundApplied() ? 1 : 0)
    .Float3("stylizeRendererBackground", ren->GetBackground()[0], ren->GetBackground()[1],
      ren->GetBackground()[2]);
  this->SetDepthMappingUniforms(u);
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::SetDepthMappingUniforms(vtkStylizeUniforms& u)
{
  this->Internals->Scene->SetDepthMappingUniforms(u.GetProgram());
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkStylizeStylePass::GetSceneTexture(int buffer)
{
  vtkStylizeGBufferPass* g = this->Internals->Scene;
  switch (buffer)
  {
    case vtkStylizeGBufferPass::COLOR_BUFFER:
      return g->GetColorTexture();
    case vtkStylizeGBufferPass::NORMAL_BUFFER:
      return g->GetNormalTexture();
    case vtkStylizeGBufferPass::POSITION_BUFFER:
      return g->GetPositionTexture();
    case vtkStylizeGBufferPass::DEPTH_BUFFER:
      return g->GetDepthTexture();
    case vtkStylizeGBufferPass::LINEAR_DEPTH_BUFFER:
      return g->GetLinearDepthTexture();
    case vtkStylizeGBufferPass::DIRECTION_BUFFER:
      return g->GetDirectionTexture();
    default:
      return nullptr;
  }
}

//------------------------------------------------------------------------------
vtkTextureObject*& vtkStylizeStylePass::TextureSlot(int slot)
{
  std::vector<vtkTextureObject*>& t = this->Internals->Textures;
  if (slot >= static_cast<int>(t.size()))
  {
    t.resize(slot + 1, nullptr);
  }
  return t[slot];
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkStylizeStylePass::EnsureTexture(int slot, int w, int h, int internalFormat)
{
  vtkTextureObject*& tex = this->TextureSlot(slot);
  vtkStylizeShaderUtilities::EnsureScreenTexture(tex, this->Internals->Window, w, h, internalFormat);
  return tex;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::FreeTexture(int slot)
{
  vtkStylizeShaderUtilities::FreeTexture(this->TextureSlot(slot), this->Internals->Window);
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::DownloadTexture(vtkTextureObject* tex, vtkFloatArray* out)
{
  vtkOpenGLFramebufferObject* fbo = this->Internals->Framebuffer;
  if (!tex || !out || !fbo)
  {
    return false;
  }
  const int w = static_cast<int>(tex->GetWidth());
  const int h = static_cast<int>(tex->GetHeight());
  out->SetNumberOfComponents(4);
  out->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  fbo->SaveCurrentBindingsAndBuffers(GL_READ_FRAMEBUFFER);
  fbo->Bind(GL_READ_FRAMEBUFFER);
  fbo->AddColorAttachment(0, tex);
  fbo->GetContext()->GetState()->vtkglReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, out->GetPointer(0));
  fbo->RemoveColorAttachments(1);
  fbo->UnBind(GL_READ_FRAMEBUFFER);
  fbo->RestorePreviousBindingsAndBuffers(GL_READ_FRAMEBUFFER);
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  vtkInternals& in = *this->Internals;
  in.BackgroundQuad.Release(w);
  for (auto& quad : in.Quads)
  {
    quad->Release(w);
  }
  in.FreeTextures(w);
  in.FreeFramebuffer(w);
  in.LayerQuad.Release(w);
  in.GBuffer->ReleaseGraphicsResources(w);
  in.LayerGBuffer->ReleaseGraphicsResources(w);
  this->ReleaseStyleResources(w);
}

//------------------------------------------------------------------------------
std::string vtkStylizeStylePass::FieldDefines(const FieldSettings& s)
{
  std::string defines;
  AddDefine(defines, true, "FIELD_NEIGHBORS " + std::to_string(s.Neighbors));
  AddDefine(defines, s.Model, "FIELD_MODEL");
  AddDefine(defines, true, "FIELD_DIRECTION " + std::to_string(s.Direction));
  return defines;
}

//------------------------------------------------------------------------------
double vtkStylizeStylePass::FocalPixelWorld(const Frame& frame)
{
  const double focal =
    frame.Parallel ? frame.PixelWorld : frame.PixelWorld * frame.Camera->GetDistance();
  return focal > 0.0 && std::isfinite(focal) ? focal : 1.0;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::SetFieldUniforms(vtkStylizeUniforms& u, const Frame& frame)
{
  // The projection onto the stages' pixels: the guard band's screen transform after the
  // camera's (row a becomes s_a row a + t_a row 3). (Not GetProjectionTransformMatrix(ren),
  // which returns a new matrix, transposed: a tile's off-centre terms were read as zero.)
  vtkMatrix4x4* projection = frame.Camera->GetProjectionTransformMatrix(
    frame.Renderer->GetTiledAspectRatio(), -1.0, 1.0);
  auto element = [&](int row, int column) {
    return frame.GuardTransform[row] * projection->GetElement(row, column) +
      frame.GuardTransform[row + 2] * projection->GetElement(3, column);
  };
  this->BindSceneTextures(u);
  u.Int2("fieldSize", frame.Size[0], frame.Size[1])
    .Float2("fieldPixelOffset", frame.FullOffset[0], frame.FullOffset[1])
    .Int("fieldParallel", frame.Parallel ? 1 : 0)
    .Float("fieldPixelWorld", frame.PixelWorld)
    .Float4("fieldProjection", element(0, 0), element(1, 1), element(0, 2), element(1, 2))
    .Float2("fieldProjOffset", element(0, 3), element(1, 3));
  this->SetDepthMappingUniforms(u);
}

//------------------------------------------------------------------------------
struct vtkStylizeStylePass::FieldPlan
{
  double SpacingWorld = 0.0; // the estimate's neighbour spacing, world units
  int MaxStride = 1;         // the estimate's largest neighbour distance, pixels
  int GradientStride = 1;    // the lighting-gradient fallback's tap distance, pixels
  // The smoothing and fill passes: tap distance (pixels), fill only.
  std::vector<std::pair<int, int>> Iterations;
};

//------------------------------------------------------------------------------
vtkStylizeStylePass::FieldPlan vtkStylizeStylePass::PlanField(
  const Frame& frame, const FieldSettings& s, double pointSize)
{
  FieldPlan plan;
  const double focalPixel = FocalPixelWorld(frame);

  // The estimate's neighbour spacing in world units: NeighborSpacing points at the focal
  // distance, at least ObjectScale times the scene's diagonal; the smoothing radius grows by the
  // same factor (at most 256 points).
  double spacingWorld = s.NeighborSpacing * pointSize * focalPixel;
  double scale = 1.0;
  if (s.ObjectScale > 0.0 && spacingWorld > 0.0)
  {
    auto valid = [](const double* b) {
      return std::all_of(b, b + 6, [](double v) { return std::isfinite(v); }) && b[0] <= b[1] &&
        b[2] <= b[3] && b[4] <= b[5];
    };
    double b[6];
    std::copy(s.SceneBounds, s.SceneBounds + 6, b);
    if (!valid(b))
    {
      frame.Renderer->ComputeVisiblePropBounds(b);
    }
    if (valid(b))
    {
      const double diagonal =
        std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
          (b[5] - b[4]) * (b[5] - b[4]));
      const double object = s.ObjectScale * diagonal;
      if (std::isfinite(object) && object > spacingWorld)
      {
        scale = object / spacingWorld;
        spacingWorld = object;
      }
    }
  }
  plan.SpacingWorld = spacingWorld;
  const double smoothingRadius = std::min(s.SmoothingRadius * scale, 256.0) * pointSize;
  plan.MaxStride = std::max(1, static_cast<int>(std::lround(s.MaxStride * pointSize)));
  plan.GradientStride = std::max(1, static_cast<int>(std::lround(2.0 * pointSize)));
  const double fillRadius = s.FillRadius > 0.0 ? std::max(1.0, s.FillRadius * pointSize) : -1.0;

  // Smoothing (all pixels, 3x3 at tap distances 1, 2, 4, ... points up to the smoothing
  // radius, then at distance 1 pixel), then filling (undefined pixels, distances 1, 2, 4, ...).
  // The taps are in points (at least a pixel), so that a magnified image is smoothed over the
  // same part of the picture.
  // A smoothing pass fills undefined pixels as it smooths (they take their neighbours'
  // directions), so the fill iterations start beyond the pyramid's largest tap distance: the
  // ones below it would repeat it (fill-only passes at those distances changed at most 0.1% of
  // the directions on the real-data meshes, and cost as much as a smoothing pass).
  int pyramid = 0;
  for (double pt = 1.0; pt <= smoothingRadius / pointSize; pt *= 2.0)
  {
    pyramid = std::max(1, static_cast<int>(std::lround(pt * pointSize)));
    plan.Iterations.emplace_back(pyramid, 0);
  }
  for (int i = 0; i < s.SmoothingIterations; ++i)
  {
    plan.Iterations.emplace_back(1, 0);
  }
  for (int r = 1; fillRadius > 0.0 && r <= fillRadius; r *= 2)
  {
    if (r > pyramid)
    {
      plan.Iterations.emplace_back(r, 1);
    }
  }
  return plan;
}

//------------------------------------------------------------------------------
double vtkStylizeStylePass::FieldReach(
  const Frame& frame, const FieldSettings& s, double pointSize)
{
  const FieldPlan plan = PlanField(frame, s, pointSize);
  double reach = plan.MaxStride + plan.GradientStride;
  for (const auto& it : plan.Iterations)
  {
    reach += it.first;
  }
  return reach;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkStylizeStylePass::RenderDirectionField(
  const Frame& frame, const FieldSettings& s, double pointSize)
{
  vtkInternals& in = *this->Internals;
  if (in.FieldStage < 0)
  {
    return nullptr;
  }
  const int w = frame.Size[0], h = frame.Size[1];
  const FieldPlan plan = PlanField(frame, s, pointSize);
  const double fallback = vtkMath::RadiansFromDegrees(s.FallbackAngle);

  // Every stage computes only the surface's pixels (SURFACE_PIXELS): the background is zero,
  // "no direction", in every texture of the field.
  // 1. Raw directions.
  vtkTextureObject*& raw0 = in.FieldTextures[0];
  vtkStylizeShaderUtilities::EnsureScreenTexture(raw0, in.Window, w, h, GL_RGBA16F);
  this->RenderStage(in.FieldStage, { raw0 }, w, h, [&](vtkStylizeUniforms& u) {
    this->SetFieldUniforms(u, frame);
    u.Float("fieldSpacing", plan.SpacingWorld)
      .Int("fieldMaxStride", plan.MaxStride)
      .Float("fieldPlanar", s.PlanarTolerance)
      .Float("fieldUmbilic", s.UmbilicTolerance);
  }, SURFACE_PIXELS);

  // 2. Smoothing and filling (PlanField()).
  const std::vector<std::pair<int, int>>& iterations = plan.Iterations;
  int current = 0;
  if (iterations.empty())
  {
    vtkStylizeShaderUtilities::FreeTexture(in.FieldTextures[1], in.Window);
  }
  else
  {
    vtkStylizeShaderUtilities::EnsureScreenTexture(
      in.FieldTextures[1], in.Window, w, h, GL_RGBA16F);
  }
  for (const auto& it : iterations)
  {
    const int next = 1 - current;
    this->RenderStage(in.FieldStage + 1, { in.FieldTextures[next] }, w, h,
      [&](vtkStylizeUniforms& u) {
        this->SetFieldUniforms(u, frame);
        u.Texture("fieldInput", in.FieldTextures[current])
          .Int("fieldRadius", it.first)
          .Int("fieldFillOnly", it.second);
      },
      SURFACE_PIXELS);
    current = next;
  }

  // 3. Fallbacks and the requested direction.
  vtkTextureObject*& resolved = in.FieldTextures[2];
  vtkStylizeShaderUtilities::EnsureScreenTexture(resolved, in.Window, w, h, GL_RGBA32F);
  this->RenderStage(in.FieldStage + 2, { resolved }, w, h, [&](vtkStylizeUniforms& u) {
    this->SetFieldUniforms(u, frame);
    u.Texture("fieldInput", in.FieldTextures[current])
      .Int("fieldGradientStride", plan.GradientStride)
      .Float2("fieldScreenDirection", std::cos(fallback), std::sin(fallback));
  }, SURFACE_PIXELS);
  in.FieldResolved = 2;
  return resolved;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkStylizeStylePass::GetDirectionFieldTexture()
{
  vtkInternals& in = *this->Internals;
  return in.FieldResolved >= 0 ? in.FieldTextures[in.FieldResolved] : nullptr;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::FreeDirectionField()
{
  this->Internals->FreeField(this->Internals->Window);
}
