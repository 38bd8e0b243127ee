// The G-buffer captures of TestLightingExtremes and TestLightingModelSwitch: every channel at full
// precision, checked finite, surface normals checked unit length.
#ifndef LightingExtremesTestHelpers_h
#define LightingExtremesTestHelpers_h

#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeTestUtilities.h"

namespace stylizetest
{
struct Buffers
{
  vtkNew<vtkFloatArray> Color, Normal, Position, Depth;
  vtkSmartPointer<vtkImageData> Image;
};

using SceneBuilder = std::function<void(vtkRenderer*, vtkStylizeLightingPass*)>;

inline void RenderBuffers(int model, bool parallel, const SceneBuilder& build, Buffers& out,
  const std::string& what, int w = 200, int h = 160)
{
  auto win = MakeWindow(w, h);
  vtkNew<vtkRenderer> ren;
  win->AddRenderer(ren);
  ren->SetBackground(0.3, 0.3, 0.3);
  vtkNew<vtkStylizeLightingPass> lighting;
  lighting->SetModel(model);
  vtkNew<vtkStylizeGBufferPass> gbuffer;
  gbuffer->SetLightingPass(lighting);
  gbuffer->SetChannels(vtkStylizeGBufferPass::NORMAL | vtkStylizeGBufferPass::POSITION);
  gbuffer->SetPrecision(vtkStylizeGBufferPass::FULL);
  ren->SetPass(gbuffer);
  ren->GetActiveCamera()->SetParallelProjection(parallel);
  build(ren, lighting);
  win->Render();
  gbuffer->DownloadChannel(vtkStylizeGBufferPass::COLOR_BUFFER, out.Color);
  gbuffer->DownloadChannel(vtkStylizeGBufferPass::NORMAL_BUFFER, out.Normal);
  gbuffer->DownloadChannel(vtkStylizeGBufferPass::POSITION_BUFFER, out.Position);
  gbuffer->DownloadChannel(vtkStylizeGBufferPass::DEPTH_BUFFER, out.Depth);
  out.Image = Capture(win);
  win->Finalize();
  const std::string tag = what + " [" + vtkStylizeLightingPass::GetModelName(model) +
    (parallel ? ", parallel]" : ", perspective]");
  bool ok = CheckFinite(out.Color, tag + " colour");
  ok = CheckFinite(out.Normal, tag + " normal") && ok;
  ok = CheckFinite(out.Position, tag + " position") && ok;
  ok = CheckFinite(out.Depth, tag + " depth") && ok;
  // Every surface sample carries a unit normal.
  vtkIdType surface = 0, badNormals = 0;
  for (vtkIdType i = 0; i < out.Normal->GetNumberOfTuples(); ++i)
  {
    double n[4];
    out.Normal->GetTuple(i, n);
    if (n[3] == 1.0)
    {
      ++surface;
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      badNormals += std::abs(len - 1.0) > 1e-3 ? 1 : 0;
    }
  }
  STYLIZE_CHECK(
    badNormals == 0, "%s: %lld non-unit normals", tag.c_str(), static_cast<long long>(badNormals));
  std::printf("%-44s surface pixels %6lld, non-finite: none%s\n", tag.c_str(),
    static_cast<long long>(surface), ok ? "" : " (FAILED)");
}
}

#endif
