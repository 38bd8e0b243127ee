/**
 * @class   vtkStylizeVolumeSurfaces
 * @brief   Volumes drawn by a style as the surfaces they show (private to the module).
 *
 * For every visible vtkVolume of a frame that the style draws (vtkStylizeStylePass::
 * StylizeVolumes, unless the volume's STYLIZE_VOLUME key says 0), a surface actor stands in for
 * the volume during the frame: the surface where the volume's scalar opacity reaches the
 * threshold (vtkStylizeVolumeSurface, recomputed only when the data or the transfer functions
 * change), coloured by the volume's colour transfer function, lit with the volume's lighting
 * coefficients, through the volume's matrix and clipping planes. Begin() gives the render state
 * with each such volume replaced by its actor and adds the actors to the renderer's props (the
 * line art and figures read them there); End() takes them out again.
 *
 * Volumes the class cannot draw so are left to VTK: data that is not one vtkDataSet (a
 * composite volume), dependent components (RGBA volumes), no scalars.
 */
#ifndef vtkStylizeVolumeSurfaces_h
#define vtkStylizeVolumeSurfaces_h

#include "vtkType.h" // for vtkMTimeType

#include <map>    // for std::map
#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

class vtkActor;
class vtkProp;
class vtkRenderState;
class vtkRenderer;
class vtkVolume;
class vtkWindow;

class vtkStylizeVolumeSurfaces
{
public:
  vtkStylizeVolumeSurfaces();
  ~vtkStylizeVolumeSurfaces();

  /**
   * The state to render: `s` itself when no volume is drawn as a surface, otherwise a state
   * whose props have the volumes replaced (valid until End()). `threshold`: the opacity
   * threshold of volumes without their own (VOLUME_OPACITY_THRESHOLD key).
   */
  const vtkRenderState* Begin(const vtkRenderState* s, double threshold);

  /**
   * Adds the surfaces of the volumes last drawn as surfaces to `ren`'s props, without updating
   * them (a figure built after the frame); End() takes them out.
   */
  void AddToRenderer(vtkRenderer* ren);

  /** Takes the surfaces out of the renderer's props. */
  void End();

  /** The number of volumes the last Begin() replaced. */
  int GetNumberOfSurfaces() const;

  /** Frees the surfaces' graphics resources. */
  void ReleaseGraphicsResources(vtkWindow* w);

  /** Whether `volume` is drawn as a surface (its data, components and key allow it). */
  static bool Drawable(vtkVolume* volume);

private:
  struct Proxy;
  Proxy* Update(vtkVolume* volume, double threshold);

  std::map<vtkVolume*, std::unique_ptr<Proxy>> Proxies;
  std::vector<vtkProp*> Props;
  std::vector<vtkActor*> Active;
  std::unique_ptr<vtkRenderState> State;
  vtkRenderer* Renderer = nullptr;
  int Count = 0;

  vtkStylizeVolumeSurfaces(const vtkStylizeVolumeSurfaces&) = delete;
  void operator=(const vtkStylizeVolumeSurfaces&) = delete;
};

#endif
