#include "ComicTestHelpers.h"
#include "vtkComicPass.h"
#include "vtkStylizeLightingPass.h"

using namespace stylizetest;

// Regression image of one variant: VTK's harness, then our strict comparison.
int TestComicRegression(int argc, char* argv[])
{
  const std::map<std::string, Configure> variants = {
    { "full", nullptr },
    { "no-edges", [](vtkRenderer*, vtkComicPass* c) { c->EdgesOff(); } },
    { "no-dots", [](vtkRenderer*, vtkComicPass* c) { c->DotsOff(); } },
    { "no-hatching", [](vtkRenderer*, vtkComicPass* c) { c->HatchingOff(); } },
    { "standard-lighting",
      [](vtkRenderer*, vtkComicPass* c)
      { c->GetLightingPass()->SetModel(vtkStylizeLightingPass::STANDARD); } },
    { "tinted",
      [](vtkRenderer*, vtkComicPass* c) { c->SetTint(vtkStylizeStylePass::ALL_COLORS); } },
    { "object-anchor", [](vtkRenderer*, vtkComicPass* c) { c->SetAnchorToObject(); } },
    { "edges", [](vtkRenderer*, vtkComicPass* c) { c->SetLayer(vtkComicPass::EDGES); } },
    { "three-phase-edges", // the paper's depth, normal and colour phases (eq. 9)
      [](vtkRenderer*, vtkComicPass* c)
      {
        c->SetEdgeWeights(1.0, 1.0, 1.0);
        c->SetLayer(vtkComicPass::EDGES);
      } },
    { "principal-hatch", // hatching around the form, in the Standard lighting's shadows
      [](vtkRenderer*, vtkComicPass* c)
      {
        c->GetLightingPass()->SetModel(vtkStylizeLightingPass::STANDARD);
        c->SetHatchOrientation(vtkComicPass::PRINCIPAL);
      } },
    { "one-direction",
      [](vtkRenderer*, vtkComicPass* c)
      {
        c->SetHatchDirections(0);
        c->SetHatchAngle(90);
        c->CrossHatchingOff();
      } },
    { "kit-lights", [](vtkRenderer* r, vtkComicPass*) { SetupLights(r, "kit"); } },
  };
  return RunStyleVariant<vtkComicPass>(argc, argv, "TestComicRegression", variants, W, H,
    [](vtkComicPass* comic) { comic->SetReferenceHeight(H); });
}
