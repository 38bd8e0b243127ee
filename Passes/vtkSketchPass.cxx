#include "vtkSketchPass.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkStylizeDirectionField.h"
#include "vtkStylizeFeatureStrokes.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeShaderUtilities.h"
#include "vtkTextureObject.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include "vtkSketchFS.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <utility>
#include <vector>

namespace
{
constexpr int NoiseTextureSize = 64;
constexpr int NoiseCell = 8;        // lattice period of Perlin and cell size of Worley, texels
constexpr double SparseDots = 0.05; // SPARSE: the share of texels that hold a dot
// SPARSE: the smallest texel, window pixels. The strokes are then wider than a pixel's
// sampling can alias (their profile is band-limited), so a sub-pixel motion moves them
// smoothly; at 1 point on a 600-pixel image (0.56 pixel) they are resampled.
constexpr double SparseMinimumTexel = 1.7;
// SPARSE: the shortest LIC step, texels (10 steps each side: strokes of 10 texels or more).
constexpr double SparseStepPerTexel = 0.5;
constexpr int InteractiveSteps = 4; // LIC steps on each side in the interactive variant

// Uniform value in [0, 1) from a 32-bit generator, the same on every standard library.
double Uniform(std::mt19937& rng)
{
  return static_cast<double>(rng() >> 8) / 16777216.0;
}

double Fade(double t)
{
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

// The direction field's stages follow these (vtkStylizeDirectionField::AddStages()).
enum Stages
{
  BLUR_X_STAGE = 0, // strided blur of the lit luminance, x then y
  BLUR_Y_STAGE,
  FINAL_STAGE // strokes and tone into the output
};
constexpr vtkStylizeStage SketchStages[] = {
  { BLUR_X_STAGE, "SKETCH_STAGE_BLUR_X", "SKETCH_STAGE_BLUR_X" },
  { BLUR_Y_STAGE, "SKETCH_STAGE_BLUR_Y", "SKETCH_STAGE_BLUR_Y" },
  { FINAL_STAGE, "SKETCH_STAGE_FINAL", "SKETCH_STAGE_FINAL" },
};
static_assert(vtkStylizeStagesInOrder(SketchStages), "the sketch's stages out of order");
enum Textures
{
  BLUR_X = 0,
  BLUR_Y,
  NOISE
};
}

class vtkSketchPass::vtkInternals
{
public:
  vtkNew<vtkStylizeDirectionField> Field;
  /** The feature lines' strokes. */
  vtkNew<vtkStylizeFeatureStrokes> Strokes;
  int NoiseKind = -1;
  double NoiseStats[2] = { 0.5, 0.29 };

  // Mappers given the direction attribute, and the array name they were given.
  std::vector<std::pair<vtkWeakPointer<vtkOpenGLPolyDataMapper>, std::string>> Mapped;
  // MODEL found no direction data in the last frame, and said so.
  bool ModelInertWarned = false;
};

/** What a frame computes: the enabled stages, their channels and defines, lengths in pixels. */
struct vtkSketchPass::Plan
{
  bool Model, Strokes, ObjectNoise, Contrast;
  bool FeatureLines; // the feature lines' strokes (in the SKETCH layer)
  SceneRequest Scene;
  std::string Defines;
  FieldSettings Field; // the direction field's settings (NaN settings replaced)
  // Settings as used (a NaN setting counts as its range's minimum), lengths in pixels.
  double PointSize;  // pixels per point
  double FocalPixel; // world size of a pixel at the focal distance
  double StepLength, StrokeContrast, CrossThreshold, ContrastSetting;
  int Steps; // LIC steps on each side
  int BlurSize[2];
  double BlurRadius; // pixels
  double NoiseUnit;
};

vtkStandardNewMacro(vtkSketchPass);

//------------------------------------------------------------------------------
vtkSketchPass::vtkSketchPass()
  : vtkStylizeStylePass(vtkStylizeLightingPass::STANDARD)
  , Internals(new vtkInternals)
{
  this->InteractiveImageReduction = 2; // the most expensive styles: a preview while dragging
  std::string source = vtkSketchFS;
  std::string mainCall = "  sketchMain();\n";
  std::vector<vtkStylizeStage> stages(std::begin(SketchStages), std::end(SketchStages));
  this->Internals->Field->AddStages(source, mainCall, stages);
  this->SetStages(source, mainCall, stages);
  this->SetDirectionArrayName("PrincipalDirectionMinAbs");
  this->ForwardProgress(this->Internals->Strokes);
}

//------------------------------------------------------------------------------
void vtkSketchPass::AnchorToSurface(bool keepNoise)
{
  this->SavedNoise = this->Noise;
  this->SavedNoiseSpace = this->NoiseSpace;
  this->SetNoiseSpace(OBJECT);
  if (!keepNoise)
  {
    this->SetNoise(SPARSE); // strokes that hold still
  }
}

//------------------------------------------------------------------------------
void vtkSketchPass::RestoreAnchors()
{
  this->SetNoise(this->SavedNoise);
  this->SetNoiseSpace(this->SavedNoiseSpace);
}

//------------------------------------------------------------------------------
void vtkSketchPass::ConfigureLightingColors(vtkStylizeLightingPass* lighting)
{
  lighting->SetColorMode(ColorModeForTint(this->Tint));
  lighting->SetSolidColorTones(true);
}

//------------------------------------------------------------------------------
int vtkSketchPass::SwapLayer(int layer)
{
  const int previous = this->Layer;
  this->SetLayer(layer);
  return previous;
}

//------------------------------------------------------------------------------
double vtkSketchPass::GetPointReferenceHeight()
{
  return std::isfinite(this->ReferenceHeight) ? this->ReferenceHeight : 0.0;
}

//------------------------------------------------------------------------------
vtkSketchPass::~vtkSketchPass()
{
  this->SetDirectionArrayName(nullptr);
}

//------------------------------------------------------------------------------
void vtkSketchPass::SetNeighbors(int n)
{
  const int snapped = n <= 2 ? 2 : (n <= 5 ? 4 : 8);
  if (snapped != this->Neighbors)
  {
    this->Neighbors = snapped;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkSketchPass::SetBrightThresholds(double t1, double t2)
{
  auto clamp01 = [](double v, double fallback)
  { return std::isfinite(v) ? std::min(1.0, std::max(0.0, v)) : fallback; };
  t1 = clamp01(t1, this->BrightThresholds[0]);
  t2 = std::max(t1, clamp01(t2, this->BrightThresholds[1]));
  if (t1 != this->BrightThresholds[0] || t2 != this->BrightThresholds[1])
  {
    this->BrightThresholds[0] = t1;
    this->BrightThresholds[1] = t2;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkSketchPass::SetPencilColor(double r, double g, double b)
{
  if (SetClampedColor(this->PencilColor, r, g, b))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkSketchPass::SetPaperColor(double r, double g, double b)
{
  if (SetClampedColor(this->PaperColor, r, g, b))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkSketchPass::GenerateNoise(int kind, int size, vtkFloatArray* out)
{
  if (!out)
  {
    return;
  }
  size = std::min(128, std::max(8, size));
  size -= size % NoiseCell;
  const int cells = size / NoiseCell;
  const vtkIdType total = static_cast<vtkIdType>(size) * size * size;
  out->SetNumberOfComponents(1);
  out->SetNumberOfTuples(total);
  std::mt19937 rng(20261121u + static_cast<unsigned>(kind));
  auto wrap = [&](int i) { return ((i % cells) + cells) % cells; };
  auto cellIndex = [&](int i, int j, int k)
  { return (wrap(k) * cells + wrap(j)) * cells + wrap(i); };

  // Evaluates value(p, c) at every texel centre p (in lattice cells; c = floor(p)), then scales
  // the values linearly to [0, 1].
  auto fill = [&](const std::function<double(const double*, const int*)>& value)
  {
    std::vector<double> raw(static_cast<size_t>(total));
    for (int z = 0; z < size; ++z)
    {
      for (int y = 0; y < size; ++y)
      {
        for (int x = 0; x < size; ++x)
        {
          const double p[3] = { (x + 0.5) / NoiseCell, (y + 0.5) / NoiseCell,
            (z + 0.5) / NoiseCell };
          const int c[3] = { static_cast<int>(std::floor(p[0])), static_cast<int>(std::floor(p[1])),
            static_cast<int>(std::floor(p[2])) };
          raw[(static_cast<size_t>(z) * size + y) * size + x] = value(p, c);
        }
      }
    }
    const auto range = std::minmax_element(raw.begin(), raw.end());
    const double lo = kind == WORLEY ? 0.0 : *range.first; // Worley: a distance, from 0
    const double span = *range.second > lo ? *range.second - lo : 1.0;
    for (vtkIdType i = 0; i < total; ++i)
    {
      out->SetValue(i, static_cast<float>((raw[i] - lo) / span));
    }
  };

  if (kind == PERLIN)
  {
    // Gradient noise on a lattice of period `cells`: random unit gradients, quintic fade.
    std::vector<std::array<double, 3>> gradients(static_cast<size_t>(cells) * cells * cells);
    for (auto& g : gradients)
    {
      double l2 = 0.0;
      do
      {
        for (double& c : g)
        {
          c = 2.0 * Uniform(rng) - 1.0;
        }
        l2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
      } while (l2 > 1.0 || l2 < 1e-4);
      for (double& c : g)
      {
        c /= std::sqrt(l2);
      }
    }
    fill(
      [&](const double* p, const int* c)
      {
        const double f[3] = { p[0] - c[0], p[1] - c[1], p[2] - c[2] };
        double v = 0.0;
        for (int corner = 0; corner < 8; ++corner)
        {
          const int o[3] = { corner & 1, (corner >> 1) & 1, (corner >> 2) & 1 };
          const auto& g = gradients[cellIndex(c[0] + o[0], c[1] + o[1], c[2] + o[2])];
          const double dot = g[0] * (f[0] - o[0]) + g[1] * (f[1] - o[1]) + g[2] * (f[2] - o[2]);
          double w = 1.0;
          for (int a = 0; a < 3; ++a)
          {
            w *= o[a] ? Fade(f[a]) : 1.0 - Fade(f[a]);
          }
          v += w * dot;
        }
        return v;
      });
    return;
  }
  if (kind == WORLEY)
  {
    // Distance to the nearest feature point (one per cell, periodic).
    std::vector<std::array<double, 3>> points(static_cast<size_t>(cells) * cells * cells);
    for (auto& q : points)
    {
      for (double& c : q)
      {
        c = Uniform(rng);
      }
    }
    fill(
      [&](const double* p, const int* c)
      {
        double best = 1e30;
        for (int k = -1; k <= 1; ++k)
        {
          for (int j = -1; j <= 1; ++j)
          {
            for (int i = -1; i <= 1; ++i)
            {
              const auto& q = points[cellIndex(c[0] + i, c[1] + j, c[2] + k)];
              const double d[3] = { c[0] + i + q[0] - p[0], c[1] + j + q[1] - p[1],
                c[2] + k + q[2] - p[2] };
              best = std::min(best, d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            }
          }
        }
        return std::sqrt(best);
      });
    return;
  }
  if (kind == SPARSE)
  {
    // Paper (1) with dark dots (0) on SparseDots of the texels: each dot, convolved along the
    // field, draws one stroke.
    for (vtkIdType i = 0; i < total; ++i)
    {
      out->SetValue(i, Uniform(rng) < SparseDots ? 0.0f : 1.0f);
    }
    return;
  }
  for (vtkIdType i = 0; i < total; ++i)
  {
    out->SetValue(i, static_cast<float>(Uniform(rng)));
  }
}

//------------------------------------------------------------------------------
void vtkSketchPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* const layers[] = { "sketch", "directions", "strokes", "tone" };
  static const char* const directions[] = { "minimum", "maximum", "bisector" };
  static const char* const noises[] = { "white", "perlin", "worley", "sparse" };
  os << indent << "Layer: " << layers[this->Layer] << "\n";
  os << indent << "DirectionSource: " << (this->DirectionSource == MODEL ? "model" : "screen")
     << "\n";
  os << indent
     << "DirectionArrayName: " << (this->DirectionArrayName ? this->DirectionArrayName : "(none)")
     << "\n";
  os << indent << "Direction: " << directions[this->Direction] << "\n";
  os << indent << "Neighbors: " << this->Neighbors << "\n";
  os << indent << "NeighborSpacing: " << this->NeighborSpacing << " pt\n";
  os << indent << "MaxStride: " << this->MaxStride << " pt\n";
  os << indent << "PlanarTolerance: " << this->PlanarTolerance << "\n";
  os << indent << "UmbilicTolerance: " << this->UmbilicTolerance << "\n";
  os << indent << "ObjectScale: " << this->ObjectScale << "\n";
  os << indent << "SceneBounds: " << this->SceneBounds[0] << " " << this->SceneBounds[1] << " "
     << this->SceneBounds[2] << " " << this->SceneBounds[3] << " " << this->SceneBounds[4] << " "
     << this->SceneBounds[5] << "\n";
  os << indent << "SmoothingRadius: " << this->SmoothingRadius << " pt\n";
  os << indent << "FieldTexelSize: " << this->FieldTexelSize << " pt\n";
  os << indent << "SmoothingIterations: " << this->SmoothingIterations << "\n";
  os << indent << "FillRadius: " << this->FillRadius << " pt\n";
  os << indent << "FallbackAngle: " << this->FallbackAngle << " deg\n";
  os << indent << "LicMode: " << (this->LicMode == SCREEN_2D ? "screen-2d" : "perspective") << "\n";
  os << indent << "StepLength: " << this->StepLength << " pt\n";
  os << indent << "Steps: " << this->Steps << "\n";
  os << indent << "Noise: " << noises[this->Noise] << "\n";
  os << indent << "NoiseSpace: " << (this->NoiseSpace == OBJECT ? "object" : "screen") << "\n";
  os << indent << "NoiseSize: " << this->NoiseSize << " pt\n";
  os << indent << "StrokeContrast: " << this->StrokeContrast << "\n";
  os << indent << "CrossHatching: " << this->CrossHatching << "\n";
  os << indent << "CrossThreshold: " << this->CrossThreshold << "\n";
  os << indent << "Contrast: " << this->Contrast << "\n";
  os << indent << "BlurRadius: " << this->BlurRadius << " pt\n";
  os << indent << "BlurStride: " << this->BlurStride << "\n";
  os << indent << "BrightThresholds: " << this->BrightThresholds[0] << " "
     << this->BrightThresholds[1] << "\n";
  os << indent << "PencilColor: " << this->PencilColor[0] << " " << this->PencilColor[1] << " "
     << this->PencilColor[2] << "\n";
  os << indent << "PaperColor: " << this->PaperColor[0] << " " << this->PaperColor[1] << " "
     << this->PaperColor[2] << "\n";
  os << indent << "Tint: " << this->Tint << "\n";
  os << indent << "ReferenceHeight: " << this->ReferenceHeight << " px\n";
  os << indent << "FeatureLines: " << this->FeatureLines << "\n";
  os << indent << "FeatureLineWidth: " << this->FeatureLineWidth << " pt\n";
  os << indent << "VectorFigureStrokes: " << (this->VectorFigureStrokes ? "on" : "off") << "\n";
}

//------------------------------------------------------------------------------
void vtkSketchPass::MapDirectionArrays(vtkRenderer* ren)
{
  const std::string name = this->DirectionArrayName ? this->DirectionArrayName : "";
  auto& mapped = this->Internals->Mapped;
  mapped.erase(std::remove_if(mapped.begin(), mapped.end(),
                 [](const std::pair<vtkWeakPointer<vtkOpenGLPolyDataMapper>, std::string>& m)
                 { return m.first == nullptr; }),
    mapped.end());
  auto directions = [&name](vtkDataSet* data)
  {
    vtkDataArray* a = data->GetPointData()->GetArray(name.c_str());
    return a && a->GetNumberOfComponents() == 3;
  };
  // The helpers of VTK's composite data mapper upload the tangents, no mapped array.
  auto tangents = [](vtkDataSet* data)
  {
    vtkDataArray* t = data->GetPointData()->GetTangents();
    return vtkFloatArray::SafeDownCast(t) && t->GetNumberOfComponents() == 3;
  };
  bool anyData = false, anyDirections = false;
  vtkActorCollection* actors = ren->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    auto* mapper = vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper());
    if (!mapper || !actor->GetVisibility())
    {
      continue;
    }
    vtkDataObject* object = mapper->GetInputDataObject(0, 0);
    if (auto* composite = vtkCompositeDataSet::SafeDownCast(object))
    {
      vtkSmartPointer<vtkCompositeDataIterator> leaf;
      leaf.TakeReference(composite->NewIterator());
      for (leaf->InitTraversal(); !leaf->IsDoneWithTraversal(); leaf->GoToNextItem())
      {
        if (auto* data = vtkDataSet::SafeDownCast(leaf->GetCurrentDataObject()))
        {
          anyData = anyData || data->GetNumberOfPoints() > 0;
          anyDirections = anyDirections || (data->GetNumberOfPoints() > 0 && tangents(data));
        }
      }
      continue;
    }
    auto* input = vtkDataSet::SafeDownCast(object);
    if (!input)
    {
      continue;
    }
    anyData = anyData || input->GetNumberOfPoints() > 0;
    if (!directions(input))
    {
      continue;
    }
    anyDirections = anyDirections || input->GetNumberOfPoints() > 0;
    auto found = std::find_if(mapped.begin(), mapped.end(),
      [&](const std::pair<vtkWeakPointer<vtkOpenGLPolyDataMapper>, std::string>& m)
      { return m.first == mapper; });
    if (found != mapped.end() && found->second == name)
    {
      continue;
    }
    mapper->MapDataArrayToVertexAttribute(
      "stylizeDirectionMC", name.c_str(), vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
    if (found != mapped.end())
    {
      found->second = name;
    }
    else
    {
      mapped.emplace_back(mapper, name);
    }
  }
  // Said once while it lasts: MODEL with nothing to read is the SCREEN estimate everywhere.
  const bool inert = anyData && !anyDirections;
  if (inert && !this->Internals->ModelInertWarned)
  {
    vtkWarningMacro(<< "DirectionSource is MODEL, but no visible data has the 3-component point "
                       "array \""
                    << name
                    << "\" (DirectionArrayName) or, for composite data (ParaView), 3-component "
                       "float tangents: the directions are estimated on screen. "
                       "vtkStylizePrincipalCurvatures (ParaView: the Principal Curvatures "
                       "filter) computes them.");
  }
  this->Internals->ModelInertWarned = inert;
}

//------------------------------------------------------------------------------
bool vtkSketchPass::DownloadDirections(vtkFloatArray* out)
{
  return this->DownloadTexture(this->Internals->Field->GetTexture(), out);
}

//------------------------------------------------------------------------------
void vtkSketchPass::ReleaseStyleResources(vtkWindow* w)
{
  this->Internals->Field->Free(w);
  this->Internals->Strokes->Free(w);
}

//------------------------------------------------------------------------------
vtkIdType vtkSketchPass::GetStyleTextureBytes()
{
  return this->Internals->Field->GetTextureBytes() + this->Internals->Strokes->GetTextureBytes();
}

//------------------------------------------------------------------------------
double vtkSketchPass::GetReach(const Frame& frame)
{
  const Plan p = this->PlanFrame(frame);
  double reach = vtkStylizeDirectionField::Reach(frame, p.Field, p.PointSize) + 1.0;
  if (p.Strokes)
  {
    // A stroke's steps are StepLength points where it starts; in perspective a surface that
    // turns toward the camera lengthens them on the screen: twice the length bounds them here.
    const double factor = this->LicMode == SCREEN_2D ? 1.0 : 2.0;
    reach += factor * p.Steps * p.StepLength * p.PointSize + 1.0;
  }
  if (p.Contrast)
  {
    reach = std::max(reach, p.BlurRadius + 2.0 * this->BlurStride);
  }
  if (p.FeatureLines)
  {
    reach = std::max(reach, this->FeatureLineReach(p.PointSize) + 1.0);
  }
  return reach;
}

//------------------------------------------------------------------------------
double vtkSketchPass::FeatureLineReach(double pointSize) const
{
  return vtkStylizeFeatureStrokes::Reach(
    vtkStylizeFeatureStrokes::Settings::ForStyle(this->FeatureLines, this->FeatureLineWidth,
      this->IsoLines, this->IsoLineWidth, this->IsoLineSpacing),
    pointSize);
}

//------------------------------------------------------------------------------
int vtkSketchPass::GetGuardAlignment(const Frame&)
{
  return this->BlurStride;
}

//------------------------------------------------------------------------------
bool vtkSketchPass::RenderStyle(const vtkRenderState* s, const Frame& frame)
{
  const Plan plan = this->PlanFrame(frame);
  if (plan.Model)
  {
    this->MapDirectionArrays(frame.Renderer);
  }
  if (!this->RenderScene(s, plan.Scene))
  {
    return false;
  }
  this->SetShaderDefines(plan.Defines);
  if (plan.Strokes)
  {
    this->UpdateNoise(frame);
  }
  this->Internals->Field->Render(this, frame, plan.Field, plan.PointSize);
  if (plan.Contrast)
  {
    this->RenderBlurStages(frame, plan);
  }
  else
  {
    this->FreeTexture(BLUR_X);
    this->FreeTexture(BLUR_Y);
  }
  if (plan.FeatureLines)
  {
    this->Internals->Strokes->RenderFrame(this, frame,
      vtkStylizeFeatureStrokes::Settings::ForStyle(this->FeatureLines, this->FeatureLineWidth,
        this->IsoLines, this->IsoLineWidth, this->IsoLineSpacing));
  }
  else
  {
    this->Internals->Strokes->Free(frame.Window);
  }
  this->RenderFinalStage(frame, plan);
  return true;
}

//------------------------------------------------------------------------------
vtkSketchPass::Plan vtkSketchPass::PlanFrame(const Frame& frame) const
{
  Plan p;
  // Strokes are drawn in the SKETCH and STROKES layers; the tone (and so the blur) is read by
  // the SKETCH and TONE layers.
  p.Model = this->DirectionSource == MODEL;
  p.Strokes = this->Layer == SKETCH || this->Layer == STROKES;
  const bool tone = this->Layer == SKETCH || this->Layer == TONE;
  p.ObjectNoise = p.Strokes && this->NoiseSpace == OBJECT;
  // (the interactive variant skips the contrast's blur)
  p.Contrast = tone && this->Contrast > 0.0 && !frame.Interactive;
  const bool cross = this->CrossHatching && this->Layer == SKETCH;
  p.Scene.Channels = vtkStylizeGBufferPass::LINEAR_DEPTH | vtkStylizeGBufferPass::NORMAL;
  // The estimate differentiates normals: half floats (3 digits) would dominate its error. The
  // lit colour needs no more than half floats (the G-buffer's Precision).
  p.Scene.NormalPrecision = vtkStylizeGBufferPass::FULL;
  if (p.ObjectNoise)
  {
    p.Scene.Channels |= vtkStylizeGBufferPass::POSITION;
    p.Scene.PositionSpace = vtkStylizeGBufferPass::OBJECT;
  }
  if (p.Model)
  {
    p.Scene.Channels |= vtkStylizeGBufferPass::DIRECTION;
  }

  // The clamp macros let NaN through: a NaN setting counts as its range's minimum.
  auto finite = [](double v, double fallback) { return std::isfinite(v) ? v : fallback; };
  auto* self = const_cast<vtkSketchPass*>(this); // the Min/Max getters are not const
  FieldSettings& f = p.Field;
  f.Neighbors = this->Neighbors;
  f.NeighborSpacing = finite(this->NeighborSpacing, self->GetNeighborSpacingMinValue());
  f.MaxStride = finite(this->MaxStride, self->GetMaxStrideMinValue());
  f.ObjectScale = finite(this->ObjectScale, self->GetObjectScaleMinValue());
  std::copy(this->SceneBounds, this->SceneBounds + 6, f.SceneBounds);
  f.PlanarTolerance = finite(this->PlanarTolerance, self->GetPlanarToleranceMinValue());
  f.UmbilicTolerance = finite(this->UmbilicTolerance, self->GetUmbilicToleranceMinValue());
  f.SmoothingRadius = finite(this->SmoothingRadius, self->GetSmoothingRadiusMinValue());
  f.SmoothingIterations = this->SmoothingIterations;
  f.TexelSize = finite(this->FieldTexelSize, self->GetFieldTexelSizeMinValue());
  f.FillRadius = finite(this->FillRadius, self->GetFillRadiusMinValue());
  f.FallbackAngle = finite(this->FallbackAngle, self->GetFallbackAngleMinValue());
  f.Direction = this->Direction;
  f.Model = p.Model;

  p.Defines = vtkStylizeDirectionField::Defines(f);
  auto define = [&p](bool on, const std::string& name) { AddDefine(p.Defines, on, name); };
  define(!p.ObjectNoise, "SKETCH_NOISE_SCREEN");
  define(p.ObjectNoise && this->Noise == SPARSE, "SKETCH_NOISE_INTERPOLATED");
  define(this->LicMode == SCREEN_2D, "SKETCH_SCREEN_LIC");
  define(cross, "SKETCH_CROSS");
  define(p.Contrast, "SKETCH_CONTRAST");
  define(this->Tint != BLACK_AND_WHITE, "SKETCH_TINTED");
  define(true, "SKETCH_LAYER " + std::to_string(this->Layer));
  p.FeatureLines = ((this->FeatureLines && this->FeatureLineWidth > 0.0) || this->IsoLines > 0) &&
    this->Layer == SKETCH && this->GetTranslucentLayer() == 0;
  define(p.FeatureLines, "SKETCH_FEATURE_LINES");

  p.StepLength = finite(this->StepLength, self->GetStepLengthMinValue());
  p.Steps = this->Steps;
  if (frame.Interactive)
  {
    // The cheaper variant while the user drags: the raw directions on a grid twice as coarse
    // (no smoothing, no fill), strokes in fewer, longer steps (the same length), no contrast.
    f.TexelSize = 2.0 * std::max(1.0, f.TexelSize);
    f.SmoothingRadius = 0.0;
    f.SmoothingIterations = 0;
    f.FillRadius = 0.0;
    p.Steps = std::min(this->Steps, InteractiveSteps);
    p.StepLength *= static_cast<double>(this->Steps) / std::max(p.Steps, 1);
  }
  p.StrokeContrast = finite(this->StrokeContrast, self->GetStrokeContrastMinValue());
  p.CrossThreshold = finite(this->CrossThreshold, self->GetCrossThresholdMinValue());
  p.ContrastSetting = finite(this->Contrast, self->GetContrastMinValue());

  // Points -> pixels of this (possibly magnified) image; world lengths at the focal distance.
  p.PointSize = self->PointSize(frame);
  p.FocalPixel = vtkStylizeDirectionField::FocalPixelWorld(frame);
  const int stride = this->BlurStride;
  p.BlurSize[0] = (frame.Size[0] + stride - 1) / stride;
  p.BlurSize[1] = (frame.Size[1] + stride - 1) / stride;
  p.BlurRadius = finite(this->BlurRadius, self->GetBlurRadiusMinValue()) * p.PointSize;
  double noiseSize = finite(this->NoiseSize, self->GetNoiseSizeMinValue());
  if (this->Noise == SPARSE)
  {
    // A texel of at least SparseMinimumTexel pixels of the window (a magnified screenshot: of
    // its tiles), and steps of at least SparseStepPerTexel texels (on a small image the steps
    // in points would otherwise turn the strokes into spots).
    noiseSize = std::max(noiseSize, SparseMinimumTexel * frame.TileScale[1] / p.PointSize);
    p.StepLength =
      std::max(p.StepLength, SparseStepPerTexel * noiseSize * this->Steps / std::max(p.Steps, 1));
  }
  p.NoiseUnit = p.ObjectNoise ? noiseSize * p.PointSize * p.FocalPixel : noiseSize * p.PointSize;
  return p;
}

//------------------------------------------------------------------------------
void vtkSketchPass::UpdateNoise(const Frame& frame)
{
  vtkInternals& in = *this->Internals;
  vtkTextureObject*& noise = this->TextureSlot(NOISE);
  if (noise && in.NoiseKind == this->Noise && noise->GetContext() == frame.Window)
  {
    return;
  }
  this->FreeTexture(NOISE);
  vtkNew<vtkFloatArray> values;
  vtkSketchPass::GenerateNoise(this->Noise, NoiseTextureSize, values);
  const vtkIdType n = values->GetNumberOfTuples();
  double sum = 0.0, sum2 = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double v = values->GetValue(i);
    sum += v;
    sum2 += v * v;
  }
  in.NoiseStats[0] = sum / n;
  in.NoiseStats[1] = std::sqrt(std::max(0.0, sum2 / n - in.NoiseStats[0] * in.NoiseStats[0]));
  noise = vtkTextureObject::New();
  noise->SetContext(frame.Window);
  noise->SetWrapS(vtkTextureObject::Repeat);
  noise->SetWrapT(vtkTextureObject::Repeat);
  noise->SetWrapR(vtkTextureObject::Repeat);
  const int filter = this->Noise == WHITE ? vtkTextureObject::Nearest : vtkTextureObject::Linear;
  // SPARSE is read prefiltered over the pixel's footprint on the surface (textureGrad):
  // mipmapped, isotropic (anisotropic filtering keeps the texels' detail along the footprint's
  // long axis, and with it flicker: docs/figures.md, flicker)
  const bool prefiltered = this->Noise == SPARSE;
  noise->SetMinificationFilter(prefiltered ? vtkTextureObject::LinearMipmapLinear : filter);
  noise->SetGenerateMipmap(prefiltered);
  noise->SetMaxLevel(prefiltered ? 1000 : 0);
  noise->SetMagnificationFilter(filter);
  noise->Create3DFromRaw(
    NoiseTextureSize, NoiseTextureSize, NoiseTextureSize, 1, VTK_FLOAT, values->GetPointer(0));
  if (prefiltered)
  {
    noise->Activate();
    glGenerateMipmap(GL_TEXTURE_3D);
    noise->Deactivate();
  }
  in.NoiseKind = this->Noise;
}

//------------------------------------------------------------------------------
void vtkSketchPass::RenderBlurStages(const Frame& frame, const Plan& p)
{
  const int bw = p.BlurSize[0], bh = p.BlurSize[1];
  vtkTextureObject* blurX = this->EnsureTexture(BLUR_X, bw, bh, GL_R32F);
  vtkTextureObject* blurY = this->EnsureTexture(BLUR_Y, bw, bh, GL_R32F);
  blurY->SetMinificationFilter(vtkTextureObject::Linear);
  blurY->SetMagnificationFilter(vtkTextureObject::Linear);
  const int taps = static_cast<int>(std::ceil(p.BlurRadius / this->BlurStride));
  auto uniforms = [&](vtkStylizeUniforms& u)
  {
    this->SetFieldUniforms(u, frame);
    u.Int("sketchBlurStride", this->BlurStride)
      .Float("sketchBlurSigma", std::max(0.5, p.BlurRadius / 3.0))
      .Int("sketchBlurTaps", taps)
      .Int2("sketchBlurSize", bw, bh);
  };
  this->RenderStage(BLUR_X_STAGE, { blurX }, bw, bh, uniforms);
  this->RenderStage(BLUR_Y_STAGE, { blurY }, bw, bh,
    [&](vtkStylizeUniforms& u)
    {
      uniforms(u);
      u.Texture("sketchInput", blurX);
    });
}

//------------------------------------------------------------------------------
void vtkSketchPass::RenderFinalStage(const Frame& frame, const Plan& p)
{
  const vtkInternals& in = *this->Internals;
  this->RenderStageToOutput(
    frame, FINAL_STAGE, true,
    [&](vtkStylizeUniforms& u)
    {
      this->SetFieldUniforms(u, frame);
      u.Texture("sketchField", this->Internals->Field->GetTexture())
        .Texture("sketchBlur", this->TextureSlot(BLUR_Y))
        .Float2(
          "sketchBlurExtent", p.BlurSize[0] * this->BlurStride, p.BlurSize[1] * this->BlurStride)
        .Texture("sketchNoise", this->TextureSlot(NOISE))
        .Float2("sketchNoiseStats", in.NoiseStats[0], in.NoiseStats[1])
        .Float("sketchNoiseScale", 1.0 / (p.NoiseUnit * NoiseTextureSize))
        .Float("sketchStepPixels", p.StepLength * p.PointSize)
        .Int("sketchSteps", p.Steps)
        .Float("sketchStrokeContrast", p.StrokeContrast)
        .Float("sketchContrast", p.ContrastSetting)
        .Float2("sketchBright", this->BrightThresholds[0], this->BrightThresholds[1])
        .Float("sketchCross", p.CrossThreshold)
        .Float3("sketchPencil", this->PencilColor[0], this->PencilColor[1], this->PencilColor[2])
        .Float3("sketchPaper", this->PaperColor[0], this->PaperColor[1], this->PaperColor[2]);
      if (p.FeatureLines)
      {
        u.Texture("sketchFeatureInk", this->Internals->Strokes->GetTexture())
          .Float("sketchPointPixels", p.PointSize);
      }
      this->SetSceneOutputUniforms(u, frame.Renderer);
    },
    // the background keeps its colour: the stage runs where the scene is (and its lines)
    p.FeatureLines ? static_cast<int>(std::ceil(this->FeatureLineReach(p.PointSize))) : 0);
}
