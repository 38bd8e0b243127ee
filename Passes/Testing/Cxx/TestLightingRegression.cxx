#include "LightingTestHelpers.h"
#include "vtkStylizeLightingPass.h"

using namespace stylizetest;

// Regression image of one model and light set-up: VTK's harness, then our strict comparison.
int TestLightingRegression(int argc, char* argv[])
{
  Args args = ParseArgs(argc, argv);
  if (args.Positional.size() < 2)
  {
    std::fprintf(stderr, "usage: TestLightingRegression MODEL SETUP -V baseline -T dir\n");
    return 1;
  }
  const int model = vtkStylizeLightingPass::GetModelFromName(args.Positional[0].c_str());
  const std::string setup = args.Positional[1];
  const bool parallel = args.Positional.size() > 2 && args.Positional[2] == "parallel";

  auto scene = MakeLightingScene(setup, parallel, 300, 240);
  vtkRenderWindow* win = scene.Window;
  vtkNew<vtkStylizeLightingPass> lighting;
  lighting->SetModel(model);
  scene.Renderer->SetPass(lighting);
  win->Render();
  const int verdict = RegressionVerdict(win, argc, argv, args, 2, 0.0005, 24);
  win->Finalize();
  return verdict;
}
