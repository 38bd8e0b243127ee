#include "vtkPixelArtPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeShaderUtilities.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkPixelArtFS.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace
{
// Eq. 10 of the pixel-art paper (values 1..64), row-major.
const int DitherMatrix[64] = { 1, 49, 13, 61, 4, 52, 16, 64, 33, 17, 45, 29, 36, 20, 48, 32, 9, 57,
  5, 53, 12, 60, 8, 56, 41, 25, 37, 21, 44, 28, 40, 24, 3, 51, 15, 63, 2, 50, 14, 62, 35, 19, 47,
  31, 34, 18, 46, 30, 11, 59, 7, 55, 10, 58, 6, 54, 43, 27, 39, 23, 42, 26, 38, 22 };

// DawnBringer's 16-colour palette (2011), a pixel-art standard.
const double Palette16[48] = { 20 / 255., 12 / 255., 28 / 255., 68 / 255., 36 / 255., 52 / 255.,
  48 / 255., 52 / 255., 109 / 255., 78 / 255., 74 / 255., 78 / 255., 133 / 255., 76 / 255.,
  48 / 255., 52 / 255., 101 / 255., 36 / 255., 208 / 255., 70 / 255., 72 / 255., 117 / 255.,
  113 / 255., 97 / 255., 89 / 255., 125 / 255., 206 / 255., 210 / 255., 125 / 255., 44 / 255.,
  133 / 255., 149 / 255., 161 / 255., 109 / 255., 170 / 255., 44 / 255., 210 / 255., 170 / 255.,
  153 / 255., 109 / 255., 194 / 255., 202 / 255., 218 / 255., 212 / 255., 94 / 255., 222 / 255.,
  238 / 255., 214 / 255. };

// Floor division and a non-negative modulo for possibly negative integers.
long long FloorDiv(long long a, long long b)
{
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}
int PositiveMod(long long a, long long b)
{
  const long long m = a % b;
  return static_cast<int>(m < 0 ? m + b : m);
}

enum Stages
{
  REDUCE_STAGE = 0, // FAITHFUL: average each block of the full-resolution G-buffer
  GAUSS_STAGE,      // grayscale and the paper's 3x3 Gaussian
  GRADIENT_STAGE,   // Sobel gradient
  CLASSIFY_STAGE,   // non-maximum suppression, double threshold, depth and normal edges
  HYSTERESIS_STAGE, // one step of hysteresis
  STYLIZE_STAGE,    // the art pixels: palette, dither, outlines
  UPSAMPLE_STAGE    // the art pixels into the output
};
constexpr vtkStylizeStage PixelArtStages[] = {
  { REDUCE_STAGE, "PIXEL_STAGE_REDUCE", "PIXEL_STAGE_REDUCE" },
  { GAUSS_STAGE, "PIXEL_STAGE_GAUSS", "PIXEL_STAGE_GAUSS" },
  { GRADIENT_STAGE, "PIXEL_STAGE_GRADIENT", "PIXEL_STAGE_GRADIENT" },
  { CLASSIFY_STAGE, "PIXEL_STAGE_CLASSIFY", "PIXEL_STAGE_CLASSIFY" },
  { HYSTERESIS_STAGE, "PIXEL_STAGE_HYSTERESIS", "PIXEL_STAGE_HYSTERESIS" },
  { STYLIZE_STAGE, "PIXEL_STAGE_STYLIZE", "PIXEL_STAGE_STYLIZE" },
  { UPSAMPLE_STAGE, "PIXEL_STAGE_UPSAMPLE", "PIXEL_STAGE_UPSAMPLE" },
};
static_assert(vtkStylizeStagesInOrder(PixelArtStages), "pixel art's stages out of order");
enum Textures
{
  REDUCED_COLOR = 0,
  REDUCED_LINEAR,
  REDUCED_NORMAL,
  REDUCED_POSITION,
  GRAY,
  GRADIENT,
  CLASSES_0,
  CLASSES_1,
  ART,
  ART_OUTPUT, // the art pixels in output colours, blitted into the output (Plan::Blit)
  PALETTE
};
}

class vtkPixelArtPass::vtkInternals
{
public:
  std::vector<float> PaletteData; // what the PALETTE texture holds (RGBA)
  double PaletteSpread = 0.0;     // its median colour spacing
  std::vector<double> Custom;     // the CUSTOM palette, RGB
  int Block[2] = { 1, 1 };
  int Grid[2] = { 0, 0 };
};

/** What a frame computes: the art-pixel grid, the enabled stages, their channels and defines. */
struct vtkPixelArtPass::Plan
{
  int Block[2];        // art pixel size in screen pixels
  int Grid[2];         // art pixels over the viewport
  int Origin[2];       // the first art pixel's corner, viewport pixels
  int ExtentOrigin[2]; // FAITHFUL: the rendered extent of the blocks, viewport pixels
  int Extent[2];
  int DitherOrigin[2];
  double Shift[2];   // the snap shift, pixels
  double ArtWorld;   // world size of an art pixel (times the depth in perspective)
  double AnchorUnit; // world size of a dither cell on the surface
  double TexelUnit;  // world size of a surface art pixel (a texel) at the focal point
  bool Fast, WriteDepth, Canny, Sobel, DepthEdges, NormalEdges, Edges, SurfaceAnchor;
  bool Texels; // SURFACE at full resolution: the art pixels are fixed to the surface
  bool Blit; // every screen pixel is its art pixel's: the art stage writes output colours, blitted
  std::vector<float> Colours; // the list palette (RGBA); empty for LEVELS and GRAYS
  SceneRequest Scene;
  std::string Defines;
};

/** The textures the art-resolution stages read (the G-buffer's, or their block averages). */
struct vtkPixelArtPass::Inputs
{
  vtkTextureObject* Colour;
  vtkTextureObject* Linear;
  vtkTextureObject* Normal;
  vtkTextureObject* Position;
  vtkTextureObject* Depth; // the full-resolution depth, read by the upsample stage only
};

vtkStandardNewMacro(vtkPixelArtPass);
vtkCxxSetObjectMacro(vtkPixelArtPass, LookupTable, vtkScalarsToColors);

//------------------------------------------------------------------------------
vtkPixelArtPass::vtkPixelArtPass()
  : vtkStylizeStylePass(vtkStylizeLightingPass::PIXEL_ART)
  , Internals(new vtkInternals)
{
  this->SetStages(
    vtkPixelArtFS, "  pixelMain();\n", { std::begin(PixelArtStages), std::end(PixelArtStages) });
}

//------------------------------------------------------------------------------
void vtkPixelArtPass::AnchorToSurface(bool)
{
  this->SavedDitherAnchor = this->DitherAnchor;
  this->SetDitherAnchor(SURFACE);
}

//------------------------------------------------------------------------------
void vtkPixelArtPass::RestoreAnchors()
{
  this->SetDitherAnchor(this->SavedDitherAnchor);
}

//------------------------------------------------------------------------------
void vtkPixelArtPass::ConfigureLightingColors(vtkStylizeLightingPass* lighting)
{
  lighting->SetColorMode(this->ColoredLights ? vtkStylizeLightingPass::LIT_COLORS
                                             : vtkStylizeLightingPass::NEUTRAL_LIGHTS);
  lighting->SetSolidColorTones(false);
}

//------------------------------------------------------------------------------
int vtkPixelArtPass::SwapLayer(int layer)
{
  const int previous = this->Layer;
  this->SetLayer(layer);
  return previous;
}

//------------------------------------------------------------------------------
vtkPixelArtPass::~vtkPixelArtPass()
{
  this->SetLookupTable(nullptr);
}

//------------------------------------------------------------------------------
const int* vtkPixelArtPass::GetDitherMatrix()
{
  return DitherMatrix;
}

//------------------------------------------------------------------------------
const double* vtkPixelArtPass::GetPalette16()
{
  return Palette16;
}

namespace
{
double Clamp01(double v)
{
  return std::isfinite(v) ? std::min(1.0, std::max(0.0, v)) : 0.0;
}
}

//------------------------------------------------------------------------------
void vtkPixelArtPass::SetOutlineColor(double r, double g, double b)
{
  const double c[3] = { Clamp01(r), Clamp01(g), Clamp01(b) };
  if (c[0] != this->OutlineColor[0] || c[1] != this->OutlineColor[1] ||
    c[2] != this->OutlineColor[2])
  {
    std::copy(c, c + 3, this->OutlineColor);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPixelArtPass::AddPaletteColor(double r, double g, double b)
{
  if (this->Internals->Custom.size() >= 3 * 256)
  {
    vtkWarningMacro("The custom palette holds at most 256 colours; colour ignored.");
    return;
  }
  this->Internals->Custom.insert(
    this->Internals->Custom.end(), { Clamp01(r), Clamp01(g), Clamp01(b) });
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPixelArtPass::RemoveAllPaletteColors()
{
  if (!this->Internals->Custom.empty())
  {
    this->Internals->Custom.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkPixelArtPass::GetNumberOfPaletteColors() const
{
  return static_cast<int>(this->Internals->Custom.size() / 3);
}

//------------------------------------------------------------------------------
bool vtkPixelArtPass::GetPaletteColor(int i, double rgb[3]) const
{
  if (i < 0 || i >= this->GetNumberOfPaletteColors())
  {
    return false;
  }
  std::copy(&this->Internals->Custom[3 * i], &this->Internals->Custom[3 * i] + 3, rgb);
  return true;
}

//------------------------------------------------------------------------------
void vtkPixelArtPass::GetLastGrid(int blockSize[2], int gridSize[2]) const
{
  blockSize[0] = this->Internals->Block[0];
  blockSize[1] = this->Internals->Block[1];
  gridSize[0] = this->Internals->Grid[0];
  gridSize[1] = this->Internals->Grid[1];
}

//------------------------------------------------------------------------------
void vtkPixelArtPass::PrintSelf(ostream& os, vtkIndent indent)
{
  static const char* const modes[] = { "fast", "faithful" };
  static const char* const detectors[] = { "none", "sobel", "canny" };
  static const char* const palettes[] = { "levels", "grays", "palette16", "custom", "colormap" };
  static const char* const anchors[] = { "screen", "grid", "surface" };
  static const char* const layers[] = { "pixel-art", "pixelated", "edges" };
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << modes[this->Mode] << "\n";
  os << indent << "PixelSize: " << this->PixelSize << " px\n";
  os << indent << "ArtPixelsAcross: " << this->ArtPixelsAcross << "\n";
  os << indent << "EdgeDetector: " << detectors[this->EdgeDetector] << "\n";
  os << indent << "LowThreshold: " << this->LowThreshold << "\n";
  os << indent << "HighThreshold: " << this->HighThreshold << "\n";
  os << indent << "HysteresisIterations: " << this->HysteresisIterations << "\n";
  os << indent << "DepthEdges: " << this->DepthEdges << " (threshold " << this->DepthThreshold
     << ")\n";
  os << indent << "NormalEdges: " << this->NormalEdges << " (threshold " << this->NormalThreshold
     << ")\n";
  os << indent << "OutlineColor: " << this->OutlineColor[0] << " " << this->OutlineColor[1] << " "
     << this->OutlineColor[2] << "\n";
  os << indent << "Palette: " << palettes[this->Palette] << "\n";
  os << indent << "Levels: " << this->Levels << "\n";
  os << indent << "PaletteColors: " << this->GetNumberOfPaletteColors() << "\n";
  os << indent << "LookupTable: " << (this->LookupTable ? "set" : "(the data's)") << "\n";
  os << indent << "ColormapColors: " << this->ColormapColors << "\n";
  os << indent << "ColormapShades: " << this->ColormapShades << "\n";
  os << indent << "DitherStrength: " << this->DitherStrength << "\n";
  os << indent << "DitherSize: " << this->DitherSize << "\n";
  os << indent << "DitherAnchor: " << anchors[this->DitherAnchor] << "\n";
  os << indent << "SnapToGrid: " << this->SnapToGrid << "\n";
  os << indent << "ColoredLights: " << this->ColoredLights << "\n";
  os << indent << "StylizeBackground: " << this->StylizeBackground << "\n";
  os << indent << "Layer: " << layers[this->Layer] << "\n";
  os << indent << "DepthOutput: " << (this->DepthOutput == DEPTH_ALWAYS ? "always" : "auto")
     << "\n";
}

namespace
{
// The lookup table of the first visible actor that maps scalars through one (not a mapper
// that merely could: vtkMapper::GetLookupTable() makes a default table on demand).
vtkScalarsToColors* FindLookupTable(const vtkRenderState* s)
{
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkActor* actor = vtkActor::SafeDownCast(s->GetPropArray()[i]);
    vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
    if (!actor || !actor->GetVisibility() || !mapper || !mapper->GetScalarVisibility() ||
      mapper->GetColorMode() == VTK_COLOR_MODE_DIRECT_SCALARS)
    {
      continue;
    }
    int cellFlag = 0;
    vtkDataSet* input = mapper->GetInputAsDataSet();
    vtkDataArray* scalars = input
      ? vtkDataArray::SafeDownCast(
          vtkAbstractMapper::GetAbstractScalars(input, mapper->GetScalarMode(),
            mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), cellFlag))
      : nullptr;
    if (!scalars)
    {
      continue;
    }
    // A vector array is mapped through the table by its magnitude or one component (as VTK's
    // scalar colouring does, vtkScalarsToColors::SetVectorModeToMagnitude): the table's range
    // and colours are then the colormap too. Vectors shown as RGB colours have no colormap.
    vtkScalarsToColors* lut = mapper->GetLookupTable();
    if (scalars->GetNumberOfComponents() == 1 ||
      (lut && lut->GetVectorMode() != vtkScalarsToColors::RGBCOLORS))
    {
      return lut;
    }
  }
  return nullptr;
}

// The median distance from each colour to its nearest other colour.
double MedianSpacing(const std::vector<float>& rgba)
{
  const size_t n = rgba.size() / 4;
  if (n < 2)
  {
    return 0.0;
  }
  std::vector<double> nearest(n, 1e30);
  for (size_t i = 0; i < n; ++i)
  {
    for (size_t j = 0; j < n; ++j)
    {
      if (i == j)
      {
        continue;
      }
      double d = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        const double e = rgba[4 * i + c] - rgba[4 * j + c];
        d += e * e;
      }
      nearest[i] = std::min(nearest[i], std::sqrt(d));
    }
  }
  std::nth_element(nearest.begin(), nearest.begin() + n / 2, nearest.end());
  return nearest[n / 2] < 1e29 ? nearest[n / 2] : 0.0;
}
}

//------------------------------------------------------------------------------
bool vtkPixelArtPass::RenderStyle(const vtkRenderState* s, const Frame& frame)
{
  const Plan plan = this->PlanFrame(s, frame);
  this->Internals->Block[0] = plan.Block[0];
  this->Internals->Block[1] = plan.Block[1];
  this->Internals->Grid[0] = plan.Grid[0];
  this->Internals->Grid[1] = plan.Grid[1];
  if (!this->RenderScene(s, plan.Scene))
  {
    return false;
  }
  this->UpdatePalette(frame, plan);
  this->SetShaderDefines(plan.Defines);
  Inputs inputs = { this->GetSceneTexture(vtkStylizeGBufferPass::COLOR_BUFFER),
    this->GetSceneTexture(vtkStylizeGBufferPass::LINEAR_DEPTH_BUFFER),
    this->GetSceneTexture(vtkStylizeGBufferPass::NORMAL_BUFFER),
    this->GetSceneTexture(vtkStylizeGBufferPass::POSITION_BUFFER),
    this->GetSceneTexture(vtkStylizeGBufferPass::DEPTH_BUFFER) };
  const Inputs scene = inputs; // full resolution unless FAST
  if (!plan.Fast)
  {
    this->RenderReduceStage(frame, plan, inputs);
  }
  vtkTextureObject* edges = plan.Edges ? this->RenderEdgeStages(frame, plan, inputs) : nullptr;
  this->RenderArtStage(frame, plan, inputs, edges);
  // Texels find their colour edges on the art pixels' smoothed gray.
  this->RenderUpsampleStage(frame, plan, scene,
    plan.Texels && (plan.Canny || plan.Sobel) ? this->TextureSlot(GRAY) : nullptr);
  return true;
}

//------------------------------------------------------------------------------
vtkPixelArtPass::Plan vtkPixelArtPass::PlanFrame(const vtkRenderState* s, const Frame& frame)
{
  Plan p;
  this->PlanGrid(frame, p);
  this->PlanPalette(s, p);

  // What this frame computes.
  p.Fast = this->Mode == FAST || frame.Interactive; // the interactive variant is FAST
  p.WriteDepth = this->DepthOutput == DEPTH_ALWAYS || this->HasPlainAnnotations();
  for (int i = 0; i < s->GetPropArrayCount() && !p.WriteDepth; ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    p.WriteDepth =
      prop->GetVisibility() && (prop->HasTranslucentPolygonalGeometry() || prop->IsA("vtkVolume"));
  }
  const bool layerEdges = this->Layer != PIXELATED;
  p.Canny = layerEdges && this->EdgeDetector == CANNY;
  p.Sobel = layerEdges && this->EdgeDetector == SOBEL;
  p.DepthEdges = layerEdges && this->DepthEdges;
  p.NormalEdges = layerEdges && this->NormalEdges;
  p.Edges = p.Canny || p.Sobel || p.DepthEdges || p.NormalEdges;
  p.SurfaceAnchor = this->Layer == PIXEL_ART && this->DitherAnchor == SURFACE;

  // The G-buffer: at the art-pixel resolution over the grid (FAST) or at full resolution over
  // the blocks' extent (FAITHFUL), shifted onto the grid.
  SceneRequest& r = p.Scene;
  r.Channels = vtkStylizeGBufferPass::LINEAR_DEPTH;
  if (p.NormalEdges)
  {
    r.Channels |= vtkStylizeGBufferPass::NORMAL;
  }
  if (p.SurfaceAnchor)
  {
    r.Channels |= vtkStylizeGBufferPass::POSITION;
    r.PositionSpace = vtkStylizeGBufferPass::OBJECT;
  }
  const int* size = frame.Size;
  for (int a = 0; a < 2; ++a)
  {
    const double first = p.Fast ? p.Origin[a] : p.ExtentOrigin[a];
    const double span = p.Fast ? static_cast<double>(p.Grid[a]) * p.Block[a] : p.Extent[a];
    r.ScreenTransform[a] = size[a] / span;
    r.ScreenTransform[2 + a] =
      r.ScreenTransform[a] - 1.0 - 2.0 * first / span + 2.0 * p.Shift[a] / span;
    r.AfterShift[a] = 2.0 * p.Shift[a] / size[a];
  }
  if (p.Fast)
  {
    r.Resolution[0] = p.Grid[0];
    r.Resolution[1] = p.Grid[1];
  }
  else if (p.Extent[0] != size[0] || p.Extent[1] != size[1])
  {
    r.Resolution[0] = p.Extent[0];
    r.Resolution[1] = p.Extent[1];
  }

  // World size of an art pixel (depth edges), of a texel and of a dither cell on the surface.
  p.ArtWorld = frame.PixelWorld * p.Block[1];
  p.TexelUnit = frame.Parallel ? p.ArtWorld : p.ArtWorld * frame.Camera->GetDistance();
  if (!(p.TexelUnit > 0.0) || !std::isfinite(p.TexelUnit))
  {
    p.TexelUnit = 1.0;
  }
  p.AnchorUnit = p.TexelUnit * this->DitherSize;
  if (!std::isfinite(p.AnchorUnit))
  {
    p.AnchorUnit = 1.0;
  }
  // The surface's own art pixels need the full-resolution positions (not in FAST).
  p.Texels = p.SurfaceAnchor && !p.Fast;
  // Without texels or depth each screen pixel shows its art pixel's output colour: the art stage
  // computes it once per art pixel and a nearest-neighbour blit writes the screen (about half
  // the full-size stage's 14-16 ms at 1920x1080 on llvmpipe).
  p.Blit = !p.Texels && !p.WriteDepth && this->CanBlitToOutput(frame);

  auto define = [&p](bool on, const std::string& name) { AddDefine(p.Defines, on, name); };
  define(p.Fast, "PIXEL_FAST");
  define(p.Canny, "PIXEL_CANNY");
  define(p.Sobel, "PIXEL_SOBEL");
  define(p.DepthEdges, "PIXEL_DEPTH_EDGES");
  define(p.NormalEdges, "PIXEL_NORMAL_EDGES");
  define(p.NormalEdges, "PIXEL_NORMALS");
  define(p.SurfaceAnchor, "PIXEL_POSITIONS");
  define(p.Edges, "PIXEL_EDGES");
  define(p.SurfaceAnchor, "PIXEL_SURFACE_ANCHOR");
  define(p.Texels, "PIXEL_TEXELS");
  define(this->StylizeBackground, "PIXEL_STYLIZE_BACKGROUND");
  define(p.WriteDepth, "PIXEL_WRITE_DEPTH");
  define(p.Blit, "PIXEL_BLIT_OUTPUT");
  const int palette = p.Colours.empty() ? (this->Palette == GRAYS ? 1 : 0) : 2;
  p.Defines += "#define PIXEL_PALETTE " + std::to_string(palette) + "\n";
  p.Defines += "#define PIXEL_LAYER " + std::to_string(this->Layer) + "\n";
  p.Defines += "#define PIXEL_REDUCE_SAMPLES ivec2(" + std::to_string(std::min(p.Block[0], 16)) +
    ", " + std::to_string(std::min(p.Block[1], 16)) + ")\n";
  return p;
}

//------------------------------------------------------------------------------
void vtkPixelArtPass::PlanGrid(const Frame& frame, Plan& p) const
{
  const long long offset[2] = { std::llround(frame.FullOffset[0]),
    std::llround(frame.FullOffset[1]) };
  const int* size = frame.Size;

  // Art pixel size in screen pixels.
  if (this->ArtPixelsAcross > 0)
  {
    p.Block[0] = p.Block[1] = static_cast<int>(
      std::max(1.0, std::min(1.0e6, std::round(frame.FullSize[0] / this->ArtPixelsAcross))));
  }
  else
  {
    p.Block[0] = this->PixelSize * frame.TileScale[0];
    p.Block[1] = this->PixelSize * frame.TileScale[1];
  }

  // The grid: art columns i0 .. i1 of the full image cover this viewport. FAITHFUL renders the
  // full-resolution extent of these blocks (clipped to the full image), so that an art pixel
  // that straddles two tiles of a magnified screenshot averages the same pixels in both.
  // A tile's side that borders another tile gets a guard band of art pixels as far as the
  // outline stages read (the 3x3 Gaussian, Sobel, non-maximum suppression, one more for each
  // hysteresis step, one for the depth and normal classes), so that the outlines are those of
  // a direct render at the full size. (A scene from a delegate's image holds nothing beyond
  // the tile.)
  const long long guard = this->DelegatePass ? 0 : 4 + this->HysteresisIterations;
  long long first[2];
  for (int a = 0; a < 2; ++a)
  {
    const int block = p.Block[a];
    const long long full = std::llround(frame.FullSize[a]);
    long long i0 = FloorDiv(offset[a], block);
    long long i1 = FloorDiv(offset[a] + size[a] - 1, block);
    if (offset[a] > 0)
    {
      i0 = std::max(0LL, i0 - guard);
    }
    if (offset[a] + size[a] < full)
    {
      i1 = std::min(FloorDiv(full - 1, block), i1 + guard);
    }
    first[a] = i0;
    p.Grid[a] = static_cast<int>(i1 - i0 + 1);
    p.Origin[a] = static_cast<int>(i0 * block - offset[a]);
    const long long lo = std::max(i0 * block, 0LL);
    const long long hi = std::max(std::min((i1 + 1) * block, full), offset[a] + size[a]);
    p.ExtentOrigin[a] = static_cast<int>(std::min(lo, offset[a]) - offset[a]);
    p.Extent[a] = static_cast<int>(hi - offset[a] - p.ExtentOrigin[a]);
    if (p.Extent[a] > std::max(3 * size[a], 4096))
    {
      // Art pixels far larger than a tile: reduce the tile's own pixels only (a seam is
      // possible) rather than render a texture many times the tile's size.
      p.ExtentOrigin[a] = 0;
      p.Extent[a] = size[a];
    }
  }

  // Where the world origin falls, in full-image pixels; the snap shift that puts it on the grid.
  p.Shift[0] = p.Shift[1] = 0.0;
  long long gridOrigin[2] = { 0, 0 }; // art index of the world origin in the full image
  const double aspect = frame.Renderer->GetTiledAspectRatio();
  vtkMatrix4x4* m = frame.Camera->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0);
  const double clip[4] = { m->GetElement(0, 3), m->GetElement(1, 3), m->GetElement(2, 3),
    m->GetElement(3, 3) };
  if (clip[3] > 0.0 && std::isfinite(clip[0]) && std::isfinite(clip[1]))
  {
    for (int a = 0; a < 2; ++a)
    {
      const double ndc = clip[a] / clip[3];
      const double pixel = (ndc + 1.0) * 0.5 * size[a] + static_cast<double>(offset[a]);
      if (std::isfinite(pixel) && std::abs(pixel) < 1.0e15)
      {
        const double cells = std::round(pixel / p.Block[a]);
        gridOrigin[a] = static_cast<long long>(cells);
        if (frame.Parallel && this->SnapToGrid)
        {
          p.Shift[a] = cells * p.Block[a] - pixel;
        }
      }
    }
  }
  for (int a = 0; a < 2; ++a)
  {
    const long long index = this->DitherAnchor == SCREEN ? first[a] : first[a] - gridOrigin[a];
    p.DitherOrigin[a] = PositiveMod(index, 8LL * this->DitherSize);
  }
}

//------------------------------------------------------------------------------
void vtkPixelArtPass::PlanPalette(const vtkRenderState* s, Plan& p) const
{
  auto addColour = [&p](double r, double g, double b)
  {
    p.Colours.insert(p.Colours.end(),
      { static_cast<float>(r), static_cast<float>(g), static_cast<float>(b), 1.0f });
  };
  if (this->Palette == PALETTE16)
  {
    for (int i = 0; i < 16; ++i)
    {
      addColour(Palette16[3 * i], Palette16[3 * i + 1], Palette16[3 * i + 2]);
    }
  }
  else if (this->Palette == CUSTOM)
  {
    const std::vector<double>& custom = this->Internals->Custom;
    for (size_t i = 0; i + 2 < custom.size(); i += 3)
    {
      addColour(custom[i], custom[i + 1], custom[i + 2]);
    }
  }
  else if (this->Palette == COLORMAP)
  {
    vtkScalarsToColors* lut = this->LookupTable ? this->LookupTable : FindLookupTable(s);
    if (lut)
    {
      const double* range = lut->GetRange();
      addColour(0.0, 0.0, 0.0);
      for (int i = 0; i < this->ColormapColors; ++i)
      {
        const double v = range[0] + (i + 0.5) / this->ColormapColors * (range[1] - range[0]);
        double rgb[3];
        lut->GetColor(v, rgb);
        for (int k = 1; k <= this->ColormapShades; ++k)
        {
          const double f = static_cast<double>(k) / this->ColormapShades;
          addColour(Clamp01(rgb[0] * f), Clamp01(rgb[1] * f), Clamp01(rgb[2] * f));
        }
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkPixelArtPass::UpdatePalette(const Frame& frame, const Plan& plan)
{
  vtkInternals& in = *this->Internals;
  vtkTextureObject*& texture = this->TextureSlot(PALETTE);
  if (this->Layer != PIXEL_ART || plan.Colours.empty() ||
    (plan.Colours == in.PaletteData && texture && texture->GetContext() == frame.Window))
  {
    return;
  }
  this->FreeTexture(PALETTE);
  texture = vtkTextureObject::New();
  texture->SetContext(frame.Window);
  texture->Create2DFromRaw(static_cast<unsigned int>(plan.Colours.size() / 4), 1, 4, VTK_FLOAT,
    const_cast<float*>(plan.Colours.data()));
  in.PaletteData = plan.Colours;
  in.PaletteSpread = MedianSpacing(plan.Colours);
}

//------------------------------------------------------------------------------
void vtkPixelArtPass::SetStageUniforms(vtkStylizeUniforms& u, const Frame& frame, const Plan& p,
  const Inputs& inputs, vtkTextureObject* input, vtkTextureObject* art)
{
  const vtkInternals& in = *this->Internals;
  u.Texture("stylizeColorTexture", inputs.Colour)
    .Texture("stylizeLinearDepthTexture", inputs.Linear)
    .Texture("stylizeNormalTexture", inputs.Normal)
    .Texture("stylizePositionTexture", inputs.Position)
    .Texture("stylizeDepthTexture", inputs.Depth)
    .Texture("pixelInputTexture", input)
    .Texture("pixelArtTexture", art)
    .Texture("pixelPaletteTexture", this->TextureSlot(PALETTE))
    .Int2("pixelArtSize", p.Grid[0], p.Grid[1])
    .Int2("pixelViewportSize", frame.Size[0], frame.Size[1])
    .Int2("pixelBlock", p.Block[0], p.Block[1])
    .Int2("pixelGridOrigin", p.Origin[0], p.Origin[1])
    .Int2("pixelExtentOrigin", p.ExtentOrigin[0], p.ExtentOrigin[1])
    .Int2("pixelExtentSize", p.Extent[0], p.Extent[1])
    .Int2("pixelDitherOrigin", p.DitherOrigin[0], p.DitherOrigin[1])
    .Int("pixelDitherSize", this->DitherSize)
    .Float("pixelDitherStrength", this->DitherStrength)
    .Int("pixelLevels", this->Levels)
    .Int("pixelPaletteSize", static_cast<int>(in.PaletteData.size() / 4))
    .Float("pixelPaletteSpread", in.PaletteSpread)
    .Float("pixelLow", this->LowThreshold)
    .Float("pixelHigh", this->HighThreshold)
    .Float("pixelDepthThreshold", this->DepthThreshold)
    .Float("pixelNormalThreshold", this->NormalThreshold)
    .Float("pixelArtWorld", p.ArtWorld)
    .Int("pixelParallel", frame.Parallel ? 1 : 0)
    .Float("pixelAnchorUnit", p.AnchorUnit)
    .Float("pixelTexelUnit", p.TexelUnit)
    .Float3(
      "pixelOutlineColor", this->OutlineColor[0], this->OutlineColor[1], this->OutlineColor[2])
    .Int("pixelEmittedLayer", this->GetTranslucentLayerEmitted() ? 1 : 0);
  this->SetSceneOutputUniforms(u, frame.Renderer);
}

//------------------------------------------------------------------------------
void vtkPixelArtPass::RenderReduceStage(const Frame& frame, const Plan& p, Inputs& inputs)
{
  const int nx = p.Grid[0], ny = p.Grid[1];
  const bool full = this->GetGBufferPass()->GetPrecision() == vtkStylizeGBufferPass::FULL;
  vtkTextureObject* colour =
    this->EnsureTexture(REDUCED_COLOR, nx, ny, full ? GL_RGBA32F : GL_RGBA16F);
  vtkTextureObject* linear = this->EnsureTexture(REDUCED_LINEAR, nx, ny, GL_R32F);
  vtkTextureObject* normal =
    p.NormalEdges ? this->EnsureTexture(REDUCED_NORMAL, nx, ny, GL_RGBA16F) : nullptr;
  vtkTextureObject* position =
    p.SurfaceAnchor ? this->EnsureTexture(REDUCED_POSITION, nx, ny, GL_RGBA32F) : nullptr;
  auto uniforms = [&](vtkStylizeUniforms& u)
  { this->SetStageUniforms(u, frame, p, inputs, nullptr, nullptr); };
  if (normal && position)
  {
    this->RenderStage(REDUCE_STAGE, { colour, linear, normal, position }, nx, ny, uniforms);
  }
  else if (normal || position)
  {
    this->RenderStage(
      REDUCE_STAGE, { colour, linear, normal ? normal : position }, nx, ny, uniforms);
  }
  else
  {
    this->RenderStage(REDUCE_STAGE, { colour, linear }, nx, ny, uniforms);
  }
  inputs.Colour = colour;
  inputs.Linear = linear;
  inputs.Normal = normal;
  inputs.Position = position;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkPixelArtPass::RenderEdgeStages(
  const Frame& frame, const Plan& p, const Inputs& inputs)
{
  const int nx = p.Grid[0], ny = p.Grid[1];
  Inputs art = inputs;
  art.Depth = nullptr; // not read at the art resolution
  auto stage = [&](int index, vtkTextureObject* target, vtkTextureObject* input)
  {
    this->RenderStage(index, { target }, nx, ny,
      [&](vtkStylizeUniforms& u) { this->SetStageUniforms(u, frame, p, art, input, nullptr); });
  };
  vtkTextureObject* classes = this->EnsureTexture(CLASSES_0, nx, ny, GL_R32F);
  vtkTextureObject* gradient = nullptr;
  if (p.Canny || p.Sobel)
  {
    vtkTextureObject* gray = this->EnsureTexture(GRAY, nx, ny, GL_R32F);
    gradient = this->EnsureTexture(GRADIENT, nx, ny, GL_RGBA32F);
    stage(GAUSS_STAGE, gray, nullptr);
    stage(GRADIENT_STAGE, gradient, gray);
  }
  else
  {
    gradient = this->TextureSlot(GRADIENT); // not read without Canny or Sobel
  }
  stage(CLASSIFY_STAGE, classes, gradient);
  vtkTextureObject* edges = classes;
  if (p.Canny && this->HysteresisIterations > 0)
  {
    vtkTextureObject* other = this->EnsureTexture(CLASSES_1, nx, ny, GL_R32F);
    for (int i = 0; i < this->HysteresisIterations; ++i)
    {
      vtkTextureObject* target = edges == classes ? other : classes;
      stage(HYSTERESIS_STAGE, target, edges);
      edges = target;
    }
  }
  return edges;
}

//------------------------------------------------------------------------------
void vtkPixelArtPass::RenderArtStage(
  const Frame& frame, const Plan& p, const Inputs& inputs, vtkTextureObject* edges)
{
  const int nx = p.Grid[0], ny = p.Grid[1];
  Inputs art = inputs;
  art.Depth = nullptr; // not read at the art resolution
  vtkTextureObject* target = p.Blit ? this->EnsureTexture(ART_OUTPUT, nx, ny, GL_RGBA8)
                                    : this->EnsureTexture(ART, nx, ny, GL_RGBA16F);
  this->RenderStage(STYLIZE_STAGE, { target }, nx, ny,
    [&](vtkStylizeUniforms& u) { this->SetStageUniforms(u, frame, p, art, edges, nullptr); });
}

//------------------------------------------------------------------------------
void vtkPixelArtPass::RenderUpsampleStage(
  const Frame& frame, const Plan& p, const Inputs& inputs, vtkTextureObject* gray)
{
  if (p.Blit)
  {
    const int rect[4] = { p.Origin[0], p.Origin[1], p.Origin[0] + p.Grid[0] * p.Block[0],
      p.Origin[1] + p.Grid[1] * p.Block[1] };
    this->BlitToOutput(frame, this->TextureSlot(ART_OUTPUT), rect);
    return;
  }
  this->RenderStageToOutput(frame, UPSAMPLE_STAGE, p.WriteDepth,
    [&](vtkStylizeUniforms& u)
    { this->SetStageUniforms(u, frame, p, inputs, gray, this->TextureSlot(ART)); });
}
