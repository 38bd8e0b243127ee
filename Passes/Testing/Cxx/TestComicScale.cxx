#include "ComicTestHelpers.h"
#include "vtkComicPass.h"

using namespace stylizetest;

// The same scene scaled by 1e-6, 1 and 1e6, and seen with a near/far ratio of 1e7, gives the
// same picture, in perspective and parallel projection.
int TestComicScale(int, char*[])
{
  for (bool parallel : { false, true })
  {
    const std::string proj = parallel ? "parallel" : "perspective";
    auto reference = RenderComic(nullptr, W, H, 1, 1.0, parallel);
    for (double scale : { 1e-6, 1e6 })
    {
      auto img = RenderComic(nullptr, W, H, 1, scale, parallel);
      char what[128];
      std::snprintf(what, sizeof(what), "scale %g vs 1, %s", scale, proj.c_str());
      StrictCompare(img, reference, 128, 0.003, 255, what);
    }
    for (double scale : { 1e-6, 1.0, 1e6 })
    {
      auto img = RenderComic(
        [scale](vtkRenderer* r, vtkComicPass*)
        {
          double range[2];
          r->GetActiveCamera()->GetClippingRange(range);
          const double farPlane = range[1] * 1.5;
          r->GetActiveCamera()->SetClippingRange(farPlane * 1e-7, farPlane);
          (void)scale;
        },
        W, H, 1, scale, parallel);
      char what[128];
      std::snprintf(what, sizeof(what), "near/far 1e7 at scale %g vs 1, %s", scale, proj.c_str());
      if (!StrictCompare(img, reference, 128, 0.003, 255, what))
      {
        WritePNG(img, "comic-nearfar-" + proj + ".png");
        WritePNG(reference, "comic-reference-" + proj + ".png");
      }
    }
  }
  return stylizetest::Failures == 0 ? 0 : 1;
}
