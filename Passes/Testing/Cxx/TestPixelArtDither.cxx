#include "PixelArtTestHelpers.h"
#include "vtkPixelArtPass.h"
#include <algorithm>
#include <array>

using namespace stylizetest;

namespace
{
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

/** The pass's spread for a list palette: the median distance to the nearest other colour. */
double PaletteSpread(const std::vector<std::array<double, 3>>& palette)
{
  std::vector<double> nearest;
  for (size_t i = 0; i < palette.size(); ++i)
  {
    double best = 1e30;
    for (size_t j = 0; j < palette.size(); ++j)
    {
      if (i != j)
      {
        double d = 0;
        for (int c = 0; c < 3; ++c)
        {
          d += (palette[i][c] - palette[j][c]) * (palette[i][c] - palette[j][c]);
        }
        best = std::min(best, std::sqrt(d));
      }
    }
    nearest.push_back(best);
  }
  std::nth_element(nearest.begin(), nearest.begin() + nearest.size() / 2, nearest.end());
  return nearest[nearest.size() / 2];
}
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
  const double spread = PaletteSpread(custom);

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
