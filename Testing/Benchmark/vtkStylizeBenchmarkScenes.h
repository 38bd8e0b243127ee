/**
 * vtkStylizeBenchmark: what is rendered. A scene's mesh (spheres, the scanned bunny, the wavelet
 * isosurface) moved into the unit sphere's box, its camera framing, the deterministic lights
 * every configuration gets, and the render passes of each configuration by name.
 */
#ifndef vtkStylizeBenchmarkScenes_h
#define vtkStylizeBenchmarkScenes_h

#include "vtkStylizeBenchmarkOptions.h"

#include "vtkRenderPass.h"
#include "vtkSmartPointer.h"

#include <functional>
#include <string>
#include <vector>

class vtkActor;
class vtkImageData;
class vtkPolyData;
class vtkRenderer;
class vtkVolume;

namespace vtkstylizebenchmark
{
/** Camera framing of a scene: VTK's ResetCamera() view of the mesh. */
struct Framing
{
  double Center[3];
  double Diagonal;
  double CoveredPixels; // approximate number of pixels the sphere covers
};

/**
 * The scene's mesh with point normals, moved and scaled into the unit sphere's box (centred at
 * the origin, largest half-extent 1) so that every scene is framed alike. nullptr (and a line on
 * stderr) when the scanned mesh cannot be read.
 */
vtkSmartPointer<vtkPolyData> MakeSceneMesh(const SceneSpec& scene, const Options& opt);

/**
 * A volume scene's image (Options::Volume), or nullptr and a line on stderr. Its "mesh" for
 * MakeSceneMesh() is the eight corners of its bounds (no cells): the framing, lights and
 * camera of every scene come from a mesh.
 */
vtkSmartPointer<vtkImageData> ReadSceneVolume(const Options& opt);

/**
 * The volume scenes' prop: VTK's GPU ray caster (vtkGPUVolumeRayCastMapper), linear
 * interpolation, shaded, with the transfer functions of VTK's MedicalDemo4 example (skin at a
 * sixth of full opacity, bone nearly opaque: realdata.volumes' headsq). Its mapper's input is
 * set per scene.
 */
vtkSmartPointer<vtkVolume> MakeVolumeProp();

Framing FrameMesh(vtkPolyData* mesh, const Options& opt);

/**
 * Fills the renderer with @p count lights (vtkStylizeSceneLights): one light is VTK's default
 * headlight; more are scene lights spread over a sphere of radius 4 R around the object
 * (golden-angle spiral), in turn directional, positional point (cone 180 degrees) and
 * positional spot (cone 30 degrees, exponent 2) lights, so that each kind's shader path is
 * timed, all aimed at the centre, white, intensity 1.5 / count so the summed lighting stays in
 * range.
 */
void SetLights(vtkRenderer* ren, int count, const double center[3], double radius);

/** The passes of one configuration; they live as long as the render window that uses them. */
struct ConfigPasses
{
  vtkSmartPointer<vtkRenderPass> Root; // set on the renderer; nullptr for "plain"
  std::vector<vtkSmartPointer<vtkRenderPass>> Keep;
  std::string Description;
  /** Props beside the mesh's actor (VTK's line tools), added once with that actor; may be null. */
  std::function<void(vtkRenderer*, vtkActor*)> AddProps;
  /** Gives those props each scene's mesh; may be null. */
  std::function<void(vtkPolyData*)> SetMesh;
};

/**
 * The passes of configuration @p name (one of AllConfigs()); @p diagonal scales SSAO's radius
 * and bias. The suffixes -nocull, -translucent and -interactive modify the configuration before
 * them; the window and actor settings they also need are the runner's.
 */
ConfigPasses MakeConfig(const std::string& name, double diagonal);

/** Whether @p s ends with @p tail (and is longer than it). */
bool EndsWith(const std::string& s, const std::string& tail);
}

#endif
