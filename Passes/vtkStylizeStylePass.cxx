#include "vtkStylizeStylePass.h"

#include "vtkCamera.h"
#include "vtkFloatArray.h"
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
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkStylizeCommonFS.h"
#include "vtkStylizeDepthFS.h"
#include "vtkStylizeFieldFS.h"
#include "vtkStylizeScreenFS.h"

#include "vtkMath.h"
#include "vtkMatrix4x4.h"

#include <algorithm>
#include <cmath>
#include <utility>

class vtkStylizeStylePass::vtkInternals
{
public:
  vtkNew<vtkStylizeLightingPass> Lighting;
  vtkNew<vtkStylizeGBufferPass> GBuffer;

  // Shader assembly: the style's source, its stages and the last frame's defines.
  std::string StyleSource;
  std::string MainCall;
  std::vector<std::string> StageDefines;
  std::string Defines;
  std::vector<std::string> Declarations; // one per stage
  std::vector<std::unique_ptr<vtkStylizeScreenQuad>> Quads;

  vtkOpenGLRenderWindow* Window = nullptr; // of the frame being rendered
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  std::vector<vtkTextureObject*> Textures; // the style's slots
  bool StageFailed = false;

  // The direction field: its first stage's index (-1: the style has none) and its textures
  // (the raw field's ping-pong pair and the resolved field).
  int FieldStage = -1;
  vtkTextureObject* FieldTextures[3] = { nullptr, nullptr, nullptr };
  int FieldResolved = -1; // index in FieldTextures of the last resolved field

  void FreeFramebuffer(vtkWindow* w)
  {
    if (this->Framebuffer)
    {
      if (w)
      {
        this->Framebuffer->ReleaseGraphicsResources(w);
      }
      this->Framebuffer->Delete();
      this->Framebuffer = nullptr;
    }
  }

  void FreeTextures(vtkWindow* w)
  {
    for (vtkTextureObject*& t : this->Textures)
    {
      vtkStylizeShaderUtilities::FreeTexture(t, w);
    }
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
  os << indent << "LightingPass:\n";
  this->Internals->Lighting->PrintSelf(os, indent.GetNextIndent());
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
bool vtkStylizeStylePass::BeginFrame(const vtkRenderState* s, Frame& frame)
{
  vtkOpenGLClearErrorMacro();
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
    frame.TileScale[a] = full.TileScale[a];
  }
  frame.Camera = ren->GetActiveCamera();
  frame.Parallel = frame.Camera->GetParallelProjection() != 0;
  frame.PixelWorld =
    vtkStylizeShaderUtilities::PixelWorldSize(frame.Camera, frame.Size[0], frame.Size[1]);
  return true;
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::RenderScene(const vtkRenderState* s, const SceneRequest& request)
{
  vtkStylizeGBufferPass* gbuffer = this->Internals->GBuffer;
  gbuffer->SetSceneImagePass(this->DelegatePass);
  gbuffer->SetChannels(request.Channels);
  if (request.Channels & vtkStylizeGBufferPass::POSITION)
  {
    gbuffer->SetPositionSpace(request.PositionSpace);
  }
  gbuffer->SetGeometryResolution(request.Resolution[0], request.Resolution[1]);
  const double* t = request.ScreenTransform;
  gbuffer->SetGeometryScreenTransform(t[0], t[1], t[2], t[3]);
  gbuffer->SetAfterScreenShift(request.AfterShift[0], request.AfterShift[1]);
  if (!gbuffer->RenderGeometry(s))
  {
    this->EndFrame(s);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::EndFrame(const vtkRenderState* s)
{
  vtkStylizeGBufferPass* gbuffer = this->Internals->GBuffer;
  gbuffer->RenderAfterGeometry(s);
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
  std::initializer_list<vtkTextureObject*> targets, int w, int h, const StageUniforms& uniforms)
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

  if (!in.Framebuffer)
  {
    in.Framebuffer = vtkOpenGLFramebufferObject::New();
    in.Framebuffer->SetContext(renWin);
  }
  vtkOpenGLFramebufferObject* fbo = in.Framebuffer;
  fbo->SaveCurrentBindingsAndBuffers();
  fbo->Bind();
  unsigned int n = 0;
  for (vtkTextureObject* t : targets)
  {
    fbo->AddColorAttachment(n++, t);
  }
  fbo->ActivateDrawBuffers(n);
  ostate->vtkglViewport(0, 0, w, h);
  ostate->vtkglScissor(0, 0, w, h);
  vtkShaderProgram* program = in.Prepare(stage);
  if (program)
  {
    vtkStylizeUniforms u(program);
    uniforms(u);
    in.Quads[stage]->Render();
  }
  fbo->RemoveColorAttachments(n);
  fbo->UnBind();
  fbo->RestorePreviousBindingsAndBuffers();
  return program != nullptr;
}

//------------------------------------------------------------------------------
bool vtkStylizeStylePass::RenderStageToOutput(
  const Frame& frame, int stage, bool writeDepth, const StageUniforms& uniforms)
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLState* ostate = in.Window->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(ostate, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglViewport(frame.Origin[0], frame.Origin[1], frame.Size[0], frame.Size[1]);
  ostate->vtkglScissor(frame.Origin[0], frame.Origin[1], frame.Size[0], frame.Size[1]);
  ostate->vtkglDepthMask(GL_TRUE);
  if (writeDepth)
  {
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_ALWAYS);
  }
  else
  {
    ostate->vtkglEnable(GL_SCISSOR_TEST);
    ostate->vtkglClearDepth(1.0);
    ostate->vtkglClear(GL_DEPTH_BUFFER_BIT);
    ostate->vtkglDisable(GL_DEPTH_TEST);
  }
  vtkShaderProgram* program = in.Prepare(stage);
  if (program)
  {
    vtkStylizeUniforms u(program);
    uniforms(u);
    in.Quads[stage]->Render();
  }
  return program != nullptr;
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::BindSceneTextures(vtkStylizeUniforms& u)
{
  vtkStylizeGBufferPass* g = this->Internals->GBuffer;
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
  u.Int("stylizeDiscardBackground", ren->Transparent() ? 1 : 0)
    .Int("stylizeSceneFromImage", this->Internals->GBuffer->GetSceneFromImage() ? 1 : 0);
  this->SetDepthMappingUniforms(u);
}

//------------------------------------------------------------------------------
void vtkStylizeStylePass::SetDepthMappingUniforms(vtkStylizeUniforms& u)
{
  this->Internals->GBuffer->SetDepthMappingUniforms(u.GetProgram());
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkStylizeStylePass::GetSceneTexture(int buffer)
{
  vtkStylizeGBufferPass* g = this->Internals->GBuffer;
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
  glReadBuffer(GL_COLOR_ATTACHMENT0);
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
  for (auto& quad : in.Quads)
  {
    quad->Release(w);
  }
  in.FreeTextures(w);
  in.FreeFramebuffer(w);
  in.GBuffer->ReleaseGraphicsResources(w);
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
  vtkMatrix4x4* projection = frame.Camera->GetProjectionTransformMatrix(frame.Renderer);
  this->BindSceneTextures(u);
  u.Int2("fieldSize", frame.Size[0], frame.Size[1])
    .Float2("fieldPixelOffset", frame.FullOffset[0], frame.FullOffset[1])
    .Int("fieldParallel", frame.Parallel ? 1 : 0)
    .Float("fieldPixelWorld", frame.PixelWorld)
    .Float4("fieldProjection", projection->GetElement(0, 0), projection->GetElement(1, 1),
      projection->GetElement(0, 2), projection->GetElement(1, 2))
    .Float2("fieldProjOffset", projection->GetElement(0, 3), projection->GetElement(1, 3));
  this->SetDepthMappingUniforms(u);
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
  const double smoothingRadius = std::min(s.SmoothingRadius * scale, 256.0) * pointSize;
  const int maxStride = std::max(1, static_cast<int>(std::lround(s.MaxStride * pointSize)));
  const double fillRadius = s.FillRadius > 0.0 ? std::max(1.0, s.FillRadius * pointSize) : -1.0;
  const double fallback = vtkMath::RadiansFromDegrees(s.FallbackAngle);

  // 1. Raw directions.
  vtkTextureObject*& raw0 = in.FieldTextures[0];
  vtkStylizeShaderUtilities::EnsureScreenTexture(raw0, in.Window, w, h, GL_RGBA16F);
  this->RenderStage(in.FieldStage, { raw0 }, w, h, [&](vtkStylizeUniforms& u) {
    this->SetFieldUniforms(u, frame);
    u.Float("fieldSpacing", spacingWorld)
      .Int("fieldMaxStride", maxStride)
      .Float("fieldPlanar", s.PlanarTolerance)
      .Float("fieldUmbilic", s.UmbilicTolerance);
  });

  // 2. Smoothing (all pixels, 3x3 at tap distances 1, 2, 4, ... points up to the smoothing
  // radius, then at distance 1 pixel), then filling (undefined pixels, distances 1, 2, 4, ...).
  // The taps are in points (at least a pixel), so that a magnified image is smoothed over the
  // same part of the picture.
  std::vector<std::pair<int, int>> iterations; // tap distance, fill only
  for (double pt = 1.0; pt <= smoothingRadius / pointSize; pt *= 2.0)
  {
    iterations.emplace_back(std::max(1, static_cast<int>(std::lround(pt * pointSize))), 0);
  }
  for (int i = 0; i < s.SmoothingIterations; ++i)
  {
    iterations.emplace_back(1, 0);
  }
  for (int r = 1; fillRadius > 0.0 && r <= fillRadius; r *= 2)
  {
    iterations.emplace_back(r, 1);
  }
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
      });
    current = next;
  }

  // 3. Fallbacks and the requested direction.
  vtkTextureObject*& resolved = in.FieldTextures[2];
  vtkStylizeShaderUtilities::EnsureScreenTexture(resolved, in.Window, w, h, GL_RGBA32F);
  this->RenderStage(in.FieldStage + 2, { resolved }, w, h, [&](vtkStylizeUniforms& u) {
    this->SetFieldUniforms(u, frame);
    u.Texture("fieldInput", in.FieldTextures[current])
      .Int("fieldGradientStride", std::max(1, static_cast<int>(std::lround(2.0 * pointSize))))
      .Float2("fieldScreenDirection", std::cos(fallback), std::sin(fallback));
  });
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
