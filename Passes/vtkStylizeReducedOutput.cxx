#include "vtkStylizeReducedOutput.h"

#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkStylizeStageRunner.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>

#include "vtkStylizeUpscaleFS.h"

//------------------------------------------------------------------------------
vtkStylizeReducedOutput::~vtkStylizeReducedOutput()
{
  // (the quad frees its own program when it goes)
  vtkStylizeShaderUtilities::FreeTexture(this->Color, nullptr);
  vtkStylizeShaderUtilities::FreeTexture(this->Depth, nullptr);
  vtkStylizeStageRunner::FreeFramebuffer(this->Framebuffer, nullptr);
}

//------------------------------------------------------------------------------
bool vtkStylizeReducedOutput::Begin(
  vtkOpenGLRenderWindow* window, int w, int h, const int viewport[4])
{
  using Utilities = vtkStylizeShaderUtilities;
  if (this->Window && this->Window != window)
  {
    // Another window: the framebuffer belongs to the old context (the textures are remade by
    // EnsureScreenTexture, the program by the quad).
    vtkStylizeStageRunner::FreeFramebuffer(this->Framebuffer, nullptr);
  }
  Utilities::EnsureScreenTexture(this->Color, window, w, h, GL_RGBA8);
  Utilities::EnsureScreenTexture(this->Depth, window, w, h, GL_DEPTH_COMPONENT32F);
  if (!this->Color || !this->Depth || !this->Color->GetHandle() || !this->Depth->GetHandle())
  {
    return false;
  }
  this->Color->SetMagnificationFilter(vtkTextureObject::Linear);
  this->Window = window;
  vtkOpenGLFramebufferObject* fbo =
    vtkStylizeStageRunner::BindFramebuffer(this->Framebuffer, window);
  fbo->AddColorAttachment(0, this->Color);
  fbo->AddDepthAttachment(this->Depth);
  fbo->ActivateDrawBuffers(1);
  std::copy(viewport, viewport + 4, this->Viewport);
  this->Active = true;
  this->Written = false;
  return true;
}

//------------------------------------------------------------------------------
void vtkStylizeReducedOutput::End()
{
  if (!this->Active)
  {
    return;
  }
  this->Active = false;
  this->Framebuffer->UnBind();
  this->Framebuffer->RestorePreviousBindingsAndBuffers();
  if (!this->Written)
  {
    return;
  }
  vtkOpenGLState* ostate = this->Window->GetState();
  static const std::string body = "  stylizeUpscale();\n";
  vtkShaderProgram* program = this->Quad.Prepare(this->Window, vtkStylizeUpscaleFS, body);
  if (!program)
  {
    return;
  }
  vtkStylizeScopedOutputState saved(ostate);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  const int* v = this->Viewport;
  ostate->vtkglViewport(v[0], v[1], v[2], v[3]);
  ostate->vtkglScissor(v[0], v[1], v[2], v[3]);
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  this->Color->Activate();
  this->Depth->Activate();
  program->SetUniformi("stylizeReducedColor", this->Color->GetTextureUnit());
  program->SetUniformi("stylizeReducedDepth", this->Depth->GetTextureUnit());
  this->Quad.Render();
  this->Depth->Deactivate();
  this->Color->Deactivate();
  vtkOpenGLCheckErrorMacro("failed after vtkStylizeReducedOutput::End");
}

//------------------------------------------------------------------------------
vtkIdType vtkStylizeReducedOutput::GetTextureBytes() const
{
  return vtkStylizeShaderUtilities::TextureBytes(this->Color) +
    vtkStylizeShaderUtilities::TextureBytes(this->Depth);
}

//------------------------------------------------------------------------------
void vtkStylizeReducedOutput::Release(vtkWindow* w)
{
  this->Written = false;
  this->End(); // binds the window again, draws nothing
  vtkStylizeShaderUtilities::FreeTexture(this->Color, w);
  vtkStylizeShaderUtilities::FreeTexture(this->Depth, w);
  vtkStylizeStageRunner::FreeFramebuffer(this->Framebuffer, w);
  this->Quad.Release(w);
  this->Window = nullptr;
}
