/**
 * @class   vtkStylizeSurfaceRepresentation
 * @brief   ParaView's surface representation with per-representation comic lighting settings.
 *
 * The representation type "Stylized Surface" of ParaView's geometry representation: a surface
 * (all of vtkGeometryRepresentationWithFaces) whose actor carries vtkStylizeLightingPass's
 * per-actor settings: the comic subject factor (ambient term for the subject of the picture),
 * the gray levels at the near and far ends of the depth range and the specular gain. They
 * apply when OverrideLighting is on; otherwise the actor uses the view's lighting settings.
 * The values live in the actor's property keys, so each rank's lighting pass sees them before
 * IceT compositing.
 */

#ifndef vtkStylizeSurfaceRepresentation_h
#define vtkStylizeSurfaceRepresentation_h

#include "vtkGeometryRepresentationWithFaces.h"
#include "vtkStylizeParaViewViewModule.h" // for export macro

class vtkStylizeLightingPass;

class VTKSTYLIZEPARAVIEWVIEW_EXPORT vtkStylizeSurfaceRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkStylizeSurfaceRepresentation* New();
  vtkTypeMacro(vtkStylizeSurfaceRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Whether this representation's actor overrides the view's comic lighting. Default off. */
  vtkSetMacro(OverrideLighting, bool);
  vtkGetMacro(OverrideLighting, bool);
  ///@}

  ///@{
  /**
   * This representation's per-actor lighting settings, with the meaning, unit, range and
   * default of the lighting pass's settings of the same name (vtkStylizeLightingPass: they are
   * held and clamped by one, so nothing is restated here): the comic subject factor p1, the
   * gray levels at the near and far ends of the depth range, the specular gain.
   */
  void SetSubjectFactor(double p1);
  double GetSubjectFactor();
  void SetGrayLevelsNear(double levels);
  double GetGrayLevelsNear();
  void SetGrayLevelsFar(double levels);
  double GetGrayLevelsFar();
  void SetSpecularGain(double gain);
  double GetSpecularGain();
  ///@}

  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

protected:
  vtkStylizeSurfaceRepresentation();
  ~vtkStylizeSurfaceRepresentation() override;

  /** Writes (or removes) the per-actor keys on the front and back actors. */
  void ApplyLightingSettings();

  bool OverrideLighting = false;
  /** Holds the per-actor settings (their ranges and defaults are the lighting pass's). */
  vtkStylizeLightingPass* Settings;

private:
  vtkStylizeSurfaceRepresentation(const vtkStylizeSurfaceRepresentation&) = delete;
  void operator=(const vtkStylizeSurfaceRepresentation&) = delete;
};

#endif
