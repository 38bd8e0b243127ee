// vtkPixelArtPass tests: regression images (modes, palettes, edge options, anchors), strict CPU
// references for the ordered dither (gray and colour ramps, every palette kind) and for Canny and
// Sobel on a synthetic image, Canny against Sobel on the test scene, grid stability under a pan
// and an orbit, fidelity of the two pixelation modes against a supersampled reference (SSIM),
// magnified screenshots, and the extremes.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkPixelArtPass.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeImageMetrics.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeTestUtilities.h"
#include "vtkTesting.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <functional>
#include <limits>

using namespace stylizetest;

namespace
{
constexpr int W = 400, H = 300;
using Configure = std::function<void(vtkRenderer*, vtkPixelArtPass*)>;

/** RGB (0..255) of pixel (x, y) of an 8-bit image. */
std::array<double, 3> Pixel(vtkImageData* img, int x, int y)
{
  int d[3];
  img->GetDimensions(d);
  vtkDataArray* s = img->GetPointData()->GetScalars();
  const vtkIdType i = static_cast<vtkIdType>(y) * d[0] + x;
  return { s->GetComponent(i, 0), s->GetComponent(i, 1), s->GetComponent(i, 2) };
}

/** One sample per art pixel (its centre pixel) of a w x h image with the given block size. */
vtkSmartPointer<vtkImageData> ArtPixels(vtkImageData* img, int block)
{
  int d[3];
  img->GetDimensions(d);
  const int nx = (d[0] + block - 1) / block, ny = (d[1] + block - 1) / block;
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->SetDimensions(nx, ny, 1);
  out->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  vtkDataArray* o = out->GetPointData()->GetScalars();
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const auto p = Pixel(
        img, std::min(i * block + block / 2, d[0] - 1), std::min(j * block + block / 2, d[1] - 1));
      for (int c = 0; c < 3; ++c)
      {
        o->SetComponent(static_cast<vtkIdType>(j) * nx + i, c, p[c]);
      }
    }
  }
  return out;
}

/**
 * A flat picture for exact tests: nx x ny cells of `block` x `block` window pixels with the
 * given 8-bit colours, seen by a parallel camera so that each cell covers its block exactly
 * (world unit = one pixel), lit by its ambient term alone (colour = cell colour exactly). The
 * world origin lies `originCells` cells from the lower-left corner.
 */
void AddCellPicture(vtkRenderer* ren, int nx, int ny, int block,
  const std::function<std::array<unsigned char, 3>(int, int)>& colour,
  const int originCells[2] = nullptr)
{
  const double x0 = originCells ? -originCells[0] * block : 0.0;
  const double y0 = originCells ? -originCells[1] * block : 0.0;
  vtkNew<vtkPoints> points;
  for (int j = 0; j <= ny; ++j)
  {
    for (int i = 0; i <= nx; ++i)
    {
      points->InsertNextPoint(x0 + i * block, y0 + j * block, 0.0);
    }
  }
  vtkNew<vtkCellArray> quads;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const vtkIdType a = static_cast<vtkIdType>(j) * (nx + 1) + i;
      const vtkIdType ids[4] = { a, a + 1, a + nx + 2, a + nx + 1 };
      quads->InsertNextCell(4, ids);
      const auto c = colour(i, j);
      colours->InsertNextTypedTuple(c.data());
    }
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(points);
  pd->SetPolys(quads);
  pd->GetCellData()->SetScalars(colours);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(pd);
  mapper->SetColorModeToDirectScalars();
  mapper->SetScalarModeToUseCellData();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  actor->GetProperty()->SetSpecular(0.0);
  ren->AddActor(actor);
  SetupLights(ren, "none");
  const double w = nx * block, h = ny * block;
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetParallelProjection(true);
  cam->SetFocalPoint(x0 + w / 2, y0 + h / 2, 0);
  cam->SetPosition(x0 + w / 2, y0 + h / 2, 1000);
  cam->SetViewUp(0, 1, 0);
  cam->SetParallelScale(h / 2);
  cam->SetClippingRange(500, 1500);
}

/** A pass set up for the exact tests: full-precision G-buffer, no edges. */
void ExactSetup(vtkPixelArtPass* p, int block)
{
  p->GetGBufferPass()->SetPrecision(vtkStylizeGBufferPass::FULL);
  p->SetPixelSize(block);
  p->SetEdgeDetector(vtkPixelArtPass::NO_EDGES);
  p->DepthEdgesOff();
}

/** Eq. 11's threshold of dither cell q. */
double Threshold(int qx, int qy)
{
  const int* m = vtkPixelArtPass::GetDitherMatrix();
  const int x = ((qx % 8) + 8) % 8, y = ((qy % 8) + 8) % 8;
  return (m[y * 8 + x] - 0.5) / 64.0;
}

int FloorDiv(int a, int b)
{
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}
}

// Regression image of one variant: VTK's harness, then our strict comparison.
int TestPixelArtRegression(int argc, char* argv[])
{
  using P = vtkPixelArtPass;
  const std::map<std::string, Configure> variants = {
    { "faithful", nullptr },
    { "fast", [](vtkRenderer*, P* p) { p->SetModeToFast(); } },
    { "pixel-size-8", [](vtkRenderer*, P* p) { p->SetPixelSize(8); } },
    { "one-bit", [](vtkRenderer*, P* p) { p->SetPaletteToOneBit(); } },
    { "four-grays", [](vtkRenderer*, P* p) { p->SetPaletteToFourGrays(); } },
    { "palette16", [](vtkRenderer*, P* p) { p->SetPalette(P::PALETTE16); } },
    { "custom",
      [](vtkRenderer*, P* p)
      {
        for (const auto& c : std::vector<std::array<double, 3>>{ { 0.1, 0.1, 0.2 },
               { 0.9, 0.9, 0.8 }, { 0.8, 0.3, 0.2 }, { 0.3, 0.5, 0.8 }, { 0.5, 0.5, 0.5 } })
        {
          p->AddPaletteColor(c[0], c[1], c[2]);
        }
        p->SetPalette(P::CUSTOM);
      } },
    { "colormap", [](vtkRenderer*, P* p) { p->SetPalette(P::COLORMAP); } },
    { "sobel",
      [](vtkRenderer*, P* p)
      {
        p->SetEdgeDetector(P::SOBEL);
        p->DepthEdgesOff();
      } },
    { "canny-only", [](vtkRenderer*, P* p) { p->DepthEdgesOff(); } },
    { "geometric-edges",
      [](vtkRenderer*, P* p)
      {
        p->SetEdgeDetector(P::NO_EDGES);
        p->NormalEdgesOn();
        p->SetOutlineColor(0.2, 0.1, 0.4);
      } },
    { "no-edges",
      [](vtkRenderer*, P* p)
      {
        p->SetEdgeDetector(P::NO_EDGES);
        p->DepthEdgesOff();
      } },
    { "edge-layer", [](vtkRenderer*, P* p) { p->SetLayer(P::EDGES); } },
    { "pixelated", [](vtkRenderer*, P* p) { p->SetLayer(P::PIXELATED); } },
    { "surface-anchor",
      [](vtkRenderer*, P* p)
      {
        p->SetDitherAnchor(P::SURFACE);
        p->SetPaletteToFourGrays();
      } },
    { "dither-size-2",
      [](vtkRenderer*, P* p)
      {
        p->SetDitherSize(2);
        p->SetLevels(2);
      } },
    { "art-pixels-64", [](vtkRenderer*, P* p) { p->SetArtPixelsAcross(64); } },
    { "kit-lights", [](vtkRenderer* r, P*) { SetupLights(r, "kit"); } },
  };
  return RunStyleVariant<P>(argc, argv, "TestPixelArtRegression", variants, W, H);
}

// The ordered dither against its CPU formula, exactly: gray and colour ramps (every 8-bit value),
// K levels per channel, K grays (1-bit), a user palette, dither size 2, half strength, screen
// and grid anchors, both pixelation modes.
int TestPixelArtDither(int, char*[])
{
  using P = vtkPixelArtPass;
  const int nx = 64, ny = 16, block = 4;
  const int world[2] = { 5, 3 }; // the world origin, in cells from the lower-left corner
  auto rampColour = [](int i, int j, bool colour) -> std::array<unsigned char, 3>
  {
    const int k = (j * 64 + i) / 4; // 0..255, each value on 4 art pixels
    if (!colour)
    {
      return { static_cast<unsigned char>(k), static_cast<unsigned char>(k),
        static_cast<unsigned char>(k) };
    }
    return { static_cast<unsigned char>(k), static_cast<unsigned char>(255 - k),
      static_cast<unsigned char>((k * 3) % 256) };
  };
  struct Case
  {
    std::string Name;
    int Palette;
    int Levels;
    int DitherSize;
    double Strength;
    int Anchor;
    bool Colour;
  };
  const std::vector<Case> cases = {
    { "4 levels, gray ramp", P::LEVELS, 4, 1, 1.0, P::SCREEN, false },
    { "4 levels, colour ramp", P::LEVELS, 4, 1, 1.0, P::SCREEN, true },
    { "1-bit", P::GRAYS, 2, 1, 1.0, P::SCREEN, false },
    { "1-bit, grid anchor", P::GRAYS, 2, 1, 1.0, P::GRID, false },
    { "8 grays, dither size 2", P::GRAYS, 8, 2, 1.0, P::GRID, true },
    { "3 levels, half strength", P::LEVELS, 3, 1, 0.5, P::SCREEN, true },
    { "custom palette", P::CUSTOM, 0, 1, 1.0, P::SCREEN, true },
  };
  const std::vector<std::array<double, 3>> custom = { { 0, 0, 0 }, { 1, 1, 1 }, { 0.8, 0.2, 0.1 },
    { 0.1, 0.3, 0.9 } };
  // The pass's spread for a list palette: the median distance to the nearest other colour.
  std::vector<double> nearest;
  for (size_t i = 0; i < custom.size(); ++i)
  {
    double best = 1e30;
    for (size_t j = 0; j < custom.size(); ++j)
    {
      if (i != j)
      {
        double d = 0;
        for (int c = 0; c < 3; ++c)
        {
          d += (custom[i][c] - custom[j][c]) * (custom[i][c] - custom[j][c]);
        }
        best = std::min(best, std::sqrt(d));
      }
    }
    nearest.push_back(best);
  }
  std::nth_element(nearest.begin(), nearest.begin() + nearest.size() / 2, nearest.end());
  const double spread = nearest[nearest.size() / 2];

  for (const Case& k : cases)
  {
    for (int mode : { P::FAITHFUL, P::FAST })
    {
      auto win = MakeWindow(nx * block, ny * block);
      vtkNew<vtkRenderer> ren;
      win->AddRenderer(ren);
      AddCellPicture(
        ren, nx, ny, block, [&](int i, int j) { return rampColour(i, j, k.Colour); }, world);
      vtkNew<P> pass;
      ExactSetup(pass, block);
      pass->SetMode(mode);
      pass->SetPalette(k.Palette);
      if (k.Levels > 0)
      {
        pass->SetLevels(k.Levels);
      }
      for (const auto& c : custom)
      {
        pass->AddPaletteColor(c[0], c[1], c[2]);
      }
      pass->SetDitherSize(k.DitherSize);
      pass->SetDitherStrength(k.Strength);
      pass->SetDitherAnchor(k.Anchor);
      ren->SetPass(pass);
      win->Render();
      auto img = Capture(win);
      long long wrong = 0;
      double worst = 0;
      for (int j = 0; j < ny; ++j)
      {
        for (int i = 0; i < nx; ++i)
        {
          const auto in = rampColour(i, j, k.Colour);
          const int qx = k.Anchor == P::GRID ? i - world[0] : i;
          const int qy = k.Anchor == P::GRID ? j - world[1] : j;
          const double t = 0.5 +
            (Threshold(FloorDiv(qx, k.DitherSize), FloorDiv(qy, k.DitherSize)) - 0.5) * k.Strength;
          double expected[3];
          const double c[3] = { in[0] / 255.0, in[1] / 255.0, in[2] / 255.0 };
          if (k.Palette == P::LEVELS)
          {
            for (int a = 0; a < 3; ++a)
            {
              expected[a] =
                std::min(std::floor(c[a] * (k.Levels - 1) + t), k.Levels - 1.0) / (k.Levels - 1);
            }
          }
          else if (k.Palette == P::GRAYS)
          {
            const double g = (c[0] + c[1] + c[2]) / 3.0;
            const double q =
              std::min(std::floor(g * (k.Levels - 1) + t), k.Levels - 1.0) / (k.Levels - 1);
            expected[0] = expected[1] = expected[2] = q;
          }
          else
          {
            double best = 1e30;
            for (const auto& p : custom)
            {
              double d = 0;
              for (int a = 0; a < 3; ++a)
              {
                const double e = p[a] - (c[a] + (t - 0.5) * spread);
                d += e * e;
              }
              if (d < best)
              {
                best = d;
                std::copy(p.begin(), p.end(), expected);
              }
            }
          }
          // Every screen pixel of the art pixel.
          bool ok = true;
          for (int y = j * block; y < (j + 1) * block; ++y)
          {
            for (int x = i * block; x < (i + 1) * block; ++x)
            {
              const auto got = Pixel(img, x, y);
              for (int a = 0; a < 3; ++a)
              {
                const double diff = std::abs(got[a] - std::round(255.0 * expected[a]));
                worst = std::max(worst, diff);
                ok = ok && diff <= 1.0;
              }
            }
          }
          wrong += ok ? 0 : 1;
        }
      }
      std::printf("dither %-26s %-8s: %lld of %d art pixels differ from the CPU reference "
                  "(largest difference %.0f levels)\n",
        k.Name.c_str(), mode == P::FAST ? "fast" : "faithful", wrong, nx * ny, worst);
      STYLIZE_CHECK(wrong == 0, "dither %s: %lld art pixels wrong", k.Name.c_str(), wrong);
      win->Finalize();
    }
  }
  return Failures == 0 ? 0 : 1;
}

namespace
{
/** CPU Canny / Sobel on a gray image (row-major, y up), the pass's exact definitions. */
std::vector<int> ReferenceEdges(const std::vector<double>& gray, int nx, int ny, bool canny,
  double low, double high, int iterations)
{
  auto at = [&](const std::vector<double>& a, int i, int j)
  {
    i = std::min(std::max(i, 0), nx - 1);
    j = std::min(std::max(j, 0), ny - 1);
    return a[static_cast<size_t>(j) * nx + i];
  };
  std::vector<double> g(gray.size()), gx(gray.size()), gy(gray.size()), m(gray.size());
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      g[j * nx + i] = 0.0751136 *
          (at(gray, i - 1, j - 1) + at(gray, i + 1, j - 1) + at(gray, i - 1, j + 1) +
            at(gray, i + 1, j + 1)) +
        0.1238414 *
          (at(gray, i, j - 1) + at(gray, i - 1, j) + at(gray, i + 1, j) + at(gray, i, j + 1)) +
        0.2041799 * at(gray, i, j);
    }
  }
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const double x = (at(g, i + 1, j + 1) + 2 * at(g, i + 1, j) + at(g, i + 1, j - 1)) -
        (at(g, i - 1, j + 1) + 2 * at(g, i - 1, j) + at(g, i - 1, j - 1));
      const double y = (at(g, i - 1, j + 1) + 2 * at(g, i, j + 1) + at(g, i + 1, j + 1)) -
        (at(g, i - 1, j - 1) + 2 * at(g, i, j - 1) + at(g, i + 1, j - 1));
      gx[j * nx + i] = x;
      gy[j * nx + i] = y;
      m[j * nx + i] = std::sqrt(x * x + y * y);
    }
  }
  std::vector<int> cls(gray.size(), 0); // 0 none, 1 weak, 2 strong
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const size_t p = static_cast<size_t>(j) * nx + i;
      if (!canny)
      {
        cls[p] = m[p] >= high ? 2 : 0;
        continue;
      }
      const double ax = std::abs(gx[p]), ay = std::abs(gy[p]);
      int dx, dy;
      if (ay <= 0.41421356 * ax)
      {
        dx = 1, dy = 0;
      }
      else if (ay >= 2.41421356 * ax)
      {
        dx = 0, dy = 1;
      }
      else
      {
        dx = (gx[p] > 0) == (gy[p] > 0) ? 1 : -1, dy = 1;
      }
      const double eps = 1e-5 * std::max(m[p], 1e-6);
      const bool keep =
        m[p] > 0 && m[p] >= at(m, i + dx, j + dy) - eps && m[p] > at(m, i - dx, j - dy) + eps;
      cls[p] = !keep ? 0 : (m[p] >= high ? 2 : (m[p] >= std::min(low, high) ? 1 : 0));
    }
  }
  for (int it = 0; canny && it < iterations; ++it)
  {
    std::vector<int> next = cls;
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        if (cls[j * nx + i] != 1)
        {
          continue;
        }
        for (int b = -1; b <= 1; ++b)
        {
          for (int a = -1; a <= 1; ++a)
          {
            const int u = i + a, v = j + b;
            if (u >= 0 && v >= 0 && u < nx && v < ny && cls[v * nx + u] == 2)
            {
              next[j * nx + i] = 2;
            }
          }
        }
      }
    }
    cls = next;
  }
  for (int& c : cls)
  {
    c = c == 2 ? 1 : 0;
  }
  return cls;
}

/** The synthetic picture: strong and weak steps, a disc, a ramp, a diagonal band, mild noise. */
std::array<unsigned char, 3> Synthetic(int i, int j)
{
  double g = 0.2;
  if (i >= 20 && i < 70 && j >= 15 && j < 60)
  {
    g = 0.8; // strong step
  }
  if (i >= 70 && i < 95 && j >= 15 && j < 60)
  {
    // Beside the square's right edge a slow vertical ramp: the step shrinks from strong
    // (0.8 -> 0.55) to weak and to nothing along one straight edge; hysteresis follows it.
    g = 0.55 + 0.25 * (j - 15) / 45.0;
  }
  if (i >= 110 && i < 140 && j >= 80 && j < 105)
  {
    g = 0.3; // an isolated weak step: Canny drops it
  }
  const double dx = i - 50.5, dy = j - 90.5;
  if (dx * dx + dy * dy < 17.0 * 17.0)
  {
    g = 0.55; // a disc: every gradient direction
  }
  if (i >= 100 && i < 150 && j >= 10 && j < 60)
  {
    g = 0.2 + 0.006 * (i - 100); // a gentle ramp: no edge
  }
  if (std::abs((i - 100) - (j - 60)) < 2 && i >= 100 && i < 150 && j >= 60 && j < 75)
  {
    g = 0.9; // a thin diagonal band
  }
  // Deterministic noise of +-2 levels.
  const unsigned h = static_cast<unsigned>(i * 73856093u) ^ static_cast<unsigned>(j * 19349663u);
  const int noise = static_cast<int>(h % 5u) - 2;
  const int v = std::min(255, std::max(0, static_cast<int>(std::lround(g * 255)) + noise));
  return { static_cast<unsigned char>(v), static_cast<unsigned char>(v),
    static_cast<unsigned char>(v) };
}

struct EdgeStats
{
  long long Pixels = 0;    // edge pixels
  long long Blocks = 0;    // 2x2 squares made only of edge pixels (thick, ragged edges)
  long long Endpoints = 0; // edge pixels with exactly one 8-neighbour (broken or spurious ends)
};

EdgeStats Stats(const std::vector<int>& e, int nx, int ny)
{
  EdgeStats s;
  auto at = [&](int i, int j)
  { return i >= 0 && j >= 0 && i < nx && j < ny && e[static_cast<size_t>(j) * nx + i] != 0; };
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      if (!at(i, j))
      {
        continue;
      }
      ++s.Pixels;
      if (at(i + 1, j) && at(i, j + 1) && at(i + 1, j + 1))
      {
        ++s.Blocks;
      }
      int n = 0;
      for (int b = -1; b <= 1; ++b)
      {
        for (int a = -1; a <= 1; ++a)
        {
          n += (a || b) && at(i + a, j + b) ? 1 : 0;
        }
      }
      s.Endpoints += n == 1 ? 1 : 0;
    }
  }
  return s;
}

/** The edge layer of an image as 0/1 per art pixel (black = edge). */
std::vector<int> EdgeLayer(vtkImageData* img, int block)
{
  auto art = ArtPixels(img, block);
  int d[3];
  art->GetDimensions(d);
  std::vector<int> e(static_cast<size_t>(d[0]) * d[1]);
  for (int j = 0; j < d[1]; ++j)
  {
    for (int i = 0; i < d[0]; ++i)
    {
      e[static_cast<size_t>(j) * d[0] + i] = Pixel(art, i, j)[0] < 128 ? 1 : 0;
    }
  }
  return e;
}
}

// Canny and Sobel on a synthetic picture against the CPU reference, exactly; then Canny against
// Sobel on the test scene (thickness and broken ends).
int TestPixelArtCanny(int, char*[])
{
  using P = vtkPixelArtPass;
  const int nx = 160, ny = 120;
  std::vector<double> gray(static_cast<size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const auto c = Synthetic(i, j);
      gray[static_cast<size_t>(j) * nx + i] = (c[0] / 255.0 + c[1] / 255.0 + c[2] / 255.0) / 3.0;
    }
  }
  struct Case
  {
    std::string Name;
    int Detector;
    int Iterations;
    int Block;
    int Mode;
  };
  const std::vector<Case> cases = {
    { "canny, hysteresis 64", P::CANNY, 64, 1, P::FAST },
    { "canny, hysteresis 2", P::CANNY, 2, 1, P::FAST },
    { "canny, strong only", P::CANNY, 0, 1, P::FAST },
    { "canny, 3 px art pixels", P::CANNY, 16, 3, P::FAITHFUL },
    { "sobel", P::SOBEL, 0, 1, P::FAST },
  };
  for (const Case& k : cases)
  {
    auto win = MakeWindow(nx * k.Block, ny * k.Block);
    vtkNew<vtkRenderer> ren;
    win->AddRenderer(ren);
    AddCellPicture(ren, nx, ny, k.Block, Synthetic);
    vtkNew<P> pass;
    ExactSetup(pass, k.Block);
    pass->SetMode(k.Mode);
    pass->SetEdgeDetector(k.Detector);
    pass->SetHysteresisIterations(k.Iterations);
    pass->SetLayer(P::EDGES);
    ren->SetPass(pass);
    win->Render();
    auto img = Capture(win);
    const auto got = EdgeLayer(img, k.Block);
    const auto want = ReferenceEdges(gray, nx, ny, k.Detector == P::CANNY, pass->GetLowThreshold(),
      pass->GetHighThreshold(), k.Iterations);
    long long wrong = 0;
    for (size_t i = 0; i < got.size(); ++i)
    {
      wrong += got[i] != want[i] ? 1 : 0;
    }
    const EdgeStats s = Stats(want, nx, ny);
    std::printf("%-24s: %lld of %d art pixels differ from the CPU reference (%lld edge pixels)\n",
      k.Name.c_str(), wrong, nx * ny, s.Pixels);
    STYLIZE_CHECK(wrong == 0, "%s: %lld art pixels differ", k.Name.c_str(), wrong);
    STYLIZE_CHECK(s.Pixels > 200, "%s: the reference finds too few edges", k.Name.c_str());
    win->Finalize();
  }
  // The reference itself: hysteresis adds the connected weak step and not the isolated one.
  {
    const auto strong = ReferenceEdges(gray, nx, ny, true, 0.25, 0.5, 0);
    const auto full = ReferenceEdges(gray, nx, ny, true, 0.25, 0.5, 64);
    auto count = [&](const std::vector<int>& e, int i0, int i1, int j0, int j1)
    {
      long long n = 0;
      for (int j = j0; j < j1; ++j)
      {
        for (int i = i0; i < i1; ++i)
        {
          n += e[static_cast<size_t>(j) * nx + i];
        }
      }
      return n;
    };
    const long long isolated = count(full, 105, 145, 78, 110);
    const long long connectedStrong = count(strong, 68, 72, 31, 44);
    const long long connectedFull = count(full, 68, 72, 31, 44);
    std::printf("hysteresis: weak edge next to a strong one %lld -> %lld pixels; isolated weak "
                "edge %lld pixels\n",
      connectedStrong, connectedFull, isolated);
    STYLIZE_CHECK(connectedFull > connectedStrong + 10, "hysteresis does not extend weak edges");
    STYLIZE_CHECK(isolated == 0, "an isolated weak edge survives");
  }

  // Canny against Sobel on the test scene (the paper's motivation: fewer ragged edges).
  const int block = 2;
  EdgeStats stats[2];
  for (int detector : { P::SOBEL, P::CANNY })
  {
    auto img = RenderThroughPass<P>(
      [detector](vtkRenderer*, P* p)
      {
        p->SetPixelSize(block);
        p->SetEdgeDetector(detector);
        p->DepthEdgesOff();
        p->SetLayer(P::EDGES);
      },
      W, H);
    const auto e = EdgeLayer(img, block);
    const EdgeStats s = Stats(e, (W + block - 1) / block, (H + block - 1) / block);
    std::printf("test scene, %-5s: %lld edge art pixels, %lld filled 2x2 squares (%.1f%%), "
                "%lld end points\n",
      detector == P::CANNY ? "canny" : "sobel", s.Pixels, s.Blocks,
      100.0 * s.Blocks / std::max(1LL, s.Pixels), s.Endpoints);
    stats[detector == P::CANNY ? 1 : 0] = s;
  }
  STYLIZE_CHECK(stats[1].Blocks * 4 < stats[0].Blocks,
    "Canny edges are not thinner than Sobel's: %lld vs %lld filled squares", stats[1].Blocks,
    stats[0].Blocks);
  return Failures == 0 ? 0 : 1;
}

namespace
{
/** The art pixels (one sample each) of a window rendered with the pass's last grid. */
std::vector<std::array<double, 3>> ArtColours(
  vtkRenderWindow* win, vtkPixelArtPass* pass, int& nx, int& ny)
{
  int block[2], grid[2];
  pass->GetLastGrid(block, grid);
  auto img = Capture(win);
  nx = grid[0];
  ny = grid[1];
  int d[3];
  img->GetDimensions(d);
  std::vector<std::array<double, 3>> out;
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      out.push_back(Pixel(img, std::min(i * block[0] + block[0] / 2, d[0] - 1),
        std::min(j * block[1] + block[1] / 2, d[1] - 1)));
    }
  }
  return out;
}

bool Differs(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return std::abs(a[0] - b[0]) > 8 || std::abs(a[1] - b[1]) > 8 || std::abs(a[2] - b[2]) > 8;
}
}

// A stable grid: the fraction of art pixels that change per frame over a slow pan (parallel
// projection, the motion compensated to whole art pixels) and a 1 degree per frame orbit, with
// and without stabilization.
int TestPixelArtStability(int argc, char* argv[])
{
  using P = vtkPixelArtPass;
  const int frames = argc > 1 ? std::max(3, std::atoi(argv[1])) : 12;
  const int block = 4;
  double pan[2][2] = { { 0, 0 }, { 0, 0 } }; // [mode][stabilized]
  for (int mode : { P::FAITHFUL, P::FAST })
  {
    for (bool stable : { false, true })
    {
      auto scene = MakeStyledScene<P>(W, H, true,
        [&](P* pass)
        {
          pass->SetMode(mode);
          pass->SetPixelSize(block);
          pass->SetSnapToGrid(stable);
          pass->SetDitherAnchor(stable ? P::GRID : P::SCREEN);
        });
      vtkRenderWindow* win = scene.Window;
      vtkRenderer* ren = scene.Renderer;
      P* pass = scene.Pass;
      vtkCamera* cam = ren->GetActiveCamera();
      const double pixelWorld = 2.0 * cam->GetParallelScale() / H;
      double right[3];
      {
        double up[3], dop[3];
        cam->GetViewUp(up);
        cam->GetDirectionOfProjection(dop);
        vtkMath::Cross(dop, up, right);
        vtkMath::Normalize(right);
      }
      // 0.3 art pixel per frame to the right (and 0.1 up).
      const double step = 0.3 * block * pixelWorld;
      std::vector<std::array<double, 3>> previous;
      double previousX = 0, previousY = 0;
      long long changed = 0, total = 0;
      for (int f = 0; f < frames; ++f)
      {
        if (f > 0)
        {
          double fp[3], pos[3], up[3];
          cam->GetFocalPoint(fp);
          cam->GetPosition(pos);
          cam->GetViewUp(up);
          for (int c = 0; c < 3; ++c)
          {
            const double d = step * right[c] + step / 3 * up[c];
            fp[c] += d;
            pos[c] += d;
          }
          cam->SetFocalPoint(fp);
          cam->SetPosition(pos);
        }
        // The world origin's position in pixels: the scene's motion.
        vtkMatrix4x4* m =
          cam->GetCompositeProjectionTransformMatrix(static_cast<double>(W) / H, -1, 1);
        const double X = (m->GetElement(0, 3) / m->GetElement(3, 3) + 1) * 0.5 * W;
        const double Y = (m->GetElement(1, 3) / m->GetElement(3, 3) + 1) * 0.5 * H;
        win->Render();
        int nx, ny;
        const auto art = ArtColours(win, pass, nx, ny);
        if (f > 0)
        {
          // Compensate the motion by whole art pixels (what the snapped grid does exactly).
          const int sx = static_cast<int>(std::lround(X / block) - std::lround(previousX / block));
          const int sy = static_cast<int>(std::lround(Y / block) - std::lround(previousY / block));
          for (int j = 1; j < ny - 1; ++j)
          {
            for (int i = 1; i < nx - 1; ++i)
            {
              const int pi = i - sx, pj = j - sy;
              if (pi < 1 || pj < 1 || pi >= nx - 1 || pj >= ny - 1)
              {
                continue;
              }
              changed += Differs(art[j * nx + i], previous[pj * nx + pi]) ? 1 : 0;
              ++total;
            }
          }
        }
        previous = art;
        previousX = X;
        previousY = Y;
      }
      const double fraction = static_cast<double>(changed) / std::max(1LL, total);
      pan[mode][stable ? 1 : 0] = fraction;
      std::printf("pan 0.3 art px/frame, %-8s, %-13s: %.2f%% of art pixels change per frame\n",
        mode == P::FAST ? "fast" : "faithful", stable ? "stabilized" : "not stabilized",
        100.0 * fraction);
      win->Finalize();
    }
    STYLIZE_CHECK(pan[mode][1] < 0.25 * pan[mode][0],
      "the snapped grid does not stabilize a pan: %.4f vs %.4f", pan[mode][1], pan[mode][0]);
  }

  // Orbit: 1 degree per frame in perspective; art pixels that change at the same screen place,
  // for each dither anchor.
  for (int mode : { P::FAITHFUL, P::FAST })
  {
    for (int anchor : { P::SCREEN, P::GRID, P::SURFACE })
    {
      auto scene = MakeStyledScene<P>(W, H, false,
        [&](P* pass)
        {
          pass->SetMode(mode);
          pass->SetPixelSize(block);
          pass->SetDitherAnchor(anchor);
        });
      vtkRenderWindow* win = scene.Window;
      vtkRenderer* ren = scene.Renderer;
      P* pass = scene.Pass;
      std::vector<std::array<double, 3>> previous;
      long long changed = 0, total = 0;
      for (int f = 0; f < frames; ++f)
      {
        if (f > 0)
        {
          ren->GetActiveCamera()->Azimuth(1.0);
        }
        win->Render();
        int nx, ny;
        const auto art = ArtColours(win, pass, nx, ny);
        if (f > 0)
        {
          for (size_t i = 0; i < art.size(); ++i)
          {
            changed += Differs(art[i], previous[i]) ? 1 : 0;
            ++total;
          }
        }
        previous = art;
      }
      static const char* const names[] = { "screen", "grid", "surface" };
      std::printf("orbit 1 deg/frame, %-8s, dither anchored to the %-7s: %.2f%% of art pixels "
                  "change per frame\n",
        mode == P::FAST ? "fast" : "faithful", names[anchor],
        100.0 * changed / std::max(1LL, total));
      win->Finalize();
    }
  }
  return Failures == 0 ? 0 : 1;
}

// Fidelity of the two pixelation modes: SSIM of the art-pixel colours (the pixelated layer) and
// of the final image against a reference supersampled 4x4 per screen pixel (faithful at 4x the
// size), at art pixel sizes 2, 4 and 8; with the time per frame of each at this size.
int TestPixelArtFidelity(int, char*[])
{
  using P = vtkPixelArtPass;
  const int w = 480, h = 270, ss = 4;
  for (int block : { 2, 4, 8 })
  {
    for (int layer : { P::PIXELATED, P::PIXEL_ART })
    {
      auto configure = [&](int mode, int size)
      {
        return [=](vtkRenderer*, P* p)
        {
          p->SetMode(mode);
          p->SetPixelSize(size);
          p->SetLayer(layer);
        };
      };
      auto reference = ArtPixels(
        RenderThroughPass<P>(configure(P::FAITHFUL, block * ss), w * ss, h * ss), block * ss);
      double ssim[2], ms[2];
      for (int mode : { P::FAST, P::FAITHFUL })
      {
        auto scene = MakeTestScene(w, h, false);
        vtkRenderWindow* win = scene.Window;
        vtkRenderer* ren = scene.Renderer;
        vtkNew<P> pass;
        configure(mode, block)(ren, pass);
        ren->SetPass(pass);
        win->Render();
        vtkNew<vtkTimerLog> timer;
        timer->StartTimer();
        const int n = 5;
        for (int i = 0; i < n; ++i)
        {
          win->Render();
        }
        timer->StopTimer();
        ms[mode] = 1000.0 * timer->GetElapsedTime() / n;
        auto art = ArtPixels(Capture(win), block);
        ssim[mode] = vtkStylizeImageMetrics::SSIM(art, reference, 255.0);
        win->Finalize();
      }
      std::printf("art pixel %d px, %-9s layer: SSIM against 4x4 supersampling: fast %.4f "
                  "(%.1f ms), faithful %.4f (%.1f ms) at %dx%d\n",
        block, layer == P::PIXELATED ? "pixelated" : "final", ssim[P::FAST], ms[P::FAST],
        ssim[P::FAITHFUL], ms[P::FAITHFUL], w, h);
      // Larger art pixels make the fast mode's single sample a worse estimate of the block;
      // at 2 px its centre sample decides silhouettes about as well as a 2x2 majority.
      STYLIZE_CHECK(block < 8 || ssim[P::FAITHFUL] > ssim[P::FAST],
        "faithful is not closer to the supersampled reference than fast at %d px", block);
      STYLIZE_CHECK(
        ssim[P::FAITHFUL] > 0.95, "faithful SSIM %.3f at %d px", ssim[P::FAITHFUL], block);
    }
  }
  return Failures == 0 ? 0 : 1;
}

// A screenshot magnified 2x through tiles matches a direct render at twice the size with twice
// the pixel size (the same art pixels), in both modes: no seams where an art pixel straddles tiles.
int TestPixelArtMagnify(int, char*[])
{
  using P = vtkPixelArtPass;
  for (int mode : { P::FAITHFUL, P::FAST })
  {
    for (bool parallel : { false, true })
    {
      auto tiled = RenderThroughPass<P>(
        [mode](vtkRenderer*, P* p)
        {
          p->SetMode(mode);
          p->SetPixelSize(5); // 300 / 10 and 400 / 10: blocks straddle the tile borders
        },
        W, H, parallel, 2);
      auto direct = RenderThroughPass<P>(
        [mode](vtkRenderer*, P* p)
        {
          p->SetMode(mode);
          p->SetPixelSize(10);
        },
        2 * W, 2 * H, parallel);
      const std::string what = std::string(mode == P::FAST ? "fast" : "faithful") +
        (parallel ? ", parallel" : ", perspective") + ": 2x tiled vs direct";
      StrictCompare(tiled, direct, 64, 0.01, 255, what);
    }
  }
  return Failures == 0 ? 0 : 1;
}

// Extremes: pixel size 1, as large as the window and larger, a 1x1 window, a 7680x4320 render,
// 0 and 500 lights, the scene scaled by 1e-6 and 1e6, a near/far ratio of 1e7, lines and points
// only, empty data, NaN settings: no NaN or Inf in the buffers, no crash, sensible output.
int TestPixelArtExtremes(int argc, char* argv[])
{
  using P = vtkPixelArtPass;
  const bool huge = !(argc > 1 && std::string(argv[1]) == "--no-8k");
  struct Case
  {
    std::string Name;
    int Width, Height;
    double Scale;
    Configure Setup;
    bool ExpectInk;
  };
  const std::vector<Case> cases = {
    { "pixel size 1", 240, 180, 1.0, [](vtkRenderer*, P* p) { p->SetPixelSize(1); }, true },
    { "pixel size = window", 240, 180, 1.0, [](vtkRenderer*, P* p) { p->SetPixelSize(240); },
      true },
    { "pixel size 8192", 240, 180, 1.0, [](vtkRenderer*, P* p) { p->SetPixelSize(100000); }, true },
    { "1x1 window", 1, 1, 1.0, nullptr, false },
    { "0 lights", 240, 180, 1.0, [](vtkRenderer* r, P*) { SetupLights(r, "none"); }, true },
    { "500 lights", 240, 180, 1.0, [](vtkRenderer* r, P*) { SetupLights(r, "many:500"); }, true },
    { "scale 1e-6", 240, 180, 1e-6, nullptr, true },
    { "scale 1e6", 240, 180, 1e6, nullptr, true },
    { "near/far 1e7", 240, 180, 1.0, [](vtkRenderer* r, P*) { SetNearFarRatio(r, 1e-7); }, true },
    { "every option at its limits", 240, 180, 1.0,
      [](vtkRenderer*, P* p)
      {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        p->SetLowThreshold(nan);
        p->SetHighThreshold(-1);
        p->SetDepthThreshold(0);
        p->NormalEdgesOn();
        p->SetNormalThreshold(1e9);
        p->SetOutlineColor(nan, 2, -1);
        p->SetDitherStrength(nan);
        p->SetDitherSize(1000);
        p->SetDitherAnchor(P::SURFACE);
        p->SetLevels(100000);
        p->SetArtPixelsAcross(1);
        p->AddPaletteColor(nan, 0.5, 9);
        p->SetPalette(P::CUSTOM);
        p->SetHysteresisIterations(100000);
      },
      true },
    { "colormap palette without scalars", 240, 180, 1.0,
      [](vtkRenderer* r, P* p)
      {
        p->SetPalette(P::COLORMAP);
        ForEachActor(r, [](vtkActor* a) { a->GetMapper()->ScalarVisibilityOff(); });
      },
      true },
    { "lines and points only", 240, 180, 1.0,
      [](vtkRenderer* r, P*)
      { ForEachActor(r, [](vtkActor* a) { a->GetProperty()->SetRepresentationToWireframe(); }); },
      true },
    { "empty data", 240, 180, 1.0, [](vtkRenderer* r, P*) { SetEmptyScene(r); }, false },
  };
  std::vector<Case> all = cases;
  if (huge)
  {
    all.push_back({ "7680x4320", 7680, 4320, 1.0, nullptr, true });
  }
  for (const Case& k : all)
  {
    for (int mode : { P::FAITHFUL, P::FAST })
    {
      for (bool parallel : { false, true })
      {
        if (k.Width > 4000 && parallel)
        {
          continue;
        }
        auto scene = MakeTestScene(k.Width, k.Height, parallel, k.Scale);
        vtkRenderWindow* win = scene.Window;
        vtkRenderer* ren = scene.Renderer;
        vtkNew<P> pass;
        pass->SetMode(mode);
        ren->SetPass(pass);
        if (k.Setup)
        {
          k.Setup(ren, pass);
        }
        win->Render();
        const std::string tag = k.Name + (mode == P::FAST ? " [fast" : " [faithful") +
          (parallel ? ", parallel]" : ", perspective]");
        vtkStylizeGBufferPass* g = pass->GetGBufferPass();
        CheckChannelsFinite(g, tag);
        auto img = Capture(win);
        const double white[3] = { 1, 1, 1 };
        const vtkIdType ink = CountForeground(img, white);
        const double fraction = static_cast<double>(ink) / (double(k.Width) * k.Height);
        int block[2], grid[2];
        pass->GetLastGrid(block, grid);
        std::printf("%-48s grid %dx%d of %d px: %.2f%% non-white\n", tag.c_str(), grid[0], grid[1],
          block[0], 100.0 * fraction);
        // (A faithful SURFACE anchor draws the surface in texels fixed to it, each the world size
        // of an art pixel at the focal point: one art pixel may then cover several.)
        const bool texels = mode == P::FAITHFUL && pass->GetDitherAnchor() == P::SURFACE;
        if (grid[0] == 1 && grid[1] == 1 && !texels)
        {
          // One art pixel: one uniform colour (faithful: the image's average; fast: one sample).
          int d[3];
          img->GetDimensions(d);
          const auto first = Pixel(img, 0, 0);
          bool uniform = true;
          for (int y = 0; y < d[1]; ++y)
          {
            for (int x = 0; x < d[0]; ++x)
            {
              uniform = uniform && !Differs(Pixel(img, x, y), first);
            }
          }
          STYLIZE_CHECK(uniform, "%s: one art pixel but not one colour", tag.c_str());
        }
        else
        {
          STYLIZE_CHECK(!k.ExpectInk || fraction > 0.01, "%s: nothing drawn", tag.c_str());
        }
        STYLIZE_CHECK(
          k.ExpectInk || k.Width == 1 || ink == 0, "%s: ink on an empty scene", tag.c_str());
        STYLIZE_CHECK(grid[0] >= 1 && grid[1] >= 1 && block[0] >= 1, "%s: bad grid", tag.c_str());
        win->Finalize();
      }
    }
  }
  return Failures == 0 ? 0 : 1;
}
