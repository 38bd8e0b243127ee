#include "PixelArtTestHelpers.h"
#include "vtkPixelArtPass.h"
#include "vtkStylizeImageMetrics.h"
#include "vtkTimerLog.h"

using namespace stylizetest;

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
