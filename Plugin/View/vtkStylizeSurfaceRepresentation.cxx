#include "vtkStylizeSurfaceRepresentation.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPVLODActor.h"
#include "vtkPVView.h"
#include "vtkStylizeLightingPass.h"

vtkStandardNewMacro(vtkStylizeSurfaceRepresentation);

//------------------------------------------------------------------------------
vtkStylizeSurfaceRepresentation::vtkStylizeSurfaceRepresentation()
{
  // Start from the lighting pass's own defaults.
  vtkNew<vtkStylizeLightingPass> defaults;
  this->SubjectFactor = defaults->GetSubjectFactor();
  this->GrayLevelsNear = defaults->GetGrayLevelsNear();
  this->GrayLevelsFar = defaults->GetGrayLevelsFar();
  this->SpecularGain = defaults->GetSpecularGain();
}

//------------------------------------------------------------------------------
vtkStylizeSurfaceRepresentation::~vtkStylizeSurfaceRepresentation() = default;

//------------------------------------------------------------------------------
void vtkStylizeSurfaceRepresentation::ApplyLightingSettings()
{
  for (vtkProp* actor : { static_cast<vtkProp*>(this->Actor),
         static_cast<vtkProp*>(this->BackfaceActor) })
  {
    if (!actor)
    {
      continue;
    }
    if (this->OverrideLighting)
    {
      vtkStylizeLightingPass::SetActorSubjectFactor(actor, this->SubjectFactor);
      vtkStylizeLightingPass::SetActorGrayLevels(actor, this->GrayLevelsNear, this->GrayLevelsFar);
      vtkStylizeLightingPass::SetActorSpecularGain(actor, this->SpecularGain);
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
  os << indent << "SubjectFactor: " << this->SubjectFactor << "\n";
  os << indent << "GrayLevelsNear: " << this->GrayLevelsNear << "\n";
  os << indent << "GrayLevelsFar: " << this->GrayLevelsFar << "\n";
  os << indent << "SpecularGain: " << this->SpecularGain << "\n";
}
