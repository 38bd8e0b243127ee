/**
 * @class   vtkSMStylizeViewProxy
 * @brief   The client-side proxy of the VTK Stylize view (vtkPVStylizeView).
 *
 * ParaView's render-view proxy under its own class name, so that the view's definition names a
 * class (`<StylizeViewProxy>` in StylizeView.xml) that only a process with the plugin can make.
 * A client without the plugin, connected to a server that has it, then refuses to create the
 * view ("Creation of new proxy vtkSMStylizeViewProxy failed", and CreateView raises) instead of
 * aborting when its own process cannot make vtkPVStylizeView. It behaves as
 * vtkSMRenderViewProxy in every other way.
 */

#ifndef vtkSMStylizeViewProxy_h
#define vtkSMStylizeViewProxy_h

#include "vtkSMRenderViewProxy.h"
#include "vtkStylizeParaViewViewModule.h" // for export macro

class VTKSTYLIZEPARAVIEWVIEW_EXPORT vtkSMStylizeViewProxy : public vtkSMRenderViewProxy
{
public:
  static vtkSMStylizeViewProxy* New();
  vtkTypeMacro(vtkSMStylizeViewProxy, vtkSMRenderViewProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSMStylizeViewProxy() = default;
  ~vtkSMStylizeViewProxy() override = default;

private:
  vtkSMStylizeViewProxy(const vtkSMStylizeViewProxy&) = delete;
  void operator=(const vtkSMStylizeViewProxy&) = delete;
};

#endif
