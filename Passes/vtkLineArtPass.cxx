#include "vtkLineArtPass.h"

#include "vtkAppendPolyData.h"
#include "vtkComicPatterns.h"
#include "vtkFloatArray.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkStylizeFeatureLines.h"
#include "vtkStylizeFeatureStrokes.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeShaderUtilities.h"
#include "vtkWeakPointer.h"

#include "vtkLineArtFS.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <vector>

namespace
{
enum Stages
{
  FINAL_STAGE = 0 // paper, tone and ink into the output
};
constexpr vtkStylizeStage LineArtStages[] = {
  { FINAL_STAGE, "LINE_ART_STAGE_FINAL", "LINE_ART_STAGE_FINAL" },
};
static_assert(vtkStylizeStagesInOrder(LineArtStages), "the line art's stages out of order");
}

struct vtkLineArtPass::Internals
{
  vtkNew<vtkStylizeFeatureStrokes> Strokes;
  /** The translucent layers' outlines (TranslucentOutlines). */
  vtkNew<vtkStylizeFeatureStrokes> LayerStrokes;
  vtkWeakPointer<vtkRenderer> LastRenderer;
};

vtkStandardNewMacro(vtkLineArtPass);

//------------------------------------------------------------------------------
vtkLineArtPass::vtkLineArtPass()
  : vtkStylizeStylePass(vtkStylizeLightingPass::STANDARD)
  , Internal(new Internals)
{
  this->InteractiveImageReduction = 2; // the most expensive styles: a preview while dragging
  this->SetStages(vtkLineArtFS, "  lineArtMain();\n",
    std::vector<vtkStylizeStage>(std::begin(LineArtStages), std::end(LineArtStages)));
  this->ForwardProgress(this->Internal->Strokes);
}

//------------------------------------------------------------------------------
vtkLineArtPass::~vtkLineArtPass()
{
  delete this->Internal;
}

//------------------------------------------------------------------------------
void vtkLineArtPass::SetInkColor(double r, double g, double b)
{
  if (SetClampedColor(this->InkColor, r, g, b))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLineArtPass::SetPaperColor(double r, double g, double b)
{
  if (SetClampedColor(this->PaperColor, r, g, b))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkLineArtPass::SwapLayer(int layer)
{
  const int previous = this->Layer;
  this->SetLayer(layer);
  return previous;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkLineArtPass::GetStrokes()
{
  return this->Internal->Strokes->GetStrokes();
}

//------------------------------------------------------------------------------
namespace
{
/** The strokes' settings from the pass's. */
vtkStylizeFeatureStrokes::Settings StrokeSettings(vtkLineArtPass* pass)
{
  vtkStylizeFeatureStrokes::Settings s;
  s.Widths[vtkStylizeFeatureLines::CONTOUR] = pass->GetContourWidth();
  s.Widths[vtkStylizeFeatureLines::BOUNDARY] = pass->GetContourWidth();
  s.Widths[vtkStylizeFeatureLines::CREASE] = pass->GetCreaseWidth();
  s.Widths[vtkStylizeFeatureLines::RIDGE] = pass->GetRidgeWidth();
  s.Widths[vtkStylizeFeatureLines::VALLEY] = pass->GetValleyWidth();
  s.Widths[vtkStylizeFeatureLines::SUGGESTIVE_CONTOUR] = pass->GetSuggestiveWidth();
  s.DepthTaper = pass->GetDepthTaper();
  s.StrengthTaper = pass->GetStrengthTaper();
  s.CreaseAngle = pass->GetCreaseAngle();
  s.RidgeThreshold = pass->GetRidgeThreshold();
  s.SuggestiveThreshold = pass->GetSuggestiveThreshold();
  return s.WithIsoLines(pass->GetIsoLines(), pass->GetIsoLineWidth(), pass->GetIsoLineSpacing());
}

/** The translucent surfaces' lines: their outline (TranslucentOutlines), or none. */
vtkStylizeFeatureStrokes::Settings OutlineSettings(vtkLineArtPass* pass)
{
  vtkStylizeFeatureStrokes::Settings s = StrokeSettings(pass);
  for (int k = 0; k < vtkStylizeFeatureStrokes::Kinds; ++k)
  {
    const bool outline =
      k == vtkStylizeFeatureLines::CONTOUR || k == vtkStylizeFeatureLines::BOUNDARY;
    s.Widths[k] = outline && pass->GetTranslucentOutlines() ? s.Widths[k] : 0.0;
  }
  s.Translucent = true;
  return s;
}
}

//------------------------------------------------------------------------------
vtkPolyData* vtkLineArtPass::ComputeFigureStrokes(int width, int height, int tiles)
{
  Internals& in = *this->Internal;
  vtkPolyData* strokes =
    in.Strokes->RenderFigure(this, in.LastRenderer, StrokeSettings(this), width, height, tiles);
  // The translucent surfaces' outlines, as the frame's translucent layers draw them (on one
  // process: several would need the opaque pieces gathered as occluders of the translucent ones).
  vtkMultiProcessController* c = this->GetGBufferPass()->GetController();
  if (!this->TranslucentOutlines || this->GetTranslucentLayers() == 0 || !in.LastRenderer ||
    (c && c->GetNumberOfProcesses() > 1))
  {
    return strokes;
  }
  vtkPolyData* outlines = in.LayerStrokes->RenderFigure(
    this, in.LastRenderer, OutlineSettings(this), width, height, tiles);
  if (outlines->GetNumberOfCells() > 0)
  {
    // (the opaque lines' ink behind translucent surfaces, StrokeInk: the outlines at full ink,
    // so that the append keeps the array)
    if (strokes->GetPointData()->GetArray("StrokeInk") &&
      !outlines->GetPointData()->GetArray("StrokeInk"))
    {
      vtkNew<vtkFloatArray> full;
      full->SetName("StrokeInk");
      full->SetNumberOfTuples(outlines->GetNumberOfPoints());
      full->Fill(1.0);
      outlines->GetPointData()->AddArray(full);
    }
    vtkNew<vtkAppendPolyData> append;
    append->AddInputData(strokes);
    append->AddInputData(outlines);
    append->Update();
    strokes->ShallowCopy(append->GetOutput());
  }
  return strokes;
}

//------------------------------------------------------------------------------
double vtkLineArtPass::GetReach(const Frame& frame)
{
  return vtkStylizeFeatureStrokes::Reach(StrokeSettings(this), this->PointSize(frame)) + 1.0;
}

//------------------------------------------------------------------------------
double vtkLineArtPass::GetVolumeOutlineWidth(vtkRenderer* ren)
{
  // a contour's width in pixels of one tile (the G-buffer widens lines by the tile scale)
  const int* size = ren ? ren->GetSize() : nullptr;
  const double scale =
    this->ReferenceHeight > 0.0 && size && size[1] > 0 ? size[1] / this->ReferenceHeight : 1.0;
  return this->TranslucentOutlines ? std::max(1.0, this->ContourWidth * scale) : 0.0;
}

//------------------------------------------------------------------------------
void vtkLineArtPass::ConfigureLightingColors(vtkStylizeLightingPass* lighting)
{
  // gray on white paper: the light's tone, darkened by a solid colour's lightness (as the
  // sketch's), not by a colour map's
  lighting->SetColorMode(vtkStylizeLightingPass::LIGHT_TONE);
  lighting->SetSolidColorTones(true);
}

//------------------------------------------------------------------------------
bool vtkLineArtPass::RenderStyle(const vtkRenderState* s, const Frame& frame)
{
  SceneRequest scene;
  scene.Channels = vtkStylizeGBufferPass::LINEAR_DEPTH;
  if (!this->RenderScene(s, scene))
  {
    return false;
  }
  std::string defines;
  AddDefine(defines, this->Tone == SHADES, "LINE_ART_SHADES");
  AddDefine(defines, this->Tone == DOTS, "LINE_ART_DOTS");
  if (this->Tone == DOTS)
  {
    defines += vtkComicPatterns::ShaderDefines(); // the comic's dot, shared
  }
  defines += "#define LINE_ART_LAYER " + std::to_string(this->Layer) + "\n";
  this->SetShaderDefines(defines);

  // The lines against the scene's depth (every actor's), as strokes, their ink as a texture.
  // Lines are found on opaque surfaces; a translucent layer is its paper (or tone) alone, laid
  // over the line art with the surface's opacity.
  Internals& in = *this->Internal;
  in.LastRenderer = frame.Renderer;
  const bool layer = this->GetTranslucentLayer() > 0;
  const vtkStylizeFeatureStrokes::Settings settings =
    layer ? OutlineSettings(this) : StrokeSettings(this);
  vtkTextureObject* ink =
    (layer ? in.LayerStrokes : in.Strokes)->RenderFrame(this, frame, settings);

  const int margin =
    static_cast<int>(std::ceil(vtkStylizeFeatureStrokes::Reach(settings, this->PointSize(frame))));
  this->RenderStageToOutput(
    frame, FINAL_STAGE, true,
    [&](vtkStylizeUniforms& u)
    {
      this->BindSceneTextures(u);
      u.Texture("lineArtInk", ink)
        .Float3("lineArtInkColor", this->InkColor[0], this->InkColor[1], this->InkColor[2])
        .Float3("lineArtPaperColor", this->PaperColor[0], this->PaperColor[1], this->PaperColor[2])
        .Int("lineArtToneLevels", this->ToneLevels)
        .Float("lineArtToneDarkest", std::isfinite(this->ToneDarkest) ? this->ToneDarkest : 0.6)
        .Float("lineArtDotSpacing",
          (std::isfinite(this->DotSpacing) ? this->DotSpacing : 8.0) * this->PointSize(frame))
        .Float2("lineArtPixelOffset", frame.FullOffset[0], frame.FullOffset[1]);
      this->SetSceneOutputUniforms(u, frame.Renderer);
    },
    margin);
  return true;
}

//------------------------------------------------------------------------------
void vtkLineArtPass::ReleaseStyleResources(vtkWindow* w)
{
  this->Internal->Strokes->Free(w);
  this->Internal->LayerStrokes->Free(w);
}

//------------------------------------------------------------------------------
vtkIdType vtkLineArtPass::GetStyleTextureBytes()
{
  return this->Internal->Strokes->GetTextureBytes() +
    this->Internal->LayerStrokes->GetTextureBytes();
}

//------------------------------------------------------------------------------
void vtkLineArtPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ContourWidth: " << this->ContourWidth << " pt\n";
  os << indent << "CreaseWidth: " << this->CreaseWidth << " pt\n";
  os << indent << "RidgeWidth: " << this->RidgeWidth << " pt\n";
  os << indent << "ValleyWidth: " << this->ValleyWidth << " pt\n";
  os << indent << "SuggestiveWidth: " << this->SuggestiveWidth << " pt\n";
  os << indent << "DepthTaper: " << this->DepthTaper << "\n";
  os << indent << "StrengthTaper: " << this->StrengthTaper << "\n";
  os << indent << "CreaseAngle: " << this->CreaseAngle << " deg\n";
  os << indent << "RidgeThreshold: " << this->RidgeThreshold << "\n";
  os << indent << "SuggestiveThreshold: " << this->SuggestiveThreshold << "\n";
  os << indent << "TranslucentOutlines: " << (this->TranslucentOutlines ? "on" : "off") << "\n";
  os << indent
     << "Tone: " << (this->Tone == DOTS ? "dots" : (this->Tone == SHADES ? "shades" : "none"))
     << "\n";
  os << indent << "DotSpacing: " << this->DotSpacing << " pt\n";
  os << indent << "ToneLevels: " << this->ToneLevels << "\n";
  os << indent << "ToneDarkest: " << this->ToneDarkest << "\n";
  os << indent << "InkColor: " << this->InkColor[0] << " " << this->InkColor[1] << " "
     << this->InkColor[2] << "\n";
  os << indent << "PaperColor: " << this->PaperColor[0] << " " << this->PaperColor[1] << " "
     << this->PaperColor[2] << "\n";
  os << indent << "ReferenceHeight: " << this->ReferenceHeight << " px\n";
  os << indent << "Layer: " << (this->Layer == PAPER ? "paper" : "line art") << "\n";
}
