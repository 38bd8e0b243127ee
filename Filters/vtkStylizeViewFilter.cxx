#include "vtkStylizeViewFilter.h"

#include "vtkCamera.h"
#include "vtkInformation.h"
#include "vtkMatrix4x4.h"

#include <algorithm>

vtkCxxSetObjectMacro(vtkStylizeViewFilter, Camera, vtkCamera);
vtkCxxSetObjectMacro(vtkStylizeViewFilter, ModelMatrix, vtkMatrix4x4);

//------------------------------------------------------------------------------
vtkStylizeViewFilter::vtkStylizeViewFilter() = default;

//------------------------------------------------------------------------------
vtkStylizeViewFilter::~vtkStylizeViewFilter()
{
  this->SetCamera(nullptr);
  this->SetModelMatrix(nullptr);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkStylizeViewFilter::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->Camera)
  {
    t = std::max(t, this->Camera->GetMTime());
  }
  if (this->ModelMatrix)
  {
    t = std::max(t, this->ModelMatrix->GetMTime());
  }
  return t;
}

//------------------------------------------------------------------------------
int vtkStylizeViewFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
void vtkStylizeViewFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Camera: " << this->Camera << "\n";
  os << indent << "ModelMatrix: " << this->ModelMatrix << "\n";
}
