// The line art at the extremes: odd scenes (no surface, wireframe, a translucent actor's outline,
// composite data, a dataset that is not polygonal data, a single plane), scales, depth ranges,
// a 1 x 1 window and every setting at or beyond its limits. Each renders without an error from
// the pass (its GL errors included), draws ink where there are lines and none where there are
// none.
#include "vtkLineArtPass.h"
#include "vtkStylizeTestUtilities.h"

#include "vtkAppendFilter.h"
#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkDataArray.h"
#include "vtkDataSetMapper.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <limits>

using namespace stylizetest;

namespace
{
using P = vtkLineArtPass;
using Setup = std::function<void(vtkRenderer*, P*)>;

/** The number of pixels darker than mid grey: the ink (on white paper and background). */
vtkIdType InkPixels(vtkImageData* image)
{
  vtkIdType n = 0;
  const int comps = image->GetNumberOfScalarComponents();
  auto* p = static_cast<unsigned char*>(image->GetScalarPointer());
  const vtkIdType count = image->GetNumberOfPoints();
  for (vtkIdType i = 0; i < count; ++i)
  {
    const unsigned char* c = p + i * comps;
    n += (c[0] + c[1] + c[2]) < 3 * 128 ? 1 : 0;
  }
  return n;
}

void Only(vtkRenderer* r, vtkAlgorithm* source, vtkMapper* mapper = nullptr)
{
  r->RemoveAllViewProps();
  vtkSmartPointer<vtkMapper> m = mapper;
  if (!m)
  {
    m = vtkSmartPointer<vtkPolyDataMapper>::New();
  }
  m->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> a;
  a->SetMapper(m);
  r->AddActor(a);
}
}

int TestLineArtExtremes(int, char*[])
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case
  {
    std::string Name;
    int Width, Height;
    double Scale;
    Setup Configure;
    bool ExpectInk;
  };
  const std::vector<Case> cases = {
    { "the test scene", 240, 180, 1.0, nullptr, true },
    { "scale 1e-6", 240, 180, 1e-6, nullptr, true },
    { "scale 1e6", 240, 180, 1e6, nullptr, true },
    { "near/far 1e7", 240, 180, 1.0, [](vtkRenderer* r, P*) { SetNearFarRatio(r, 1e-7); }, true },
    // (the scene in one pixel: its outline, at least a pixel wide, inks it)
    { "1x1 window", 1, 1, 1.0, nullptr, true },
    { "empty scene", 240, 180, 1.0, [](vtkRenderer* r, P*) { SetEmptyScene(r); }, false },
    { "every width 0", 240, 180, 1.0,
      [](vtkRenderer*, P* p)
      {
        p->SetContourWidth(0);
        p->SetCreaseWidth(0);
        p->SetRidgeWidth(0);
        p->SetValleyWidth(0);
        p->SetSuggestiveWidth(0);
      },
      false },
    { "every setting beyond its limits", 240, 180, 1.0,
      [=](vtkRenderer*, P* p)
      {
        p->SetContourWidth(nan);
        p->SetCreaseWidth(1e9);
        p->SetRidgeWidth(-3);
        p->SetValleyWidth(inf);
        p->SetSuggestiveWidth(nan);
        p->SetDepthTaper(nan);
        p->SetStrengthTaper(7);
        p->SetCreaseAngle(-inf);
        p->SetRidgeThreshold(nan);
        p->SetSuggestiveThreshold(-1);
        p->SetTone(99);
        p->SetToneLevels(-4);
        p->SetToneDarkest(nan);
        p->SetInkColor(nan, 2, -1);
        p->SetPaperColor(nan, nan, nan);
        p->SetReferenceHeight(inf);
      },
      true },
    { "wireframe", 240, 180, 1.0,
      [](vtkRenderer* r, P*)
      { ForEachActor(r, [](vtkActor* a) { a->GetProperty()->SetRepresentationToWireframe(); }); },
      true },
    { "a translucent actor (its outline)", 240, 180, 1.0,
      [](vtkRenderer* r, P*)
      { ForEachActor(r, [](vtkActor* a) { a->GetProperty()->SetOpacity(0.5); }); },
      true },
    { "a translucent actor, TranslucentOutlines off", 240, 180, 1.0,
      [](vtkRenderer* r, P* p)
      {
        ForEachActor(r, [](vtkActor* a) { a->GetProperty()->SetOpacity(0.5); });
        p->TranslucentOutlinesOff();
      },
      false },
    { "composite data", 240, 180, 1.0,
      [](vtkRenderer* r, P*)
      {
        vtkNew<vtkSphereSource> s;
        s->SetRadius(3.0);
        s->Update();
        vtkNew<vtkMultiBlockDataSet> blocks;
        blocks->SetBlock(0, s->GetOutput());
        r->RemoveAllViewProps();
        vtkNew<vtkCompositePolyDataMapper2> m;
        m->SetInputDataObject(blocks);
        vtkNew<vtkActor> a;
        a->SetMapper(m);
        r->AddActor(a);
      },
      true },
    { "a dataset that is not polygonal data", 240, 180, 1.0,
      [](vtkRenderer* r, P*)
      {
        vtkNew<vtkSphereSource> s;
        s->SetRadius(3.0);
        vtkNew<vtkAppendFilter> grid;
        grid->SetInputConnection(s->GetOutputPort());
        vtkNew<vtkDataSetMapper> m;
        Only(r, grid, m);
      },
      true },
    { "a plane face-on", 240, 180, 1.0,
      [](vtkRenderer* r, P*)
      {
        vtkNew<vtkPlaneSource> s;
        s->SetOrigin(-4, -3, 0);
        s->SetPoint1(4, -3, 0);
        s->SetPoint2(-4, 3, 0);
        s->SetResolution(20, 20);
        Only(r, s);
      },
      true },
  };
  for (const Case& c : cases)
  {
    // one point per pixel at the cases' height: lines a few pixels wide
    auto scene = MakeStyledScene<P>(
      c.Width, c.Height, false, [](P* p) { p->SetReferenceHeight(180); }, c.Scale);
    if (c.Configure)
    {
      c.Configure(scene.Renderer, scene.Pass);
    }
    int errors = 0;
    vtkNew<vtkCallbackCommand> onError;
    onError->SetClientData(&errors);
    onError->SetCallback(
      [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
    scene.Pass->AddObserver(vtkCommand::ErrorEvent, onError);
    scene.Window->Render();
    STYLIZE_CHECK(errors == 0, "%s: %d errors from the pass", c.Name.c_str(), errors);
    auto image = Capture(scene.Window);
    const vtkIdType ink = InkPixels(image);
    std::printf("%s: %lld ink pixels, %lld strokes\n", c.Name.c_str(), static_cast<long long>(ink),
      static_cast<long long>(scene.Pass->GetStrokes()->GetNumberOfCells()));
    STYLIZE_CHECK(
      (ink > 0) == c.ExpectInk, "%s: %lld ink pixels", c.Name.c_str(), static_cast<long long>(ink));
    // a surface drawn as wireframe is drawn as its edges (creases), hidden ones removed
    if (c.Name == "wireframe")
    {
      vtkDataArray* kinds = scene.Pass->GetStrokes()->GetCellData()->GetArray("FeatureKind");
      bool creases = kinds && kinds->GetNumberOfTuples() > 0;
      for (vtkIdType i = 0; creases && i < kinds->GetNumberOfTuples(); ++i)
      {
        creases = kinds->GetTuple1(i) == 2;
      }
      STYLIZE_CHECK(creases, "wireframe: strokes other than the edges");
    }
    scene.Window->Finalize();
  }
  return Failures == 0 ? 0 : 1;
}
