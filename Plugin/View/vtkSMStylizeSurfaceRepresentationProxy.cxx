#include "vtkSMStylizeSurfaceRepresentationProxy.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkSMStylizeSurfaceRepresentationProxy);

//------------------------------------------------------------------------------
void vtkSMStylizeSurfaceRepresentationProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
