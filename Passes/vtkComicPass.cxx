#include "vtkComicPass.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
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

#include "vtkComicFS.h"
#include "vtkStylizeCommonFS.h"
#include "vtkStylizeDepthFS.h"
#include "vtkStylizeScreenFS.h"

#include <algorithm>
#include <cmath>

class vtkComicPass::vtkInternals
{
public:
  vtkNew<vtkStylizeLightingPass> Lighting;
  vtkNew<vtkStylizeGBufferPass> GBuffer;
  vtkStylizeShaderUtilities::ScreenQuad EdgeQuad;
  vtkStylizeShaderUtilities::ScreenQuad FinalQuad;
  vtkOpenGLFramebufferObject* EdgeFramebuffer = nullptr;
  vtkTextureObject* EdgeTexture = nullptr; // luminance of f_normal, k1, k2

  std::string Defines;      // the #defines of the last frame
  std::string Declarations; // the shader declarations built from them
  std::string EdgeDeclarations; // the same for the colour-edge stage

  void FreeEdgeBuffers(vtkWindow* w)
  {
    vtkStylizeShaderUtilities::FreeTexture(this->EdgeTexture, w);
    if (this->EdgeFramebuffer)
    {
      if (w)
      {
        this->EdgeFramebuffer->ReleaseGraphicsResources(w);
      }
      this->EdgeFramebuffer->Delete();
      this->EdgeFramebuffer = nullptr;
    }
  }

  void AllocateEdgeBuffers(vtkOpenGLRenderWindow* renWin, int w, int h)
  {
    vtkStylizeShaderUtilities::EnsureScreenTexture(this->EdgeTexture, renWin, w, h, GL_RGBA16F);
    if (!this->EdgeFramebuffer)
    {
      this->EdgeFramebuffer = vtkOpenGLFramebufferObject::New();
      this->EdgeFramebuffer->SetContext(renWin);
    }
  }
};

vtkStandardNewMacro(vtkComicPass);

//------------------------------------------------------------------------------
vtkComicPass::vtkComicPass()
  : Internals(new vtkInternals)
{
  this->Internals->Lighting->SetModel(vtkStylizeLightingPass::COMIC);
  this->Internals->GBuffer->SetLightingPass(this->Internals->Lighting);
}

//------------------------------------------------------------------------------
vtkComicPass::~vtkComicPass()
{
  this->Internals->FreeEdgeBuffers(nullptr);
}

//------------------------------------------------------------------------------
vtkStylizeLightingPass* vtkComicPass::GetLightingPass()
{
  return this->Internals->Lighting;
}

//------------------------------------------------------------------------------
vtkStylizeGBufferPass* vtkComicPass::GetGBufferPass()
{
  return this->Internals->GBuffer;
}

//------------------------------------------------------------------------------
void vtkComicPass::SetEdgeWeights(double depth, double normal, double color)
{
  auto clamp01 = [](double v) { return std::isfinite(v) ? std::min(1.0, std::max(0.0, v)) : 0.0; };
  const double w[3] = { clamp01(depth), clamp01(normal), clamp01(color) };
  if (w[0] != this->EdgeWeights[0] || w[1] != this->EdgeWeights[1] ||
    w[2] != this->EdgeWeights[2])
  {
    std::copy(w, w + 3, this->EdgeWeights);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkComicPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Edges: " << this->Edges << "\n";
  os << indent << "EdgeWeights: " << this->EdgeWeights[0] << " " << this->EdgeWeights[1] << " "
     << this->EdgeWeights[2] << "\n";
  os << indent << "DepthThreshold: " << this->DepthThreshold << "\n";
  os << indent << "NormalThreshold: " << this->NormalThreshold << "\n";
  os << indent << "ColorThreshold: " << this->ColorThreshold << "\n";
  os << indent << "EdgeWidth: " << this->EdgeWidth << " pt\n";
  os << indent << "Dots: " << this->Dots << "\n";
  os << indent << "DotSpacing: " << this->DotSpacing << " pt\n";
  os << indent << "DotAngle: " << this->DotAngle << " deg\n";
  os << indent << "Hatching: " << this->Hatching << "\n";
  os << indent << "HatchSpacing: " << this->HatchSpacing << " pt\n";
  os << indent << "HatchWidth: " << this->HatchWidth << " pt\n";
  os << indent << "HatchAngle: " << this->HatchAngle << " deg\n";
  os << indent << "HatchDirections: " << this->HatchDirections << "\n";
  os << indent << "CrossHatching: " << this->CrossHatching << "\n";
  os << indent << "CrossThreshold: " << this->CrossThreshold << "\n";
  os << indent << "BrightThreshold: " << this->BrightThreshold << "\n";
  os << indent << "DarkThreshold: " << this->DarkThreshold << "\n";
  os << indent << "Tinted: " << this->Tinted << "\n";
  os << indent << "Anchor: " << (this->Anchor == OBJECT ? "object" : "screen") << "\n";
  os << indent << "Layer: "
     << (this->Layer == EDGES ? "edges" : (this->Layer == PATTERN ? "pattern" : "comic")) << "\n";
  os << indent << "ReferenceHeight: " << this->ReferenceHeight << " px\n";
  os << indent << "LightingPass:\n";
  this->Internals->Lighting->PrintSelf(os, indent.GetNextIndent());
}

//------------------------------------------------------------------------------
void vtkComicPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkStylizeGBufferPass* gbuffer = this->Internals->GBuffer;
  if (!renWin)
  {
    return;
  }

  // What this frame computes: only the enabled stages, and only their channels.
  double weightSum = this->EdgeWeights[0] + this->EdgeWeights[1] + this->EdgeWeights[2];
  const bool edges = this->Edges && weightSum > 0.0;
  const bool depthEdges = edges && this->EdgeWeights[0] > 0.0;
  const bool normalEdges = edges && this->EdgeWeights[1] > 0.0;
  const bool colorEdges = edges && this->EdgeWeights[2] > 0.0;
  const bool patterns = this->Dots || this->Hatching;
  const bool objectAnchor = patterns && this->Anchor == OBJECT;
  const bool normalHatch = this->Hatching && this->HatchDirections > 0;
  int channels = vtkStylizeGBufferPass::LINEAR_DEPTH;
  if (normalEdges || normalHatch)
  {
    channels |= vtkStylizeGBufferPass::NORMAL;
  }
  if (objectAnchor)
  {
    channels |= vtkStylizeGBufferPass::POSITION;
    gbuffer->SetPositionSpace(vtkStylizeGBufferPass::OBJECT);
  }
  gbuffer->SetChannels(channels);

  if (!gbuffer->RenderGeometry(s))
  {
    gbuffer->RenderAfterGeometry(s);
    this->NumberOfRenderedProps = gbuffer->GetNumberOfRenderedProps();
    return;
  }
  int vp[4];
  gbuffer->GetViewport(vp);
  const int w = vp[2], h = vp[3];
  const int ox = vp[0], oy = vp[1];

  // Scale of the full (possibly tiled, magnified) image. vtkWindow::GetSize() includes the tile
  // scale; the tile viewport says which part of the full image this pass renders.
  const int* fullWindow = renWin->GetSize();
  const double* rvp = ren->GetViewport();
  double tvp[4];
  renWin->GetTileViewport(tvp);
  int tileScale[2];
  renWin->GetTileScale(tileScale);
  const double fullHeight = (rvp[3] - rvp[1]) * fullWindow[1];
  const double pointSize = this->ReferenceHeight > 0.0
    ? std::max(fullHeight, 1.0) / this->ReferenceHeight
    : static_cast<double>(std::max(tileScale[1], 1));
  const double offset[2] = { std::round(tvp[0] * fullWindow[0] + ox - rvp[0] * fullWindow[0]),
    std::round(tvp[1] * fullWindow[1] + oy - rvp[1] * fullWindow[1]) };

  // World size of one pixel: k * depth in perspective, k in parallel projection. The tile's own
  // camera angle and height give the full image's pixel (vtkWindowToImageFilter narrows both).
  vtkCamera* cam = ren->GetActiveCamera();
  const bool parallel = cam->GetParallelProjection() != 0;
  double pixelWorld;
  if (parallel)
  {
    pixelWorld = 2.0 * cam->GetParallelScale() / h;
  }
  else
  {
    const double t = std::tan(vtkMath::RadiansFromDegrees(cam->GetViewAngle()) * 0.5);
    pixelWorld = 2.0 * t / (cam->GetUseHorizontalViewAngle() ? w : h);
  }
  if (!(pixelWorld > 0.0) || !std::isfinite(pixelWorld))
  {
    pixelWorld = 1.0;
  }
  // Object anchoring: pattern periods in world units, from the pixel size at the focal point
  // (constant while the camera orbits, proportional to the scene's scale).
  const double focalPixel = parallel ? pixelWorld : pixelWorld * cam->GetDistance();
  const double patternUnit = objectAnchor ? focalPixel * pointSize : pointSize;

  std::string defines;
  if (depthEdges)
  {
    defines += "#define COMIC_DEPTH_EDGES\n";
  }
  if (normalEdges)
  {
    defines += "#define COMIC_NORMAL_EDGES\n";
  }
  if (colorEdges)
  {
    defines += "#define COMIC_COLOR_EDGES\n";
  }
  if (this->Dots)
  {
    defines += "#define COMIC_DOTS\n";
  }
  if (this->Hatching)
  {
    defines += "#define COMIC_HATCH\n";
    if (this->CrossHatching)
    {
      defines += "#define COMIC_CROSS\n";
    }
  }
  if (objectAnchor)
  {
    defines += "#define COMIC_OBJECT_ANCHOR\n";
  }
  if (this->Tinted)
  {
    defines += "#define COMIC_TINTED\n";
  }
  defines += "#define COMIC_LAYER " + std::to_string(this->Layer) + "\n";

  vtkTextureObject* color = gbuffer->GetColorTexture();
  vtkTextureObject* depth = gbuffer->GetDepthTexture();
  vtkTextureObject* linear = gbuffer->GetLinearDepthTexture();
  vtkTextureObject* normal = gbuffer->GetNormalTexture();
  vtkTextureObject* position = gbuffer->GetPositionTexture();
  const int stride =
    std::max(1, static_cast<int>(std::lround(this->EdgeWidth * pointSize)));
  if (weightSum <= 0.0)
  {
    weightSum = 1.0;
  }

  auto setCommon = [&](vtkShaderProgram* program) {
    auto seti = [&](const char* name, int v) {
      if (program->IsUniformUsed(name))
      {
        program->SetUniformi(name, v);
      }
    };
    auto setf = [&](const char* name, double v) {
      if (program->IsUniformUsed(name))
      {
        program->SetUniformf(name, static_cast<float>(v));
      }
    };
    auto bind = [&](const char* name, vtkTextureObject* tex) {
      if (tex && program->IsUniformUsed(name))
      {
        tex->Activate();
        program->SetUniformi(name, tex->GetTextureUnit());
      }
    };
    bind("stylizeColorTexture", color);
    bind("stylizeDepthTexture", depth);
    bind("stylizeLinearDepthTexture", linear);
    bind("stylizeNormalTexture", normal);
    bind("stylizePositionTexture", position);
    const int size[2] = { w, h };
    if (program->IsUniformUsed("comicSize"))
    {
      program->SetUniform2i("comicSize", size);
    }
    const float off[2] = { static_cast<float>(offset[0]), static_cast<float>(offset[1]) };
    if (program->IsUniformUsed("comicPixelOffset"))
    {
      program->SetUniform2f("comicPixelOffset", off);
    }
    seti("comicParallel", parallel ? 1 : 0);
    setf("comicPixelWorld", pixelWorld);
    seti("comicStride", stride);
    const float weights[3] = { static_cast<float>(this->EdgeWeights[0] / weightSum),
      static_cast<float>(this->EdgeWeights[1] / weightSum),
      static_cast<float>(this->EdgeWeights[2] / weightSum) };
    if (program->IsUniformUsed("comicEdgeWeights"))
    {
      program->SetUniform3f("comicEdgeWeights", weights);
    }
    setf("comicDepthThreshold", this->DepthThreshold);
    setf("comicNormalThreshold", this->NormalThreshold);
    setf("comicColorThreshold", this->ColorThreshold);
    setf("comicDotSpacing", this->DotSpacing * patternUnit);
    setf("comicHatchSpacing", this->HatchSpacing * patternUnit);
    setf("comicHatchWidth", std::min(1.0, this->HatchWidth / this->HatchSpacing));
    const double a = vtkMath::RadiansFromDegrees(this->DotAngle);
    const float dir[2] = { static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a)) };
    if (program->IsUniformUsed("comicDotDirection"))
    {
      program->SetUniform2f("comicDotDirection", dir);
    }
    setf("comicHatchAngle", vtkMath::RadiansFromDegrees(this->HatchAngle));
    seti("comicHatchDirections", this->HatchDirections);
    setf("comicBright", this->BrightThreshold);
    setf("comicDark", this->DarkThreshold);
    setf("comicCross", this->CrossThreshold);
    seti("comicDiscardBackground", ren->Transparent() ? 1 : 0);
    gbuffer->SetDepthMappingUniforms(program);
  };
  auto unbindAll = [&]() {
    for (vtkTextureObject* tex : { color, depth, linear, normal, position,
           this->Internals->EdgeTexture })
    {
      if (tex && tex->GetTextureUnit() >= 0)
      {
        tex->Deactivate();
      }
    }
  };

  if (defines != this->Internals->Defines || this->Internals->Declarations.empty())
  {
    this->Internals->Defines = defines;
    this->Internals->Declarations =
      defines + vtkStylizeCommonFS + vtkStylizeDepthFS + vtkStylizeScreenFS + vtkComicFS;
    this->Internals->EdgeDeclarations =
      "#define COMIC_STAGE_EDGES\n" + this->Internals->Declarations;
  }
  const std::string& declarations = this->Internals->Declarations;
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  // Stage 1 (colour edges only): luminance of f_normal, k1 and k2 into the edge buffer.
  if (colorEdges)
  {
    this->Internals->AllocateEdgeBuffers(renWin, w, h);
    vtkOpenGLFramebufferObject* fbo = this->Internals->EdgeFramebuffer;
    fbo->SaveCurrentBindingsAndBuffers();
    fbo->Bind();
    fbo->AddColorAttachment(0, this->Internals->EdgeTexture);
    fbo->ActivateDrawBuffers(1);
    ostate->vtkglViewport(0, 0, w, h);
    ostate->vtkglScissor(0, 0, w, h);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    vtkShaderProgram* program = this->Internals->EdgeQuad.Prepare(
      renWin, this->Internals->EdgeDeclarations, "  comicMain();\n");
    if (program)
    {
      setCommon(program);
      this->Internals->EdgeQuad.Render();
    }
    else
    {
      vtkErrorMacro("Could not build the comic edge shader.");
    }
    unbindAll();
    fbo->UnBind();
    fbo->RestorePreviousBindingsAndBuffers();
  }
  else
  {
    this->Internals->FreeEdgeBuffers(renWin);
  }

  // Stage 2: edges, pattern and ink into the output framebuffer, with the geometry's depth.
  ostate->vtkglViewport(ox, oy, w, h);
  ostate->vtkglScissor(ox, oy, w, h);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  vtkShaderProgram* program =
    this->Internals->FinalQuad.Prepare(renWin, declarations, "  comicMain();\n");
  if (program)
  {
    setCommon(program);
    auto bind = [&](const char* name, vtkTextureObject* tex) {
      if (tex && program->IsUniformUsed(name))
      {
        tex->Activate();
        program->SetUniformi(name, tex->GetTextureUnit());
      }
    };
    bind("comicEdgeTexture", this->Internals->EdgeTexture);
    this->Internals->FinalQuad.Render();
  }
  else
  {
    vtkErrorMacro("Could not build the comic shader.");
  }
  unbindAll();
  vtkOpenGLCheckErrorMacro("failed after vtkComicPass::Render");

  gbuffer->RenderAfterGeometry(s);
  this->NumberOfRenderedProps = gbuffer->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
void vtkComicPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Internals->EdgeQuad.Release(w);
  this->Internals->FinalQuad.Release(w);
  this->Internals->FreeEdgeBuffers(w);
  this->Internals->GBuffer->ReleaseGraphicsResources(w);
}
