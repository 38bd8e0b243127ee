/**
 * @class   vtkStylizeVolumeSurface
 * @brief   The surface a volume shows: where its scalar opacity reaches a threshold.
 *
 * A volume rendered by ray casting looks solid where its samples become opaque. This filter
 * finds that boundary as triangles: the isosurfaces of the input's scalar at every value where
 * the scalar opacity function (the volume property's vtkPiecewiseFunction) crosses
 * OpacityThreshold, so that the region of samples at least that opaque is closed by them. Where
 * that region reaches the edge of an image's whole extent, the image is padded by one sample of
 * a transparent value so that the region is closed there too (a CT's outer faces, a field's
 * box), those faces carrying the data's value there (a CT cut by its extent shows the cut's
 * data, as the ray caster does); where it reaches the outer faces of any other mesh (an
 * unstructured grid's), those faces, cut along the isovalues, close it, with the data's scalar on
 * them (but not the faces between processes' pieces: SharedPoints). With IsoValues set (the
 * volume's isosurface blend mode), those values are used instead.
 *
 * The output's point normals are the scalar's gradient, pointing out of the opaque region, and
 * its point scalars are the isovalue (the data on the faces that close it; the input array's
 * name), for colouring with the volume's colour transfer function. The styles of VTK Stylize
 * draw a volume as this surface
 * (vtkStylizeStylePass::StylizeVolumes): comic zones, pixel art, pencil strokes and feature lines
 * then apply to it like to any surface.
 *
 * Input: vtkImageData (vtkFlyingEdges3D, threaded) or any other vtkDataSet (vtkContourFilter),
 * with the scalar array chosen by SetInputArrayToProcess(0, ...) (default: the point scalars,
 * else the cell scalars, moved to the points), component Component. What the ray caster does and
 * this filter does not: the gradient opacity, cropping, and blend modes other than composite and
 * isosurface (maximum intensity and the others show no surface: the opacity's crossings are
 * used). Reports progress (ProgressEvent) from its contouring.
 *
 * @sa vtkFlyingEdges3D vtkContourFilter vtkVolumeProperty vtkStylizeStylePass
 */
#ifndef vtkStylizeVolumeSurface_h
#define vtkStylizeVolumeSurface_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"         // for vtkSmartPointer
#include "vtkStylizeFiltersModule.h" // for export macro

#include <vector> // for std::vector

class vtkDataArray;
class vtkDataSet;
class vtkImageData;
class vtkPiecewiseFunction;

class VTKSTYLIZEFILTERS_EXPORT vtkStylizeVolumeSurface : public vtkPolyDataAlgorithm
{
public:
  static vtkStylizeVolumeSurface* New();
  vtkTypeMacro(vtkStylizeVolumeSurface, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The scalar opacity function (opacity against the scalar value, as
   * vtkVolumeProperty::GetScalarOpacity()). Required unless IsoValues are set.
   */
  virtual void SetScalarOpacity(vtkPiecewiseFunction* function);
  vtkGetObjectMacro(ScalarOpacity, vtkPiecewiseFunction);
  ///@}

  ///@{
  /**
   * The opacity from which a sample counts as solid: the scalar opacity function's value (the
   * opacity of one ScalarOpacityUnitDistance of the material), dimensionless. Range [0.001, 1],
   * default 0.1.
   */
  vtkSetClampMacro(OpacityThreshold, double, 0.001, 1.0);
  vtkGetMacro(OpacityThreshold, double);
  ///@}

  ///@{
  /**
   * The extent of the whole image, in samples, when the input is one piece of it (a process's
   * piece in parallel, given as data without the pipeline's WHOLE_EXTENT): the opaque region is
   * closed only at this extent's faces, not at the piece's own, where the next piece goes on.
   * An empty extent (the default, min above max) takes the pipeline's WHOLE_EXTENT, or the
   * image's own extent.
   */
  vtkSetVector6Macro(WholeExtent, int);
  vtkGetVector6Macro(WholeExtent, int);
  ///@}

  ///@{
  /** The component of the scalar array (as the volume's first independent component). Range
   * [0, 3], default 0. */
  vtkSetClampMacro(Component, int, 0, 3);
  vtkGetMacro(Component, int);
  ///@}

  ///@{
  /**
   * Isovalues that replace the opacity's crossings (a volume drawn with the isosurface blend
   * mode: vtkVolumeProperty::GetIsoSurfaceValues()); non-finite values are ignored. Empty (the
   * default): the crossings of ScalarOpacity.
   */
  void SetIsoValues(const std::vector<double>& values);
  const std::vector<double>& GetIsoValues() const { return this->IsoValues; }
  ///@}

#if !defined(__VTK_WRAP__)
  ///@{
  /**
   * For a mesh that is not an image, split over processes (ParaView's ranks): the keys
   * (OuterPointKeys()) of the points on the other pieces' outer faces. An outer face of this
   * piece whose points all lie among them is a face between pieces, not the mesh's boundary, so
   * the opaque region is not closed there. Empty (the default): every outer face is the mesh's.
   */
  void SetSharedPoints(const std::vector<vtkTypeUInt64>& keys);
  const std::vector<vtkTypeUInt64>& GetSharedPoints() const
  {
    return this->SharedPoints;
  }
  ///@}

  /**
   * The keys of the points of `data`'s outer faces (from the exact coordinates: a point copied
   * to another process's piece has the same key), sorted, without repeats.
   */
  static std::vector<vtkTypeUInt64> OuterPointKeys(vtkDataSet* data);
#endif

  /**
   * The scalar values at which `function` crosses `threshold` within [low, high], sorted, each
   * to within 1e-9 of the range; `rising` receives whether the opacity rises through each (the
   * opaque side is the higher values). Values outside the function's nodes take its end values
   * (as VTK's volume mappers clamp them).
   */
  static std::vector<double> Crossings(vtkPiecewiseFunction* function, double threshold, double low,
    double high, std::vector<bool>* rising = nullptr);

  vtkMTimeType GetMTime() override;

protected:
  vtkStylizeVolumeSurface();
  ~vtkStylizeVolumeSurface() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /** The image padded where the opaque region meets its whole extent's faces, or null. */
  vtkSmartPointer<vtkImageData> PadToClose(vtkImageData* image, vtkDataArray* values,
    const double range[2], vtkInformationVector** inputVector);

  /** The isosurfaces of `data`'s point scalars, with normals. */
  vtkSmartPointer<vtkPolyData> Contour(
    vtkDataSet* data, bool image, const std::vector<double>& isovalues);

  vtkPiecewiseFunction* ScalarOpacity = nullptr;
  double OpacityThreshold = 0.1;
  int Component = 0;
  int WholeExtent[6] = { 0, -1, 0, -1, 0, -1 };
  std::vector<double> IsoValues;
  std::vector<vtkTypeUInt64> SharedPoints;

private:
  vtkStylizeVolumeSurface(const vtkStylizeVolumeSurface&) = delete;
  void operator=(const vtkStylizeVolumeSurface&) = delete;
};

#endif
