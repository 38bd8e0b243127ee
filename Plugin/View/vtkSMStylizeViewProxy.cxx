#include "vtkSMStylizeViewProxy.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkSMStylizeViewProxy);

//------------------------------------------------------------------------------
void vtkSMStylizeViewProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
