/**
 * @class   vtkStylizeLineVisibility
 * @brief   Hidden-line removal for polylines on surfaces (vtkStylizeFeatureLines' output):
 *          each line split where it passes behind a surface, against the scene's depth buffer
 *          or by ray casting against the scene's meshes.
 *
 * The lines are sampled every SampleSpacing pixels of the view (the Camera, which is required,
 * the ModelMatrix and the ViewportSize) and each
 * sample is tested:
 * - DEPTH_BUFFER (default): against a rendering's depth (SetDepthImage: the window depth in
 *   [0, 1] of every actor, as vtkRenderWindow::GetZbufferData gives it). A sample is visible
 *   when the farthest depth among the pixels within one pixel of it is at most DepthTolerance
 *   pixel widths in front of it: a contour sits on the edge of its own surface, and the nearest
 *   pixel must not hide it.
 * - RAY_CAST: a ray from the sample toward the viewer against every occluder (AddOccluder),
 *   starting 3 pixel widths from the sample, and for occluding contours (cell FeatureKind 0,
 *   or every line without FeatureKind) at least one mean edge length of the occluders: a
 *   contour's ray grazes its own surface, whose polygons lie up to about half an edge off the
 *   interpolated contour. The independent reference of the tests.
 * Where two neighbouring samples differ, the change is located by bisection to 1/16 of the
 * spacing. The output is the input's lines cut into runs, with the input's point data
 * interpolated and FeatureVisibility (unsigned char, 1 visible, 0 hidden) in point and cell data;
 * VisibleOnly drops the hidden runs.
 *
 * @sa vtkStylizeFeatureLines
 */
#ifndef vtkStylizeLineVisibility_h
#define vtkStylizeLineVisibility_h

#include "vtkStylizeFiltersModule.h" // for export macro
#include "vtkStylizeViewFilter.h"

#include <memory> // for std::unique_ptr

class vtkImageData;
class vtkMatrix4x4;
class vtkPolyData;
class vtkStylizeRayOccluder;

class VTKSTYLIZEFILTERS_EXPORT vtkStylizeLineVisibility : public vtkStylizeViewFilter
{
public:
  static vtkStylizeLineVisibility* New();
  vtkTypeMacro(vtkStylizeLineVisibility, vtkStylizeViewFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** How samples are tested (below). */
  enum Methods
  {
    DEPTH_BUFFER, // 0
    RAY_CAST
  };

  ///@{
  /** How samples are tested: DEPTH_BUFFER or RAY_CAST. Default DEPTH_BUFFER. */
  vtkSetClampMacro(Method, int, DEPTH_BUFFER, RAY_CAST);
  vtkGetMacro(Method, int);
  ///@}

  ///@{
  /**
   * The viewport's size, in pixels (its aspect ratio is the projection's). Range [1, 65536]
   * each, default (300, 300).
   */
  void SetViewportSize(int width, int height);
  void SetViewportSize(const int size[2]) { this->SetViewportSize(size[0], size[1]); }
  vtkGetVector2Macro(ViewportSize, int);
  ///@}

  ///@{
  /**
   * The image the camera projects onto, when the depth image is a part of it or reaches beyond
   * it (a tile of a larger image, a guard band around a viewport): its size in pixels, whose
   * aspect ratio is the projection's, and the depth image's lower-left corner in it, pixels
   * (negative beyond it). ImageSize (0, 0), the default: the depth image is that image. Sizes
   * in [0, 1e7], offsets in [-1e7, 1e7].
   */
  void SetImageSize(double width, double height);
  vtkGetVector2Macro(ImageSize, double);
  void SetImageOffset(double x, double y);
  vtkGetVector2Macro(ImageOffset, double);
  ///@}

  /** What the depth image holds. */
  enum DepthKinds
  {
    WINDOW_DEPTH, ///< window depth in [0, 1], 1 where nothing was drawn
    VIEW_DEPTH    ///< -z in view space, world units, 0 where nothing was drawn (linear depth)
  };

  ///@{
  /** What the depth image holds: WINDOW_DEPTH (default) or VIEW_DEPTH. */
  vtkSetClampMacro(DepthKind, int, WINDOW_DEPTH, VIEW_DEPTH);
  vtkGetMacro(DepthKind, int);
  ///@}

  ///@{
  /**
   * The scene's depth for DEPTH_BUFFER: one float component per pixel, DepthKind values,
   * ViewportSize pixels, row 0 at the bottom.
   */
  virtual void SetDepthImage(vtkImageData* depth);
  vtkGetObjectMacro(DepthImage, vtkImageData);
  ///@}

  ///@{
  /**
   * Surfaces that hide lines for RAY_CAST, each with its model matrix (may be null): an
   * occluder (vtkStylizeRayOccluder) is built over each at every update. RemoveAllOccluders()
   * also forgets the shared occluders.
   */
  void AddOccluder(vtkPolyData* surface, vtkMatrix4x4* matrix);
  void RemoveAllOccluders();
  ///@}

  /**
   * A surface that hides lines for RAY_CAST, built (vtkStylizeRayOccluder: its triangles in
   * world coordinates under a hierarchy). The filter only reads it: one occluder serves the
   * filters of every surface of a scene and their threads, built once rather than once per
   * filter and update.
   */
  void AddSharedOccluder(vtkStylizeRayOccluder* occluder);

  ///@{
  /** Distance between samples, in pixels. Range [0.01, 100], default 0.25. */
  vtkSetClampMacro(SampleSpacing, double, 0.01, 100.0);
  vtkGetMacro(SampleSpacing, double);
  ///@}

  ///@{
  /**
   * DEPTH_BUFFER: how far behind the nearby surface a sample may be and still count as visible,
   * in pixels (widths of a pixel at the sample's distance: a surface seen at a grazing angle
   * changes depth quickly from pixel to pixel). Range [0, 100], default 2.
   */
  vtkSetClampMacro(DepthTolerance, double, 0.0, 100.0);
  vtkGetMacro(DepthTolerance, double);
  ///@}

  ///@{
  /**
   * DEPTH_BUFFER: the least depth tolerance of occluding contours (cell FeatureKind 0, or
   * every line when the input has no FeatureKind), in world units, whatever the pixels' size. A
   * contour interpolated inside a coarse mesh's triangles lies behind the polygons that draw
   * its silhouette by up to about an edge: the mean edge length keeps such contours whole
   * (vtkLineArtPass sets it so, as RAY_CAST starts its rays an edge away). The other kinds lie
   * on the surface the depth buffer shows and keep DepthTolerance. Range [0, 1e30], default 0.
   */
  vtkSetClampMacro(WorldTolerance, double, 0.0, 1.0e30);
  vtkGetMacro(WorldTolerance, double);
  ///@}

  ///@{
  /**
   * DEPTH_BUFFER: hide the parts of boundaries (cell FeatureKind 1) across which the depth
   * buffer shows the surface going on at the same depth on both sides: the seam between two
   * pieces of one surface (the ranks' pieces in ParaView, the blocks of a partitioned dataset),
   * not an edge of the object. Default on.
   */
  vtkSetMacro(HideSeams, bool);
  vtkGetMacro(HideSeams, bool);
  vtkBooleanMacro(HideSeams, bool);
  ///@}

  ///@{
  /** Keep only the visible runs. Default off. */
  vtkSetMacro(VisibleOnly, bool);
  vtkGetMacro(VisibleOnly, bool);
  vtkBooleanMacro(VisibleOnly, bool);
  ///@}

  /** Includes the depth image's modification time (and the camera's and the matrix's). */
  vtkMTimeType GetMTime() override;

protected:
  vtkStylizeLineVisibility();
  ~vtkStylizeLineVisibility() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Method = DEPTH_BUFFER;
  int ViewportSize[2] = { 300, 300 };
  vtkImageData* DepthImage = nullptr;
  int DepthKind = WINDOW_DEPTH;
  double ImageSize[2] = { 0.0, 0.0 };
  double ImageOffset[2] = { 0.0, 0.0 };
  double SampleSpacing = 0.25;
  double DepthTolerance = 2.0;
  double WorldTolerance = 0.0;
  bool HideSeams = true;
  bool VisibleOnly = false;

private:
  vtkStylizeLineVisibility(const vtkStylizeLineVisibility&) = delete;
  void operator=(const vtkStylizeLineVisibility&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
