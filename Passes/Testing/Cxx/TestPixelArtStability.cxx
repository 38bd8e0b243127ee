#include "PixelArtTestHelpers.h"
#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkPixelArtPass.h"
#include <algorithm>
#include <array>

using namespace stylizetest;

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
