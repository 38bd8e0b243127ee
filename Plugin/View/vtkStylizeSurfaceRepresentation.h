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
   * The comic subject factor p1 of this representation (ambient La = p1 + I - 2 p1 I):
   * dimensionless, range [0, 1], default 0 (the lighting pass's default).
   */
  vtkSetClampMacro(SubjectFactor, double, 0.0, 1.0);
  vtkGetMacro(SubjectFactor, double);
  ///@}

  ///@{
  /** Comic gray levels at the near and far ends of the depth range: range [0, 100], defaults 4 and 2. */
  vtkSetClampMacro(GrayLevelsNear, double, 0.0, 100.0);
  vtkGetMacro(GrayLevelsNear, double);
  vtkSetClampMacro(GrayLevelsFar, double, 0.0, 100.0);
  vtkGetMacro(GrayLevelsFar, double);
  ///@}

  ///@{
  /** Comic specular gain: dimensionless, range [0, 100], default 1.5. */
  vtkSetClampMacro(SpecularGain, double, 0.0, 100.0);
  vtkGetMacro(SpecularGain, double);
  ///@}

  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

protected:
  vtkStylizeSurfaceRepresentation();
  ~vtkStylizeSurfaceRepresentation() override;

  /** Writes (or removes) the per-actor keys on the front and back actors. */
  void ApplyLightingSettings();

  bool OverrideLighting = false;
  double SubjectFactor = 0.0;
  double GrayLevelsNear = 4.0;
  double GrayLevelsFar = 2.0;
  double SpecularGain = 1.5;

private:
  vtkStylizeSurfaceRepresentation(const vtkStylizeSurfaceRepresentation&) = delete;
  void operator=(const vtkStylizeSurfaceRepresentation&) = delete;
};

#endif
