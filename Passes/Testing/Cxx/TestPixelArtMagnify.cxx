#include "PixelArtTestHelpers.h"
#include "vtkPixelArtPass.h"

using namespace stylizetest;

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
