#include "ComicTestHelpers.h"
#include "vtkComicPass.h"
#include "vtkMatrix4x4.h"
#include "vtkStylizeLightingPass.h"
#include <algorithm>

using namespace stylizetest;

// Stability under motion: a 1 degree per frame orbit, screen- and object-anchored patterns.
// "flip" = pixels whose ink/paper value changes at the same image position; "swim" = surface
// points whose value changes between frames (each pixel reprojected into the previous frame).
int TestComicMotion(int argc, char* argv[])
{
  const int frames = argc > 1 ? std::max(2, std::atoi(argv[1])) : 8;
  double swim[2] = { 0, 0 };
  for (int anchor : { vtkComicPass::SCREEN, vtkComicPass::OBJECT })
  {
    auto scene = MakeStyledScene<vtkComicPass>(W, H, false,
      [anchor](vtkComicPass* comic)
      {
        comic->SetReferenceHeight(H);
        comic->SetAnchor(anchor);
        // Pattern everywhere (the paper's darker lighting, normal-dependent hatching), so that the
        // measure is about the pattern and not the outlines, which are anchored in both modes.
        comic->GetLightingPass()->SetSubjectFactor(0.0);
        comic->GetLightingPass()->SetGrayLevelsFar(2.0);
        comic->GetLightingPass()->SetGrayLevelsNear(4.0);
        comic->SetHatchDirections(4);
      });
    vtkRenderWindow* win = scene.Window;
    vtkRenderer* ren = scene.Renderer;
    vtkCamera* cam = ren->GetActiveCamera();

    std::vector<unsigned char> previous;
    vtkNew<vtkMatrix4x4> previousMatrix;
    double flips = 0, swims = 0, flipBase = 0, swimBase = 0;
    for (int f = 0; f < frames; ++f)
    {
      if (f > 0)
      {
        cam->Azimuth(1.0);
      }
      win->Render();
      auto img = Capture(win);
      std::vector<unsigned char> ink(static_cast<size_t>(W) * H);
      for (vtkIdType i = 0; i < W * H; ++i)
      {
        ink[i] = Gray(img, i) < 128 ? 1 : 0;
      }
      vtkNew<vtkFloatArray> pos;
      RenderPositions(ren, win, pos);
      if (f > 0)
      {
        for (vtkIdType i = 0; i < W * H; ++i)
        {
          flips += ink[i] != previous[i] ? 1 : 0;
          flipBase += 1;
          double p[4];
          pos->GetTuple(i, p);
          if (p[3] < 0.5)
          {
            continue;
          }
          // project into the previous frame
          double q[4] = { p[0], p[1], p[2], 1.0 }, r[4];
          previousMatrix->MultiplyPoint(q, r);
          if (!(r[3] > 0))
          {
            continue;
          }
          const int x = static_cast<int>(std::floor((r[0] / r[3] * 0.5 + 0.5) * W));
          const int y = static_cast<int>(std::floor((r[1] / r[3] * 0.5 + 0.5) * H));
          if (x < 0 || y < 0 || x >= W || y >= H)
          {
            continue;
          }
          swims += ink[i] != previous[static_cast<size_t>(y) * W + x] ? 1 : 0;
          swimBase += 1;
        }
      }
      previous = ink;
      previousMatrix->DeepCopy(
        cam->GetCompositeProjectionTransformMatrix(static_cast<double>(W) / H, -1, 1));
    }
    const std::string a = anchor == vtkComicPass::OBJECT ? "object" : "screen";
    std::printf("anchor %-6s: %d frames at 1 deg/frame: %.2f%% of pixels flip per frame, "
                "%.2f%% of surface points change (swim) per frame\n",
      a.c_str(), frames, 100.0 * flips / std::max(1.0, flipBase),
      100.0 * swims / std::max(1.0, swimBase));
    swim[anchor] = swims / std::max(1.0, swimBase);
    win->Finalize();
  }
  STYLIZE_CHECK(swim[vtkComicPass::OBJECT] < 0.5 * swim[vtkComicPass::SCREEN],
    "object anchoring does not reduce swimming: %.4f vs %.4f", swim[1], swim[0]);
  return stylizetest::Failures == 0 ? 0 : 1;
}
