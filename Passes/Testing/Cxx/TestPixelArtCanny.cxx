#include "PixelArtTestHelpers.h"
#include "vtkPixelArtPass.h"
#include <algorithm>
#include <array>

using namespace stylizetest;

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
