/**
 * @class   vtkStylizeImageMetrics
 * @brief   Strict image and buffer measurements for tests and studies.
 *
 * VTK 9.1's vtkImageDifference ignores per-channel differences below about 40% and tolerates
 * shifts, so tone changes pass it unseen. These functions compare per pixel and per channel:
 * - MaximumDifference(): largest absolute difference of any component (scalar units);
 * - CountDifferences(): number of pixels with a component differing by more than a tolerance;
 * - PSNR(): peak signal-to-noise ratio in dB for a given peak value (inf for equal images);
 * - CountNonFinite(): number of NaN or infinite values in an array.
 * Images must have the same dimensions and number of components; otherwise the functions return
 * -1 (differences) or 0 (PSNR).
 */

#ifndef vtkStylizeImageMetrics_h
#define vtkStylizeImageMetrics_h

#include "vtkObject.h"
#include "vtkStylizeTestingSupportModule.h" // for export macro

class vtkDataArray;
class vtkImageData;

class VTKSTYLIZETESTINGSUPPORT_EXPORT vtkStylizeImageMetrics : public vtkObject
{
public:
  static vtkStylizeImageMetrics* New();
  vtkTypeMacro(vtkStylizeImageMetrics, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Largest absolute difference of any component of the point scalars, or -1. */
  static double MaximumDifference(vtkImageData* a, vtkImageData* b);

  /** Number of pixels where some component differs by more than tolerance, or -1. */
  static vtkIdType CountDifferences(vtkImageData* a, vtkImageData* b, double tolerance);

  /** PSNR in dB over all components for the given peak value (255 for 8-bit images). */
  static double PSNR(vtkImageData* a, vtkImageData* b, double peak);

  /**
   * Mean structural similarity (SSIM, Wang et al. 2004) of the luminance (mean of the first three
   * components, or the only one) of two images of the same size, for the given peak value: an
   * 11 x 11 Gaussian window (sigma 1.5), C1 = (0.01 peak)^2, C2 = (0.03 peak)^2, averaged over
   * the window positions inside the image (the whole image when it is smaller than the window).
   * 1 for identical images; -2 when the sizes differ or an image is missing.
   */
  static double SSIM(vtkImageData* a, vtkImageData* b, double peak);

  /** Number of NaN or infinite values among all components of the array. */
  static vtkIdType CountNonFinite(vtkDataArray* array);

  /**
   * @name Real-data measures
   * The surface is given by a mask image: an 8-bit RGB(A) image of the same view rendered on a
   * key background colour (0-255 per component); its pixels that differ from the key by more
   * than 1 in some component are the surface. Luminance is Rec. 709 of the first three
   * components (or the only one), in [0, 1] for 8-bit images. Every measure returns -2 when an
   * image is missing, the sizes differ or the mask is empty.
   */
  ///@{
  /**
   * Tone agreement of a stylized image with a reference rendering: the Pearson correlation,
   * over the surface pixels, of the stylized luminance blurred by a Gaussian of sigma pixels
   * over the surface alone (a halftone seen from afar; normalized convolution, so the
   * background does not bleed into silhouettes) with the reference luminance. 1 = the tones
   * agree.
   */
  static double ToneCorrelation(vtkImageData* styled, vtkImageData* reference, vtkImageData* mask,
    const double key[3], double sigma);

  /** Share of the surface pixels whose luminance is at least threshold (in [0, 1]): paper. */
  static double PaperShare(
    vtkImageData* styled, vtkImageData* mask, const double key[3], double threshold);

  /**
   * Tone by band of the light: among the surface pixels whose reference luminance lies in the
   * quantile band [lo, hi] (0: the darkest surface pixel, 1: the brightest; ties at the band's
   * edges included), the share whose stylized luminance is at least level (dark = false: paper)
   * or below it (dark = true: ink). BandShare(s, r, m, key, 0.75, 1, 0.9, false) is the paper
   * in the brightest quarter of the lit surface.
   */
  static double BandShare(vtkImageData* styled, vtkImageData* reference, vtkImageData* mask,
    const double key[3], double lo, double hi, double level, bool dark);

  /**
   * Local agreement of a direction field drawn as the sketch pass's directions layer (the
   * screen angle theta, modulo 180 degrees, as the hue 0.5 + 0.5 cos(2 theta - k 120 degrees),
   * k = 0, 1, 2): the mean over the surface pixels, whose window x window neighbourhood is all
   * surface, of |mean of exp(2 i theta)| over that window. 1 = parallel strokes, about 0 =
   * random directions.
   */
  static double DirectionAgreement(
    vtkImageData* directions, vtkImageData* mask, const double key[3], int window);

  /**
   * Framing: the larger of the surface's bounding box width over the image width and its
   * height over the image height (1 = the object touches two opposite sides).
   */
  static double FramingExtent(vtkImageData* mask, const double key[3]);
  ///@}

protected:
  vtkStylizeImageMetrics() = default;
  ~vtkStylizeImageMetrics() override = default;

private:
  vtkStylizeImageMetrics(const vtkStylizeImageMetrics&) = delete;
  void operator=(const vtkStylizeImageMetrics&) = delete;
};

#endif
