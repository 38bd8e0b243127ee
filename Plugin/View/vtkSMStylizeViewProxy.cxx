#include "vtkSMStylizeViewProxy.h"

#include "vtkObjectFactory.h"
#include "vtkSMPropertyHelper.h"

vtkStandardNewMacro(vtkSMStylizeViewProxy);

//------------------------------------------------------------------------------
void vtkSMStylizeViewProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

//------------------------------------------------------------------------------
void vtkSMStylizeViewProxy::PushFreezeBackground(bool freeze)
{
  if (!this->GetProperty("FreezeBackground"))
  {
    return;
  }
  vtkSMPropertyHelper(this, "FreezeBackground").Set(freeze ? 1 : 0);
  this->UpdateProperty("FreezeBackground");
  this->BackgroundFrozen = freeze;
}

//------------------------------------------------------------------------------
vtkPVXMLElement* vtkSMStylizeViewProxy::SaveXMLState(
  vtkPVXMLElement* root, vtkSMPropertyIterator* iter)
{
  // ParaView's transparent capture saves the background properties it is about to change
  // (a state file or an undo step saves with no TransparentBackground in effect).
  if (iter && vtkSMViewProxy::GetTransparentBackground() && !this->BackgroundFrozen)
  {
    this->PushFreezeBackground(true);
  }
  return this->Superclass::SaveXMLState(root, iter);
}

//------------------------------------------------------------------------------
int vtkSMStylizeViewProxy::LoadXMLState(vtkPVXMLElement* element, vtkSMProxyLocator* locator)
{
  const int result = this->Superclass::LoadXMLState(element, locator);
  if (this->BackgroundFrozen)
  {
    this->PushFreezeBackground(false);
  }
  return result;
}
