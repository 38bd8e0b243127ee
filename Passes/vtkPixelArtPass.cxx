#include "vtkPixelArtPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkShaderProgram.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeShaderUtilities.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkPixelArtFS.h"
#include "vtkStylizeCommonFS.h"
#include "vtkStylizeDepthFS.h"
#include "vtkStylizeScreenFS.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace
{
// Eq. 10 of the pixel-art paper (values 1..64), row-major.
const int DitherMatrix[64] = { 1, 49, 13, 61, 4, 52, 16, 64, 33, 17, 45, 29, 36, 20, 48, 32, 9,
  57, 5, 53, 12, 60, 8, 56, 41, 25, 37, 21, 44, 28, 40, 24, 3, 51, 15, 63, 2, 50, 14, 62, 35, 19,
  47, 31, 34, 18, 46, 30, 11, 59, 7, 55, 10, 58, 6, 54, 43, 27, 39, 23, 42, 26, 38, 22 };

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
}

class vtkPixelArtPass::vtkInternals
{
public:
  vtkNew<vtkStylizeLightingPass> Lighting;
  vtkNew<vtkStylizeGBufferPass> GBuffer;
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;

  // Art-resolution textures.
  vtkTextureObject* ReducedColor = nullptr;
  vtkTextureObject* ReducedLinear = nullptr;
  vtkTextureObject* ReducedNormal = nullptr;
  vtkTextureObject* ReducedPosition = nullptr;
  vtkTextureObject* Gray = nullptr;
  vtkTextureObject* Gradient = nullptr;
  vtkTextureObject* Classes[2] = { nullptr, nullptr };
  vtkTextureObject* Art = nullptr;
  vtkTextureObject* PaletteTexture = nullptr;
  std::vector<float> PaletteData; // what PaletteTexture holds (RGBA)
  double PaletteSpread = 0.0;     // its median colour spacing

  vtkStylizeShaderUtilities::ScreenQuad ReduceQuad, GaussQuad, GradientQuad, ClassifyQuad,
    HysteresisQuad, StylizeQuad, UpsampleQuad;
  std::string Defines;
  std::array<std::string, 7> Declarations;

  std::vector<double> Custom; // the CUSTOM palette, RGB
  int Block[2] = { 1, 1 };
  int Grid[2] = { 0, 0 };

  void FreeTextures(vtkWindow* w)
  {
    using U = vtkStylizeShaderUtilities;
    for (vtkTextureObject** t : { &this->ReducedColor, &this->ReducedLinear, &this->ReducedNormal,
           &this->ReducedPosition, &this->Gray, &this->Gradient, &this->Classes[0],
           &this->Classes[1], &this->Art, &this->PaletteTexture })
    {
      U::FreeTexture(*t, w);
    }
    this->PaletteData.clear();
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
};

vtkStandardNewMacro(vtkPixelArtPass);
vtkCxxSetObjectMacro(vtkPixelArtPass, LookupTable, vtkScalarsToColors);

//------------------------------------------------------------------------------
vtkPixelArtPass::vtkPixelArtPass()
  : Internals(new vtkInternals)
{
  this->Internals->Lighting->SetModel(vtkStylizeLightingPass::PIXEL_ART);
  this->Internals->GBuffer->SetLightingPass(this->Internals->Lighting);
}

//------------------------------------------------------------------------------
vtkPixelArtPass::~vtkPixelArtPass()
{
  this->SetLookupTable(nullptr);
  this->Internals->FreeTextures(nullptr);
}

//------------------------------------------------------------------------------
vtkStylizeLightingPass* vtkPixelArtPass::GetLightingPass()
{
  return this->Internals->Lighting;
}

//------------------------------------------------------------------------------
vtkStylizeGBufferPass* vtkPixelArtPass::GetGBufferPass()
{
  return this->Internals->GBuffer;
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
  this->Internals->Custom.insert(this->Internals->Custom.end(), { Clamp01(r), Clamp01(g), Clamp01(b) });
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
  os << indent << "StylizeBackground: " << this->StylizeBackground << "\n";
  os << indent << "Layer: " << layers[this->Layer] << "\n";
  os << indent << "DepthOutput: " << (this->DepthOutput == DEPTH_ALWAYS ? "always" : "auto")
     << "\n";
  os << indent << "LightingPass:\n";
  this->Internals->Lighting->PrintSelf(os, indent.GetNextIndent());
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
      ? vtkDataArray::SafeDownCast(vtkAbstractMapper::GetAbstractScalars(input,
          mapper->GetScalarMode(), mapper->GetArrayAccessMode(), mapper->GetArrayId(),
          mapper->GetArrayName(), cellFlag))
      : nullptr;
    if (scalars && scalars->GetNumberOfComponents() == 1)
    {
      return mapper->GetLookupTable();
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
void vtkPixelArtPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkStylizeGBufferPass* gbuffer = this->Internals->GBuffer;
  vtkInternals& in = *this->Internals;
  if (!renWin)
  {
    return;
  }
  int w, h, ox, oy;
  ren->GetTiledSizeAndOrigin(&w, &h, &ox, &oy);
  if (w < 1 || h < 1)
  {
    gbuffer->SetGeometryResolution(0, 0);
    this->RenderScene(s, gbuffer->GetChannels());
    return;
  }

  // The full (possibly tiled, magnified) image: its size and this tile's offset in it.
  using U = vtkStylizeShaderUtilities;
  const U::FullImage full = U::GetFullImage(ren, ox, oy);
  const long long offset[2] = { std::llround(full.Offset[0]), std::llround(full.Offset[1]) };

  // Art pixel size in screen pixels.
  int block[2];
  if (this->ArtPixelsAcross > 0)
  {
    block[0] = block[1] = static_cast<int>(
      std::max(1.0, std::min(1.0e6, std::round(full.Size[0] / this->ArtPixelsAcross))));
  }
  else
  {
    block[0] = this->PixelSize * full.TileScale[0];
    block[1] = this->PixelSize * full.TileScale[1];
  }

  // The grid: art columns i0 .. i1 of the full image cover this viewport. FAITHFUL renders the
  // full-resolution extent of these blocks (clipped to the full image), so that an art pixel
  // that straddles two tiles of a magnified screenshot averages the same pixels in both.
  int grid[2], origin[2], extentOrigin[2], extent[2];
  const int size[2] = { w, h };
  for (int a = 0; a < 2; ++a)
  {
    const long long i0 = FloorDiv(offset[a], block[a]);
    const long long i1 = FloorDiv(offset[a] + size[a] - 1, block[a]);
    grid[a] = static_cast<int>(i1 - i0 + 1);
    origin[a] = static_cast<int>(i0 * block[a] - offset[a]);
    const long long lo = std::max(i0 * block[a], 0LL);
    const long long hi = std::max(std::min((i1 + 1) * block[a],
      static_cast<long long>(std::llround(full.Size[a]))), offset[a] + size[a]);
    extentOrigin[a] = static_cast<int>(std::min(lo, offset[a]) - offset[a]);
    extent[a] = static_cast<int>(hi - offset[a] - extentOrigin[a]);
    if (extent[a] > 3 * size[a])
    {
      // Art pixels far larger than a tile: reduce the tile's own pixels only (a seam is
      // possible) rather than render a texture many times the tile's size.
      extentOrigin[a] = 0;
      extent[a] = size[a];
    }
  }
  in.Block[0] = block[0];
  in.Block[1] = block[1];
  in.Grid[0] = grid[0];
  in.Grid[1] = grid[1];

  // Where the world origin falls, in full-image pixels; the snap shift that puts it on the grid.
  vtkCamera* cam = ren->GetActiveCamera();
  const bool parallel = cam->GetParallelProjection() != 0;
  double shift[2] = { 0.0, 0.0 };
  long long gridOrigin[2] = { 0, 0 }; // art index of the world origin in the full image
  {
    double aspect = ren->GetTiledAspectRatio();
    vtkMatrix4x4* m = cam->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0);
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
          const double cells = std::round(pixel / block[a]);
          gridOrigin[a] = static_cast<long long>(cells);
          if (parallel && this->SnapToGrid)
          {
            shift[a] = cells * block[a] - pixel;
          }
        }
      }
    }
  }
  int ditherOrigin[2];
  for (int a = 0; a < 2; ++a)
  {
    const long long firstArt = FloorDiv(offset[a], block[a]);
    const long long index = this->DitherAnchor == SCREEN ? firstArt : firstArt - gridOrigin[a];
    ditherOrigin[a] = PositiveMod(index, 8LL * this->DitherSize);
  }

  // What this frame computes.
  const bool fast = this->Mode == FAST;
  bool writeDepth = this->DepthOutput == DEPTH_ALWAYS;
  for (int i = 0; i < s->GetPropArrayCount() && !writeDepth; ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    writeDepth = prop->GetVisibility() &&
      (prop->HasTranslucentPolygonalGeometry() || prop->IsA("vtkVolume"));
  }
  const bool layerEdges = this->Layer != PIXELATED;
  const bool canny = layerEdges && this->EdgeDetector == CANNY;
  const bool sobel = layerEdges && this->EdgeDetector == SOBEL;
  const bool depthEdges = layerEdges && this->DepthEdges;
  const bool normalEdges = layerEdges && this->NormalEdges;
  const bool edges = canny || sobel || depthEdges || normalEdges;
  const bool surfaceAnchor = this->Layer == PIXEL_ART && this->DitherAnchor == SURFACE;
  int channels = vtkStylizeGBufferPass::LINEAR_DEPTH;
  if (normalEdges)
  {
    channels |= vtkStylizeGBufferPass::NORMAL;
  }
  if (surfaceAnchor)
  {
    channels |= vtkStylizeGBufferPass::POSITION;
    gbuffer->SetPositionSpace(vtkStylizeGBufferPass::OBJECT);
  }

  // Geometry: at the art-pixel resolution over the grid (FAST) or at full resolution over the
  // blocks' extent (FAITHFUL), shifted onto the grid.
  const double shiftNDC[2] = { 2.0 * shift[0] / w, 2.0 * shift[1] / h };
  {
    double t[4];
    for (int a = 0; a < 2; ++a)
    {
      const double first = fast ? origin[a] : extentOrigin[a];
      const double span = fast ? static_cast<double>(grid[a]) * block[a] : extent[a];
      t[a] = size[a] / span;
      t[2 + a] = t[a] - 1.0 - 2.0 * first / span + 2.0 * shift[a] / span;
    }
    gbuffer->SetGeometryScreenTransform(t[0], t[1], t[2], t[3]);
    if (fast)
    {
      gbuffer->SetGeometryResolution(grid[0], grid[1]);
    }
    else if (extent[0] == w && extent[1] == h)
    {
      gbuffer->SetGeometryResolution(0, 0);
    }
    else
    {
      gbuffer->SetGeometryResolution(extent[0], extent[1]);
    }
  }
  gbuffer->SetAfterScreenShift(shiftNDC[0], shiftNDC[1]);
  if (!this->RenderScene(s, channels))
  {
    return;
  }

  // The palette (list palettes only).
  int palette = this->Palette;
  std::vector<float> colours;
  auto addColour = [&](double r, double g, double b) {
    colours.insert(colours.end(),
      { static_cast<float>(r), static_cast<float>(g), static_cast<float>(b), 1.0f });
  };
  if (palette == PALETTE16)
  {
    for (int i = 0; i < 16; ++i)
    {
      addColour(Palette16[3 * i], Palette16[3 * i + 1], Palette16[3 * i + 2]);
    }
  }
  else if (palette == CUSTOM)
  {
    for (size_t i = 0; i + 2 < in.Custom.size(); i += 3)
    {
      addColour(in.Custom[i], in.Custom[i + 1], in.Custom[i + 2]);
    }
  }
  else if (palette == COLORMAP)
  {
    vtkScalarsToColors* lut = this->LookupTable ? this->LookupTable : FindLookupTable(s);
    if (lut)
    {
      const double* range = lut->GetRange();
      addColour(0.0, 0.0, 0.0);
      for (int i = 0; i < this->ColormapColors; ++i)
      {
        const double v =
          range[0] + (i + 0.5) / this->ColormapColors * (range[1] - range[0]);
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
  if (palette >= PALETTE16 && colours.empty())
  {
    palette = LEVELS; // an empty list or no colormap
  }
  const int shaderPalette = palette == LEVELS ? 0 : (palette == GRAYS ? 1 : 2);
  const bool quantize = this->Layer == PIXEL_ART;
  if (quantize && shaderPalette == 2 &&
    (colours != in.PaletteData || !in.PaletteTexture || in.PaletteTexture->GetContext() != renWin))
  {
    vtkStylizeShaderUtilities::FreeTexture(in.PaletteTexture, renWin);
    in.PaletteTexture = vtkTextureObject::New();
    in.PaletteTexture->SetContext(renWin);
    in.PaletteTexture->Create2DFromRaw(
      static_cast<unsigned int>(colours.size() / 4), 1, 4, VTK_FLOAT, colours.data());
    in.PaletteData = colours;
    in.PaletteSpread = MedianSpacing(colours);
  }

  // Shader sources: one program per stage, rebuilt when the defines change.
  std::string defines;
  auto define = [&](bool on, const char* name) {
    if (on)
    {
      defines += std::string("#define ") + name + "\n";
    }
  };
  define(fast, "PIXEL_FAST");
  define(canny, "PIXEL_CANNY");
  define(sobel, "PIXEL_SOBEL");
  define(depthEdges, "PIXEL_DEPTH_EDGES");
  define(normalEdges, "PIXEL_NORMAL_EDGES");
  define(normalEdges, "PIXEL_NORMALS");
  define(surfaceAnchor, "PIXEL_POSITIONS");
  define(edges, "PIXEL_EDGES");
  define(surfaceAnchor, "PIXEL_SURFACE_ANCHOR");
  define(this->StylizeBackground, "PIXEL_STYLIZE_BACKGROUND");
  define(writeDepth, "PIXEL_WRITE_DEPTH");
  defines += "#define PIXEL_PALETTE " + std::to_string(shaderPalette) + "\n";
  defines += "#define PIXEL_LAYER " + std::to_string(this->Layer) + "\n";
  if (defines != in.Defines || in.Declarations[0].empty())
  {
    in.Defines = defines;
    static const char* const stages[7] = { "REDUCE", "GAUSS", "GRADIENT", "CLASSIFY",
      "HYSTERESIS", "STYLIZE", "UPSAMPLE" };
    for (int i = 0; i < 7; ++i)
    {
      in.Declarations[i] = std::string("#define PIXEL_STAGE_") + stages[i] + "\n" + defines +
        vtkStylizeCommonFS + vtkStylizeDepthFS + vtkStylizeScreenFS + vtkPixelArtFS;
    }
  }

  // World size of an art pixel (depth edges) and of a dither cell on the surface.
  const double pixelWorld = U::PixelWorldSize(cam, w, h);
  const double artWorld = pixelWorld * block[1];
  double anchorUnit = (parallel ? artWorld : artWorld * cam->GetDistance()) * this->DitherSize;
  if (!(anchorUnit > 0.0) || !std::isfinite(anchorUnit))
  {
    anchorUnit = 1.0;
  }

  // Inputs of the art-resolution stages.
  vtkTextureObject* colour = gbuffer->GetColorTexture();
  vtkTextureObject* linear = gbuffer->GetLinearDepthTexture();
  vtkTextureObject* normal = gbuffer->GetNormalTexture();
  vtkTextureObject* position = gbuffer->GetPositionTexture();
  vtkTextureObject* depth = gbuffer->GetDepthTexture();

  const int nx = grid[0], ny = grid[1];
  const bool fullPrecision = gbuffer->GetPrecision() == vtkStylizeGBufferPass::FULL;
  if (!in.Framebuffer)
  {
    in.Framebuffer = vtkOpenGLFramebufferObject::New();
    in.Framebuffer->SetContext(renWin);
  }
  vtkOpenGLFramebufferObject* fbo = in.Framebuffer;

  auto setUniforms = [&](U::Uniforms& u, vtkTextureObject* input) {
    u.Texture("stylizeColorTexture", colour)
      .Texture("stylizeLinearDepthTexture", linear)
      .Texture("stylizeNormalTexture", normal)
      .Texture("stylizePositionTexture", position)
      .Texture("stylizeDepthTexture", depth)
      .Texture("pixelInputTexture", input)
      .Texture("pixelArtTexture", in.Art)
      .Texture("pixelPaletteTexture", in.PaletteTexture)
      .Int2("pixelArtSize", nx, ny)
      .Int2("pixelViewportSize", w, h)
      .Int2("pixelBlock", block[0], block[1])
      .Int2("pixelGridOrigin", origin[0], origin[1])
      .Int2("pixelExtentOrigin", extentOrigin[0], extentOrigin[1])
      .Int2("pixelExtentSize", extent[0], extent[1])
      .Int2("pixelDitherOrigin", ditherOrigin[0], ditherOrigin[1])
      .Int("pixelDitherSize", this->DitherSize)
      .Float("pixelDitherStrength", this->DitherStrength)
      .Int("pixelLevels", this->Levels)
      .Int("pixelPaletteSize", static_cast<int>(in.PaletteData.size() / 4))
      .Float("pixelPaletteSpread", in.PaletteSpread)
      .Float("pixelLow", this->LowThreshold)
      .Float("pixelHigh", this->HighThreshold)
      .Float("pixelDepthThreshold", this->DepthThreshold)
      .Float("pixelNormalThreshold", this->NormalThreshold)
      .Float("pixelArtWorld", artWorld)
      .Int("pixelParallel", parallel ? 1 : 0)
      .Float("pixelAnchorUnit", anchorUnit)
      .Float3("pixelOutlineColor", this->OutlineColor[0], this->OutlineColor[1],
        this->OutlineColor[2])
      .SceneOutput(gbuffer, ren);
  };
  bool ok = true;
  // Runs one art-resolution stage into `targets`.
  auto stage = [&](vtkStylizeShaderUtilities::ScreenQuad& quad, int index,
                 std::initializer_list<vtkTextureObject*> targets, vtkTextureObject* input) {
    fbo->RemoveColorAttachments(4);
    unsigned int i = 0;
    for (vtkTextureObject* t : targets)
    {
      fbo->AddColorAttachment(i++, t);
    }
    fbo->ActivateDrawBuffers(i);
    vtkShaderProgram* program =
      quad.Prepare(renWin, in.Declarations[index], "  pixelMain();\n");
    if (!program)
    {
      ok = false;
      return;
    }
    U::Uniforms u(program);
    setUniforms(u, input);
    quad.Render();
  };

  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(ostate, GL_SCISSOR_TEST);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  fbo->SaveCurrentBindingsAndBuffers();
  fbo->Bind();
  ostate->vtkglViewport(0, 0, nx, ny);
  ostate->vtkglScissor(0, 0, nx, ny);
  ostate->vtkglDisable(GL_DEPTH_TEST);

  // Faithful mode: average each block of the full-resolution G-buffer.
  if (!fast)
  {
    U::EnsureScreenTexture(in.ReducedColor, renWin, nx, ny, fullPrecision ? GL_RGBA32F : GL_RGBA16F);
    U::EnsureScreenTexture(in.ReducedLinear, renWin, nx, ny, GL_R32F);
    if (normalEdges)
    {
      U::EnsureScreenTexture(in.ReducedNormal, renWin, nx, ny, GL_RGBA16F);
    }
    if (surfaceAnchor)
    {
      U::EnsureScreenTexture(in.ReducedPosition, renWin, nx, ny, GL_RGBA32F);
    }
    if (normalEdges && surfaceAnchor)
    {
      stage(in.ReduceQuad, 0, { in.ReducedColor, in.ReducedLinear, in.ReducedNormal,
                                in.ReducedPosition }, nullptr);
    }
    else if (normalEdges)
    {
      stage(in.ReduceQuad, 0, { in.ReducedColor, in.ReducedLinear, in.ReducedNormal }, nullptr);
    }
    else if (surfaceAnchor)
    {
      stage(in.ReduceQuad, 0, { in.ReducedColor, in.ReducedLinear, in.ReducedPosition }, nullptr);
    }
    else
    {
      stage(in.ReduceQuad, 0, { in.ReducedColor, in.ReducedLinear }, nullptr);
    }
    colour = in.ReducedColor;
    linear = in.ReducedLinear;
    normal = normalEdges ? in.ReducedNormal : nullptr;
    position = surfaceAnchor ? in.ReducedPosition : nullptr;
  }
  vtkTextureObject* fullDepth = depth;
  depth = nullptr; // not read at the art resolution

  // Edges: Gaussian, Sobel, classification, hysteresis.
  vtkTextureObject* edgeImage = nullptr;
  if (edges)
  {
    U::EnsureScreenTexture(in.Classes[0], renWin, nx, ny, GL_R32F);
    if (canny || sobel)
    {
      U::EnsureScreenTexture(in.Gray, renWin, nx, ny, GL_R32F);
      U::EnsureScreenTexture(in.Gradient, renWin, nx, ny, GL_RGBA32F);
      stage(in.GaussQuad, 1, { in.Gray }, nullptr);
      stage(in.GradientQuad, 2, { in.Gradient }, in.Gray);
    }
    stage(in.ClassifyQuad, 3, { in.Classes[0] }, in.Gradient);
    edgeImage = in.Classes[0];
    if (canny && this->HysteresisIterations > 0)
    {
      U::EnsureScreenTexture(in.Classes[1], renWin, nx, ny, GL_R32F);
      for (int i = 0; i < this->HysteresisIterations; ++i)
      {
        vtkTextureObject* target = edgeImage == in.Classes[0] ? in.Classes[1] : in.Classes[0];
        stage(in.HysteresisQuad, 4, { target }, edgeImage);
        edgeImage = target;
      }
    }
  }

  // The art-pixel image.
  U::EnsureScreenTexture(in.Art, renWin, nx, ny, GL_RGBA16F);
  {
    vtkTextureObject* art = in.Art;
    in.Art = nullptr; // not an input of its own stage
    stage(in.StylizeQuad, 5, { art }, edgeImage);
    in.Art = art;
  }
  fbo->RemoveColorAttachments(4);
  fbo->UnBind();
  fbo->RestorePreviousBindingsAndBuffers();

  // Upsample into the output framebuffer, with the depth.
  ostate->vtkglViewport(ox, oy, w, h);
  ostate->vtkglScissor(ox, oy, w, h);
  ostate->vtkglDepthMask(GL_TRUE);
  if (writeDepth)
  {
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_ALWAYS);
  }
  else
  {
    ostate->vtkglEnable(GL_SCISSOR_TEST);
    ostate->vtkglClearDepth(1.0);
    ostate->vtkglClear(GL_DEPTH_BUFFER_BIT);
    ostate->vtkglDisable(GL_DEPTH_TEST);
  }
  depth = fullDepth;
  vtkShaderProgram* program = in.UpsampleQuad.Prepare(renWin, in.Declarations[6], "  pixelMain();\n");
  if (program)
  {
    U::Uniforms u(program);
    setUniforms(u, nullptr);
    in.UpsampleQuad.Render();
  }
  else
  {
    ok = false;
  }
  if (!ok)
  {
    vtkErrorMacro("Could not build a pixel-art shader.");
  }
  vtkOpenGLCheckErrorMacro("failed after vtkPixelArtPass::Render");

  this->FinishScene(s);
}

//------------------------------------------------------------------------------
void vtkPixelArtPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  vtkInternals& in = *this->Internals;
  for (auto* quad : { &in.ReduceQuad, &in.GaussQuad, &in.GradientQuad, &in.ClassifyQuad,
         &in.HysteresisQuad, &in.StylizeQuad, &in.UpsampleQuad })
  {
    quad->Release(w);
  }
  in.FreeTextures(w);
  in.GBuffer->ReleaseGraphicsResources(w);
}
