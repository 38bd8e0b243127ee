/**
 * @class   vtkSMStylizeSurfaceRepresentationProxy
 * @brief   The client-side proxy of the Stylized Surface representation.
 *
 * ParaView's representation proxy under its own class name (`<StylizeSurfaceRepresentationProxy>`
 * in StylizeView.xml), for the same reason as vtkSMStylizeViewProxy: the plugin adds this
 * representation to every geometry representation, so a client without the plugin, connected
 * to a server that has it, would abort on the first Show() when its process cannot make
 * vtkStylizeSurfaceRepresentation. With a class only the plugin provides, the client refuses
 * the representation with an error instead. It behaves as vtkSMRepresentationProxy otherwise.
 */

#ifndef vtkSMStylizeSurfaceRepresentationProxy_h
#define vtkSMStylizeSurfaceRepresentationProxy_h

#include "vtkSMRepresentationProxy.h"
#include "vtkStylizeParaViewViewModule.h" // for export macro

class VTKSTYLIZEPARAVIEWVIEW_EXPORT vtkSMStylizeSurfaceRepresentationProxy
  : public vtkSMRepresentationProxy
{
public:
  static vtkSMStylizeSurfaceRepresentationProxy* New();
  vtkTypeMacro(vtkSMStylizeSurfaceRepresentationProxy, vtkSMRepresentationProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSMStylizeSurfaceRepresentationProxy() = default;
  ~vtkSMStylizeSurfaceRepresentationProxy() override = default;

private:
  vtkSMStylizeSurfaceRepresentationProxy(const vtkSMStylizeSurfaceRepresentationProxy&) = delete;
  void operator=(const vtkSMStylizeSurfaceRepresentationProxy&) = delete;
};

#endif
