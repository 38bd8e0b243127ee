#include "ComicTestHelpers.h"
#include "vtkComicPass.h"

using namespace stylizetest;

namespace
{
/** 2x2 box average of an RGB image (the 1x view of a 2x image). */
vtkSmartPointer<vtkImageData> Downsample2(vtkImageData* big)
{
  int d[3];
  big->GetDimensions(d);
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->SetDimensions(d[0] / 2, d[1] / 2, 1);
  out->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  vtkDataArray* s = big->GetPointData()->GetScalars();
  vtkDataArray* o = out->GetPointData()->GetScalars();
  for (int y = 0; y < d[1] / 2; ++y)
  {
    for (int x = 0; x < d[0] / 2; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        double sum = 0;
        for (int j = 0; j < 2; ++j)
        {
          for (int i = 0; i < 2; ++i)
          {
            sum += s->GetComponent((2 * y + j) * d[0] + 2 * x + i, c);
          }
        }
        o->SetComponent(y * (d[0] / 2) + x, c, std::floor(sum / 4.0 + 0.5));
      }
    }
  }
  return out;
}
}

// A screenshot magnified 2x (tiled) is the same picture at twice the detail: it equals a direct
// render at twice the size (no seams), and its 2x2 average equals the 1x image.
int TestComicMagnify(int, char*[])
{
  for (int anchor : { vtkComicPass::SCREEN, vtkComicPass::OBJECT })
  {
    const std::string a = anchor == vtkComicPass::OBJECT ? "object" : "screen";
    Configure cfg = [anchor](vtkRenderer*, vtkComicPass* c)
    {
      c->SetAnchor(anchor);
      c->SetReferenceHeight(H);
    };
    auto one = RenderComic(cfg, W, H, 1);
    auto tiled = RenderComic(cfg, W, H, 2);
    auto direct = RenderComic(cfg, 2 * W, 2 * H, 1);
    int d[3];
    tiled->GetDimensions(d);
    STYLIZE_CHECK(d[0] == 2 * W && d[1] == 2 * H, "tiled image is %dx%d", d[0], d[1]);
    StrictCompare(tiled, direct, 128, 0.002, 255, a + ": 2x tiled vs 2x direct render (seams)");
    auto down = Downsample2(tiled);
    StrictCompare(down, one, 96, 0.03, 255, a + ": 2x tiled averaged 2x2 vs 1x");
    WritePNG(tiled, "comic-magnified-" + a + ".png");
  }
  return stylizetest::Failures == 0 ? 0 : 1;
}
