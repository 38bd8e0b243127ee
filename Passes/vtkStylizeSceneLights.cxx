#include "vtkStylizeSceneLights.h"

#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkStylizeSceneLights);

//------------------------------------------------------------------------------
void vtkStylizeSceneLights::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

//------------------------------------------------------------------------------
void vtkStylizeSceneLights::AddLights(vtkRenderer* renderer, int count, const double center[3],
  double distance, double totalIntensity, int cycle, double pointConeAngle)
{
  if (!renderer)
  {
    return;
  }
  renderer->AutomaticLightCreationOff();
  renderer->RemoveAllLights();
  if (count <= 0)
  {
    return;
  }
  if (count == 1)
  {
    vtkNew<vtkLight> headlight; // what vtkRenderer::CreateLight() makes
    headlight->SetLightTypeToHeadlight();
    renderer->AddLight(headlight);
    return;
  }
  const int kinds = cycle == DIRECTIONAL_POINT_SPOT ? 3 : 2;
  const double intensity = std::min(1.0, totalIntensity / count);
  const double golden = vtkMath::Pi() * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i)
  {
    const double y = 1.0 - 2.0 * (i + 0.5) / count;
    const double r = std::sqrt(std::max(0.0, 1.0 - y * y));
    const double phi = golden * i;
    const double dir[3] = { r * std::cos(phi), y, r * std::sin(phi) };
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetColor(1.0, 1.0, 1.0);
    light->SetIntensity(intensity);
    light->SetFocalPoint(center[0], center[1], center[2]);
    light->SetPosition(
      center[0] + distance * dir[0], center[1] + distance * dir[1], center[2] + distance * dir[2]);
    switch (i % kinds)
    {
      case 0:
        light->PositionalOff(); // directional, from the position towards the focal point
        break;
      case 1:
        light->PositionalOn();
        light->SetConeAngle(pointConeAngle);
        light->SetAttenuationValues(1.0, 0.0, 0.0);
        break;
      default:
        light->PositionalOn();
        light->SetConeAngle(30.0); // a spot light on the data
        light->SetExponent(2.0);
        light->SetAttenuationValues(1.0, 0.0, 0.0);
        break;
    }
    renderer->AddLight(light);
  }
}
