#include "vtkSketchPass.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeShaderUtilities.h"
#include "vtkTextureObject.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include "vtkSketchFS.h"
#include "vtkStylizeCommonFS.h"
#include "vtkStylizeDepthFS.h"
#include "vtkStylizeScreenFS.h"

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
constexpr int NoiseCell = 8; // lattice period of Perlin and cell size of Worley, texels

// Uniform value in [0, 1) from a 32-bit generator, the same on every standard library.
double Uniform(std::mt19937& rng)
{
  return static_cast<double>(rng() >> 8) / 16777216.0;
}

double Fade(double t)
{
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}
}

class vtkSketchPass::vtkInternals
{
public:
  vtkNew<vtkStylizeLightingPass> Lighting;
  vtkNew<vtkStylizeGBufferPass> GBuffer;
  vtkStylizeShaderUtilities::ScreenQuad EstimateQuad;
  vtkStylizeShaderUtilities::ScreenQuad SmoothQuad;
  vtkStylizeShaderUtilities::ScreenQuad ResolveQuad;
  vtkStylizeShaderUtilities::ScreenQuad BlurXQuad;
  vtkStylizeShaderUtilities::ScreenQuad BlurYQuad;
  vtkStylizeShaderUtilities::ScreenQuad FinalQuad;
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  vtkTextureObject* Field[2] = { nullptr, nullptr }; // raw field ping-pong
  vtkTextureObject* Resolved = nullptr;               // xyz direction, w linear depth
  vtkTextureObject* BlurX = nullptr;
  vtkTextureObject* BlurY = nullptr;
  vtkTextureObject* NoiseTexture = nullptr;
  int NoiseKind = -1;
  double NoiseStats[2] = { 0.5, 0.29 };

  std::string Defines;
  std::string Declarations[6]; // estimate, smooth, resolve, blur x, blur y, final

  // Mappers given the direction attribute, and the array name they were given.
  std::vector<std::pair<vtkWeakPointer<vtkOpenGLPolyDataMapper>, std::string>> Mapped;

  void FreeTextures(vtkWindow* w)
  {
    for (vtkTextureObject** t :
      { &this->Field[0], &this->Field[1], &this->Resolved, &this->BlurX, &this->BlurY })
    {
      vtkStylizeShaderUtilities::FreeTexture(*t, w);
    }
    vtkStylizeShaderUtilities::FreeTexture(this->NoiseTexture, w);
    this->NoiseKind = -1;
    if (this->Framebuffer)
    {
      if (w)
      {
        this->Framebuffer->ReleaseGraphicsResources(w);
      }
      this->Framebuffer->Delete();
      this->Framebuffer = nullptr;
    }
  }

  void EnsureNoise(vtkOpenGLRenderWindow* renWin, int kind)
  {
    if (this->NoiseTexture && this->NoiseKind == kind &&
      this->NoiseTexture->GetContext() == renWin)
    {
      return;
    }
    vtkStylizeShaderUtilities::FreeTexture(this->NoiseTexture, renWin);
    vtkNew<vtkFloatArray> values;
    vtkSketchPass::GenerateNoise(kind, NoiseTextureSize, values);
    const vtkIdType n = values->GetNumberOfTuples();
    double sum = 0.0, sum2 = 0.0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double v = values->GetValue(i);
      sum += v;
      sum2 += v * v;
    }
    this->NoiseStats[0] = sum / n;
    this->NoiseStats[1] = std::sqrt(std::max(0.0, sum2 / n - this->NoiseStats[0] * this->NoiseStats[0]));
    this->NoiseTexture = vtkTextureObject::New();
    this->NoiseTexture->SetContext(renWin);
    this->NoiseTexture->SetWrapS(vtkTextureObject::Repeat);
    this->NoiseTexture->SetWrapT(vtkTextureObject::Repeat);
    this->NoiseTexture->SetWrapR(vtkTextureObject::Repeat);
    const int filter = kind == vtkSketchPass::WHITE ? vtkTextureObject::Nearest
                                                    : vtkTextureObject::Linear;
    this->NoiseTexture->SetMinificationFilter(filter);
    this->NoiseTexture->SetMagnificationFilter(filter);
    this->NoiseTexture->Create3DFromRaw(NoiseTextureSize, NoiseTextureSize, NoiseTextureSize, 1,
      VTK_FLOAT, values->GetPointer(0));
    this->NoiseKind = kind;
  }
};

vtkStandardNewMacro(vtkSketchPass);

//------------------------------------------------------------------------------
vtkSketchPass::vtkSketchPass()
  : Internals(new vtkInternals)
{
  this->Internals->Lighting->SetModel(vtkStylizeLightingPass::STANDARD);
  this->Internals->GBuffer->SetLightingPass(this->Internals->Lighting);
  // The estimate differentiates normals: half floats (3 digits) would dominate its error.
  this->Internals->GBuffer->SetPrecision(vtkStylizeGBufferPass::FULL);
  this->SetDirectionArrayName("PrincipalDirectionMin");
}

//------------------------------------------------------------------------------
vtkSketchPass::~vtkSketchPass()
{
  this->Internals->FreeTextures(nullptr);
  this->SetDirectionArrayName(nullptr);
}

//------------------------------------------------------------------------------
vtkStylizeLightingPass* vtkSketchPass::GetLightingPass()
{
  return this->Internals->Lighting;
}

//------------------------------------------------------------------------------
vtkStylizeGBufferPass* vtkSketchPass::GetGBufferPass()
{
  return this->Internals->GBuffer;
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
  auto clamp01 = [](double v, double fallback) {
    return std::isfinite(v) ? std::min(1.0, std::max(0.0, v)) : fallback;
  };
  t1 = clamp01(t1, this->BrightThresholds[0]);
  t2 = std::max(t1, clamp01(t2, this->BrightThresholds[1]));
  if (t1 != this->BrightThresholds[0] || t2 != this->BrightThresholds[1])
  {
    this->BrightThresholds[0] = t1;
    this->BrightThresholds[1] = t2;
    this->Modified();
  }
}

namespace
{
bool SetColor(double target[3], double r, double g, double b)
{
  const double in[3] = { r, g, b };
  bool changed = false;
  for (int i = 0; i < 3; ++i)
  {
    const double v = std::isfinite(in[i]) ? std::min(1.0, std::max(0.0, in[i])) : target[i];
    changed = changed || v != target[i];
    target[i] = v;
  }
  return changed;
}
}

//------------------------------------------------------------------------------
void vtkSketchPass::SetPencilColor(double r, double g, double b)
{
  if (SetColor(this->PencilColor, r, g, b))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkSketchPass::SetPaperColor(double r, double g, double b)
{
  if (SetColor(this->PaperColor, r, g, b))
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
  auto cellIndex = [&](int i, int j, int k) { return (wrap(k) * cells + wrap(j)) * cells + wrap(i); };

  // Evaluates value(p, c) at every texel centre p (in lattice cells; c = floor(p)), then scales
  // the values linearly to [0, 1].
  auto fill = [&](const std::function<double(const double*, const int*)>& value) {
    std::vector<double> raw(static_cast<size_t>(total));
    for (int z = 0; z < size; ++z)
    {
      for (int y = 0; y < size; ++y)
      {
        for (int x = 0; x < size; ++x)
        {
          const double p[3] = { (x + 0.5) / NoiseCell, (y + 0.5) / NoiseCell,
            (z + 0.5) / NoiseCell };
          const int c[3] = { static_cast<int>(std::floor(p[0])),
            static_cast<int>(std::floor(p[1])), static_cast<int>(std::floor(p[2])) };
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
    fill([&](const double* p, const int* c) {
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
    fill([&](const double* p, const int* c) {
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
  static const char* const noises[] = { "white", "perlin", "worley" };
  os << indent << "Layer: " << layers[this->Layer] << "\n";
  os << indent << "DirectionSource: " << (this->DirectionSource == MODEL ? "model" : "screen")
     << "\n";
  os << indent << "DirectionArrayName: "
     << (this->DirectionArrayName ? this->DirectionArrayName : "(none)") << "\n";
  os << indent << "Direction: " << directions[this->Direction] << "\n";
  os << indent << "Neighbors: " << this->Neighbors << "\n";
  os << indent << "NeighborSpacing: " << this->NeighborSpacing << " pt\n";
  os << indent << "MaxStride: " << this->MaxStride << " pt\n";
  os << indent << "PlanarTolerance: " << this->PlanarTolerance << "\n";
  os << indent << "UmbilicTolerance: " << this->UmbilicTolerance << "\n";
  os << indent << "SmoothingIterations: " << this->SmoothingIterations << "\n";
  os << indent << "FillRadius: " << this->FillRadius << " pt\n";
  os << indent << "FallbackAngle: " << this->FallbackAngle << " deg\n";
  os << indent << "LicMode: " << (this->LicMode == SCREEN_2D ? "screen-2d" : "perspective")
     << "\n";
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
  os << indent << "Tinted: " << this->Tinted << "\n";
  os << indent << "ReferenceHeight: " << this->ReferenceHeight << " px\n";
  os << indent << "LightingPass:\n";
  this->Internals->Lighting->PrintSelf(os, indent.GetNextIndent());
}

//------------------------------------------------------------------------------
void vtkSketchPass::MapDirectionArrays(vtkRenderer* ren)
{
  const std::string name = this->DirectionArrayName ? this->DirectionArrayName : "";
  auto& mapped = this->Internals->Mapped;
  mapped.erase(std::remove_if(mapped.begin(), mapped.end(),
                 [](const std::pair<vtkWeakPointer<vtkOpenGLPolyDataMapper>, std::string>& m) {
                   return m.first == nullptr;
                 }),
    mapped.end());
  vtkActorCollection* actors = ren->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    auto* mapper = vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper());
    vtkDataSet* input = mapper ? vtkDataSet::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
    if (!input || !input->GetPointData()->GetArray(name.c_str()) ||
      input->GetPointData()->GetArray(name.c_str())->GetNumberOfComponents() != 3)
    {
      continue;
    }
    auto found = std::find_if(mapped.begin(), mapped.end(),
      [&](const std::pair<vtkWeakPointer<vtkOpenGLPolyDataMapper>, std::string>& m) {
        return m.first == mapper;
      });
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
}

//------------------------------------------------------------------------------
bool vtkSketchPass::DownloadDirections(vtkFloatArray* out)
{
  vtkTextureObject* tex = this->Internals->Resolved;
  if (!tex || !out || !this->Internals->Framebuffer)
  {
    return false;
  }
  const int w = static_cast<int>(tex->GetWidth());
  const int h = static_cast<int>(tex->GetHeight());
  out->SetNumberOfComponents(4);
  out->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  vtkOpenGLFramebufferObject* fbo = this->Internals->Framebuffer;
  fbo->SaveCurrentBindingsAndBuffers(GL_READ_FRAMEBUFFER);
  fbo->Bind(GL_READ_FRAMEBUFFER);
  fbo->AddColorAttachment(0, tex);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, out->GetPointer(0));
  fbo->RemoveColorAttachments(1);
  fbo->UnBind(GL_READ_FRAMEBUFFER);
  fbo->RestorePreviousBindingsAndBuffers(GL_READ_FRAMEBUFFER);
  return true;
}

//------------------------------------------------------------------------------
void vtkSketchPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkInternals& in = *this->Internals;
  vtkStylizeGBufferPass* gbuffer = in.GBuffer;
  if (!renWin)
  {
    return;
  }
  using U = vtkStylizeShaderUtilities;

  // What this frame computes: only the enabled stages, and only their channels.
  const bool model = this->DirectionSource == MODEL;
  // Strokes are drawn in the SKETCH and STROKES layers; the tone (and so the blur) is read by
  // the SKETCH and TONE layers.
  const bool strokes = this->Layer == SKETCH || this->Layer == STROKES;
  const bool tone = this->Layer == SKETCH || this->Layer == TONE;
  const bool objectNoise = strokes && this->NoiseSpace == OBJECT;
  const bool contrast = tone && this->Contrast > 0.0;
  const bool cross = this->CrossHatching && this->Layer == SKETCH;
  int channels = vtkStylizeGBufferPass::LINEAR_DEPTH | vtkStylizeGBufferPass::NORMAL;
  if (objectNoise)
  {
    channels |= vtkStylizeGBufferPass::POSITION;
    gbuffer->SetPositionSpace(vtkStylizeGBufferPass::OBJECT);
  }
  if (model)
  {
    channels |= vtkStylizeGBufferPass::DIRECTION;
    this->MapDirectionArrays(ren);
  }
  if (!this->RenderScene(s, channels))
  {
    return;
  }
  int vp[4];
  gbuffer->GetViewport(vp);
  const int w = vp[2], h = vp[3];
  const int ox = vp[0], oy = vp[1];

  // The clamp macros let NaN through: a NaN setting counts as its range's minimum.
  auto finite = [](double v, double fallback) { return std::isfinite(v) ? v : fallback; };
  const double referenceHeight = finite(this->ReferenceHeight, this->GetReferenceHeightMinValue());
  const double neighborSpacing = finite(this->NeighborSpacing, this->GetNeighborSpacingMinValue());
  const double maxStrideSetting = finite(this->MaxStride, this->GetMaxStrideMinValue());
  const double planar = finite(this->PlanarTolerance, this->GetPlanarToleranceMinValue());
  const double umbilic = finite(this->UmbilicTolerance, this->GetUmbilicToleranceMinValue());
  const double fillSetting = finite(this->FillRadius, this->GetFillRadiusMinValue());
  const double fallbackAngle = finite(this->FallbackAngle, this->GetFallbackAngleMinValue());
  const double stepLength = finite(this->StepLength, this->GetStepLengthMinValue());
  const double noiseSize = finite(this->NoiseSize, this->GetNoiseSizeMinValue());
  const double strokeContrast = finite(this->StrokeContrast, this->GetStrokeContrastMinValue());
  const double crossThreshold = finite(this->CrossThreshold, this->GetCrossThresholdMinValue());
  const double contrastSetting = finite(this->Contrast, this->GetContrastMinValue());
  const double blurSetting = finite(this->BlurRadius, this->GetBlurRadiusMinValue());

  // Points -> pixels of this (possibly magnified) image; world lengths at the focal distance.
  const U::FullImage full = U::GetFullImage(ren, ox, oy);
  const double pointSize = full.Size[1] / referenceHeight;
  vtkCamera* cam = ren->GetActiveCamera();
  const bool parallel = cam->GetParallelProjection() != 0;
  const double pixelWorld = U::PixelWorldSize(cam, w, h);
  double focalPixel = parallel ? pixelWorld : pixelWorld * cam->GetDistance();
  if (!(focalPixel > 0.0) || !std::isfinite(focalPixel))
  {
    focalPixel = 1.0;
  }
  vtkMatrix4x4* projection = cam->GetProjectionTransformMatrix(ren);
  const double p00 = projection->GetElement(0, 0), p11 = projection->GetElement(1, 1);
  const double p02 = projection->GetElement(0, 2), p12 = projection->GetElement(1, 2);
  const double p03 = projection->GetElement(0, 3), p13 = projection->GetElement(1, 3);

  std::string defines;
  auto define = [&](bool on, const std::string& name) {
    if (on)
    {
      defines += "#define " + name + "\n";
    }
  };
  define(true, "SKETCH_NEIGHBORS " + std::to_string(this->Neighbors));
  define(model, "SKETCH_MODEL");
  define(true, "SKETCH_DIRECTION " + std::to_string(this->Direction));
  define(!objectNoise, "SKETCH_NOISE_SCREEN");
  define(this->LicMode == SCREEN_2D, "SKETCH_SCREEN_LIC");
  define(cross, "SKETCH_CROSS");
  define(contrast, "SKETCH_CONTRAST");
  define(this->Tinted, "SKETCH_TINTED");
  define(true, "SKETCH_LAYER " + std::to_string(this->Layer));
  if (defines != in.Defines || in.Declarations[0].empty())
  {
    in.Defines = defines;
    static const char* const stages[6] = { "ESTIMATE", "SMOOTH", "RESOLVE", "BLUR_X", "BLUR_Y",
      "FINAL" };
    for (int i = 0; i < 6; ++i)
    {
      in.Declarations[i] = std::string("#define SKETCH_STAGE_") + stages[i] + "\n" + defines +
        vtkStylizeCommonFS + vtkStylizeDepthFS + vtkStylizeScreenFS + vtkSketchFS;
    }
  }

  vtkTextureObject* colour = gbuffer->GetColorTexture();
  vtkTextureObject* depth = gbuffer->GetDepthTexture();
  vtkTextureObject* linear = gbuffer->GetLinearDepthTexture();
  vtkTextureObject* normal = gbuffer->GetNormalTexture();
  vtkTextureObject* position = gbuffer->GetPositionTexture();
  vtkTextureObject* direction = gbuffer->GetDirectionTexture();
  if (strokes)
  {
    in.EnsureNoise(renWin, this->Noise);
  }

  const int maxStride = std::max(1, static_cast<int>(std::lround(maxStrideSetting * pointSize)));
  const double spacingWorld = neighborSpacing * pointSize * focalPixel;
  const int blurStride = this->BlurStride;
  const int blurW = (w + blurStride - 1) / blurStride, blurH = (h + blurStride - 1) / blurStride;
  const double blurRadius = blurSetting * pointSize;
  const double noiseUnit =
    objectNoise ? noiseSize * pointSize * focalPixel : noiseSize * pointSize;
  const double fallback = vtkMath::RadiansFromDegrees(fallbackAngle);

  auto setCommon = [&](U::Uniforms& u) {
    u.Texture("stylizeColorTexture", colour)
      .Texture("stylizeDepthTexture", depth)
      .Texture("stylizeLinearDepthTexture", linear)
      .Texture("stylizeNormalTexture", normal)
      .Texture("stylizePositionTexture", position)
      .Texture("stylizeDirectionTexture", direction)
      .Int2("sketchSize", w, h)
      .Float2("sketchPixelOffset", full.Offset[0], full.Offset[1])
      .Int("sketchParallel", parallel ? 1 : 0)
      .Float("sketchPixelWorld", pixelWorld);
    u.Float4("sketchProjection", p00, p11, p02, p12).Float2("sketchProjOffset", p03, p13);
    gbuffer->SetDepthMappingUniforms(u.GetProgram());
  };

  if (!in.Framebuffer)
  {
    in.Framebuffer = vtkOpenGLFramebufferObject::New();
    in.Framebuffer->SetContext(renWin);
  }
  vtkOpenGLFramebufferObject* fbo = in.Framebuffer;
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  bool ok = true;
  // Runs one stage into `target` (tw x th).
  auto stage = [&](U::ScreenQuad& quad, int index, vtkTextureObject* target, int tw, int th,
                 const std::function<void(U::Uniforms&)>& extra) {
    fbo->RemoveColorAttachments(1);
    fbo->AddColorAttachment(0, target);
    fbo->ActivateDrawBuffers(1);
    ostate->vtkglViewport(0, 0, tw, th);
    ostate->vtkglScissor(0, 0, tw, th);
    vtkShaderProgram* program = quad.Prepare(renWin, in.Declarations[index], "  sketchMain();\n");
    if (!program)
    {
      ok = false;
      return;
    }
    U::Uniforms u(program);
    setCommon(u);
    extra(u);
    quad.Render();
  };

  fbo->SaveCurrentBindingsAndBuffers();
  fbo->Bind();
  ostate->vtkglDisable(GL_DEPTH_TEST);

  // 1. Raw directions.
  U::EnsureScreenTexture(in.Field[0], renWin, w, h, GL_RGBA16F);
  U::EnsureScreenTexture(in.Resolved, renWin, w, h, GL_RGBA32F);
  stage(in.EstimateQuad, 0, in.Field[0], w, h, [&](U::Uniforms& u) {
    u.Float("sketchSpacing", spacingWorld)
      .Int("sketchMaxStride", maxStride)
      .Float("sketchPlanar", planar)
      .Float("sketchUmbilic", umbilic);
  });
  int current = 0;

  // 2. Smoothing (all pixels, 3x3), then filling (undefined pixels, distances 1, 2, 4, ...).
  std::vector<std::pair<int, int>> iterations; // radius, fill only
  for (int i = 0; i < this->SmoothingIterations; ++i)
  {
    iterations.emplace_back(1, 0);
  }
  const double fillRadius = fillSetting * pointSize;
  for (int r = 1; fillSetting > 0.0 && r <= std::max(1.0, fillRadius); r *= 2)
  {
    iterations.emplace_back(r, 1);
  }
  if (iterations.empty())
  {
    U::FreeTexture(in.Field[1], renWin);
  }
  else
  {
    U::EnsureScreenTexture(in.Field[1], renWin, w, h, GL_RGBA16F);
  }
  for (const auto& it : iterations)
  {
    vtkTextureObject* input = in.Field[current];
    stage(in.SmoothQuad, 1, in.Field[1 - current], w, h, [&](U::Uniforms& u) {
      u.Texture("sketchInput", input).Int("sketchRadius", it.first).Int("sketchFillOnly", it.second);
    });
    current = 1 - current;
  }

  // 3. Fallbacks and the requested direction.
  {
    vtkTextureObject* input = in.Field[current];
    stage(in.ResolveQuad, 2, in.Resolved, w, h, [&](U::Uniforms& u) {
      u.Texture("sketchInput", input)
        .Int("sketchGradientStride", std::max(1, static_cast<int>(std::lround(2.0 * pointSize))))
        .Float2("sketchScreenDirection", std::cos(fallback), std::sin(fallback));
    });
  }

  // 4. The strided blur of the lit luminance.
  if (contrast)
  {
    U::EnsureScreenTexture(in.BlurX, renWin, blurW, blurH, GL_R32F);
    U::EnsureScreenTexture(in.BlurY, renWin, blurW, blurH, GL_R32F);
    in.BlurY->SetMinificationFilter(vtkTextureObject::Linear);
    in.BlurY->SetMagnificationFilter(vtkTextureObject::Linear);
    const int taps = static_cast<int>(std::ceil(blurRadius / blurStride));
    auto blurUniforms = [&](U::Uniforms& u) {
      u.Int("sketchBlurStride", blurStride)
        .Float("sketchBlurSigma", std::max(0.5, blurRadius / 3.0))
        .Int("sketchBlurTaps", taps)
        .Int2("sketchBlurSize", blurW, blurH);
    };
    stage(in.BlurXQuad, 3, in.BlurX, blurW, blurH, blurUniforms);
    stage(in.BlurYQuad, 4, in.BlurY, blurW, blurH, [&](U::Uniforms& u) {
      blurUniforms(u);
      u.Texture("sketchInput", in.BlurX);
    });
  }
  else
  {
    U::FreeTexture(in.BlurX, renWin);
    U::FreeTexture(in.BlurY, renWin);
  }
  fbo->RemoveColorAttachments(1);
  fbo->UnBind();
  fbo->RestorePreviousBindingsAndBuffers();

  // 5. Strokes and tone into the output framebuffer, with the geometry's depth.
  ostate->vtkglViewport(ox, oy, w, h);
  ostate->vtkglScissor(ox, oy, w, h);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  vtkShaderProgram* program = in.FinalQuad.Prepare(renWin, in.Declarations[5], "  sketchMain();\n");
  if (program)
  {
    U::Uniforms u(program);
    setCommon(u);
    u.Texture("sketchField", in.Resolved)
      .Texture("sketchBlur", in.BlurY)
      .Texture("sketchNoise", in.NoiseTexture)
      .Float2("sketchNoiseStats", in.NoiseStats[0], in.NoiseStats[1])
      .Float("sketchNoiseScale", 1.0 / (noiseUnit * NoiseTextureSize))
      .Float("sketchStepPixels", stepLength * pointSize)
      .Int("sketchSteps", this->Steps)
      .Float("sketchStrokeContrast", strokeContrast)
      .Float("sketchContrast", contrastSetting)
      .Float2("sketchBright", this->BrightThresholds[0], this->BrightThresholds[1])
      .Float("sketchCross", crossThreshold)
      .Float3("sketchPencil", this->PencilColor[0], this->PencilColor[1], this->PencilColor[2])
      .Float3("sketchPaper", this->PaperColor[0], this->PaperColor[1], this->PaperColor[2])
      .SceneOutput(gbuffer, ren);
    in.FinalQuad.Render();
  }
  else
  {
    ok = false;
  }
  if (!ok)
  {
    vtkErrorMacro("Could not build a sketch shader.");
  }
  vtkOpenGLCheckErrorMacro("failed after vtkSketchPass::Render");

  this->FinishScene(s);
}

//------------------------------------------------------------------------------
void vtkSketchPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  vtkInternals& in = *this->Internals;
  for (auto* quad : { &in.EstimateQuad, &in.SmoothQuad, &in.ResolveQuad, &in.BlurXQuad,
         &in.BlurYQuad, &in.FinalQuad })
  {
    quad->Release(w);
  }
  in.FreeTextures(w);
  in.GBuffer->ReleaseGraphicsResources(w);
}
