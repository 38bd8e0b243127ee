/**
 * @file   vtkStylizeVolumeFog.h
 * @brief  A volume's fog as VTK's ray casting accumulates it, per point of a surface (private to
 *         the module: vtkStylizeVolumeSurfaces' HAZE_FOG).
 */
#ifndef vtkStylizeVolumeFog_h
#define vtkStylizeVolumeFog_h

class vtkDataArray;
class vtkImageData;
class vtkPiecewiseFunction;
class vtkPolyData;
class vtkScalarsToColors;
class vtkUnsignedCharArray;

/**
 * Per point of `haze` (a surface where the opacity reaches `level`, in the image's coordinates),
 * the colour and opacity VTK's ray casting accumulates along the ray from the eye (`eye`, or the
 * direction `dop` for a parallel projection, both in the image's coordinates) through `image`'s
 * point `scalars`: for the haze's nearest layer on the ray, from where the ray enters the image;
 * then up to the haze's next crossing, the solid surface (an opacity of `solid`) or the image's
 * end, so that the layers composited front to back add up to the whole ray. Each sample's opacity
 * is corrected for the step as VTK's (1 - (1 - a)^(step / unit)); the result's opacity is times
 * `scale`. `mask`: where a resampled image lies in its data (0: nothing there), or null. Written
 * as `out` (RGBA bytes). False when the image cannot be sampled so.
 */
bool vtkStylizeAccumulateHaze(vtkPolyData* haze, vtkImageData* image, vtkDataArray* scalars,
  vtkPiecewiseFunction* opacity, vtkScalarsToColors* colors, double unit, double level,
  double solid, double scale, const double eye[3], const double dop[3], bool parallel,
  vtkDataArray* mask, vtkUnsignedCharArray* out);

#endif
