#include "vtkStylizeStageRunner.h"

#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkStylizeShaderUtilities.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkStylizeCommonFS.h"
#include "vtkStylizeDepthFS.h"
#include "vtkStylizeScreenFS.h"

#include <algorithm>

vtkStandardNewMacro(vtkStylizeStageRunner);

//------------------------------------------------------------------------------
vtkStylizeStageRunner::vtkStylizeStageRunner() = default;

//------------------------------------------------------------------------------
vtkStylizeStageRunner::~vtkStylizeStageRunner()
{
  FreeFramebuffer(this->Framebuffer, nullptr);
}

//------------------------------------------------------------------------------
void vtkStylizeStageRunner::SetStages(const std::string& source, const std::string& mainCall,
  const std::vector<std::string>& defines, const std::vector<std::string>& names)
{
  this->Source = source;
  this->MainCall = mainCall;
  this->StageDefines = defines;
  this->StageNames = names;
  this->StageNames.resize(defines.size());
  this->Defines.clear();
  this->Declarations.assign(defines.size(), std::string());
  this->Quads.clear();
  for (size_t i = 0; i < defines.size(); ++i)
  {
    this->Quads.emplace_back(new vtkStylizeScreenQuad);
  }
}

//------------------------------------------------------------------------------
void vtkStylizeStageRunner::SetDefines(const std::string& defines)
{
  if (defines == this->Defines && !this->Declarations.empty() && !this->Declarations[0].empty())
  {
    return;
  }
  this->Defines = defines;
  const std::string shared =
    defines + vtkStylizeCommonFS + vtkStylizeDepthFS + vtkStylizeScreenFS + this->Source;
  for (size_t i = 0; i < this->StageDefines.size(); ++i)
  {
    const std::string& stage = this->StageDefines[i];
    this->Declarations[i] = stage.empty() ? shared : "#define " + stage + "\n" + shared;
  }
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkStylizeStageRunner::Prepare(int stage)
{
  vtkShaderProgram* program =
    this->Quads[stage]->Prepare(this->Window, this->Declarations[stage], this->MainCall);
  this->NoteFailure(!program);
  return program;
}

//------------------------------------------------------------------------------
vtkOpenGLFramebufferObject* vtkStylizeStageRunner::BindFramebuffer(
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

//------------------------------------------------------------------------------
void vtkStylizeStageRunner::FreeFramebuffer(vtkOpenGLFramebufferObject*& fbo, vtkWindow* w)
{
  if (fbo)
  {
    if (w)
    {
      fbo->ReleaseGraphicsResources(w);
    }
    fbo->Delete();
    fbo = nullptr;
  }
}

//------------------------------------------------------------------------------
bool vtkStylizeStageRunner::Run(int stage, std::initializer_list<vtkTextureObject*> targets, int w,
  int h, const StageUniforms& uniforms, vtkTextureObject* cullDepth)
{
  vtkOpenGLState* ostate = this->Window->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  vtkOpenGLFramebufferObject* fbo = BindFramebuffer(this->Framebuffer, this->Window);
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
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglClearColor clearColorSaver(ostate);
  GLdouble depthRange[2] = { 0.0, 1.0 };
  this->TimeBegin();
  if (cullDepth)
  {
    ostate->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
    fbo->AddDepthAttachment(cullDepth);
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_GREATER);
    ostate->vtkglDepthMask(GL_FALSE);
    glGetDoublev(GL_DEPTH_RANGE, depthRange);
    glDepthRange(1.0, 1.0);
  }
  vtkShaderProgram* program = this->Prepare(stage);
  if (program)
  {
    vtkStylizeUniforms u(program);
    uniforms(u);
    this->Quads[stage]->Render();
  }
  this->TimeEnd(this->StageNames[stage]);
  if (cullDepth)
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
bool vtkStylizeStageRunner::RunHere(int stage, const StageUniforms& uniforms)
{
  vtkShaderProgram* program = this->Prepare(stage);
  if (program)
  {
    vtkStylizeUniforms u(program);
    uniforms(u);
    this->TimeBegin();
    this->Quads[stage]->Render();
    this->TimeEnd(this->StageNames[stage]);
  }
  return program != nullptr;
}

//------------------------------------------------------------------------------
void vtkStylizeStageRunner::TimeBegin()
{
  if (this->Timing)
  {
    glFinish();
    this->TimingStart = std::chrono::steady_clock::now();
  }
}

//------------------------------------------------------------------------------
void vtkStylizeStageRunner::TimeEnd(const std::string& name)
{
  if (!this->Timing)
  {
    return;
  }
  glFinish();
  const double ms =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - this->TimingStart)
      .count();
  auto it = std::find_if(
    this->Times.begin(), this->Times.end(), [&](const StageTime& t) { return t.Name == name; });
  if (it == this->Times.end())
  {
    this->Times.push_back(StageTime{ name, 0.0, 0 });
    it = this->Times.end() - 1;
  }
  it->Milliseconds += ms;
  it->Runs++;
}

//------------------------------------------------------------------------------
const char* vtkStylizeStageRunner::GetTimedStageName(int i) const
{
  return i >= 0 && i < this->GetNumberOfTimedStages() ? this->Times[i].Name.c_str() : nullptr;
}

//------------------------------------------------------------------------------
double vtkStylizeStageRunner::GetTimedStageMilliseconds(int i) const
{
  return i >= 0 && i < this->GetNumberOfTimedStages() ? this->Times[i].Milliseconds : 0.0;
}

//------------------------------------------------------------------------------
int vtkStylizeStageRunner::GetTimedStageRuns(int i) const
{
  return i >= 0 && i < this->GetNumberOfTimedStages() ? this->Times[i].Runs : 0;
}

//------------------------------------------------------------------------------
void vtkStylizeStageRunner::ReleaseGraphicsResources(vtkWindow* w)
{
  for (auto& quad : this->Quads)
  {
    quad->Release(w);
  }
  FreeFramebuffer(this->Framebuffer, w);
}

//------------------------------------------------------------------------------
bool vtkStylizeStageRunner::BlitHere(
  vtkTextureObject* tex, const int rect[4], const std::string& name)
{
  vtkOpenGLFramebufferObject* fbo = this->Framebuffer;
  if (!tex || !fbo)
  {
    return false;
  }
  vtkOpenGLState* ostate = fbo->GetContext()->GetState();
  this->TimeBegin();
  fbo->SaveCurrentBindingsAndBuffers(GL_READ_FRAMEBUFFER);
  fbo->Bind(GL_READ_FRAMEBUFFER);
  fbo->AddColorAttachment(0, tex);
  ostate->vtkglReadBuffer(GL_COLOR_ATTACHMENT0);
  ostate->vtkglBlitFramebuffer(0, 0, static_cast<int>(tex->GetWidth()),
    static_cast<int>(tex->GetHeight()), rect[0], rect[1], rect[2], rect[3], GL_COLOR_BUFFER_BIT,
    GL_NEAREST);
  fbo->RemoveColorAttachments(1);
  fbo->UnBind(GL_READ_FRAMEBUFFER);
  fbo->RestorePreviousBindingsAndBuffers(GL_READ_FRAMEBUFFER);
  this->TimeEnd(name);
  return true;
}

//------------------------------------------------------------------------------
bool vtkStylizeStageRunner::Download(vtkTextureObject* tex, vtkFloatArray* out)
{
  vtkOpenGLFramebufferObject* fbo = this->Framebuffer;
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
