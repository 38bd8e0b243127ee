#include "vtkStylizeShaderUtilities.h"

#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"

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
vtkStylizeShaderUtilities::ScreenQuad::~ScreenQuad()
{
  delete this->Helper;
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkStylizeShaderUtilities::ScreenQuad::Prepare(
  vtkOpenGLRenderWindow* renWin, const std::string& declarations, const std::string& body)
{
  std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
  vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Decl", declarations);
  vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Impl", body);
  if (this->Helper && (fs != this->Source || renWin != this->Window))
  {
    delete this->Helper;
    this->Helper = nullptr;
  }
  if (!this->Helper)
  {
    this->Source = fs;
    this->Window = renWin;
    this->Helper = new vtkOpenGLQuadHelper(
      renWin, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fs.c_str(), "");
  }
  else
  {
    renWin->GetShaderCache()->ReadyShaderProgram(this->Helper->Program);
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
  this->Source.clear();
  this->Window = nullptr;
}
