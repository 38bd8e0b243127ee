#include "vtkStylizeSurfaceRepresentation.h"

#include "vtkObjectFactory.h"
#include "vtkPVLODActor.h"
#include "vtkPVView.h"
#include "vtkStylizeLightingPass.h"

vtkStandardNewMacro(vtkStylizeSurfaceRepresentation);

//------------------------------------------------------------------------------
vtkStylizeSurfaceRepresentation::vtkStylizeSurfaceRepresentation()
  : Settings(vtkStylizeLightingPass::New())
{
}

//------------------------------------------------------------------------------
vtkStylizeSurfaceRepresentation::~vtkStylizeSurfaceRepresentation()
{
  this->Settings->Delete();
}

// Each setting is the lighting pass's: it clamps, and the representation is modified when the
// value changes.
#define STYLIZE_FORWARD_SETTING(name)                                                              \
  void vtkStylizeSurfaceRepresentation::Set##name(double value)                                    \
  {                                                                                                \
    const vtkMTimeType before = this->Settings->GetMTime();                                        \
    this->Settings->Set##name(value);                                                              \
    if (this->Settings->GetMTime() != before)                                                      \
    {                                                                                              \
      this->Modified();                                                                            \
    }                                                                                              \
  }                                                                                                \
  double vtkStylizeSurfaceRepresentation::Get##name()                                              \
  {                                                                                                \
    return this->Settings->Get##name();                                                            \
  }
STYLIZE_FORWARD_SETTING(SubjectFactor)
STYLIZE_FORWARD_SETTING(GrayLevelsNear)
STYLIZE_FORWARD_SETTING(GrayLevelsFar)
STYLIZE_FORWARD_SETTING(SpecularGain)
#undef STYLIZE_FORWARD_SETTING

//------------------------------------------------------------------------------
void vtkStylizeSurfaceRepresentation::ApplyLightingSettings()
{
  for (vtkProp* actor :
    { static_cast<vtkProp*>(this->Actor), static_cast<vtkProp*>(this->BackfaceActor) })
  {
    if (!actor)
    {
      continue;
    }
    if (this->OverrideLighting)
    {
      vtkStylizeLightingPass* s = this->Settings;
      vtkStylizeLightingPass::SetActorSubjectFactor(actor, s->GetSubjectFactor());
      vtkStylizeLightingPass::SetActorGrayLevels(
        actor, s->GetGrayLevelsNear(), s->GetGrayLevelsFar());
      vtkStylizeLightingPass::SetActorSpecularGain(actor, s->GetSpecularGain());
    }
    else
    {
      vtkStylizeLightingPass::RemoveActorSettings(actor);
    }
  }
}

//------------------------------------------------------------------------------
int vtkStylizeSurfaceRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (request_type == vtkPVView::REQUEST_RENDER())
  {
    this->ApplyLightingSettings();
  }
  return this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo);
}

//------------------------------------------------------------------------------
void vtkStylizeSurfaceRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OverrideLighting: " << this->OverrideLighting << "\n";
  os << indent << "SubjectFactor: " << this->Settings->GetSubjectFactor() << "\n";
  os << indent << "GrayLevelsNear: " << this->Settings->GetGrayLevelsNear() << "\n";
  os << indent << "GrayLevelsFar: " << this->Settings->GetGrayLevelsFar() << "\n";
  os << indent << "SpecularGain: " << this->Settings->GetSpecularGain() << "\n";
}
