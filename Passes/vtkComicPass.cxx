#include "vtkComicPass.h"

#include "vtkCamera.h"
#include "vtkComicPatterns.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkStylizeDirectionField.h"
#include "vtkStylizeFeatureStrokes.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeShaderUtilities.h"
#include "vtk_glew.h"

#include "vtkComicFS.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <vector>

namespace
{
// The direction field's stages follow these (vtkStylizeDirectionField::AddStages()).
enum Stages
{
  EDGE_STAGE = 0,     // luminance of f_normal, k1 and k2 (colour edges only)
  COMPOSITE_STAGE = 1 // edges, pattern and ink into the output
};
constexpr vtkStylizeStage ComicStages[] = {
  { EDGE_STAGE, "COMIC_STAGE_EDGES", "COMIC_STAGE_EDGES" },
  { COMPOSITE_STAGE, "COMIC_STAGE_COMPOSITE", "COMIC_STAGE_COMPOSITE" },
};
static_assert(vtkStylizeStagesInOrder(ComicStages), "the comic's stages out of order");
enum Textures
{
  EDGE_TEXTURE = 0
};
}

/** What a frame computes: only the enabled stages, and only their channels. */
struct vtkComicPass::Plan
{
  bool DepthEdges, NormalEdges, ColorEdges, ObjectAnchor;
  bool FeatureLines;                          // the feature lines' strokes (and the iso-lines)
  vtkStylizeFeatureStrokes::Settings Strokes; // their settings
  bool Principal;                             // hatching along the principal direction field
  FieldSettings Field;                        // its settings: the defaults
  double WeightSum;                           // of the enabled edge phases, 1 when none
  SceneRequest Scene;
  std::string Defines;
};

vtkStandardNewMacro(vtkComicPass);

//------------------------------------------------------------------------------
vtkComicPass::vtkComicPass()
  : vtkStylizeStylePass(vtkStylizeLightingPass::COMIC)
  , Field(vtkStylizeDirectionField::New())
  , Strokes(vtkStylizeFeatureStrokes::New())
{
  std::string source = vtkComicFS;
  std::string mainCall = "  comicMain();\n";
  std::vector<vtkStylizeStage> stages(std::begin(ComicStages), std::end(ComicStages));
  this->Field->AddStages(source, mainCall, stages);
  this->SetStages(source, mainCall, stages);
  this->ForwardProgress(this->Strokes);
}

//------------------------------------------------------------------------------
vtkComicPass::~vtkComicPass()
{
  this->Field->Delete();
  this->Strokes->Delete();
}

//------------------------------------------------------------------------------
void vtkComicPass::ReleaseStyleResources(vtkWindow* w)
{
  this->Field->Free(w);
  this->Strokes->Free(w);
}

//------------------------------------------------------------------------------
vtkIdType vtkComicPass::GetStyleTextureBytes()
{
  return this->Field->GetTextureBytes() + this->Strokes->GetTextureBytes();
}

//------------------------------------------------------------------------------
void vtkComicPass::SetEdgeWeights(double depth, double normal, double color)
{
  auto clamp01 = [](double v) { return std::isfinite(v) ? std::min(1.0, std::max(0.0, v)) : 0.0; };
  const double w[3] = { clamp01(depth), clamp01(normal), clamp01(color) };
  if (w[0] != this->EdgeWeights[0] || w[1] != this->EdgeWeights[1] || w[2] != this->EdgeWeights[2])
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
  os << indent << "FeatureLines: " << this->FeatureLines << "\n";
  os << indent << "FeatureLineWidth: " << this->FeatureLineWidth << " pt\n";
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
  os << indent
     << "HatchOrientation: " << (this->HatchOrientation == PRINCIPAL ? "principal" : "fixed")
     << "\n";
  os << indent << "Tint: " << this->Tint << "\n";
  os << indent << "Anchor: " << (this->Anchor == OBJECT ? "object" : "screen") << "\n";
  os << indent << "Layer: "
     << (this->Layer == EDGES ? "edges" : (this->Layer == PATTERN ? "pattern" : "comic")) << "\n";
  os << indent << "ReferenceHeight: " << this->ReferenceHeight << " px\n";
}

//------------------------------------------------------------------------------
void vtkComicPass::ConfigureLightingColors(vtkStylizeLightingPass* lighting)
{
  lighting->SetColorMode(ColorModeForTint(this->Tint));
  // A dark solid colour (black glyphs, a dark part) is hatched as a comic's inker would; light
  // ones (VTK's white, ParaView's, the program's light gray) stay paper in the light.
  lighting->SetSolidColorTones(true);
  lighting->SetSolidColorWhite(0.75);
}

//------------------------------------------------------------------------------
bool vtkComicPass::RenderStyle(const vtkRenderState* s, const Frame& frame)
{
  const Plan plan = this->PlanFrame(frame.Interactive);
  if (!this->RenderScene(s, plan.Scene))
  {
    return false;
  }
  this->SetShaderDefines(plan.Defines);
  if (plan.ColorEdges)
  {
    this->RenderEdgeStage(frame, plan);
  }
  else
  {
    this->FreeTexture(EDGE_TEXTURE);
  }
  if (plan.Principal)
  {
    this->Field->Render(this, frame, plan.Field, this->PointSize(frame));
  }
  else
  {
    this->Field->Free(frame.Window);
  }
  if (plan.FeatureLines)
  {
    this->Strokes->RenderFrame(this, frame, plan.Strokes);
  }
  else
  {
    this->Strokes->Free(frame.Window);
  }
  this->RenderCompositeStage(frame, plan);
  return true;
}

//------------------------------------------------------------------------------
vtkComicPass::Plan vtkComicPass::PlanFrame(bool interactive) const
{
  Plan p;
  const double weightSum = this->EdgeWeights[0] + this->EdgeWeights[1] + this->EdgeWeights[2];
  const bool edges = this->Edges && weightSum > 0.0;
  p.WeightSum = weightSum > 0.0 ? weightSum : 1.0;
  p.DepthEdges = edges && this->EdgeWeights[0] > 0.0;
  // The interactive variant draws the outline and the patterns only: no normal or colour edges
  // (the normal channel is not rendered unless normal-directed hatching reads it) and hatching
  // at the fixed angle (no direction field).
  p.NormalEdges = edges && this->EdgeWeights[1] > 0.0 && !interactive;
  p.ColorEdges = edges && this->EdgeWeights[2] > 0.0 && !interactive;
  p.Strokes = vtkStylizeFeatureStrokes::Settings::ForStyle(this->FeatureLines,
    this->FeatureLineWidth, this->IsoLines, this->IsoLineWidth, this->IsoLineSpacing);
  p.FeatureLines = ((this->FeatureLines && this->FeatureLineWidth > 0.0) || this->IsoLines > 0) &&
    this->GetTranslucentLayer() == 0;
  const bool patterns = this->Dots || this->Hatching;
  p.ObjectAnchor = patterns && this->Anchor == OBJECT;
  p.Principal = this->Hatching && this->HatchOrientation == PRINCIPAL && !interactive;
  const bool normalHatch = this->Hatching && this->HatchDirections > 0;

  p.Scene.Channels = vtkStylizeGBufferPass::LINEAR_DEPTH;
  if (p.NormalEdges || normalHatch || p.Principal)
  {
    p.Scene.Channels |= vtkStylizeGBufferPass::NORMAL;
  }
  if (p.ObjectAnchor)
  {
    p.Scene.Channels |= vtkStylizeGBufferPass::POSITION;
    p.Scene.PositionSpace = vtkStylizeGBufferPass::OBJECT;
  }

  if (p.Principal)
  {
    p.Defines = vtkStylizeDirectionField::Defines(p.Field);
  }
  auto define = [&p](bool on, const std::string& name) { AddDefine(p.Defines, on, name); };
  define(p.Principal, "COMIC_HATCH_PRINCIPAL");
  define(p.DepthEdges, "COMIC_DEPTH_EDGES");
  define(p.NormalEdges, "COMIC_NORMAL_EDGES");
  define(p.ColorEdges, "COMIC_COLOR_EDGES");
  define(p.FeatureLines, "COMIC_FEATURE_LINES");
  define(this->Dots, "COMIC_DOTS");
  define(this->Hatching, "COMIC_HATCH");
  define(this->Hatching && this->CrossHatching, "COMIC_CROSS");
  define(p.ObjectAnchor, "COMIC_OBJECT_ANCHOR");
  define(this->Tint != BLACK_AND_WHITE, "COMIC_TINTED");
  p.Defines += "#define COMIC_LAYER " + std::to_string(this->Layer) + "\n";
  // the pattern's constants, shared with the vector figure
  p.Defines += vtkComicPatterns::ShaderDefines();
  return p;
}

//------------------------------------------------------------------------------
void vtkComicPass::SetStageUniforms(vtkStylizeUniforms& u, const Frame& frame, const Plan& plan)
{
  const double pointSize = this->PointSize(frame);
  // Object anchoring: pattern periods in world units, from the pixel size at the focal point
  // (constant while the camera orbits, proportional to the scene's scale).
  const double focalPixel = vtkStylizeDirectionField::FocalPixelWorld(frame);
  const double patternUnit = plan.ObjectAnchor ? focalPixel * pointSize : pointSize;
  const int stride = std::max(1, static_cast<int>(std::lround(this->EdgeWidth * pointSize)));
  const double* weights = this->EdgeWeights;
  const double dotAngle = vtkMath::RadiansFromDegrees(this->DotAngle);

  if (plan.Principal)
  {
    this->SetFieldUniforms(u, frame); // the G-buffer textures and the field's camera
    u.Texture("comicField", this->Field->GetTexture())
      .Int("comicHatchSteps", vtkComicPatterns::PrincipalSteps(this->HatchDirections));
  }
  else
  {
    this->BindSceneTextures(u);
  }
  u.Int2("comicSize", frame.Size[0], frame.Size[1])
    .Float2("comicPixelOffset", frame.FullOffset[0], frame.FullOffset[1])
    .Int("comicParallel", frame.Parallel ? 1 : 0)
    .Float("comicPixelWorld", frame.PixelWorld)
    .Int("comicStride", stride)
    .Float3("comicEdgeWeights", weights[0] / plan.WeightSum, weights[1] / plan.WeightSum,
      weights[2] / plan.WeightSum)
    .Float("comicDepthThreshold", this->DepthThreshold)
    .Float("comicNormalThreshold", this->NormalThreshold)
    .Float("comicColorThreshold", this->ColorThreshold)
    .Float("comicDotSpacing", this->DotSpacing * patternUnit)
    .Float("comicHatchSpacing", this->HatchSpacing * patternUnit)
    .Float(
      "comicHatchWidth", vtkComicPatterns::HatchWidthFraction(this->HatchWidth, this->HatchSpacing))
    .Float2("comicDotDirection", std::cos(dotAngle), std::sin(dotAngle))
    .Float("comicHatchAngle", vtkMath::RadiansFromDegrees(this->HatchAngle))
    .Int("comicHatchDirections", this->HatchDirections)
    .Float("comicBright", this->BrightThreshold)
    .Float("comicDark", this->DarkThreshold)
    .Float("comicCross", this->CrossThreshold)
    .Int("comicEmittedLayer", this->GetTranslucentLayerEmitted() ? 1 : 0);
  this->SetSceneOutputUniforms(u, frame.Renderer);
}

//------------------------------------------------------------------------------
void vtkComicPass::AnchorToSurface(bool)
{
  this->SavedAnchor = this->Anchor;
  this->SetAnchor(OBJECT);
}

//------------------------------------------------------------------------------
void vtkComicPass::RestoreAnchors()
{
  this->SetAnchor(this->SavedAnchor);
}

//------------------------------------------------------------------------------
vtkPolyData* vtkComicPass::ComputeFigureStrokes(int width, int height, int tiles)
{
  const Plan plan = this->PlanFrame(false);
  vtkRenderer* renderer = this->Strokes->GetLastRenderer();
  if (!plan.FeatureLines || !renderer)
  {
    this->NoStrokes->Initialize();
    return this->NoStrokes;
  }
  return this->Strokes->RenderFigure(this, renderer, plan.Strokes, width, height, tiles);
}

//------------------------------------------------------------------------------
int vtkComicPass::SwapLayer(int layer)
{
  const int previous = this->Layer;
  this->SetLayer(layer);
  return previous;
}

//------------------------------------------------------------------------------
double vtkComicPass::GetReach(const Frame& frame)
{
  const Plan plan = this->PlanFrame(frame.Interactive);
  const double pointSize = this->PointSize(frame);
  const double stride = std::max(1.0, std::round(this->EdgeWidth * pointSize));
  // Colour edges: the composite stage's taps read the edge stage's, which read their own.
  double reach = (plan.ColorEdges ? 2.0 : 1.0) * stride + 1.0;
  if (plan.Principal)
  {
    reach = std::max(reach, vtkStylizeDirectionField::Reach(frame, plan.Field, pointSize) + 1.0);
  }
  if (plan.FeatureLines)
  {
    reach = std::max(reach, vtkStylizeFeatureStrokes::Reach(plan.Strokes, pointSize) + 1.0);
  }
  return reach;
}

//------------------------------------------------------------------------------
void vtkComicPass::RenderEdgeStage(const Frame& frame, const Plan& plan)
{
  const int w = frame.Size[0], h = frame.Size[1];
  vtkTextureObject* edges = this->EnsureTexture(EDGE_TEXTURE, w, h, GL_RGBA16F);
  this->RenderStage(EDGE_STAGE, { edges }, w, h,
    [&](vtkStylizeUniforms& u) { this->SetStageUniforms(u, frame, plan); });
}

//------------------------------------------------------------------------------
void vtkComicPass::RenderCompositeStage(const Frame& frame, const Plan& plan)
{
  // Away from the scene only the outline (within the edge stride of a surface) differs from
  // the background, unless colour edges also find the background's own gradients (or a
  // figure's layer records the background as such).
  int margin = std::max(1, static_cast<int>(std::lround(this->EdgeWidth * this->PointSize(frame))));
  if (plan.FeatureLines)
  {
    // the strokes reach beyond the surfaces by half their width
    margin = std::max(margin,
      static_cast<int>(
        std::ceil(vtkStylizeFeatureStrokes::Reach(plan.Strokes, this->PointSize(frame)))));
  }
  this->RenderStageToOutput(
    frame, COMPOSITE_STAGE, true,
    [&](vtkStylizeUniforms& u)
    {
      this->SetStageUniforms(u, frame, plan);
      u.Texture("comicEdgeTexture", this->TextureSlot(EDGE_TEXTURE));
      if (plan.FeatureLines)
      {
        u.Texture("comicFeatureInk", this->Strokes->GetTexture());
      }
    },
    plan.ColorEdges || this->Layer >= FIGURE_INPUTS ? -1 : margin);
}
