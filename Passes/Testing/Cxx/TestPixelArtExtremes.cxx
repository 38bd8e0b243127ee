#include "PixelArtTestHelpers.h"
#include "vtkActor.h"
#include "vtkPixelArtPass.h"
#include "vtkStylizeGBufferPass.h"
#include <limits>

using namespace stylizetest;

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
