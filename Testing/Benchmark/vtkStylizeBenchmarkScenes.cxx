// vtkStylizeBenchmark: the scenes' meshes, framing and lights, and each configuration's passes.

#include "vtkStylizeBenchmarkScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCameraPass.h"
#include "vtkColorTransferFunction.h"
#include "vtkComicPass.h"
#include "vtkContourFilter.h"
#include "vtkEDLShading.h"
#include "vtkFeatureEdges.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkLineArtPass.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPLYReader.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPixelArtPass.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkPolyDataSilhouette.h"
#include "vtkProperty.h"
#include "vtkRTAnalyticSource.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkSSAOPass.h"
#include "vtkSketchPass.h"
#include "vtkSobelGradientMagnitudePass.h"
#include "vtkSphereSource.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeSceneLights.h"
#include "vtkStylizeStylePass.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLImageDataReader.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace vtkstylizebenchmark
{
//------------------------------------------------------------------------------------------------
// Scenes

namespace
{
/**
 * Points `reader` at the real-data file `path` (`what` it holds, the `option` that names another);
 * false, with a line on stderr, when the reader cannot read it.
 */
template <class Reader>
bool OpenDataFile(Reader* reader, const std::string& path, const char* what, const char* option)
{
  if (!reader->CanReadFile(path.c_str()))
  {
    std::cerr << "Cannot read " << what << " " << path << " (run the test realdata.setup, or give "
              << option << " FILE)\n";
    return false;
  }
  reader->SetFileName(path.c_str());
  return true;
}
}

vtkSmartPointer<vtkImageData> ReadSceneVolume(const Options& opt)
{
  vtkNew<vtkXMLImageDataReader> reader;
  if (!OpenDataFile(reader.Get(), opt.Volume, "the volume", "--volume"))
  {
    return nullptr;
  }
  reader->Update();
  return reader->GetOutput();
}

vtkSmartPointer<vtkVolume> MakeVolumeProp()
{
  vtkNew<vtkColorTransferFunction> colors;
  colors->AddRGBPoint(0, 0.0, 0.0, 0.0);
  colors->AddRGBPoint(500, 1.0, 0.5, 0.3);
  colors->AddRGBPoint(1000, 1.0, 0.5, 0.3);
  colors->AddRGBPoint(1150, 1.0, 1.0, 0.9);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(500, 0.15);
  opacity->AddPoint(1000, 0.15);
  opacity->AddPoint(1150, 0.85);
  vtkNew<vtkVolumeProperty> property;
  property->SetInterpolationTypeToLinear();
  property->ShadeOn();
  property->SetColor(colors);
  property->SetScalarOpacity(opacity);
  vtkNew<vtkGPUVolumeRayCastMapper> mapper;
  auto volume = vtkSmartPointer<vtkVolume>::New();
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  return volume;
}

vtkSmartPointer<vtkPolyData> MakeSceneMesh(const SceneSpec& scene, const Options& opt)
{
  if (scene.Volume)
  {
    vtkSmartPointer<vtkImageData> image = ReadSceneVolume(opt);
    if (!image)
    {
      return nullptr;
    }
    double b[6];
    image->GetBounds(b);
    vtkNew<vtkPoints> corners;
    for (int i = 0; i < 8; ++i)
    {
      corners->InsertNextPoint(b[i & 1], b[2 + ((i >> 1) & 1)], b[4 + ((i >> 2) & 1)]);
    }
    auto box = vtkSmartPointer<vtkPolyData>::New();
    box->SetPoints(corners);
    return box;
  }
  vtkSmartPointer<vtkPolyData> raw;
  if (scene.Theta > 0)
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(scene.Theta);
    sphere->SetPhiResolution(scene.Phi);
    sphere->SetRadius(1.0);
    sphere->Update();
    return sphere->GetOutput(); // already in place, with normals
  }
  if (scene.Name == "bunny")
  {
    vtkNew<vtkPLYReader> reader;
    if (!OpenDataFile(reader.Get(), opt.Bunny, "the scanned mesh", "--bunny"))
    {
      return nullptr;
    }
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputConnection(reader->GetOutputPort());
    normals->SplittingOff();
    normals->ConsistencyOn();
    normals->Update();
    raw = normals->GetOutput();
  }
  else
  {
    vtkNew<vtkRTAnalyticSource> wavelet;
    wavelet->SetWholeExtent(-120, 120, -120, 120, -120, 120);
    vtkNew<vtkContourFilter> contour;
    contour->SetInputConnection(wavelet->GetOutputPort());
    contour->SetValue(0, 160.0);
    contour->ComputeNormalsOn();
    contour->ComputeScalarsOff();
    contour->Update();
    raw = contour->GetOutput();
  }
  double b[6];
  raw->GetBounds(b);
  const double half = 0.5 * std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] });
  vtkNew<vtkTransform> t;
  t->Scale(1.0 / half, 1.0 / half, 1.0 / half);
  t->Translate(-0.5 * (b[0] + b[1]), -0.5 * (b[2] + b[3]), -0.5 * (b[4] + b[5]));
  vtkNew<vtkTransformPolyDataFilter> place;
  place->SetInputData(raw);
  place->SetTransform(t);
  place->Update();
  return place->GetOutput();
}

Framing FrameMesh(vtkPolyData* mesh, const Options& opt)
{
  Framing f;
  double b[6];
  mesh->GetBounds(b);
  for (int i = 0; i < 3; ++i)
  {
    f.Center[i] = 0.5 * (b[2 * i] + b[2 * i + 1]);
  }
  f.Diagonal = std::sqrt(
    (b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
  vtkNew<vtkRenderer> ren;
  ren->ResetCamera(b);
  vtkCamera* cam = ren->GetActiveCamera();
  const double radius = 0.5 * (b[1] - b[0]);
  const double angular = std::asin(std::min(1.0, radius / cam->GetDistance()));
  const double halfHeight = std::tan(vtkMath::RadiansFromDegrees(0.5 * cam->GetViewAngle()));
  const double pixelRadius = 0.5 * opt.Height * std::tan(angular) / halfHeight;
  f.CoveredPixels = vtkMath::Pi() * pixelRadius * pixelRadius;
  return f;
}

//------------------------------------------------------------------------------------------------
// Lights: the same deterministic set for every configuration.

void SetLights(vtkRenderer* ren, int count, const double center[3], double radius)
{
  vtkStylizeSceneLights::AddLights(
    ren, count, center, 4.0 * radius, 1.5, vtkStylizeSceneLights::DIRECTIONAL_POINT_SPOT, 180.0);
}

//------------------------------------------------------------------------------------------------
// Configurations

bool EndsWith(const std::string& s, const std::string& tail)
{
  return s.size() > tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

namespace
{
vtkSmartPointer<vtkStylizeLightingPass> Lighting(const std::string& model)
{
  auto pass = vtkSmartPointer<vtkStylizeLightingPass>::New();
  pass->SetModel(vtkStylizeLightingPass::GetModelFromName(model.c_str()));
  return pass;
}

/** VTK's own screen-space passes (sobel, ssao, edl), each over a vtkRenderStepsPass. */
ConfigPasses MakeVtkConfig(const std::string& name, double diagonal)
{
  ConfigPasses c;
  auto steps = vtkSmartPointer<vtkRenderStepsPass>::New();
  c.Keep = { steps };
  if (name == "sobel")
  {
    auto sobel = vtkSmartPointer<vtkSobelGradientMagnitudePass>::New();
    sobel->SetDelegatePass(steps);
    c.Root = sobel;
    c.Description = "vtkSobelGradientMagnitudePass, delegate vtkRenderStepsPass";
  }
  else if (name == "ssao")
  {
    auto ssao = vtkSmartPointer<vtkSSAOPass>::New();
    ssao->SetDelegatePass(steps);
    ssao->SetRadius(0.1 * diagonal);
    ssao->SetBias(0.001 * diagonal);
    std::ostringstream d;
    d << "vtkSSAOPass, delegate vtkRenderStepsPass, radius 0.1 x diagonal, bias 0.001 x "
         "diagonal, kernel "
      << ssao->GetKernelSize() << ", blur " << (ssao->GetBlur() ? "on" : "off");
    c.Root = ssao;
    c.Description = d.str();
  }
  else
  {
    auto edl = vtkSmartPointer<vtkEDLShading>::New();
    edl->SetDelegatePass(steps);
    c.Root = edl;
    c.Description = "vtkEDLShading, delegate vtkRenderStepsPass";
  }
  return c;
}

/**
 * gbuf-MODEL (channels NORMAL|POSITION), gbuf-standard-color (colour and depth only) and
 * gbuf-comic-lin: what the comic pass renders before its screen-space stage, the Comic lighting
 * into a G-buffer with the comic pass's default channels, composited.
 */
ConfigPasses MakeGBufferConfig(const std::string& name)
{
  ConfigPasses c;
  auto gbuf = vtkSmartPointer<vtkStylizeGBufferPass>::New();
  c.Root = gbuf;
  if (name == "gbuf-comic-lin")
  {
    auto pass = Lighting("comic");
    gbuf->SetLightingPass(pass);
    gbuf->SetChannels(vtkStylizeGBufferPass::NORMAL | vtkStylizeGBufferPass::LINEAR_DEPTH);
    c.Keep = { pass };
    c.Description = "vtkStylizeGBufferPass with vtkStylizeLightingPass (comic), channels "
                    "NORMAL|LINEAR_DEPTH (the comic pass's G-buffer, without its screen stage)";
    return c;
  }
  const bool colorOnly = name == "gbuf-standard-color";
  const std::string model = colorOnly ? "standard" : name.substr(5);
  auto pass = Lighting(model);
  gbuf->SetLightingPass(pass);
  gbuf->SetChannels(
    colorOnly ? 0 : (vtkStylizeGBufferPass::NORMAL | vtkStylizeGBufferPass::POSITION));
  c.Keep = { pass };
  c.Description = "vtkStylizeGBufferPass with vtkStylizeLightingPass (" + model + "), " +
    (colorOnly ? "colour and depth only" : "channels NORMAL|POSITION");
  return c;
}

ConfigPasses MakeComicConfig(const std::string& name)
{
  ConfigPasses c;
  auto comic = vtkSmartPointer<vtkComicPass>::New();
  if (name == "comic-geometric")
  {
    comic->SetEdgeWeights(1, 1, 0);
  }
  c.Root = comic;
  c.Description = name == "comic"
    ? "vtkComicPass, defaults (depth and normal edges, dots, hatching, screen anchor)"
    : "vtkComicPass, depth and normal edges (the defaults' edges since issue 14), dots, "
      "hatching";
  return c;
}

/**
 * The image path (ParaView's, after IceT): the style runs over its delegate's colour and
 * depth, lit by the style's own lighting pass (default delegate), normals reconstructed.
 */
ConfigPasses MakeImageConfig(const std::string& name)
{
  ConfigPasses c;
  vtkSmartPointer<vtkStylizeStylePass> style;
  if (name == "comic-image")
  {
    style = vtkSmartPointer<vtkComicPass>::New();
  }
  else if (name == "pixel-image")
  {
    style = vtkSmartPointer<vtkPixelArtPass>::New();
  }
  else
  {
    style = vtkSmartPointer<vtkSketchPass>::New();
  }
  auto camera = vtkSmartPointer<vtkCameraPass>::New();
  camera->SetDelegatePass(style->GetLightingPass());
  style->SetDelegatePass(camera);
  c.Root = style;
  c.Keep = { camera };
  c.Description = std::string(style->GetClassName()) +
    " over its delegate's image (camera pass -> its lighting pass), defaults: the path ParaView "
    "takes after compositing";
  return c;
}

/**
 * pixel-MODE-SIZE: vtkPixelArtPass with its defaults (Canny and depth edges, 4 levels per
 * channel, grid-anchored dither) in the given mode at the given art pixel size.
 */
ConfigPasses MakePixelConfig(const std::string& name)
{
  ConfigPasses c;
  const auto dash = name.rfind('-');
  const std::string mode = name.substr(6, dash - 6);
  const int size = std::atoi(name.c_str() + dash + 1);
  auto pixel = vtkSmartPointer<vtkPixelArtPass>::New();
  pixel->SetMode(mode == "fast" ? vtkPixelArtPass::FAST : vtkPixelArtPass::FAITHFUL);
  pixel->SetPixelSize(std::max(1, size));
  c.Root = pixel;
  c.Description = "vtkPixelArtPass, " + mode + " pixelation, art pixel " +
    std::to_string(std::max(1, size)) + " px, defaults (Canny + depth edges, 4 levels, dither)";
  return c;
}

/**
 * sketch-N: vtkSketchPass with its defaults (10 LIC steps, white noise, cross-hatching,
 * contrast with blur stride 4) and N neighbours. sketch-8-stage: the sketch pass's own G-buffer
 * alone (standard lighting, full precision, normals, linear depth and object positions);
 * sketch-8 minus this is the screen-space sketch stage.
 */
ConfigPasses MakeSketchConfig(const std::string& name)
{
  ConfigPasses c;
  if (name == "sketch-8-stage")
  {
    auto gbuf = vtkSmartPointer<vtkStylizeGBufferPass>::New();
    gbuf->SetLightingPass(Lighting("standard"));
    gbuf->SetPrecision(vtkStylizeGBufferPass::FULL);
    gbuf->SetPositionSpace(vtkStylizeGBufferPass::OBJECT);
    gbuf->SetChannels(vtkStylizeGBufferPass::NORMAL | vtkStylizeGBufferPass::POSITION |
      vtkStylizeGBufferPass::LINEAR_DEPTH);
    c.Root = gbuf;
    c.Description = "the G-buffer vtkSketchPass renders (standard lighting, full precision, "
                    "normal, object position, linear depth), composited";
    return c;
  }
  auto sketch = vtkSmartPointer<vtkSketchPass>::New();
  sketch->SetNeighbors(std::atoi(name.c_str() + 7));
  c.Root = sketch;
  c.Description = "vtkSketchPass, " + std::to_string(sketch->GetNeighbors()) +
    " neighbours, defaults (10 LIC steps each side, white noise, cross-hatching, blur stride 4)";
  return c;
}

/**
 * lines: vtkLineArtPass with its defaults. vtk-lines: VTK's own line tools on the same mesh, over
 * VTK's default rendering: vtkPolyDataSilhouette (the contour edges for the camera, recomputed
 * as it moves) and vtkFeatureEdges (boundaries and edges sharper than 40 degrees, as the line
 * art's creases), drawn 2 pixels wide in black.
 */
ConfigPasses MakeLinesConfig(const std::string& name)
{
  ConfigPasses c;
  if (name == "lines")
  {
    c.Root = vtkSmartPointer<vtkLineArtPass>::New();
    c.Description = "vtkLineArtPass, defaults (every kind of line, hidden lines removed)";
    return c;
  }
  auto silhouette = vtkSmartPointer<vtkPolyDataSilhouette>::New();
  silhouette->SetDirectionToCameraOrigin();
  silhouette->BorderEdgesOff();
  auto edges = vtkSmartPointer<vtkFeatureEdges>::New();
  edges->SetFeatureAngle(40.0);
  edges->BoundaryEdgesOn();
  edges->FeatureEdgesOn();
  edges->NonManifoldEdgesOff();
  edges->ManifoldEdgesOff();
  edges->ColoringOff();
  c.AddProps = [silhouette, edges](vtkRenderer* ren, vtkActor* surface)
  {
    silhouette->SetCamera(ren->GetActiveCamera());
    silhouette->SetProp3D(surface);
    for (vtkAlgorithm* lines :
      { static_cast<vtkAlgorithm*>(silhouette), static_cast<vtkAlgorithm*>(edges) })
    {
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputConnection(lines->GetOutputPort());
      mapper->ScalarVisibilityOff();
      // lines drawn over the surface they lie on
      mapper->SetResolveCoincidentTopologyToPolygonOffset();
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->GetProperty()->SetColor(0.0, 0.0, 0.0);
      actor->GetProperty()->SetLineWidth(2.0);
      actor->GetProperty()->LightingOff();
      ren->AddActor(actor);
    }
  };
  c.SetMesh = [silhouette, edges](vtkPolyData* mesh)
  {
    silhouette->SetInputData(mesh);
    edges->SetInputData(mesh);
  };
  c.Description = "VTK's default rendering with vtkPolyDataSilhouette and vtkFeatureEdges (40 "
                  "degrees, boundaries) drawn 2 px wide";
  return c;
}

/** A configuration without a suffix (-nocull, -translucent, -fullsize, -interactive). */
ConfigPasses MakeBaseConfig(const std::string& name, double diagonal)
{
  auto starts = [&name](const char* head) { return name.rfind(head, 0) == 0; };
  if (name == "plain")
  {
    ConfigPasses c;
    c.Description = "VTK's default rendering, no pass";
    return c;
  }
  if (name == "sobel" || name == "ssao" || name == "edl")
  {
    return MakeVtkConfig(name, diagonal);
  }
  if (starts("light-"))
  {
    ConfigPasses c;
    c.Root = Lighting(name.substr(6));
    c.Description = "vtkStylizeLightingPass (" + name.substr(6) + "), default delegate";
    return c;
  }
  if (name == "comic" || name == "comic-geometric")
  {
    return MakeComicConfig(name);
  }
  if (name == "lines" || name == "vtk-lines")
  {
    return MakeLinesConfig(name);
  }
  if (name == "comic-image" || name == "pixel-image" || name == "sketch-image")
  {
    return MakeImageConfig(name);
  }
  if (starts("pixel-"))
  {
    return MakePixelConfig(name);
  }
  if (starts("sketch-"))
  {
    return MakeSketchConfig(name);
  }
  if (starts("gbuf-"))
  {
    return MakeGBufferConfig(name);
  }
  return ConfigPasses();
}
}

ConfigPasses MakeConfig(const std::string& name, double diagonal)
{
  if (EndsWith(name, "-nocull"))
  {
    // NAME-nocull: configuration NAME (a style) with background culling off
    // (vtkStylizeStylePass::BackgroundCullingOff(): every stage over every pixel, the styles'
    // cost before issue 15's culling; the pictures are identical).
    ConfigPasses c = MakeConfig(name.substr(0, name.size() - 7), diagonal);
    if (auto* style = vtkStylizeStylePass::SafeDownCast(c.Root))
    {
      style->BackgroundCullingOff();
      c.Description += "; background culling off (every stage over every pixel)";
    }
    return c;
  }
  if (EndsWith(name, "-translucent"))
  {
    // NAME-translucent: NAME with the actor at opacity 0.35 (the runner sets it): a style draws
    // its translucent layers (TranslucentLayers, default 4), plain VTK peels with its own depth
    // peeling (the renderer's UseDepthPeeling, 4 peels).
    ConfigPasses c = MakeConfig(name.substr(0, name.size() - 12), diagonal);
    c.Description += c.Root ? "; the actor at opacity 0.35 (the style's translucent layers, 4)"
                            : "; the actor at opacity 0.35, VTK's depth peeling (4 peels)";
    return c;
  }
  if (EndsWith(name, "-fullsize"))
  {
    // NAME-fullsize: the style NAME with InteractiveImageReduction 1 (its interactive variant,
    // as NAME-fullsize-interactive, at the window's full size: the cost before issue 41).
    ConfigPasses c = MakeConfig(name.substr(0, name.size() - 9), diagonal);
    if (auto* style = vtkStylizeStylePass::SafeDownCast(c.Root))
    {
      style->SetInteractiveImageReduction(1);
      c.Description += "; InteractiveImageReduction 1 (interactive frames at full size)";
    }
    return c;
  }
  if (EndsWith(name, "-interactive"))
  {
    // NAME-interactive: the style NAME while the window asks for an interactive rate (15 frames
    // per second, as VTK's interactors do while the user drags): its interactive variant.
    ConfigPasses c = MakeConfig(name.substr(0, name.size() - 12), diagonal);
    c.Description += "; the window's desired update rate 15 (the interactive variant)";
    return c;
  }
  return MakeBaseConfig(name, diagonal);
}
}
