#include "vtkSMStylizeViewProxy.h"

#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxyProperty.h"

#include <algorithm>
#include <vector>

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

//------------------------------------------------------------------------------
vtkImageData* vtkSMStylizeViewProxy::CaptureWindowInternal(int magX, int magY)
{
  vtkRenderWindow* window = this->GetRenderWindow();
  const bool styled =
    this->GetProperty("Style") && vtkSMPropertyHelper(this, "Style").GetAsInt() != 0;
  int size[2] = { 0, 0 };
  vtkSMPropertyHelper(this, "ViewSize").Get(size, 2);
  const double full[2] = { static_cast<double>(size[0]) * magX,
    static_cast<double>(size[1]) * magY };
  // (ParaView 5.11 renders every view, the GUI's included, into its own offscreen buffers,
  // which may be larger than the screen.)
  if (!styled || (magX <= 1 && magY <= 1) || !window || !this->GetProperty("PPI") ||
    !this->GetProperty("WindowScale") || full[0] > MaxOnePieceSide || full[1] > MaxOnePieceSide ||
    full[0] * full[1] > MaxOnePiecePixels)
  {
    return this->Superclass::CaptureWindowInternal(magX, magY);
  }
  vtkSMPropertyHelper viewSize(this, "ViewSize");
  vtkSMPropertyHelper ppi(this, "PPI");
  vtkSMPropertyHelper scale(this, "WindowScale");
  const int savedPPI = ppi.GetAsInt();
  const int fullSize[2] = { size[0] * magX, size[1] * magY };
  viewSize.Set(fullSize, 2);
  ppi.Set(savedPPI * std::max(magX, magY));
  const int magnification[2] = { magX, magY };
  scale.Set(magnification, 2);
  this->UpdateVTKObjects();
  vtkImageData* image = this->Superclass::CaptureWindowInternal(1, 1);
  viewSize.Set(size, 2);
  ppi.Set(savedPPI);
  const int one[2] = { 1, 1 };
  scale.Set(one, 2);
  this->UpdateVTKObjects();
  return image;
}

//------------------------------------------------------------------------------
void vtkSMStylizeViewProxy::Update()
{
  this->UpdatePlainVolumes();
  this->Superclass::Update();
}

//------------------------------------------------------------------------------
void vtkSMStylizeViewProxy::UpdatePlainVolumes()
{
  auto* shown = vtkSMProxyProperty::SafeDownCast(this->GetProperty("Representations"));
  auto* plain = vtkSMProxyProperty::SafeDownCast(this->GetProperty("PlainVolumeDisplays"));
  if (!shown || !plain)
  {
    return;
  }
  std::vector<vtkSMProxy*> displays;
  for (unsigned int i = 0; i < shown->GetNumberOfProxies(); ++i)
  {
    vtkSMProxy* display = shown->GetProxy(i);
    vtkSMProperty* stylize = display ? display->GetProperty("StylizeVolume") : nullptr;
    if (stylize && vtkSMPropertyHelper(stylize).GetAsInt() == 0)
    {
      displays.push_back(display);
    }
  }
  bool same = displays.size() == plain->GetNumberOfProxies();
  for (unsigned int i = 0; same && i < displays.size(); ++i)
  {
    same = plain->GetProxy(i) == displays[i];
  }
  if (!same)
  {
    plain->SetProxies(static_cast<unsigned int>(displays.size()), displays.data());
    this->UpdateProperty("PlainVolumeDisplays");
  }
}
