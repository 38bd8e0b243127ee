#include "ComicTestHelpers.h"
#include "vtkCellArray.h"
#include "vtkComicPass.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include <limits>

using namespace stylizetest;

// Extremes: pd = 0, one gray level, 0 and 500 lights, lines-and-points-only data, empty data,
// degenerate settings. No NaN/Inf in the float buffers, no crash, sensible pictures.
int TestComicExtremes(int, char*[])
{
  struct Case
  {
    std::string Name;
    Configure Setup;
    bool ExpectInk;
  };
  const std::vector<Case> cases = {
    { "pd = 0",
      [](vtkRenderer*, vtkComicPass* c)
      {
        c->GetLightingPass()->SetGrayLevelsNear(0);
        c->GetLightingPass()->SetGrayLevelsFar(0);
      },
      true },
    { "one gray level",
      [](vtkRenderer*, vtkComicPass* c)
      {
        c->GetLightingPass()->SetGrayLevelsNear(1);
        c->GetLightingPass()->SetGrayLevelsFar(1);
      },
      true },
    { "no lights", [](vtkRenderer* r, vtkComicPass*) { SetupLights(r, "none"); }, true },
    { "500 lights", [](vtkRenderer* r, vtkComicPass*) { SetupLights(r, "many:500"); }, true },
    { "thresholds at their limits",
      [](vtkRenderer*, vtkComicPass* c)
      {
        c->SetDepthThreshold(0);
        c->SetNormalThreshold(1e9);
        c->SetColorThreshold(-1);
        c->SetEdgeWeights(std::numeric_limits<double>::quiet_NaN(), 2.0, -1.0);
        c->SetBrightThreshold(0.2);
        c->SetDarkThreshold(0.8);
        c->SetEdgeWidth(1e9);
        c->SetDotSpacing(0);
        c->SetHatchWidth(1e9);
      },
      true },
    { "object anchor, tinted",
      [](vtkRenderer*, vtkComicPass* c)
      {
        c->SetAnchorToObject();
        c->SetTint(vtkStylizeStylePass::ALL_COLORS);
      },
      true },
  };
  for (const Case& k : cases)
  {
    for (bool parallel : { false, true })
    {
      auto scene = MakeTestScene(240, 180, parallel);
      vtkRenderWindow* win = scene.Window;
      vtkRenderer* ren = scene.Renderer;
      vtkNew<vtkComicPass> comic;
      ren->SetPass(comic);
      k.Setup(ren, comic);
      win->Render();
      vtkStylizeGBufferPass* g = comic->GetGBufferPass();
      const std::string tag = k.Name + (parallel ? " [parallel]" : " [perspective]");
      CheckChannelsFinite(g, tag);
      auto img = Capture(win);
      const double white[3] = { 1, 1, 1 };
      const vtkIdType ink = CountForeground(img, white);
      std::printf("%-28s non-white pixels: %lld\n", tag.c_str(), static_cast<long long>(ink));
      STYLIZE_CHECK(!k.ExpectInk || ink > 1000, "%s: nothing drawn", tag.c_str());
      STYLIZE_CHECK(ink < 240 * 180 / 2, "%s: more than half the image is ink", tag.c_str());
      win->Finalize();
    }
  }

  // Lines and points only (no surface): they keep their tone; empty data: only the background.
  for (int kind = 0; kind < 2; ++kind)
  {
    auto win = MakeWindow(200, 150);
    vtkNew<vtkRenderer> ren;
    win->AddRenderer(ren);
    ren->SetBackground(1, 1, 1);
    vtkNew<vtkPolyData> pd;
    vtkNew<vtkPoints> pts;
    vtkNew<vtkCellArray> lines, verts;
    if (kind == 0)
    {
      for (int i = 0; i < 20; ++i)
      {
        pts->InsertNextPoint(std::cos(i * 0.3), std::sin(i * 0.3), 0.05 * i);
      }
      lines->InsertNextCell(10);
      for (int i = 0; i < 10; ++i)
      {
        lines->InsertCellPoint(i);
      }
      for (int i = 10; i < 20; ++i)
      {
        verts->InsertNextCell(1);
        verts->InsertCellPoint(i);
      }
    }
    pd->SetPoints(pts);
    pd->SetLines(lines);
    pd->SetVerts(verts);
    vtkNew<vtkPolyDataMapper> m;
    m->SetInputData(pd);
    vtkNew<vtkActor> actor;
    actor->SetMapper(m);
    actor->GetProperty()->SetColor(0.1, 0.1, 0.1);
    actor->GetProperty()->SetLineWidth(3);
    actor->GetProperty()->SetPointSize(5);
    ren->AddActor(actor);
    PlaceCamera(ren, 1.0, 0, 0, 5.0, 0.0);
    vtkNew<vtkComicPass> comic;
    ren->SetPass(comic);
    win->Render();
    auto img = Capture(win);
    const double white[3] = { 1, 1, 1 };
    const vtkIdType ink = CountForeground(img, white);
    std::printf("%s: non-white pixels %lld\n", kind == 0 ? "lines and points" : "empty data",
      static_cast<long long>(ink));
    if (kind == 0)
    {
      STYLIZE_CHECK(ink > 100, "lines and points: not drawn (%lld)", static_cast<long long>(ink));
    }
    else
    {
      STYLIZE_CHECK(ink == 0, "empty data: %lld non-white pixels", static_cast<long long>(ink));
    }
    win->Finalize();
  }
  return stylizetest::Failures == 0 ? 0 : 1;
}
