#include "vtkStylizeVolumeSurfaces.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommunicator.h"
#include "vtkContourFilter.h"
#include "vtkContourValues.h"
#include "vtkDataSet.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStylizeLightingPass.h"
#include "vtkStylizeStylePass.h"
#include "vtkStylizeVolumeFog.h"
#include "vtkStylizeVolumeSolidCut.h"
#include "vtkStylizeVolumeSurface.h"
#include "vtkThreshold.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGridVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

struct vtkStylizeVolumeSurfaces::Proxy
{
  /** A surface of the volume, drawn by its own actor. */
  struct Part
  {
    vtkNew<vtkStylizeVolumeSurface> Surface;
    vtkNew<vtkPolyDataMapper> Mapper;
    vtkNew<vtkActor> Actor;
    std::string Selected; // the input array last selected
  };
  vtkWeakPointer<vtkVolume> Volume;
  Part Solid; // where the opacity reaches the threshold
  Part Haze;  // translucent, where the opacity reaches a tenth of the threshold
  vtkNew<vtkMatrix4x4> Matrix;
  vtkNew<vtkColorTransferFunction> Gray; // a gray transfer function as colours
  bool Hazy = false;                     // the haze drawn in this frame
  // The haze's accumulated colours (HAZE_FOG): what they were computed for.
  vtkMTimeType FogTime = 0;
  double FogScale = -1.0;
  double FogSolid = -1.0;
  bool Fogged = false; // the haze drawn with them
  // With the fog: the solid surface where it looks solid from the eye (drawn while Clipped),
  // and the haze as the fog samples it (vtkStylizeVolumeSolidCut::FogSurface()).
  vtkStylizeVolumeSolidCut Cut;
  bool Clipped = false;
  bool SolidDepth = false; // (where it looks solid kept for the G-buffer: Begin()'s solidDepth)
  // On several processes, each drawing its piece: the whole volume's solid surface (from the
  // gathered image) cut by the same rule, where the fog asks (the same on every process).
  vtkNew<vtkStylizeVolumeSurface> WholeSolid;
  vtkStylizeVolumeSolidCut WholeCut;
  vtkSmartPointer<vtkPolyData> FineShell;
  vtkMTimeType FineShellTime = 0;
  // Data that is not an image, resampled on an image for the fog (when the data changes).
  vtkSmartPointer<vtkImageData> Resampled;
  vtkMTimeType ResampledTime = 0;
  vtkStylizeVolumeFog Fog; // (its tables kept while the data and functions are unchanged)
  // The fog's outline: where the whole ray's opacity reaches one half (Begin()'s `outline`), on
  // the cells of the rays' nearest layer alone (the other layers' points hold -1: a contour
  // across the border between the layers would draw a false outline there).
  vtkNew<vtkThreshold> Nearest;
  vtkNew<vtkContourFilter> Contour;
  vtkNew<vtkPolyData> OutlineLines; // (the contour moved towards the eye: TowardsEye())
  vtkNew<vtkPolyDataMapper> OutlineMapper;
  vtkNew<vtkActor> Outline;
  bool Outlined = false; // drawn in this frame
};

vtkInformationKeyMacro(vtkStylizeVolumeSurfaces, FOG_SHELL, Integer);

namespace
{
/** The haze's surface: where the opacity reaches this share of the solid's threshold. */
constexpr double HazeLevel = 0.1;

/**
 * A surface's light as the volume's `property` shades it (unshaded: a surface's defaults, so
 * that the style's light still shapes it), or none (`emitted`: its colours drawn as they are).
 */
void Light(vtkActor* actor, vtkVolumeProperty* property, bool emitted)
{
  vtkInformation* keys = actor->GetPropertyKeys();
  if (!keys)
  {
    vtkNew<vtkInformation> info;
    actor->SetPropertyKeys(info);
    keys = info;
  }
  if (!keys->Has(vtkStylizeLightingPass::EMITTED_COLORS()) ||
    keys->Get(vtkStylizeLightingPass::EMITTED_COLORS()) != (emitted ? 1.0 : 0.0))
  {
    keys->Set(vtkStylizeLightingPass::EMITTED_COLORS(), emitted ? 1.0 : 0.0);
  }
  vtkProperty* look = actor->GetProperty();
  const bool shade = property->GetShade(0) != 0 && !emitted;
  look->SetAmbient(emitted ? 1.0 : shade ? property->GetAmbient(0) : 0.0);
  look->SetDiffuse(emitted ? 0.0 : shade ? property->GetDiffuse(0) : 1.0);
  look->SetSpecular(shade ? property->GetSpecular(0) : 0.0);
  look->SetSpecularPower(shade ? property->GetSpecularPower(0) : 1.0);
}

/**
 * `lines` with each point moved by `distance` along its view ray towards the eye (`eye`, or
 * against `dop` for a parallel projection), as `out`: drawn where they are in the picture, in
 * front of the haze layer they lie on, which would otherwise cover them.
 */
void TowardsEye(vtkPolyData* lines, const double eye[3], const double dop[3], bool parallel,
  double distance, vtkPolyData* out)
{
  vtkNew<vtkPoints> moved;
  moved->SetDataTypeToDouble();
  const vtkIdType n = lines->GetNumberOfPoints();
  moved->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3], d[3];
    lines->GetPoint(i, x);
    for (int a = 0; a < 3; ++a)
    {
      d[a] = parallel ? -dop[a] : eye[a] - x[a];
    }
    const double length = vtkMath::Norm(d);
    const double k = length > 0.0 ? std::min(distance, 0.5 * length) / length : 0.0;
    moved->SetPoint(i, x[0] + k * d[0], x[1] + k * d[1], x[2] + k * d[2]);
  }
  out->Initialize();
  out->SetPoints(moved);
  out->SetLines(lines->GetLines());
}

/** The volume's own setting under `key` of its property keys, or `fallback`. */
double VolumeThreshold(vtkVolume* volume, double fallback)
{
  vtkInformation* keys = volume->GetPropertyKeys();
  if (keys && keys->Has(vtkStylizeStylePass::VOLUME_OPACITY_THRESHOLD()))
  {
    const double t = keys->Get(vtkStylizeStylePass::VOLUME_OPACITY_THRESHOLD());
    return std::isfinite(t) ? std::min(1.0, std::max(0.001, t)) : fallback;
  }
  return fallback;
}

/**
 * The mapper's scalar selection as the filter's input array; `selected` keeps the last one
 * (SetInputArrayToProcess() modifies the filter at every call, which would recompute the
 * surface at every frame).
 */
void SelectArray(
  vtkAbstractVolumeMapper* mapper, vtkDataSet* data, vtkAlgorithm* filter, std::string& selected)
{
  auto select = [&](int association, const char* name, int attribute)
  {
    const std::string key = std::to_string(association) + (name ? std::string("/") + name : "") +
      "#" + std::to_string(attribute);
    if (key != selected)
    {
      selected = key;
      if (name)
      {
        filter->SetInputArrayToProcess(0, 0, 0, association, name);
      }
      else
      {
        filter->SetInputArrayToProcess(0, 0, 0, association, attribute);
      }
    }
  };
  const int mode = mapper->GetScalarMode();
  const bool cells =
    mode == VTK_SCALAR_MODE_USE_CELL_DATA || mode == VTK_SCALAR_MODE_USE_CELL_FIELD_DATA;
  const int association =
    cells ? vtkDataObject::FIELD_ASSOCIATION_CELLS : vtkDataObject::FIELD_ASSOCIATION_POINTS;
  if (mode == VTK_SCALAR_MODE_USE_POINT_FIELD_DATA || mode == VTK_SCALAR_MODE_USE_CELL_FIELD_DATA)
  {
    const char* name = mapper->GetArrayName();
    if (mapper->GetArrayAccessMode() == VTK_GET_ARRAY_BY_ID && data)
    {
      vtkFieldData* fd = cells ? static_cast<vtkFieldData*>(data->GetCellData())
                               : static_cast<vtkFieldData*>(data->GetPointData());
      vtkAbstractArray* a = fd->GetAbstractArray(mapper->GetArrayId());
      name = a ? a->GetName() : nullptr;
    }
    if (name)
    {
      select(association, name, -1);
      return;
    }
  }
  // The default: point scalars, else cell scalars (as VTK's volume mappers choose).
  const bool cellScalars = mode == VTK_SCALAR_MODE_USE_CELL_DATA ||
    (mode == VTK_SCALAR_MODE_DEFAULT && data && !data->GetPointData()->GetScalars() &&
      data->GetCellData()->GetScalars());
  select(
    cellScalars ? vtkDataObject::FIELD_ASSOCIATION_CELLS : vtkDataObject::FIELD_ASSOCIATION_POINTS,
    nullptr, vtkDataSetAttributes::SCALARS);
}

/**
 * Gives `surface` the volume's data (the mapper's input connection, for the pipeline's whole
 * extent, or its data), its array (`selected`: see SelectArray()), the whole image's extent, the
 * opacity function and the threshold.
 */
void Feed(vtkStylizeVolumeSurface* surface, std::string& selected, vtkAbstractVolumeMapper* mapper,
  vtkDataSet* data, const int whole[6], const std::vector<vtkTypeUInt64>& shared,
  vtkPiecewiseFunction* opacity, double threshold)
{
  if (mapper->GetNumberOfInputConnections(0) > 0)
  {
    if (surface->GetInputConnection(0, 0) != mapper->GetInputConnection(0, 0))
    {
      surface->SetInputConnection(mapper->GetInputConnection(0, 0));
    }
  }
  else if (surface->GetInputDataObject(0, 0) != data)
  {
    surface->SetInputData(data);
  }
  SelectArray(mapper, data, surface, selected);
  surface->SetWholeExtent(const_cast<int*>(whole));
  surface->SetSharedPoints(shared);
  surface->SetScalarOpacity(opacity);
  surface->SetOpacityThreshold(threshold);
}

/**
 * What the fog samples: `image`'s `scalars` through `property`'s opacity and `colors`, lit as
 * the volume's mapper `vm` lights it (VTK's unstructured-grid mappers take the opacity as an
 * attenuation and do not shade).
 */
vtkStylizeVolumeFog::Volume FogVolume(vtkImageData* image, vtkDataArray* scalars,
  vtkScalarsToColors* colors, vtkVolumeProperty* property, vtkAbstractVolumeMapper* vm,
  bool twoSided)
{
  vtkStylizeVolumeFog::Volume volume;
  volume.Image = image;
  volume.Scalars = scalars;
  volume.Opacity = property->GetScalarOpacity(0);
  volume.Colors = colors;
  volume.Mask = image->GetPointData()->GetArray("vtkValidPointMask");
  volume.Unit = property->GetScalarOpacityUnitDistance(0);
  const bool unstructured = vtkUnstructuredGridVolumeMapper::SafeDownCast(vm) != nullptr;
  volume.Attenuation = unstructured;
  volume.Light.On = property->GetShade(0) != 0 && !unstructured;
  volume.Light.Ambient = property->GetAmbient(0);
  volume.Light.Diffuse = property->GetDiffuse(0);
  volume.Light.Specular = property->GetSpecular(0);
  volume.Light.Power = property->GetSpecularPower(0);
  volume.Light.TwoSided = twoSided;
  return volume;
}
}

//------------------------------------------------------------------------------
vtkDataSet* vtkStylizeVolumeSurfaces::UpdatedInput(vtkAbstractVolumeMapper* mapper)
{
  if (mapper->GetNumberOfInputConnections(0) > 0)
  {
    mapper->GetInputAlgorithm()->Update();
  }
  return mapper->GetDataSetInput();
}

//------------------------------------------------------------------------------
vtkAbstractCellLocator* vtkStylizeVolumeSurfaces::CutSolid(Proxy& p, vtkDataSet* data,
  vtkImageData* gathered, const vtkStylizeVolumeFog::Volume& volume, double solid,
  const double eye[3], const double dop[3], bool parallel)
{
  // (where it looks solid along the rays, for the G-buffer's depth: Begin()'s solidDepth)
  p.Clipped = p.Cut.Cut(
    p.Solid.Surface->GetOutput(), data, p.Fog, volume, solid, eye, dop, parallel, p.SolidDepth);
  if (!p.Clipped || !gathered)
  {
    return p.Clipped ? p.Cut.GetLocator() : nullptr;
  }
  p.WholeSolid->SetInputData(gathered);
  p.WholeSolid->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, volume.Scalars->GetName());
  p.WholeSolid->SetScalarOpacity(volume.Opacity);
  p.WholeSolid->SetOpacityThreshold(solid);
  p.WholeSolid->Update();
  return p.WholeCut.Cut(
           p.WholeSolid->GetOutput(), gathered, p.Fog, volume, solid, eye, dop, parallel)
    ? p.WholeCut.GetLocator()
    : nullptr;
}

//------------------------------------------------------------------------------
void vtkStylizeVolumeSurfaces::ColourHaze(Proxy& p, vtkDataSet* data, vtkVolumeProperty* property,
  vtkScalarsToColors* colors, double solid, double haze, bool fog, vtkRenderer* ren, double outline,
  vtkImageData* gathered)
{
  vtkCamera* camera = ren ? ren->GetActiveCamera() : nullptr;
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  vtkPolyData* shell = p.Haze.Surface->GetOutput();
  // (the array the volume's mapper draws, as it chooses it)
  int cells = 0;
  vtkAbstractVolumeMapper* vm = p.Volume ? p.Volume->GetMapper() : nullptr;
  vtkDataArray* scalars = data && vm
    ? vtkAbstractMapper::GetScalars(data, vm->GetScalarMode(), vm->GetArrayAccessMode(),
        vm->GetArrayId(), vm->GetArrayName(), cells)
    : nullptr;
  auto* image = vtkImageData::SafeDownCast(data);
  if (gathered && fog && scalars)
  {
    // (several processes: the whole volume, gathered from their pieces)
    image = gathered;
    scalars = scalars->GetName() ? image->GetPointData()->GetArray(scalars->GetName()) : nullptr;
    cells = 0;
  }
  else if ((!image || cells) && fog && scalars && data->GetNumberOfCells() > 0)
  {
    // Other data, or cell scalars, sampled on an image of up to SampledPoints along its longest
    // side (where the image lies outside the data, vtkValidPointMask is 0 and the fog nothing);
    // there the array of the scalars' name.
    if (!p.Resampled || p.ResampledTime < data->GetMTime())
    {
      // (probed as several processes probe their pieces: the same samples on any number)
      p.Resampled = vtkStylizeVolumeFog::GatherImage(
        data, scalars->GetName(), nullptr, vtkStylizeVolumeFog::SampledPoints);
      p.ResampledTime = data->GetMTime();
    }
    image = p.Resampled;
    scalars = scalars->GetName() ? image->GetPointData()->GetArray(scalars->GetName()) : nullptr;
    cells = 0;
  }
  fog = fog && camera && image && scalars && cells == 0 && shell->GetPoints();
  if (fog)
  {
    shell = vtkStylizeVolumeSolidCut::FogSurface(shell, data, image, p.FineShell, p.FineShellTime);
    const vtkStylizeVolumeFog::Volume volume =
      FogVolume(image, scalars, colors, property, vm, ren->GetTwoSidedLighting() != 0);
    // (the renderer's time follows its camera's: in `time`, with the view)
    const vtkMTimeType dataTime = std::max({ shell->GetPoints()->GetMTime(), p.Matrix->GetMTime(),
      opacity->GetMTime(), colors->GetMTime(), data->GetMTime(), property->GetMTime() });
    const vtkMTimeType time = std::max({ dataTime, camera->GetMTime(), ren->GetMTime() });
    // While the camera moves (the window's desired update rate at least one frame a second, as
    // VTK's interactor styles and ParaView's interactive renders set it) the last view's fog is
    // kept: it is made again at the still frame that ends the interaction.
    vtkRenderWindow* window = ren->GetRenderWindow();
    const bool moving = p.Fogged && window && window->GetDesiredUpdateRate() >= 1.0 &&
      dataTime <= p.FogTime && time > p.FogTime;
    if (!p.Fogged || (time > p.FogTime && !moving) || haze != p.FogScale || solid != p.FogSolid ||
      !shell->GetPointData()->GetArray("StylizeHazeRGBA") ||
      (outline > 0.0 && !shell->GetPointData()->GetArray("StylizeHazeWhole")))
    {
      // the eye (or the view direction) in the image's coordinates
      vtkNew<vtkMatrix4x4> inverse;
      vtkMatrix4x4::Invert(p.Matrix, inverse);
      double eye[4] = { 0.0, 0.0, 0.0, 1.0 }, dop[4] = { 0.0, 0.0, 0.0, 0.0 };
      camera->GetPosition(eye);
      camera->GetDirectionOfProjection(dop);
      inverse->MultiplyPoint(eye, eye);
      inverse->MultiplyPoint(dop, dop);
      if (eye[3] != 0.0)
      {
        for (int a = 0; a < 3; ++a)
        {
          eye[a] /= eye[3];
        }
      }
      // The solid surface where its material is thick enough to look solid along the view
      // rays; the fog stops where it is drawn and goes on through the rest.
      const bool parallel = camera->GetParallelProjection() != 0;
      vtkAbstractCellLocator* drawn = CutSolid(
        p, data, image == gathered ? gathered : nullptr, volume, solid, eye, dop, parallel);
      vtkNew<vtkUnsignedCharArray> rgba;
      rgba->SetName("StylizeHazeRGBA");
      vtkNew<vtkFloatArray> whole;
      whole->SetName("StylizeHazeWhole");
      fog = p.Fog.Accumulate(shell, volume, HazeLevel * solid, solid, haze, eye, dop, parallel,
        rgba, outline > 0.0 ? whole.GetPointer() : nullptr, drawn);
      if (fog)
      {
        shell->GetPointData()->AddArray(rgba);
        if (outline > 0.0)
        {
          shell->GetPointData()->AddArray(whole);
          p.Nearest->SetInputData(shell);
          p.Contour->Update();
          const double* spacing = image->GetSpacing();
          TowardsEye(p.Contour->GetOutput(), eye, dop, parallel,
            std::min({ std::abs(spacing[0]), std::abs(spacing[1]), std::abs(spacing[2]) }),
            p.OutlineLines);
        }
        p.FogTime = time;
        p.FogScale = haze;
        p.FogSolid = solid;
      }
    }
  }
  p.Fogged = fog;
  vtkPolyDataMapper* m = p.Haze.Mapper;
  if (fog)
  {
    m->SetScalarModeToUsePointFieldData();
    m->SelectColorArray("StylizeHazeRGBA");
    m->SetColorModeToDirectScalars();
  }
  else
  {
    m->SetScalarModeToUsePointData();
    m->SetColorModeToDefault();
  }
  // (the fog's colours are VTK's, lit as it lights them: drawn as they are)
  Light(p.Haze.Actor, property, fog);
  p.Outlined = fog && outline > 0.0;
  if (p.Outlined)
  {
    p.Outline->GetProperty()->SetLineWidth(static_cast<float>(outline));
  }
  vtkInformation* keys = p.Haze.Actor->GetPropertyKeys(); // (Light() made them)
  if (keys->Get(FOG_SHELL()) != (p.Outlined ? 1 : 0))
  {
    keys->Set(FOG_SHELL(), p.Outlined ? 1 : 0);
  }
  p.Haze.Actor->GetProperty()->SetOpacity(fog ? 1.0 : haze);
}

//------------------------------------------------------------------------------
vtkStylizeVolumeSurfaces::vtkStylizeVolumeSurfaces() = default;

//------------------------------------------------------------------------------
vtkStylizeVolumeSurfaces::~vtkStylizeVolumeSurfaces()
{
  this->End();
}

//------------------------------------------------------------------------------
bool vtkStylizeVolumeSurfaces::Drawable(vtkVolume* volume)
{
  if (!volume || !volume->GetVisibility() || !volume->GetMapper() || !volume->GetProperty())
  {
    return false;
  }
  vtkInformation* keys = volume->GetPropertyKeys();
  if (keys && keys->Has(vtkStylizeStylePass::STYLIZE_VOLUME()) &&
    keys->Get(vtkStylizeStylePass::STYLIZE_VOLUME()) == 0)
  {
    return false;
  }
  vtkAbstractVolumeMapper* mapper = volume->GetMapper();
  vtkDataSet* data = UpdatedInput(mapper);
  if (!data || data->GetNumberOfPoints() == 0)
  {
    return false;
  }
  vtkDataArray* scalars = data->GetPointData()->GetScalars() ? data->GetPointData()->GetScalars()
                                                             : data->GetCellData()->GetScalars();
  const bool named = mapper->GetScalarMode() == VTK_SCALAR_MODE_USE_POINT_FIELD_DATA ||
    mapper->GetScalarMode() == VTK_SCALAR_MODE_USE_CELL_FIELD_DATA;
  if (!scalars && !named)
  {
    return false;
  }
  const int components = scalars ? scalars->GetNumberOfComponents() : 1;
  return components == 1 || volume->GetProperty()->GetIndependentComponents();
}

//------------------------------------------------------------------------------
bool vtkStylizeVolumeSurfaces::HasHaze(vtkPiecewiseFunction* f, double threshold)
{
  if (!f || f->GetSize() == 0)
  {
    return false;
  }
  const double low = HazeLevel * threshold;
  auto hazy = [&](double o) { return o >= low && o < threshold; };
  double range[2];
  f->GetRange(range);
  for (int i = 0; i <= 1024; ++i)
  {
    if (hazy(f->GetValue(range[0] + (range[1] - range[0]) * i / 1024.0)))
    {
      return true;
    }
  }
  for (int i = 0; i < f->GetSize(); ++i)
  {
    double node[4];
    f->GetNodeValue(i, node);
    if (hazy(node[1]))
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
vtkStylizeVolumeSurfaces::Proxy* vtkStylizeVolumeSurfaces::Update(vtkVolume* volume,
  double threshold, double haze, bool fog, double outline, vtkImageData* gathered, vtkRenderer* ren,
  const int whole[6], const std::vector<vtkTypeUInt64>& shared)
{
  std::unique_ptr<Proxy>& slot = this->Proxies[volume];
  if (!slot || slot->Volume.GetPointer() != volume)
  {
    slot.reset(new Proxy);
    slot->Volume = volume;
    // each surface drawn by its actor, coloured by its point scalars, placed by the volume's matrix
    for (auto* part : { &slot->Solid, &slot->Haze })
    {
      part->Mapper->SetInputConnection(part->Surface->GetOutputPort());
      part->Mapper->ScalarVisibilityOn();
      part->Mapper->SetScalarModeToUsePointData();
      part->Mapper->UseLookupTableScalarRangeOn();
      part->Actor->SetMapper(part->Mapper);
      part->Actor->SetUserMatrix(slot->Matrix);
      part->Actor->PickableOff();
    }
    // (the cut solid's depth: where it looks solid, vtkStylizeGBufferPass's stylizeLooksSolid)
    slot->Solid.Mapper->MapDataArrayToVertexAttribute("stylizeLooksSolid",
      vtkStylizeVolumeSolidCut::LooksSolidAt, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
    // (the fog's outline: black lines, unlit, not coloured by the array)
    slot->Nearest->SetInputArrayToProcess(
      0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "StylizeHazeWhole");
    slot->Nearest->SetLowerThreshold(-0.5);
    slot->Nearest->SetUpperThreshold(VTK_FLOAT_MAX);
    slot->Nearest->SetThresholdFunction(vtkThreshold::THRESHOLD_BETWEEN);
    slot->Nearest->AllScalarsOn();
    slot->Contour->SetInputConnection(slot->Nearest->GetOutputPort());
    slot->Contour->SetInputArrayToProcess(
      0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "StylizeHazeWhole");
    slot->Contour->SetValue(0, 0.5);
    slot->Contour->ComputeScalarsOff();
    slot->Contour->ComputeNormalsOff();
    slot->OutlineMapper->SetInputData(slot->OutlineLines);
    slot->OutlineMapper->ScalarVisibilityOff();
    slot->Outline->SetMapper(slot->OutlineMapper);
    slot->Outline->SetUserMatrix(slot->Matrix);
    slot->Outline->PickableOff();
    slot->Outline->GetProperty()->SetColor(0.0, 0.0, 0.0);
    slot->Outline->GetProperty()->LightingOff();
  }
  Proxy& p = *slot;
  p.SolidDepth = this->SolidDepth;
  vtkAbstractVolumeMapper* mapper = volume->GetMapper();
  vtkVolumeProperty* property = volume->GetProperty();

  // The surface: from the mapper's input connection (the pipeline's whole extent), or its data.
  vtkDataSet* data = UpdatedInput(mapper);
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  const double solid = VolumeThreshold(volume, threshold);
  Feed(p.Solid.Surface, p.Solid.Selected, mapper, data, whole, shared, opacity, solid);
  std::vector<double> iso;
  auto* volumeMapper = vtkVolumeMapper::SafeDownCast(mapper);
  if (volumeMapper && volumeMapper->GetBlendMode() == vtkVolumeMapper::ISOSURFACE_BLEND &&
    property->GetIsoSurfaceValues())
  {
    vtkContourValues* values = property->GetIsoSurfaceValues();
    for (int i = 0; i < values->GetNumberOfContours(); ++i)
    {
      iso.push_back(values->GetValue(i));
    }
  }
  p.Solid.Surface->SetIsoValues(iso);

  // Its colour, light, place and clipping: the volume's (set only when they change: a changed
  // property or matrix would rebuild the actors' shaders or buffers at every frame).
  vtkScalarsToColors* colors = property->GetRGBTransferFunction(0);
  if (property->GetColorChannels(0) != 3)
  {
    vtkPiecewiseFunction* gray = property->GetGrayTransferFunction(0);
    if (p.Gray->GetMTime() < gray->GetMTime())
    {
      p.Gray->RemoveAllPoints();
      for (int i = 0; i < gray->GetSize(); ++i)
      {
        double node[4];
        gray->GetNodeValue(i, node);
        p.Gray->AddRGBPoint(node[0], node[1], node[1], node[1], node[2], node[3]);
      }
    }
    colors = p.Gray;
  }
  vtkMatrix4x4* matrix = volume->GetMatrix();
  if (!std::equal(&p.Matrix->Element[0][0], &p.Matrix->Element[0][0] + 16, &matrix->Element[0][0]))
  {
    p.Matrix->DeepCopy(matrix);
  }
  // The haze (not with the volume's own isovalues: those are its surfaces).
  p.Hazy = haze > 0.0 && iso.empty() && HasHaze(opacity, solid);
  p.Outlined = false;
  if (p.Hazy)
  {
    Feed(p.Haze.Surface, p.Haze.Selected, mapper, data, whole, shared, opacity, HazeLevel * solid);
  }
  for (Proxy::Part* part : { &p.Solid, &p.Haze })
  {
    if (part == &p.Haze && !p.Hazy)
    {
      break;
    }
    part->Mapper->SetLookupTable(colors);
    if (part == &p.Solid)
    {
      Light(part->Actor, property, false);
    }
    if (part->Mapper->GetClippingPlanes() != mapper->GetClippingPlanes())
    {
      part->Mapper->SetClippingPlanes(mapper->GetClippingPlanes());
    }
    part->Surface->Update();
  }
  if (p.Hazy)
  {
    ColourHaze(p, data, property, colors, solid, haze, fog, ren, outline, gathered);
  }
  // (with the fog, the haze as the fog sampled it)
  vtkPolyDataMapper* hazeMapper = p.Haze.Mapper;
  if (p.Hazy && p.Fogged && p.FineShell)
  {
    if (hazeMapper->GetInputDataObject(0, 0) != p.FineShell)
    {
      hazeMapper->SetInputData(p.FineShell);
    }
  }
  else if (hazeMapper->GetInputConnection(0, 0) != p.Haze.Surface->GetOutputPort())
  {
    hazeMapper->SetInputConnection(p.Haze.Surface->GetOutputPort());
  }
  vtkAlgorithmOutput* drawn =
    p.Hazy && p.Fogged && p.Clipped ? p.Cut.GetOutputPort() : p.Solid.Surface->GetOutputPort();
  if (p.Solid.Mapper->GetInputConnection(0, 0) != drawn)
  {
    p.Solid.Mapper->SetInputConnection(drawn);
  }
  return &p;
}

//------------------------------------------------------------------------------
const vtkRenderState* vtkStylizeVolumeSurfaces::Begin(const vtkRenderState* s, double threshold,
  double haze, bool fog, vtkMultiProcessController* controller, double outline, bool solidDepth)
{
  this->SolidDepth = solidDepth;

  this->End();
  this->Count = 0;
  this->Hazes.clear();
  this->Props.assign(s->GetPropArray(), s->GetPropArray() + s->GetPropArrayCount());
  const std::vector<std::array<int, 6>> wholes = WholeExtents(this->Props, controller);
  const std::vector<std::vector<vtkTypeUInt64>> shared = this->SharedPoints(controller);
  // (on several processes, each holding a piece, the fog samples the whole volume gathered)
  const std::vector<vtkImageData*> gathered = fog && haze > 0.0
    ? this->FogImages(controller)
    : std::vector<vtkImageData*>(wholes.size(), nullptr);
  size_t v = 0; // the volumes' index in `wholes` and `shared`
  std::vector<vtkActor*> outlines;
  for (vtkProp*& prop : this->Props)
  {
    auto* volume = vtkVolume::SafeDownCast(prop);
    const int* whole = volume ? wholes[v].data() : nullptr;
    const std::vector<vtkTypeUInt64>* own = volume ? &shared[v++] : nullptr;
    if (Drawable(volume))
    {
      Proxy* p = this->Update(
        volume, threshold, haze, fog, outline, gathered[v - 1], s->GetRenderer(), whole, *own);
      prop = p->Solid.Actor;
      this->Active.push_back(p->Solid.Actor);
      if (p->Hazy)
      {
        this->Hazes.push_back(p->Haze.Actor);
      }
      if (p->Outlined)
      {
        outlines.push_back(p->Outline);
      }
    }
  }
  // (the fogs' outlines, opaque lines, then the haze surfaces after the props: translucent
  // actors, drawn in the translucent layers)
  this->Props.insert(this->Props.end(), outlines.begin(), outlines.end());
  this->Props.insert(this->Props.end(), this->Hazes.begin(), this->Hazes.end());
  // Volumes gone from the scene free their surfaces.
  for (auto it = this->Proxies.begin(); it != this->Proxies.end();)
  {
    const bool used = std::find(this->Active.begin(), this->Active.end(),
                        it->second->Solid.Actor) != this->Active.end();
    it = used || it->second->Volume ? std::next(it) : this->Proxies.erase(it);
  }
  this->Count = static_cast<int>(this->Active.size());
  if (this->Active.empty())
  {
    return s;
  }
  vtkRenderer* ren = s->GetRenderer();
  this->State.reset(new vtkRenderState(ren));
  this->State->SetPropArrayAndCount(this->Props.data(), static_cast<int>(this->Props.size()));
  this->State->SetFrameBuffer(s->GetFrameBuffer());
  this->State->SetRequiredKeys(s->GetRequiredKeys());
  this->Active.insert(this->Active.end(), this->Hazes.begin(), this->Hazes.end());
  this->Active.insert(this->Active.end(), outlines.begin(), outlines.end());
  this->Hazes.clear();
  for (vtkActor* actor : this->Active)
  {
    ren->GetViewProps()->AddItem(actor);
  }
  this->Renderer = ren;
  return this->State.get();
}

//------------------------------------------------------------------------------
void vtkStylizeVolumeSurfaces::AddToRenderer(vtkRenderer* ren)
{
  this->End();
  if (!ren)
  {
    return;
  }
  vtkPropCollection* props = ren->GetViewProps();
  for (auto& entry : this->Proxies)
  {
    vtkVolume* volume = entry.second->Volume;
    if (volume && props->IsItemPresent(volume) && Drawable(volume))
    {
      props->AddItem(entry.second->Solid.Actor);
      this->Active.push_back(entry.second->Solid.Actor);
      if (entry.second->Hazy)
      {
        props->AddItem(entry.second->Haze.Actor);
        this->Active.push_back(entry.second->Haze.Actor);
      }
      if (entry.second->Outlined)
      {
        props->AddItem(entry.second->Outline);
        this->Active.push_back(entry.second->Outline);
      }
    }
  }
  this->Renderer = this->Active.empty() ? nullptr : ren;
}

//------------------------------------------------------------------------------
void vtkStylizeVolumeSurfaces::End()
{
  if (this->Renderer)
  {
    for (vtkActor* actor : this->Active)
    {
      this->Renderer->GetViewProps()->RemoveItem(actor);
    }
  }
  this->Renderer = nullptr;
  this->Active.clear();
  this->State.reset();
}

//------------------------------------------------------------------------------
int vtkStylizeVolumeSurfaces::GetNumberOfSurfaces() const
{
  return this->Count;
}

//------------------------------------------------------------------------------
void vtkStylizeVolumeSurfaces::ReleaseGraphicsResources(vtkWindow* w)
{
  for (auto& entry : this->Proxies)
  {
    entry.second->Solid.Actor->ReleaseGraphicsResources(w);
    entry.second->Haze.Actor->ReleaseGraphicsResources(w);
    entry.second->Outline->ReleaseGraphicsResources(w);
  }
}
