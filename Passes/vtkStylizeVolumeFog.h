/**
 * @file   vtkStylizeVolumeFog.h
 * @brief  A volume's fog as VTK's ray casting accumulates it, per point of a surface (private to
 *         the module: vtkStylizeVolumeSurfaces' HAZE_FOG).
 */
#ifndef vtkStylizeVolumeFog_h
#define vtkStylizeVolumeFog_h

#include "vtkSmartPointer.h" // for vtkSmartPointer
#include "vtkType.h"         // for vtkMTimeType

#include <memory> // for std::unique_ptr
#include <mutex>  // for std::mutex
#include <vector> // for std::vector

class vtkAbstractCellLocator;
class vtkDataArray;
class vtkDataSet;
class vtkMultiProcessController;
class vtkFloatArray;
class vtkGenericCell;
class vtkImageData;
class vtkPiecewiseFunction;
class vtkPolyData;
class vtkScalarsToColors;
class vtkUnsignedCharArray;

class vtkStylizeVolumeFog
{
public:
  /** VTK's volume shading (vtkVolumeProperty's Shade and its coefficients, a headlight). */
  struct Shading
  {
    bool On = false;
    double Ambient = 0.1, Diffuse = 0.7, Specular = 0.2, Power = 10.0;
    bool TwoSided = true; // the renderer's TwoSidedLighting
  };

  /** What the fog is sampled from: `Image`'s point `Scalars` through the transfer functions. */
  struct Volume
  {
    vtkImageData* Image = nullptr;
    vtkDataArray* Scalars = nullptr;
    vtkPiecewiseFunction* Opacity = nullptr;
    vtkScalarsToColors* Colors = nullptr;
    vtkDataArray* Mask = nullptr; // where a resampled image lies in its data (0: not), or null
    double Unit = 1.0;            // the opacity's unit distance
    // VTK's unstructured-grid mappers' model: the opacity over a unit distance is the material's
    // attenuation coefficient (a step's opacity 1 - exp(-a step / unit)), not an opacity to
    // correct for the step (1 - (1 - a)^(step / unit), the image ray casters').
    bool Attenuation = false;
    Shading Light;
  };

  /**
   * The opacity the view ray must reach through solid material (with the fog in front of it)
   * for the material to look solid: thinner material (where the opacity reaches the solid level
   * only along a short chord) is drawn as fog, as VTK's ray casting shows it, and its surface
   * left out (SolidOpacity()).
   */
  static constexpr double LooksSolid = 0.5;

  /**
   * Solid material whose chord reaches this opacity stops the fog without asking the solid
   * surface as drawn (Accumulate()'s `drawn`): the surface is cut at LooksSolid, and the two
   * can disagree only near that value.
   */
  static constexpr double Thick = 0.75;

  vtkStylizeVolumeFog();
  ~vtkStylizeVolumeFog();

  /**
   * Per point of `haze` (a surface where the opacity reaches `level`, in the image's
   * coordinates), the colour and opacity VTK's ray casting accumulates along the ray from the eye
   * (`eye`, or the direction `dop` for a parallel projection, both in the image's coordinates):
   * for the haze's nearest layer on the ray, from where the ray enters the image; then up to the
   * haze's next crossing, the solid surface (an opacity of `solid`) or the image's end, so that
   * the layers composited front to back add up to the whole ray. With `drawn` (a locator on the
   * solid surface as the style draws it: where its material looks solid, SolidOpacity() at
   * least LooksSolid), the fog stops at solid material only where its chord reaches Thick or
   * where that surface lies within a few steps, and goes on through the rest (thin material,
   * drawn as fog); without, at the first solid sample. Each sample's opacity is
   * corrected for the step as VTK's (1 - (1 - a)^(step / unit), or 1 - exp(-a step / unit) with
   * Volume::Attenuation) and, with shading, its colour lit
   * as VTK's ray caster lights it (the gradient by central differences as the normal, the
   * headlight); the result's opacity is times `scale`. Written as `out` (RGBA bytes); `whole`
   * (or null): per point, the whole ray's opacity (through the solid material too, as VTK
   * accumulates it; times `scale`) for the points of the ray's nearest layer; for the others, the
   * opacity from the point on where the ray leaves the haze (the back of a fold: at its
   * silhouette, what lies just past it) and -1 where it enters it (a layer hidden behind a
   * nearer one, left out of the outline's contour). The
   * image's scalars as floats and the transfer functions' tables are kept until the data or the
   * functions change. False when the image cannot be sampled so.
   */
  bool Accumulate(vtkPolyData* haze, const Volume& volume, double level, double solid, double scale,
    const double eye[3], const double dop[3], bool parallel, vtkUnsignedCharArray* out,
    vtkFloatArray* whole = nullptr, vtkAbstractCellLocator* drawn = nullptr);

  /**
   * Per point of `surface` (where the opacity reaches `solid`, in the image's coordinates), the
   * opacity the view ray (from `eye`, or along `dop` for a parallel projection) accumulates from
   * where it enters the image through the solid material the point starts: the fog in front of
   * the point, then, from the first sample at least `solid` within a few steps, the samples on
   * while at least `solid`, composited as VTK does, up to Thick. The surface is drawn where this
   * reaches LooksSolid (VTK's picture there is at least half opaque); below, the fog goes through
   * the material. Written as `out`; with `reach`, per point the distance along its view ray (in
   * the image's coordinates) to where it reaches LooksSolid (0 when the fog in front of the point
   * does, or the material ends within two samples past it): opaque geometry in front of that
   * shows through the material, as in VTK's picture. False when the image cannot be sampled so.
   */
  bool SolidOpacity(vtkPolyData* surface, const Volume& volume, double solid, const double eye[3],
    const double dop[3], bool parallel, vtkFloatArray* out, vtkFloatArray* reach = nullptr);

  /**
   * Data that is not an image (or with cell scalars) is sampled for the fog on an image of this
   * many points along its longest side, on one process and gathered from several alike.
   */
  static constexpr int SampledPoints = 64;

  /**
   * Image pieces gathered from several processes (GatherImage()) keep their own grid up to this
   * many points in all (so that the fog samples what one process holding the whole image
   * samples); larger images are gathered onto `points` along their longest side.
   */
  static constexpr vtkIdType GatheredGridPoints = 4 * 1024 * 1024;

  /**
   * Over several processes that each hold a piece of the same volume (collective: every process
   * calls it for the same volumes in the same order): every piece's array `name` resampled onto
   * one image over the union of the pieces' bounds and combined over the processes, so that each
   * samples the whole volume; its vtkValidPointMask is 1 where some piece holds data. The image
   * has the pieces' own grid when every piece is an image of point scalars with at most
   * GatheredGridPoints points in all (the same samples as on one process); else `points` along
   * its longest side. `piece` may be null or empty. Null when no piece has data. With no
   * controller, or one process, `piece` alone is sampled so (the same samples as its part of a
   * gathered image).
   */
  static vtkSmartPointer<vtkImageData> GatherImage(
    vtkDataSet* piece, const char* name, vtkMultiProcessController* c, int points);

private:
  struct Tables;
  std::unique_ptr<Tables> Kept;

  /** What the rays of one call share: the image's extent, the step and its opacities. */
  struct Rays
  {
    int Extent[6], Dims[3];
    double Step = 0.0;                       // in the image's coordinates: half its finest spacing
    std::vector<double> Corrected;           // per table bin, a step's opacity
    double T0[3], Tx[3][3];                  // the map to the continuous index
    vtkAbstractCellLocator* Drawn = nullptr; // (Accumulate()'s `drawn`)
    std::mutex* Lock = nullptr;
    vtkGenericCell* Cell = nullptr; // (the locator's queries', under Lock)
  };
  /** Brings the tables up to date and fills `r` for `volume`; false when it cannot be sampled. */
  bool Prepare(const Volume& volume, Rays& r);
  /** `work(id, ray, first, last)` for each point's view ray (its steps in the image). */
  template <typename Work>
  void ForRays(vtkPolyData* surface, const Volume& v, const Rays& r, const double eye[3],
    const double dop[3], bool parallel, Work work);

  vtkStylizeVolumeFog(const vtkStylizeVolumeFog&) = delete;
  void operator=(const vtkStylizeVolumeFog&) = delete;
};

#endif
