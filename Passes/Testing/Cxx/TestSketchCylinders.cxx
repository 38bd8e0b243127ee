#include "vtkClipPolyData.h"
#include "vtkPlane.h"
#include "vtkReverseSense.h"
#include "vtkSketchPass.h"
#include "vtkStylizePrincipalCurvatures.h"
#include "vtkStylizeTestUtilities.h"

using namespace stylizetest;

// MINIMUM and MAXIMUM mean the same in SCREEN and MODEL mode: by absolute curvature, along and
// around a cylinder, whether it is seen from outside (convex) or from inside (concave, normals
// towards the viewer, where the signed minimum curvature runs around it). The share of surface
// pixels whose direction is within 20 degrees of the expected one must be at least 90%.
int TestSketchCylinders(int, char*[])
{
  using P = vtkSketchPass;
  for (bool concave : { false, true })
  {
    for (int source : { P::SCREEN, P::MODEL })
    {
      for (int direction : { P::MINIMUM, P::MAXIMUM })
      {
        vtkNew<vtkCylinderSource> cylinder; // axis along y
        cylinder->SetRadius(2.0);
        cylinder->SetHeight(6.0);
        cylinder->SetResolution(256);
        cylinder->CappingOff();
        vtkSmartPointer<vtkPolyDataAlgorithm> surface = cylinder;
        vtkNew<vtkClipPolyData> clip; // the half at z < 0: a trough seen from +z
        vtkNew<vtkReverseSense> inward;
        if (concave)
        {
          vtkNew<vtkPlane> plane;
          plane->SetNormal(0, 0, -1);
          clip->SetInputConnection(cylinder->GetOutputPort());
          clip->SetClipFunction(plane);
          inward->SetInputConnection(clip->GetOutputPort());
          inward->ReverseCellsOn();
          inward->ReverseNormalsOn();
          surface = inward;
        }
        vtkNew<vtkStylizePrincipalCurvatures> curvatures;
        curvatures->SetInputConnection(surface->GetOutputPort());
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputConnection(curvatures->GetOutputPort());
        vtkNew<vtkActor> actor;
        actor->SetMapper(mapper);
        auto window = MakeWindow(240, 180);
        vtkNew<vtkRenderer> ren;
        window->AddRenderer(ren);
        ren->SetBackground(1, 1, 1);
        ren->AddActor(actor);
        vtkCamera* cam = ren->GetActiveCamera();
        cam->SetFocalPoint(0, 0, concave ? -1.0 : 0.0);
        cam->SetPosition(0, 0, 12);
        cam->SetViewUp(0, 1, 0);
        cam->SetViewAngle(30);
        ren->ResetCameraClippingRange();
        vtkNew<P> pass;
        pass->SetDirectionSource(source);
        pass->SetDirection(direction);
        ren->SetPass(pass);
        window->Render();
        vtkNew<vtkFloatArray> field;
        const std::string tag = std::string(concave ? "concave" : "convex") + " cylinder, " +
          (source == P::SCREEN ? "screen" : "model") + " mode, " +
          (direction == P::MINIMUM ? "MINIMUM" : "MAXIMUM");
        STYLIZE_CHECK(pass->DownloadDirections(field), "%s: no field", tag.c_str());
        // View space is world space turned by nothing here: the axis is view y.
        vtkIdType surfacePixels = 0, expected = 0;
        const double cos20 = std::cos(vtkMath::RadiansFromDegrees(20.0));
        for (vtkIdType i = 0; i < field->GetNumberOfTuples(); ++i)
        {
          const float* v = field->GetPointer(4 * i);
          if (!(v[3] > 0.0f))
          {
            continue;
          }
          ++surfacePixels;
          const double along = std::abs(v[1]) /
            std::max(
              1e-12, std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]));
          const bool ok = direction == P::MINIMUM
            ? along > cos20
            : along < std::sin(vtkMath::RadiansFromDegrees(20.0));
          expected += ok ? 1 : 0;
        }
        const double share = surfacePixels ? double(expected) / surfacePixels : 0.0;
        std::printf("%-44s %6lld surface pixels, %5.1f%% %s\n", tag.c_str(),
          static_cast<long long>(surfacePixels), 100.0 * share,
          direction == P::MINIMUM ? "along the axis" : "around it");
        STYLIZE_CHECK(surfacePixels > 5000, "%s: too few surface pixels", tag.c_str());
        STYLIZE_CHECK(share >= 0.9, "%s: %.1f%% of the pixels in the expected direction",
          tag.c_str(), 100.0 * share);
        window->Finalize();
      }
    }
  }
  return Failures == 0 ? 0 : 1;
}
