// vtkStylizeLineVisibility against input that does not hold what it claims (issue 53): a depth
// image whose array is shorter than its dimensions is refused with an error (it was read past
// its end), and a FeatureKind array shorter than the lines is ignored with a warning, the lines
// counting as contours (it was read past its end, from several threads, through the array's
// shared tuple buffer, and again when each line's values were copied to its visible runs).
#include "vtkStylizeLineVisibility.h"
#include "vtkStylizeTestChecks.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <string>
#include <vector>

using namespace stylizetest;

namespace
{
constexpr int W = 32, H = 24;

/** Three horizontal lines across the view of the default camera (at z = 1, looking down -z). */
vtkSmartPointer<vtkPolyData> ThreeLines()
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  for (int i = 0; i < 3; ++i)
  {
    const double y = -0.1 + 0.1 * i;
    const vtkIdType ids[2] = { points->InsertNextPoint(-0.2, y, 0.0),
      points->InsertNextPoint(0.2, y, 0.0) };
    lines->InsertNextCell(2, ids);
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetLines(lines);
  return pd;
}

/** A W x H window-depth image, all background (1), of `tuples` values. */
vtkSmartPointer<vtkImageData> DepthImage(vtkIdType tuples)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(W, H, 1);
  vtkNew<vtkFloatArray> depth;
  depth->SetNumberOfTuples(tuples);
  depth->FillValue(1.0f);
  image->GetPointData()->SetScalars(depth);
  return image;
}

struct Errors
{
  int Count = 0;
  static void Count1(vtkObject*, unsigned long, void* self, void*)
  {
    ++static_cast<Errors*>(self)->Count;
  }
};

/** Runs the filter on `lines` against `depth`; returns the errors it reported. */
int Run(vtkPolyData* lines, vtkImageData* depth, vtkIdType& outputLines,
  std::vector<double>* outputKinds = nullptr)
{
  vtkNew<vtkCamera> camera;
  vtkNew<vtkStylizeLineVisibility> vis;
  Errors errors;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(&Errors::Count1);
  observer->SetClientData(&errors);
  vis->AddObserver(vtkCommand::ErrorEvent, observer);
  vis->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, observer);
  vis->SetInputData(lines);
  vis->SetCamera(camera);
  vis->SetViewportSize(W, H);
  vis->SetDepthImage(depth);
  vis->Update();
  outputLines = vis->GetOutput()->GetNumberOfLines();
  vtkDataArray* kinds = vis->GetOutput()->GetCellData()->GetArray("FeatureKind");
  for (vtkIdType c = 0; outputKinds && kinds && c < kinds->GetNumberOfTuples(); ++c)
  {
    outputKinds->push_back(kinds->GetComponent(c, 0));
  }
  return errors.Count;
}
}

int TestLineVisibility(int, char*[])
{
  // the whole array: every line visible against the background, no error
  vtkIdType n = 0;
  int errors = Run(ThreeLines(), DepthImage(W * H), n);
  std::printf("full depth image: %d errors, %lld lines\n", errors, static_cast<long long>(n));
  STYLIZE_CHECK(errors == 0 && n == 3, "full depth image: %d errors, %lld lines", errors,
    static_cast<long long>(n));

  // a short array behind full dimensions: refused
  errors = Run(ThreeLines(), DepthImage(10), n);
  std::printf("depth array of 10 values for %dx%d: %d errors, %lld lines\n", W, H, errors,
    static_cast<long long>(n));
  STYLIZE_CHECK(
    errors > 0 && n == 0, "a depth array of 10 values for %dx%d pixels: %d errors", W, H, errors);

  // a FeatureKind array of one value for three lines: ignored, every line a contour
  auto lines = ThreeLines();
  vtkNew<vtkUnsignedCharArray> kinds;
  kinds->SetName("FeatureKind");
  kinds->InsertNextValue(2); // a crease
  lines->GetCellData()->AddArray(kinds);
  errors = Run(lines, DepthImage(W * H), n);
  std::printf("FeatureKind of 1 value for 3 lines: %d errors, %lld lines\n", errors,
    static_cast<long long>(n));
  STYLIZE_CHECK(errors == 0 && n == 3, "short FeatureKind: %d errors, %lld lines", errors,
    static_cast<long long>(n));

  // Many lines of every kind, traced by vtkSMPTools' threads: the same lines and kinds as one
  // thread gives (the threads read the kinds from a copy made before them; under
  // ThreadSanitizer, scripts/test-sanitizers.sh, this is the filter's threaded path).
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkUnsignedCharArray> manyKinds;
  manyKinds->SetName("FeatureKind");
  for (int i = 0; i < 4000; ++i)
  {
    const double x = -0.3 + 0.6 * (i % 80) / 80.0, y = -0.2 + 0.4 * (i / 80) / 50.0;
    const vtkIdType ids[2] = { points->InsertNextPoint(x, y, 0.0),
      points->InsertNextPoint(x + 0.005, y + 0.003, 0.0) };
    cells->InsertNextCell(2, ids);
    manyKinds->InsertNextValue(static_cast<unsigned char>(i % 6));
  }
  auto many = vtkSmartPointer<vtkPolyData>::New();
  many->SetPoints(points);
  many->SetLines(cells);
  many->GetCellData()->AddArray(manyKinds);
  const std::string backend = vtkSMPTools::GetBackend();
  vtkIdType threaded = 0, sequential = 0;
  std::vector<double> threadedKinds, sequentialKinds;
  errors = Run(many, DepthImage(W * H), threaded, &threadedKinds);
  vtkSMPTools::SetBackend("Sequential");
  errors += Run(many, DepthImage(W * H), sequential, &sequentialKinds);
  vtkSMPTools::SetBackend(backend.c_str());
  std::printf("4000 lines of 6 kinds: %lld lines on %s, %lld on one thread\n",
    static_cast<long long>(threaded), backend.c_str(), static_cast<long long>(sequential));
  STYLIZE_CHECK(errors == 0 && threaded == sequential && threaded > 0 &&
      threadedKinds == sequentialKinds && threadedKinds.size() == 4000,
    "4000 lines: %lld threaded, %lld sequential, %d errors", static_cast<long long>(threaded),
    static_cast<long long>(sequential), errors);
  return Failures == 0 ? 0 : 1;
}
