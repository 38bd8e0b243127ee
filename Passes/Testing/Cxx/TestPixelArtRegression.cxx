#include "PixelArtTestHelpers.h"
#include "vtkPixelArtPass.h"
#include <array>

using namespace stylizetest;

// Regression image of one variant: VTK's harness, then our strict comparison.
int TestPixelArtRegression(int argc, char* argv[])
{
  using P = vtkPixelArtPass;
  const std::map<std::string, Configure> variants = {
    { "faithful", nullptr },
    { "fast", [](vtkRenderer*, P* p) { p->SetModeToFast(); } },
    { "pixel-size-8", [](vtkRenderer*, P* p) { p->SetPixelSize(8); } },
    { "one-bit", [](vtkRenderer*, P* p) { p->SetPaletteToOneBit(); } },
    { "four-grays", [](vtkRenderer*, P* p) { p->SetPaletteToFourGrays(); } },
    { "palette16", [](vtkRenderer*, P* p) { p->SetPalette(P::PALETTE16); } },
    { "custom",
      [](vtkRenderer*, P* p)
      {
        for (const auto& c : std::vector<std::array<double, 3>>{ { 0.1, 0.1, 0.2 },
               { 0.9, 0.9, 0.8 }, { 0.8, 0.3, 0.2 }, { 0.3, 0.5, 0.8 }, { 0.5, 0.5, 0.5 } })
        {
          p->AddPaletteColor(c[0], c[1], c[2]);
        }
        p->SetPalette(P::CUSTOM);
      } },
    { "colormap", [](vtkRenderer*, P* p) { p->SetPalette(P::COLORMAP); } },
    { "sobel",
      [](vtkRenderer*, P* p)
      {
        p->SetEdgeDetector(P::SOBEL);
        p->DepthEdgesOff();
      } },
    { "canny-only", [](vtkRenderer*, P* p) { p->DepthEdgesOff(); } },
    { "geometric-edges",
      [](vtkRenderer*, P* p)
      {
        p->SetEdgeDetector(P::NO_EDGES);
        p->NormalEdgesOn();
        p->SetOutlineColor(0.2, 0.1, 0.4);
      } },
    { "no-edges",
      [](vtkRenderer*, P* p)
      {
        p->SetEdgeDetector(P::NO_EDGES);
        p->DepthEdgesOff();
      } },
    { "edge-layer", [](vtkRenderer*, P* p) { p->SetLayer(P::EDGES); } },
    { "pixelated", [](vtkRenderer*, P* p) { p->SetLayer(P::PIXELATED); } },
    { "surface-anchor",
      [](vtkRenderer*, P* p)
      {
        p->SetDitherAnchor(P::SURFACE);
        p->SetPaletteToFourGrays();
      } },
    { "dither-size-2",
      [](vtkRenderer*, P* p)
      {
        p->SetDitherSize(2);
        p->SetLevels(2);
      } },
    { "art-pixels-64", [](vtkRenderer*, P* p) { p->SetArtPixelsAcross(64); } },
    { "kit-lights", [](vtkRenderer* r, P*) { SetupLights(r, "kit"); } },
  };
  return RunStyleVariant<P>(argc, argv, "TestPixelArtRegression", variants, W, H);
}
