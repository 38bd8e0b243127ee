/**
 * @class   vtkStylizeVolumeSolidCut
 * @brief   A volume's solid surface where it looks solid from the eye, and the surfaces as the
 *          fog samples them (private to the module: vtkStylizeVolumeSurfaces' HAZE_FOG).
 *
 * VTK's ray casting shows solid material (where the opacity reaches the solid level) as solid
 * only where the view ray, through the fog in front and the material's chord, accumulates
 * enough opacity; thinner material (a ball's rim, a shell seen face on, the back of a vessel
 * whose wall thins out) is a translucent fog. Cut() keeps the solid surface where that opacity
 * (vtkStylizeVolumeFog::SolidOpacity()) reaches vtkStylizeVolumeFog::LooksSolid, and gives a
 * locator on what it keeps, at which the fog stops (vtkStylizeVolumeFog::Accumulate()'s
 * `drawn`): the fog goes on through the rest, so that the two agree by construction.
 */
#ifndef vtkStylizeVolumeSolidCut_h
#define vtkStylizeVolumeSolidCut_h

#include "vtkNew.h"          // for vtkNew
#include "vtkSmartPointer.h" // for vtkSmartPointer
#include "vtkType.h"         // for vtkMTimeType

#include "vtkStylizeVolumeFog.h" // for vtkStylizeVolumeFog::Volume

class vtkAbstractCellLocator;
class vtkAlgorithmOutput;
class vtkClipPolyData;
class vtkDataSet;
class vtkImageData;
class vtkPolyData;
class vtkStaticCellLocator;

class vtkStylizeVolumeSolidCut
{
public:
  vtkStylizeVolumeSolidCut();
  ~vtkStylizeVolumeSolidCut();

  /**
   * Cuts `solid` (the solid surface, where the opacity reaches `level`, of the volume of `data`
   * that `fog` samples as `volume`) to where it looks solid along the view rays from `eye` (or
   * along `dop`, parallel), in the image's coordinates. False when the image cannot be sampled
   * or the surface is empty: then the whole surface is drawn and the fog stops at the first
   * solid sample. With `reach`, the surface kept has the point array LooksSolidAt.
   */
  bool Cut(vtkPolyData* solid, vtkDataSet* data, vtkStylizeVolumeFog& fog,
    const vtkStylizeVolumeFog::Volume& volume, double level, const double eye[3],
    const double dop[3], bool parallel, bool reach = false);

  /**
   * The point array of the surface Cut() keeps: per point, the distance along its view ray (in
   * the image's coordinates) to where it reaches vtkStylizeVolumeFog::LooksSolid
   * (vtkStylizeVolumeFog::SolidOpacity()'s `reach`). The G-buffer stores the depth there
   * (vtkStylizeGBufferPass, the attribute stylizeLooksSolid): opaque geometry inside the
   * material in front of it shows through.
   */
  static constexpr const char* LooksSolidAt = "StylizeLooksSolidAt";

  /** The surface Cut() kept, to draw (valid after it returned true). */
  vtkAlgorithmOutput* GetOutputPort();

  /** A locator on the surface Cut() kept (valid after it returned true). */
  vtkAbstractCellLocator* GetLocator();

  /**
   * `surface` as the fog samples it: for data that is not an image (its surfaces' cells span
   * much of the view, over which what the view rays find changes), refined to edges of at most
   * two of `image`'s spacings (Refined()), kept in `kept` while `surface` is unchanged
   * (`time`); for an image, whose surfaces have cells of its samples' size, `surface` itself.
   */
  static vtkPolyData* FogSurface(vtkPolyData* surface, vtkDataSet* data, vtkImageData* image,
    vtkSmartPointer<vtkPolyData>& kept, vtkMTimeType& time);

  /**
   * `surface` as triangles split until no edge is longer than `length` (each edge split at its
   * middle, whatever the triangles around it do: the result has no cracks), the new points' data
   * interpolated along their edges; at most `most` points (the splitting stops there).
   */
  static vtkSmartPointer<vtkPolyData> Refined(vtkPolyData* surface, double length, vtkIdType most);

private:
  vtkSmartPointer<vtkPolyData> Fine; // (the solid surface as the fog samples it)
  vtkMTimeType FineTime = 0;
  vtkNew<vtkPolyData> Chords; // (Fine with the chords' opacity: Looks' input)
  vtkNew<vtkClipPolyData> Looks;
  vtkNew<vtkStaticCellLocator> Drawn; // (on Looks' output)

  vtkStylizeVolumeSolidCut(const vtkStylizeVolumeSolidCut&) = delete;
  void operator=(const vtkStylizeVolumeSolidCut&) = delete;
};

#endif
