#include "SketchTestHelpers.h"
#include "vtkSketchPass.h"
#include "vtkStylizePrincipalCurvatures.h"

using namespace stylizetest;

namespace
{
constexpr int W = 400, H = 300;

/** Puts vtkStylizePrincipalCurvatures behind every actor's mapper (model-space directions). */
void AddCurvatureArrays(vtkRenderer* ren)
{
  ForEachActor(ren,
    [](vtkActor* a)
    {
      vtkMapper* m = a->GetMapper();
      vtkNew<vtkStylizePrincipalCurvatures> filter;
      filter->SetInputConnection(m->GetInputConnection(0, 0));
      m->SetInputConnection(filter->GetOutputPort());
    });
}
}

int TestSketchRegression(int argc, char* argv[])
{
  using P = vtkSketchPass;
  const std::map<std::string, Configure> variants = {
    { "sketch", nullptr },
    { "directions", [](vtkRenderer*, P* p) { p->SetLayer(P::DIRECTIONS); } },
    { "strokes", [](vtkRenderer*, P* p) { p->SetLayer(P::STROKES); } },
    { "tone", [](vtkRenderer*, P* p) { p->SetLayer(P::TONE); } },
    { "perlin", [](vtkRenderer*, P* p) { p->SetNoise(P::PERLIN); } },
    { "worley", [](vtkRenderer*, P* p) { p->SetNoise(P::WORLEY); } },
    { "sparse", [](vtkRenderer*, P* p) { p->SetNoise(P::SPARSE); } },
    { "bisector", [](vtkRenderer*, P* p) { p->SetDirection(P::BISECTOR); } },
    { "minimum", [](vtkRenderer*, P* p) { p->SetDirection(P::MINIMUM); } },
    { "neighbors-2",
      [](vtkRenderer*, P* p)
      {
        p->SetNeighbors(2);
        p->SetLayer(P::DIRECTIONS);
      } },
    { "model",
      [](vtkRenderer* r, P* p)
      {
        AddCurvatureArrays(r);
        p->SetDirectionSource(P::MODEL);
      } },
    { "model-directions",
      [](vtkRenderer* r, P* p)
      {
        AddCurvatureArrays(r);
        p->SetDirectionSource(P::MODEL);
        p->SetLayer(P::DIRECTIONS);
      } },
    { "screen-lic", [](vtkRenderer*, P* p) { p->SetLicMode(P::SCREEN_2D); } },
    { "screen-noise", [](vtkRenderer*, P* p) { p->SetNoiseSpace(P::SCREEN_SPACE); } },
    { "long-strokes",
      [](vtkRenderer*, P* p)
      {
        p->SetStepLength(4);
        p->SetSteps(16);
      } },
    { "high-contrast",
      [](vtkRenderer*, P* p)
      {
        p->SetContrast(2.0);
        p->SetBlurStride(6);
        p->SetBrightThresholds(0.6, 0.8);
      } },
    { "no-cross", [](vtkRenderer*, P* p) { p->CrossHatchingOff(); } },
    { "tinted",
      [](vtkRenderer*, P* p)
      {
        p->SetTint(vtkStylizeStylePass::ALL_COLORS);
        p->SetPencilColor(0.2, 0.1, 0.3);
      } },
    { "kit-lights", [](vtkRenderer* r, P*) { SetupLights(r, "kit"); } },
  };
  // Besides the image: every surface pixel has a unit direction.
  return RunStyleVariant<P>(argc, argv, "TestSketchRegression", variants, W, H, nullptr,
    [](P* pass, const std::string& name) { CheckField(pass, "sketch." + name, true); });
}
