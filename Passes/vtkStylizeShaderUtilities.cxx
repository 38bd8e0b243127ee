#include "vtkStylizeShaderUtilities.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>

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
  if (internalFormat == GL_DEPTH24_STENCIL8)
  {
    tex->AllocateDepthStencil(w, h);
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
vtkStylizeScreenQuad::~vtkStylizeScreenQuad()
{
  delete this->Helper;
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkStylizeScreenQuad::Prepare(
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
void vtkStylizeScreenQuad::Render()
{
  if (this->Helper)
  {
    this->Helper->Render();
  }
}

//------------------------------------------------------------------------------
void vtkStylizeScreenQuad::Release(vtkWindow* w)
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

//------------------------------------------------------------------------------
vtkStylizeShaderUtilities::FullImage vtkStylizeShaderUtilities::GetFullImage(
  vtkRenderer* ren, int ox, int oy)
{
  FullImage image;
  vtkWindow* win = ren->GetVTKWindow();
  const int* window = win->GetSize(); // includes the tile scale
  const double* rvp = ren->GetViewport();
  double tvp[4];
  win->GetTileViewport(tvp);
  win->GetTileScale(image.TileScale);
  image.TileScale[0] = std::max(1, image.TileScale[0]);
  image.TileScale[1] = std::max(1, image.TileScale[1]);
  const int origin[2] = { ox, oy };
  for (int a = 0; a < 2; ++a)
  {
    image.Size[a] = std::max(1.0, (rvp[a + 2] - rvp[a]) * window[a]);
    image.Offset[a] = std::round(tvp[a] * window[a] + origin[a] - rvp[a] * window[a]);
  }
  return image;
}

//------------------------------------------------------------------------------
bool vtkStylizeShaderUtilities::PropsScreenRectangle(vtkRenderer* ren, vtkCamera* cam,
  const double guard[4], const int size[2], int tileScale, int margin, int rect[4])
{
  double b[6];
  ren->ComputeVisiblePropBounds(b);
  if (!vtkMath::AreBoundsInitialized(b) ||
    !std::all_of(b, b + 6, [](double v) { return std::isfinite(v); }))
  {
    return false;
  }
  // Points and lines reach half their size beyond their vertices.
  double extent = 0.0;
  vtkActorCollection* actors = ren->GetActors();
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
  const double pad = margin + 2.0 + std::ceil(extent * tileScale);
  vtkMatrix4x4* m =
    cam->GetCompositeProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1.0, 1.0);
  double lo[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX }, hi[2] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (int corner = 0; corner < 8; ++corner)
  {
    const double x[4] = { b[corner & 1], b[2 + ((corner >> 1) & 1)], b[4 + ((corner >> 2) & 1)],
      1.0 };
    double c[4];
    m->MultiplyPoint(x, c);
    if (!(c[3] > 1e-6 * (std::abs(c[0]) + std::abs(c[1]) + std::abs(c[2]))) || !std::isfinite(c[3]))
    {
      return false; // a corner behind the eye: the projection does not bound the scene
    }
    for (int a = 0; a < 2; ++a)
    {
      const double ndc = guard[a] * c[a] / c[3] + guard[a + 2];
      const double pixel = (ndc + 1.0) * 0.5 * size[a];
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
    rect[a] = static_cast<int>(std::max(0.0, std::min(l, static_cast<double>(size[a]))));
    rect[a + 2] = static_cast<int>(std::max(0.0, std::min(h, static_cast<double>(size[a]))));
  }
  // Worth it only when the rectangle leaves a part of the viewport out.
  return rect[0] > 0 || rect[1] > 0 || rect[2] < size[0] || rect[3] < size[1];
}

//------------------------------------------------------------------------------
double vtkStylizeShaderUtilities::PixelWorldSize(vtkCamera* cam, int w, int h)
{
  double size;
  if (cam->GetParallelProjection())
  {
    size = 2.0 * cam->GetParallelScale() / h;
  }
  else
  {
    const double t = std::tan(vtkMath::RadiansFromDegrees(cam->GetViewAngle()) * 0.5);
    size = 2.0 * t / (cam->GetUseHorizontalViewAngle() ? w : h);
  }
  return (size > 0.0 && std::isfinite(size)) ? size : 1.0;
}

//------------------------------------------------------------------------------
vtkStylizeUniforms::~vtkStylizeUniforms()
{
  for (vtkTextureObject* tex : this->Bound)
  {
    if (tex->GetTextureUnit() >= 0)
    {
      tex->Deactivate();
    }
  }
}

//------------------------------------------------------------------------------
vtkStylizeUniforms& vtkStylizeUniforms::Int(const char* name, int v)
{
  if (this->Program->IsUniformUsed(name))
  {
    this->Program->SetUniformi(name, v);
  }
  return *this;
}

//------------------------------------------------------------------------------
vtkStylizeUniforms& vtkStylizeUniforms::Float(const char* name, double v)
{
  if (this->Program->IsUniformUsed(name))
  {
    this->Program->SetUniformf(name, static_cast<float>(v));
  }
  return *this;
}

//------------------------------------------------------------------------------
vtkStylizeUniforms& vtkStylizeUniforms::Int2(const char* name, int x, int y)
{
  if (this->Program->IsUniformUsed(name))
  {
    const int v[2] = { x, y };
    this->Program->SetUniform2i(name, v);
  }
  return *this;
}

//------------------------------------------------------------------------------
vtkStylizeUniforms& vtkStylizeUniforms::Float2(const char* name, double x, double y)
{
  if (this->Program->IsUniformUsed(name))
  {
    const float v[2] = { static_cast<float>(x), static_cast<float>(y) };
    this->Program->SetUniform2f(name, v);
  }
  return *this;
}

//------------------------------------------------------------------------------
vtkStylizeUniforms& vtkStylizeUniforms::Float3(const char* name, double x, double y, double z)
{
  if (this->Program->IsUniformUsed(name))
  {
    const float v[3] = { static_cast<float>(x), static_cast<float>(y), static_cast<float>(z) };
    this->Program->SetUniform3f(name, v);
  }
  return *this;
}

//------------------------------------------------------------------------------
vtkStylizeUniforms& vtkStylizeUniforms::Float4(
  const char* name, double x, double y, double z, double w)
{
  if (this->Program->IsUniformUsed(name))
  {
    const float v[4] = { static_cast<float>(x), static_cast<float>(y), static_cast<float>(z),
      static_cast<float>(w) };
    this->Program->SetUniform4f(name, v);
  }
  return *this;
}

//------------------------------------------------------------------------------
vtkStylizeUniforms& vtkStylizeUniforms::Texture(const char* name, vtkTextureObject* tex)
{
  if (tex && this->Program->IsUniformUsed(name))
  {
    tex->Activate();
    this->Bound.push_back(tex);
    this->Program->SetUniformi(name, tex->GetTextureUnit());
  }
  return *this;
}

//------------------------------------------------------------------------------
vtkIdType vtkStylizeShaderUtilities::TextureBytes(vtkTextureObject* t)
{
  if (!t || !t->GetHandle())
  {
    return 0;
  }
  int texel = 0;
  // Depth textures (AllocateDepth(Float32)) keep their format, not an internal format.
  const unsigned int format = t->GetFormat(VTK_FLOAT, 1, false) == GL_DEPTH_COMPONENT
    ? GL_DEPTH_COMPONENT32F
    : t->GetInternalFormat(VTK_FLOAT, 4, false);
  switch (format)
  {
    case GL_RGBA32F:
      texel = 16;
      break;
    case GL_RGBA16F:
    case GL_RG32F:
      texel = 8;
      break;
    case GL_RGB32F:
      texel = 12;
      break;
    case GL_RGB16F:
      texel = 6;
      break;
    case GL_R32F:
    case GL_RG16F:
    case GL_RGBA8:
    case GL_DEPTH_COMPONENT32F:
    case GL_DEPTH24_STENCIL8:
      texel = 4;
      break;
    case GL_R16F:
    case GL_RG8:
      texel = 2;
      break;
    case GL_R8:
      texel = 1;
      break;
    default:
      texel = 16; // unknown: counted as the largest colour format
  }
  return static_cast<vtkIdType>(t->GetWidth()) * t->GetHeight() *
    std::max(1, static_cast<int>(t->GetDepth())) * texel;
}

//------------------------------------------------------------------------------
vtkStylizeScopedOutputState::vtkStylizeScopedOutputState(vtkOpenGLState* state)
  : Blend(state, GL_BLEND)
  , DepthTest(state, GL_DEPTH_TEST)
  , ScissorTest(state, GL_SCISSOR_TEST)
  , BlendFunc(state)
  , Viewport(state)
  , Scissor(state)
{
}
