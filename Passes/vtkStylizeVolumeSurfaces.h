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
 * With a haze opacity above 0, a volume whose opacity function holds values between a tenth of
 * the threshold and the threshold (a faint material around the solid one: skin over a CT's bone)
 * also gets a translucent surface of that opacity where its opacity first reaches a tenth of the
 * threshold: a translucent actor, which the style draws in its translucent layers.
 *
 * Volumes the class cannot draw so are left to VTK: data that is not one vtkDataSet (a
 * composite volume), dependent components (RGBA volumes), no scalars.
 */
#ifndef vtkStylizeVolumeSurfaces_h
#define vtkStylizeVolumeSurfaces_h

#include "vtkStylizeVolumeFog.h" // for vtkStylizeVolumeFog::Volume
#include "vtkType.h"             // for vtkMTimeType

#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <array>  // for std::array
#include <map>    // for std::map
#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

class vtkAbstractCellLocator;
class vtkAbstractVolumeMapper;
class vtkActor;
class vtkCamera;
class vtkDataSet;
class vtkImageData;
class vtkInformationIntegerKey;
class vtkMultiProcessController;
class vtkPiecewiseFunction;
class vtkProp;
class vtkRenderState;
class vtkRenderer;
class vtkScalarsToColors;
class vtkVolume;
class vtkVolumeProperty;
class vtkWindow;

class vtkStylizeVolumeSurfaces
{
public:
  vtkStylizeVolumeSurfaces();
  ~vtkStylizeVolumeSurfaces();

  /**
   * The state to render: `s` itself when no volume is drawn as a surface, otherwise a state
   * whose props have the volumes replaced (valid until End()). `threshold`: the opacity
   * threshold of volumes without their own (VOLUME_OPACITY_THRESHOLD key); `haze`, the haze's
   * opacity (0: none); `controller`, over several processes that each draw their pieces of the
   * same volumes (a compositor's ranks): the processes' image extents are combined so that each
   * piece's surface is closed at the whole image's faces only, and the points of other meshes'
   * outer faces are exchanged so that a piece is not closed where another piece goes on (all
   * processes call Begin()). `outline` (a line width in pixels, 0: none): with the fog, the
   * outline of where the volume looks solid (the whole view ray's opacity, as VTK accumulates
   * it, reaches one half) drawn as black lines on the haze's nearest layer, the haze's own
   * outline then left out (FOG_SHELL). `solidDepth`: with the fog, the solid surface carries
   * where its view rays look solid (vtkStylizeVolumeSolidCut::LooksSolidAt), the depth the
   * G-buffer stores for it, so that opaque geometry inside its material in front of that shows
   * through as in VTK's picture: for a G-buffer that draws the props itself, or that is rebuilt
   * from an image whose channel source draws them (ParaView's ranks; the source hands over the
   * surface's own linear depth: docs/gbuffer.md).
   */
  const vtkRenderState* Begin(const vtkRenderState* s, double threshold, double haze = 0.0,
    bool fog = false, vtkMultiProcessController* controller = nullptr, double outline = 0.0,
    bool solidDepth = false);

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

  /**
   * Set (1) on a haze actor whose outline is drawn as the fog's (Begin()'s `outline`): the line
   * art leaves out its translucent outline.
   */
  static vtkInformationIntegerKey* FOG_SHELL();

  /** Whether `volume` is drawn as a surface (its data, components and key allow it). */
  static bool Drawable(vtkVolume* volume);

  /**
   * Whether the opacity function `f` holds a haze below `threshold`: values at least a tenth of
   * it and below it, anywhere in its range (sampled at 1024 points and at its nodes).
   */
  static bool HasHaze(vtkPiecewiseFunction* f, double threshold);

private:
  struct Proxy;
  /**
   * Colours the haze of `p` as VTK's ray casting shows it (`fog`: its points' colour and opacity
   * accumulated along the view rays from `ren`'s camera to the solid surface, lit as the volume's
   * `property` shades it, recomputed only when the view, the haze, the place, the light or the
   * transfer functions change), or leaves it at the `haze` opacity (fog false, or data that is
   * not an image with point scalars).
   */
  /** The mapper's input, brought up to date. */
  static vtkDataSet* UpdatedInput(vtkAbstractVolumeMapper* mapper);
  /**
   * Per vtkVolume among `props`, in order, the extent of the whole image it draws a piece of:
   * over several processes, the union of the processes' image extents (each process holds the
   * same volumes, each drawing its piece: ParaView's ranks); otherwise, or for data that is not
   * an image, or when the processes do not hold the same number of volumes, an empty extent (the
   * surface filter then takes the pipeline's or the image's own). Collective.
   */
  static std::vector<std::array<int, 6>> WholeExtents(
    const std::vector<vtkProp*>& props, vtkMultiProcessController* c);
  /**
   * With the fog: `p`'s solid surface cut to where it looks solid from the eye (`eye`, or along
   * `dop`, parallel; vtkStylizeVolumeSolidCut), and the locator the fog asks where the solid is
   * drawn: on the cut surface, or over several processes (`gathered`: the whole volume, each
   * process drawing its piece) on the whole volume's solid surface cut by the same rule. Null
   * when it cannot be cut (the whole surface drawn).
   */
  static vtkAbstractCellLocator* CutSolid(Proxy& p, vtkDataSet* data, vtkImageData* gathered,
    const vtkStylizeVolumeFog::Volume& volume, double solid, const double eye[3],
    const double dop[3], bool parallel);
  static void ColourHaze(Proxy& p, vtkDataSet* data, vtkVolumeProperty* property,
    vtkScalarsToColors* colors, double solid, double haze, bool fog, vtkRenderer* ren,
    double outline, vtkImageData* gathered);
  Proxy* Update(vtkVolume* volume, double threshold, double haze, bool fog, double outline,
    vtkImageData* gathered, vtkRenderer* ren, const int whole[6],
    const std::vector<vtkTypeUInt64>& shared);
  /**
   * Per vtkVolume among Props, in order: over several processes, the keys of the points on the
   * other processes' pieces' outer faces (vtkStylizeVolumeSurface::SetSharedPoints()) for data
   * that is not an image; otherwise none. Collective.
   */
  std::vector<std::vector<vtkTypeUInt64>> SharedPoints(vtkMultiProcessController* c);

  /** A piece's outer point keys, kept while its data is unchanged. */
  struct OuterKeys
  {
    vtkMTimeType Time = 0;
    std::vector<vtkTypeUInt64> Keys;
  };
  std::map<vtkDataSet*, OuterKeys> OuterKeyCache;
  std::vector<std::vector<vtkTypeUInt64>> LastShared; // the last exchange's result

  /**
   * Per vtkVolume among Props, in order, over several processes: the whole volume the fog
   * samples (vtkStylizeVolumeFog::GatherImage(), again only when some piece changed), or null.
   * Collective.
   */
  std::vector<vtkImageData*> FogImages(vtkMultiProcessController* c);
  struct Gathered
  {
    vtkSmartPointer<vtkImageData> Image;
    vtkMTimeType Time = 0;
    std::string Name; // the array drawn
  };
  std::map<vtkVolume*, Gathered> GatheredImages;

  std::map<vtkVolume*, std::unique_ptr<Proxy>> Proxies;
  std::vector<vtkProp*> Props;
  std::vector<vtkActor*> Active;
  std::vector<vtkActor*> Hazes; // (Begin()'s haze actors, then in Active)
  std::unique_ptr<vtkRenderState> State;
  vtkRenderer* Renderer = nullptr;
  int Count = 0;
  bool SolidDepth = false; // (Begin()'s solidDepth)

  vtkStylizeVolumeSurfaces(const vtkStylizeVolumeSurfaces&) = delete;
  void operator=(const vtkStylizeVolumeSurfaces&) = delete;
};

#endif
