#include "vtkLineArtPass.h"
#include "vtkStylizeTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkPolyData.h"

using namespace stylizetest;

int TestLineArtRegression(int argc, char* argv[])
{
  using P = vtkLineArtPass;
  using Configure = std::function<void(vtkRenderer*, P*)>;
  const std::map<std::string, Configure> variants = {
    { "lines", nullptr },
    { "shades", [](vtkRenderer*, P* p) { p->SetTone(P::SHADES); } },
    { "four-shades",
      [](vtkRenderer*, P* p)
      {
        p->SetTone(P::SHADES);
        p->SetToneLevels(4);
        p->SetToneDarkest(0.3);
      } },
    { "dots",
      [](vtkRenderer*, P* p)
      {
        p->SetTone(P::DOTS);
        p->SetDotSpacing(6);
      } },
    { "outline",
      [](vtkRenderer*, P* p)
      {
        p->SetRidgeWidth(0);
        p->SetValleyWidth(0);
        p->SetSuggestiveWidth(0);
      } },
    { "even-width",
      [](vtkRenderer*, P* p)
      {
        p->SetDepthTaper(0);
        p->SetStrengthTaper(0);
      } },
    { "heavy",
      [](vtkRenderer*, P* p)
      {
        p->SetContourWidth(6);
        p->SetCreaseWidth(4);
      } },
    { "colors",
      [](vtkRenderer*, P* p)
      {
        p->SetInkColor(0.1, 0.2, 0.6);
        p->SetPaperColor(1.0, 0.95, 0.85);
        p->SetTone(P::SHADES);
      } },
    { "paper-layer",
      [](vtkRenderer*, P* p)
      {
        p->SetTone(P::SHADES);
        p->SetLayer(P::PAPER);
      } },
    { "kit-lights",
      [](vtkRenderer* r, P* p)
      {
        SetupLights(r, "kit");
        p->SetTone(P::SHADES);
      } },
  };
  // Besides the image: strokes with contours (the test objects are smooth primitives; the
  // other kinds are measured on real data, realdata.lineart).
  auto inspect = [](P* pass, const std::string& name)
  {
    vtkDataArray* kinds = pass->GetStrokes()->GetCellData()->GetArray("FeatureKind");
    bool contours = false;
    for (vtkIdType i = 0; kinds && i < kinds->GetNumberOfTuples(); ++i)
    {
      contours = contours || kinds->GetTuple1(i) == 0;
    }
    STYLIZE_CHECK(contours, "lines.%s: no contour strokes", name.c_str());
  };
  // one point per pixel at this height: lines a few pixels wide
  return RunStyleVariant<P>(
    argc, argv, "TestLineArtRegression", variants, 400, 300,
    [](P* p) { p->SetReferenceHeight(300); }, inspect);
}
