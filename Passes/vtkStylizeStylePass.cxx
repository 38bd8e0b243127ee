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
#include "vtkStylizeScreenFS.h"

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
  std::vector<std::string> stageDefines, const char* mainCall)
  : Internals(new vtkInternals)
{
  vtkInternals& in = *this->Internals;
  in.Lighting->SetModel(lightingModel);
  in.GBuffer->SetLightingPass(in.Lighting);
  in.StyleSource = styleSource;
  in.MainCall = mainCall;
  in.StageDefines = std::move(stageDefines);
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
