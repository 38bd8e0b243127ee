#include "vtkStylizeStylePass.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommunicator.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeShaderUtilities.h"
#include "vtkStylizeStageRunner.h"
#include "vtkStylizeStylePassInternals.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkStylizeCommonFS.h"
#include "vtkStylizeDepthFS.h"
#include "vtkStylizeScreenFS.h"

#include "vtkMatrix4x4.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

vtkInformationKeyMacro(vtkStylizeStylePass, STYLIZE_VOLUME, Integer);
vtkInformationKeyMacro(vtkStylizeStylePass, VOLUME_OPACITY_THRESHOLD, Double);

//------------------------------------------------------------------------------
vtkStylizeStylePass::vtkStylizeStylePass(int lightingModel)
  : Internals(new vtkInternals)
{
  vtkInternals& in = *this->Internals;
  in.Lighting->SetModel(lightingModel);
  in.GBuffer->SetLightingPass(in.Lighting);
  in.LayerGBuffer->SetLightingPass(in.Lighting);
  in.Scene = in.GBuffer;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::ForwardProgress(vtkObject* source)
{
  vtkNew<vtkCallbackCommand> forward;
  forward->SetClientData(this);
  forward->SetCallback([](vtkObject*, unsigned long, void* self, void* data)
    { static_cast<vtkStylizeStylePass*>(self)->InvokeEvent(vtkCommand::ProgressEvent, data); });
  source->AddObserver(vtkCommand::ProgressEvent, forward);
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::SetStages(const std::string& source, const std::string& mainCall,
  const std::vector<vtkStylizeStage>& stages)
{
  std::vector<std::string> defines, names;
  for (size_t i = 0; i < stages.size(); ++i)
  {
    if (stages[i].Index != static_cast<int>(i))
    {
      vtkErrorMacro("Stage " << i << " of " << this->GetClassName() << " is out of order.");
    }
    defines.emplace_back(stages[i].Define);
    names.emplace_back(stages[i].Name);
  }
  this->Internals->Runner->SetStages(source, mainCall, defines, names);
}

//------------------------------------------------------------------------------
vtkStylizeStylePass::~vtkStylizeStylePass()
{
  this->Internals->FreeTextures(nullptr);
  vtkStylizeStageRunner::FreeFramebuffer(this->Internals->LayerFramebuffer, nullptr);
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scene: "
     << (this->DelegatePass ? "the delegate's image (colour and depth)" : "the geometry") << "\n";
  os << indent << "InteractiveUpdateRate: " << this->InteractiveUpdateRate << "\n";
  os << indent << "InteractiveImageReduction: " << this->InteractiveImageReduction << "\n";
  os << indent << "WindowScale: " << this->WindowScale[0] << " " << this->WindowScale[1] << "\n";
  os << indent << "IsoLines: " << this->IsoLines << " (width " << this->IsoLineWidth
     << " pt, spacing " << this->IsoLineSpacing << ")\n";
  os << indent << "BackgroundCulling: " << (this->Internals->Culling ? "on" : "off") << "\n";
  os << indent << "StageTiming: " << (this->Internals->Runner->Timing ? "on" : "off") << "\n";
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
void vtkStylizeStylePass::ConfigureLightingColors(vtkStylizeLightingPass* lighting)
{
  lighting->SetColorMode(vtkStylizeLightingPass::LIT_COLORS);
  lighting->SetSolidColorTones(false);
}

//------------------------------------------------------------------------------
int vtkStylizeStylePass::ColorModeForTint(int tint)
{
  return tint == ALL_COLORS ? vtkStylizeLightingPass::ALL_HUES
                            : (tint == DATA_COLORS ? vtkStylizeLightingPass::DATA_HUES
                                                   : vtkStylizeLightingPass::LIGHT_TONE);
}

//------------------------------------------------------------------------------
vtkStylizeGBufferPass* vtkStylizeStylePass::GetGBufferPass()
{
  return this->Internals->GBuffer;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::StageTimingOn()
{
  this->Internals->Runner->Timing = true;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::StageTimingOff()
{
  this->Internals->Runner->Timing = false;
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::GetStageTiming()
{
  return this->Internals->Runner->Timing;
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
    vtkStylizeShaderUtilities::TextureBytes(in.LayerTexture) + in.Reduced.GetTextureBytes();
  for (vtkTextureObject* t : in.Textures)
  {
    total += vtkStylizeShaderUtilities::TextureBytes(t);
  }
  return total + this->GetStyleTextureBytes();
}

//------------------------------------------------------------------------------
int vtkStylizeStylePass::GetNumberOfTimedStages()
{
  return this->Internals->Runner->GetNumberOfTimedStages();
}

//------------------------------------------------------------------------------
const char* vtkStylizeStylePass::GetTimedStageName(int i)
{
  return this->Internals->Runner->GetTimedStageName(i);
}

//------------------------------------------------------------------------------
double vtkStylizeStylePass::GetTimedStageMilliseconds(int i)
{
  return this->Internals->Runner->GetTimedStageMilliseconds(i);
}

//------------------------------------------------------------------------------
int vtkStylizeStylePass::GetTimedStageRuns(int i)
{
  return this->Internals->Runner->GetTimedStageRuns(i);
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::AnchorPatternsToSurface(bool keepNoise)
{
  if (this->PatternsAnchored)
  {
    this->RestoreAnchors(); // the settings saved first stay the ones to restore
  }
  this->AnchorToSurface(keepNoise);
  this->PatternsAnchored = true;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::RestorePatternAnchors()
{
  if (this->PatternsAnchored)
  {
    this->RestoreAnchors();
    this->PatternsAnchored = false;
  }
}

//------------------------------------------------------------------------------
vtkStylizeGBufferPass* vtkStylizeStylePass::GetSceneGBufferPass()
{
  return this->Internals->Scene;
}

//------------------------------------------------------------------------------
int vtkStylizeStylePass::GetTranslucentLayer() const
{
  return this->Internals->Layer;
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::GetTranslucentLayerEmitted() const
{
  return this->Internals->Layer > 0 && this->Internals->EmittedLayers;
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::EmittedLayers(const vtkRenderState* s)
{
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
    if (prop && prop->GetVisibility() && prop->HasTranslucentPolygonalGeometry() &&
      !(keys && keys->Has(vtkStylizeLightingPass::EMITTED_COLORS()) &&
        keys->Get(vtkStylizeLightingPass::EMITTED_COLORS()) >= 0.5))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::SetClampedColor(double target[3], double r, double g, double b)
{
  const double in[3] = { r, g, b };
  bool changed = false;
  for (int i = 0; i < 3; ++i)
  {
    const double v = std::isfinite(in[i]) ? std::min(1.0, std::max(0.0, in[i])) : target[i];
    changed = changed || v != target[i];
    target[i] = v;
  }
  return changed;
}

//------------------------------------------------------------------------------
double vtkStylizeStylePass::GetPixelsPerPoint(int height, int tiles)
{
  const double reference = this->GetPointReferenceHeight();
  return reference > 0.0 ? std::max(1, height) / reference
                         : std::max(1, tiles) * static_cast<double>(this->WindowScale[1]);
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::RenderScene(const vtkRenderState* s, const SceneRequest& request)
{
  vtkStylizeGBufferPass* gbuffer = this->Internals->Scene;
  const int layer = this->Internals->Layer;
  this->ConfigureLightingColors(this->Internals->Lighting);
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
  this->Internals->Runner->TimeBegin();
  const bool rendered = layer > 0
    ? gbuffer->RenderTranslucentLayer(s, this->Internals->GBuffer, layer - 1)
    : gbuffer->RenderGeometry(s);
  this->Internals->Runner->TimeEnd(layer > 0 ? "LAYER_SCENE" : "SCENE");
  if (!rendered && layer == 0)
  {
    this->EndFrame(s);
  }
  return rendered;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::Render(const vtkRenderState* original)
{
  // Volumes drawn in the style stand in the state (and the renderer's props) as surfaces.
  vtkStylizeVolumeSurfaces& volumes = this->Internals->Volumes;
  const double threshold =
    std::isfinite(this->VolumeOpacityThreshold) ? this->VolumeOpacityThreshold : 0.1;
  // (behind a compositor, ParaView's, the state reaches each rank's G-buffer pass: each rank
  // draws the surfaces of its volumes' pieces; a solid surface stores the depth where it looks
  // solid when the G-buffer draws the props, or its channel source does and hands over their own
  // linear depth)
  vtkStylizeGBufferPass* gbuffer = this->Internals->GBuffer;
  const bool solidDepth = !gbuffer->GetSceneImagePass() || gbuffer->GetChannelSource();
  const vtkRenderState* s = this->StylizeVolumes && !original->GetRenderer()->GetSelector()
    ? volumes.Begin(original, threshold, std::isfinite(this->VolumeHaze) ? this->VolumeHaze : 0.0,
        this->VolumeHazeMode == HAZE_FOG, gbuffer->GetController(),
        this->GetVolumeOutlineWidth(original->GetRenderer()), solidDepth)
    : original;
  s = this->SeparateAnnotations(s);
  Frame frame;
  if (this->BeginFrame(s, frame) && this->RenderStyle(s, frame))
  {
    this->RenderTranslucentLayers(s, frame);
    this->EndFrame(s);
  }
  vtkInternals& in = *this->Internals;
  in.GBuffer->SetAfterProps({});
  in.Annotations.clear();
  in.SceneState.reset();
  volumes.End();
}

//------------------------------------------------------------------------------
const vtkRenderState* vtkStylizeStylePass::SeparateAnnotations(const vtkRenderState* s)
{
  vtkInternals& in = *this->Internals;
  in.Annotations.clear();
  in.SceneProps.clear();
  // (behind a compositor: when the processes' own G-buffer pass left them out of its picture,
  // ParaView's view on one process)
  vtkStylizeGBufferPass* source = in.GBuffer->GetChannelSource();
  const bool plain =
    this->PlainAnnotations && (!this->DelegatePass || (source && source->GetLeaveOutAnnotations()));
  // (the volumes left to VTK that the channel source left out of its picture: drawn over the
  // style's, as VTK draws them when the style renders the geometry itself)
  const bool volumes = source && source->GetLeaveOutVolumes();
  if ((plain || volumes) && !s->GetRenderer()->GetSelector())
  {
    for (int i = 0; i < s->GetPropArrayCount(); ++i)
    {
      vtkProp* prop = s->GetPropArray()[i];
      const bool after =
        (plain && IsAnnotation(prop)) || (volumes && prop && prop->IsA("vtkVolume"));
      (after ? in.Annotations : in.SceneProps).push_back(prop);
    }
  }
  in.GBuffer->SetAfterProps(in.Annotations);
  if (in.Annotations.empty())
  {
    return s;
  }
  in.SceneState.reset(new vtkRenderState(s->GetRenderer()));
  in.SceneState->SetPropArrayAndCount(in.SceneProps.data(), static_cast<int>(in.SceneProps.size()));
  in.SceneState->SetFrameBuffer(s->GetFrameBuffer());
  in.SceneState->SetRequiredKeys(s->GetRequiredKeys());
  return in.SceneState.get();
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::IsAnnotation(vtkProp* prop)
{
  static const char* const classes[] = { "vtkCubeAxesActor", "vtkPolarAxesActor",
    "vtkGridAxesActor3D", "vtkGridAxesActor2D", "vtkGridAxes3DActor", "vtkGridAxes2DActor",
    "vtkAxesActor", "vtkAxisActor", "vtkTextActor3D", "vtkBillboardTextActor3D", "vtkAxisFollower",
    "vtkProp3DAxisFollower" };
  for (const char* name : classes)
  {
    if (prop && prop->IsA(name))
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::HasPlainAnnotations()
{
  return !this->Internals->Annotations.empty();
}

//------------------------------------------------------------------------------
int vtkStylizeStylePass::GetNumberOfVolumeSurfaces()
{
  return this->StylizeVolumes ? this->Internals->Volumes.GetNumberOfSurfaces() : 0;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::AddVolumeSurfaces(vtkRenderer* ren)
{
  if (this->StylizeVolumes)
  {
    this->Internals->Volumes.AddToRenderer(ren);
  }
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::RemoveVolumeSurfaces()
{
  this->Internals->Volumes.End();
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
  int surfaces = layers && !EmittedLayers(s) ? 1 : 0; // (a translucent prop with a surface)
  vtkMultiProcessController* controller = in.GBuffer->GetController();
  if (layers && controller && controller->GetNumberOfProcesses() > 1)
  {
    // Several processes, each with its props: the layers are composited across them (a
    // collective call per layer), so all of them draw layers when any has translucent geometry.
    int local[2] = { translucent, surfaces }, all[2];
    controller->AllReduce(local, all, 2, vtkCommunicator::MAX_OP);
    translucent = all[0];
    surfaces = all[1];
  }
  layers = layers && translucent != 0;
  in.EmittedLayers = surfaces == 0;
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
  vtkOpenGLFramebufferObject* fbo =
    vtkStylizeStageRunner::BindFramebuffer(in.LayerFramebuffer, win);
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
  in.Runner->NoteFailure(!program);
  if (!program)
  {
    return;
  }
  vtkStylizeScopedOutputState saved(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  ostate->vtkglViewport(frame.Origin[0], frame.Origin[1], frame.Size[0], frame.Size[1]);
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  ostate->vtkglScissor(frame.Origin[0] + frame.Guard[0], frame.Origin[1] + frame.Guard[1],
    frame.Size[0] - frame.Guard[0] - frame.Guard[2],
    frame.Size[1] - frame.Guard[1] - frame.Guard[3]);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  vtkStylizeUniforms u(program);
  u.Texture("stylizeLayersTexture", in.LayerTexture);
  in.Runner->TimeBegin();
  in.LayerQuad.Render();
  in.Runner->TimeEnd("LAYERS");
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::EndFrame(const vtkRenderState* s)
{
  vtkStylizeGBufferPass* gbuffer = this->Internals->GBuffer;
  if (this->Internals->Reduced.IsActive())
  {
    this->Internals->Runner->TimeBegin();
    this->Internals->Reduced.End();
    this->Internals->Runner->TimeEnd("UPSCALE");
  }
  this->Internals->Runner->TimeBegin();
  gbuffer->RenderAfterGeometry(s);
  this->Internals->Runner->TimeEnd("AFTER");
  this->NumberOfRenderedProps = gbuffer->GetNumberOfRenderedProps();
  if (this->Internals->Runner->GetFailed())
  {
    vtkErrorMacro("Could not build a " << this->GetClassName() << " shader.");
  }
  vtkOpenGLCheckErrorMacro("failed after " << this->GetClassName() << "::Render");
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::SetShaderDefines(const std::string& defines)
{
  this->Internals->Runner->SetDefines(defines);
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
bool vtkStylizeStylePass::RenderStage(int stage, std::initializer_list<vtkTextureObject*> targets,
  int w, int h, const StageUniforms& uniforms, int coverage, vtkTextureObject* cullDepth)
{
  // Surface-only stages skip the background by an early depth test against the G-buffer's
  // depth (or the one given), where it has the stage's size.
  vtkInternals& in = *this->Internals;
  vtkTextureObject* depth = cullDepth ? cullDepth : in.Scene->GetDepthTexture();
  const bool cull = in.Culling && coverage == SURFACE_PIXELS && depth &&
    static_cast<int>(depth->GetWidth()) == w && static_cast<int>(depth->GetHeight()) == h;
  return in.Runner->Run(stage, targets, w, h, uniforms, cull ? depth : nullptr);
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::RenderStageToOutput(
  const Frame& frame, int stage, bool writeDepth, const StageUniforms& uniforms, int margin)
{
  return this->WriteOutput(
    frame, writeDepth, margin, [&] { return this->Internals->Runner->RunHere(stage, uniforms); });
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::CanBlitToOutput(const Frame& frame) const
{
  const vtkInternals& in = *this->Internals;
  if (in.Layer > 0 || !frame.Renderer || frame.Renderer->Transparent())
  {
    return false;
  }
  GLint samples = 0, second = GL_NONE;
  glGetIntegerv(GL_SAMPLE_BUFFERS, &samples);
  glGetIntegerv(GL_DRAW_BUFFER1, &second);
  return samples == 0 && second == GL_NONE;
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::BlitToOutput(
  const Frame& frame, vtkTextureObject* source, const int rect[4])
{
  const int window[4] = { frame.Origin[0] + rect[0], frame.Origin[1] + rect[1],
    frame.Origin[0] + rect[2], frame.Origin[1] + rect[3] };
  return this->WriteOutput(frame, false, -1,
    [&] { return this->Internals->Runner->BlitHere(source, window, "output blit"); });
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::WriteOutput(
  const Frame& frame, bool writeDepth, int margin, const std::function<bool()>& write)
{
  vtkInternals& in = *this->Internals;
  if (in.Reduced.IsActive())
  {
    in.Reduced.MarkWritten();
  }
  vtkOpenGLState* ostate = frame.Window->GetState();
  vtkStylizeScopedOutputState saved(ostate);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
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
  auto scissor = [&](int x0, int y0, int x1, int y1)
  {
    x0 = std::max(x0, view[0]);
    y0 = std::max(y0, view[1]);
    x1 = std::min(x1, view[2]);
    y1 = std::min(y1, view[3]);
    ostate->vtkglScissor(
      frame.Origin[0] + x0, frame.Origin[1] + y0, std::max(0, x1 - x0), std::max(0, y1 - y0));
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
  if (in.Culling && writeDepth && margin >= 0 && this->SceneRectangle(frame, margin, rect))
  {
    const bool drawn = this->RenderBackgroundStrips(frame, rect, layer, scissor);
    if (rect[2] <= rect[0] || rect[3] <= rect[1])
    {
      return drawn; // nothing of the scene is in view
    }
    scissor(rect[0], rect[1], rect[2], rect[3]);
  }
  return write();
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::RenderBackgroundStrips(const Frame& frame, const int rect[4], bool layer,
  const std::function<void(int, int, int, int)>& scissor)
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLState* ostate = frame.Window->GetState();
  in.Runner->TimeBegin();
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
    background = in.BackgroundQuad.Prepare(frame.Window, source, "  stylizeBackgroundMain();\n");
    in.Runner->NoteFailure(!background);
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
  in.Runner->TimeEnd("BACKGROUND");
  return layered || clear || background;
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::SceneRectangle(const Frame& frame, int margin, int rect[4])
{
  // A scene from an image (IceT's composited picture) holds more than the local props.
  if (this->Internals->GBuffer->GetSceneFromImage() || !frame.Camera)
  {
    return false;
  }
  return vtkStylizeShaderUtilities::PropsScreenRectangle(frame.Renderer, frame.Camera,
    frame.GuardTransform, frame.Size, std::max(frame.TileScale[0], frame.TileScale[1]), margin,
    rect);
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
    .Int("stylizeTranslucentLayer", this->Internals->Layer)
    .Int("stylizeSceneFromImage", gbuffer->GetSceneFromImage() ? 1 : 0)
    .Float4(
      "stylizeImageBackground", bg[0], bg[1], bg[2], gbuffer->GetImageBackgroundApplied() ? 1 : 0)
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
  return this->Internals->Scene->GetBufferTexture(buffer);
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
  vtkStylizeShaderUtilities::EnsureScreenTexture(
    tex, this->Internals->Runner->GetWindow(), w, h, internalFormat);
  return tex;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::FreeTexture(int slot)
{
  vtkStylizeShaderUtilities::FreeTexture(
    this->TextureSlot(slot), this->Internals->Runner->GetWindow());
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::DownloadTexture(vtkTextureObject* tex, vtkFloatArray* out)
{
  return this->Internals->Runner->Download(tex, out);
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  vtkInternals& in = *this->Internals;
  in.BackgroundQuad.Release(w);
  in.Runner->ReleaseGraphicsResources(w);
  in.FreeTextures(w);
  in.Reduced.Release(w);
  vtkStylizeStageRunner::FreeFramebuffer(in.LayerFramebuffer, w);
  in.LayerQuad.Release(w);
  in.GBuffer->ReleaseGraphicsResources(w);
  in.LayerGBuffer->ReleaseGraphicsResources(w);
  in.Volumes.ReleaseGraphicsResources(w);
  this->ReleaseStyleResources(w);
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::SetFieldUniforms(vtkStylizeUniforms& u, const Frame& frame)
{
  // The projection onto the stages' pixels: the guard band's screen transform after the
  // camera's (row a becomes s_a row a + t_a row 3). (Not GetProjectionTransformMatrix(ren),
  // which returns a new matrix, transposed: read as this one, a tile's off-centre terms are lost.)
  vtkMatrix4x4* projection =
    frame.Camera->GetProjectionTransformMatrix(frame.Renderer->GetTiledAspectRatio(), -1.0, 1.0);
  auto element = [&](int row, int column)
  {
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
