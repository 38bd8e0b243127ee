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
  if (!this->RenderScene(s, channels))
  {
    return;
  }
  int vp[4];
  gbuffer->GetViewport(vp);
  const int w = vp[2], h = vp[3];
  const int ox = vp[0], oy = vp[1];

  // Scale of the full (possibly tiled, magnified) image and this tile's offset in it.
  using Utilities = vtkStylizeShaderUtilities;
  const Utilities::FullImage full = Utilities::GetFullImage(ren, ox, oy);
  const double pointSize = this->ReferenceHeight > 0.0 ? full.Size[1] / this->ReferenceHeight
                                                       : static_cast<double>(full.TileScale[1]);

  // World size of one pixel: k * depth in perspective, k in parallel projection.
  vtkCamera* cam = ren->GetActiveCamera();
  const bool parallel = cam->GetParallelProjection() != 0;
  const double pixelWorld = Utilities::PixelWorldSize(cam, w, h);
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

  auto setCommon = [&](Utilities::Uniforms& u) {
    u.Texture("stylizeColorTexture", color)
      .Texture("stylizeDepthTexture", depth)
      .Texture("stylizeLinearDepthTexture", linear)
      .Texture("stylizeNormalTexture", normal)
      .Texture("stylizePositionTexture", position)
      .Int2("comicSize", w, h)
      .Float2("comicPixelOffset", full.Offset[0], full.Offset[1])
      .Int("comicParallel", parallel ? 1 : 0)
      .Float("comicPixelWorld", pixelWorld)
      .Int("comicStride", stride)
      .Float3("comicEdgeWeights", this->EdgeWeights[0] / weightSum,
        this->EdgeWeights[1] / weightSum, this->EdgeWeights[2] / weightSum)
      .Float("comicDepthThreshold", this->DepthThreshold)
      .Float("comicNormalThreshold", this->NormalThreshold)
      .Float("comicColorThreshold", this->ColorThreshold)
      .Float("comicDotSpacing", this->DotSpacing * patternUnit)
      .Float("comicHatchSpacing", this->HatchSpacing * patternUnit)
      .Float("comicHatchWidth", std::min(1.0, this->HatchWidth / this->HatchSpacing));
    const double a = vtkMath::RadiansFromDegrees(this->DotAngle);
    u.Float2("comicDotDirection", std::cos(a), std::sin(a))
      .Float("comicHatchAngle", vtkMath::RadiansFromDegrees(this->HatchAngle))
      .Int("comicHatchDirections", this->HatchDirections)
      .Float("comicBright", this->BrightThreshold)
      .Float("comicDark", this->DarkThreshold)
      .Float("comicCross", this->CrossThreshold)
      .SceneOutput(gbuffer, ren);
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
      Utilities::Uniforms u(program);
      setCommon(u);
      this->Internals->EdgeQuad.Render();
    }
    else
    {
      vtkErrorMacro("Could not build the comic edge shader.");
    }
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
    Utilities::Uniforms u(program);
    setCommon(u);
    u.Texture("comicEdgeTexture", this->Internals->EdgeTexture);
    this->Internals->FinalQuad.Render();
  }
  else
  {
    vtkErrorMacro("Could not build the comic shader.");
  }
  vtkOpenGLCheckErrorMacro("failed after vtkComicPass::Render");

  this->FinishScene(s);
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
