#include "vtkStylizeShaderUtilities.h"

#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkStylizeCommonFS.h"
#include "vtkStylizeFaceNormal.h"

//------------------------------------------------------------------------------
void vtkStylizeShaderUtilities::InjectCommon(std::string& fs)
{
  if (fs.find("VTK_STYLIZE_COMMON") == std::string::npos)
  {
    vtkShaderProgram::Substitute(
      fs, "//VTK::System::Dec", std::string("//VTK::System::Dec\n") + vtkStylizeCommonFS, false);
  }
  if (fs.find("vec3 stylizeFaceN =") == std::string::npos &&
    fs.find("vec4 vertexVC =") != std::string::npos)
  {
    vtkShaderProgram::Substitute(fs, "//VTK::UniformFlow::Impl",
      std::string(vtkStylizeFaceNormal) + "\n  //VTK::UniformFlow::Impl", false);
  }
}

//------------------------------------------------------------------------------
void vtkStylizeShaderUtilities::EnsureScreenTexture(vtkTextureObject*& tex,
  vtkOpenGLRenderWindow* renWin, int w, int h, int internalFormat, bool recreate)
{
  if (tex && (recreate || tex->GetContext() != renWin))
  {
    tex->Delete();
    tex = nullptr;
  }
  if (tex)
  {
    tex->Resize(w, h);
    return;
  }
  tex = vtkTextureObject::New();
  tex->SetContext(renWin);
  tex->SetMinificationFilter(vtkTextureObject::Nearest);
  tex->SetMagnificationFilter(vtkTextureObject::Nearest);
  tex->SetWrapS(vtkTextureObject::ClampToEdge);
  tex->SetWrapT(vtkTextureObject::ClampToEdge);
  if (internalFormat == GL_DEPTH_COMPONENT32F)
  {
    tex->AllocateDepth(w, h, vtkTextureObject::Float32);
    return;
  }
  const int comps = (internalFormat == GL_R32F || internalFormat == GL_R16F) ? 1 : 4;
  tex->SetInternalFormat(internalFormat);
  tex->SetFormat(comps == 1 ? GL_RED : GL_RGBA);
  tex->SetDataType(GL_FLOAT);
  tex->Allocate2D(w, h, comps, VTK_FLOAT);
}

//------------------------------------------------------------------------------
void vtkStylizeShaderUtilities::FreeTexture(vtkTextureObject*& tex, vtkWindow* w)
{
  if (tex)
  {
    if (w)
    {
      tex->ReleaseGraphicsResources(w);
    }
    tex->Delete();
    tex = nullptr;
  }
}

//------------------------------------------------------------------------------
vtkStylizeShaderUtilities::ScreenQuad::~ScreenQuad()
{
  delete this->Helper;
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkStylizeShaderUtilities::ScreenQuad::Prepare(
  vtkOpenGLRenderWindow* renWin, const std::string& declarations, const std::string& body)
{
  // Same inputs as the last build: no string work on the per-frame path.
  if (this->Helper && renWin == this->Window && body == this->Body &&
    declarations == this->Declarations)
  {
    renWin->GetShaderCache()->ReadyShaderProgram(this->Helper->Program);
  }
  else
  {
    delete this->Helper;
    std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
    vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Decl", declarations);
    vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Impl", body);
    this->Declarations = declarations;
    this->Body = body;
    this->Window = renWin;
    this->Helper = new vtkOpenGLQuadHelper(
      renWin, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fs.c_str(), "");
  }
  if (!this->Helper->Program || !this->Helper->Program->GetCompiled())
  {
    return nullptr;
  }
  return this->Helper->Program;
}

//------------------------------------------------------------------------------
void vtkStylizeShaderUtilities::ScreenQuad::Render()
{
  if (this->Helper)
  {
    this->Helper->Render();
  }
}

//------------------------------------------------------------------------------
void vtkStylizeShaderUtilities::ScreenQuad::Release(vtkWindow* w)
{
  if (this->Helper)
  {
    this->Helper->ReleaseGraphicsResources(w);
    delete this->Helper;
    this->Helper = nullptr;
  }
  this->Declarations.clear();
  this->Body.clear();
  this->Window = nullptr;
}
