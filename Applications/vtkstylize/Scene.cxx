// vtkstylize: the scene: actors and their colouring, the title and scalar bar, lights, camera.
#include "Scene.h"

#include "vtkstylizeCommon.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkComicPass.h"
#include "vtkCoordinate.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkLineArtPass.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkScalarBarActor.h"
#include "vtkSketchPass.h"
#include "vtkSmartPointer.h"
#include "vtkStylizeSceneLights.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace vtkstylize
{
namespace
{
// A neutral gray: the pixel-art levels palette dithers each channel with the same threshold, so a
// neutral colour stays neutral, while a warm gray (0.80, 0.80, 0.78 before) got yellow specks
// wherever the threshold fell between its blue and its red and green.
constexpr double SolidColor[3] = { 0.80, 0.80, 0.80 };

/** Diverging cool-to-warm colour map (Moreland) over [lo, hi]. */
vtkSmartPointer<vtkColorTransferFunction> CoolWarm(double lo, double hi)
{
  vtkNew<vtkColorTransferFunction> ctf;
  ctf->SetColorSpaceToDiverging();
  ctf->AddRGBPoint(lo, 0.230, 0.299, 0.754);
  ctf->AddRGBPoint(hi, 0.706, 0.016, 0.150);
  return ctf;
}

/** Viridis-like sequential colour map over [lo, hi]. */
vtkSmartPointer<vtkColorTransferFunction> Viridis(double lo, double hi)
{
  static const double nodes[5][3] = { { 0.267, 0.005, 0.329 }, { 0.229, 0.322, 0.546 },
    { 0.128, 0.567, 0.551 }, { 0.369, 0.789, 0.383 }, { 0.993, 0.906, 0.144 } };
  vtkNew<vtkColorTransferFunction> ctf;
  ctf->SetColorSpaceToLab();
  for (int i = 0; i < 5; ++i)
  {
    ctf->AddRGBPoint(lo + (hi - lo) * i / 4.0, nodes[i][0], nodes[i][1], nodes[i][2]);
  }
  return ctf;
}

/** How a part is coloured. */
struct Coloring
{
  std::string Array; // empty: solid
  int Association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  bool Direct = false; // unsigned char RGB(A): the values are the colours
};

vtkDataArray* FindArray(vtkPolyData* pd, const std::string& name, int& association)
{
  if (vtkDataArray* a = pd->GetPointData()->GetArray(name.c_str()))
  {
    association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
    return a;
  }
  if (vtkDataArray* a = pd->GetCellData()->GetArray(name.c_str()))
  {
    association = vtkDataObject::FIELD_ASSOCIATION_CELLS;
    return a;
  }
  return nullptr;
}

Coloring ChooseColoring(const Part& part, const Options& opt, bool builtIn)
{
  Coloring c;
  if (opt.NoScalars)
  {
    return c;
  }
  vtkPolyData* pd = part.Surface;
  std::string name = opt.ColorBy;
  if (name.empty())
  {
    if (builtIn)
    {
      name = part.Name == "parametric" ? "Height" : part.Name == "streamlines" ? "Speed" : "";
    }
    else if (vtkDataArray* s = pd->GetPointData()->GetScalars())
    {
      name = s->GetName() ? s->GetName() : "";
      if (name.empty())
      {
        s->SetName("Scalars");
        name = "Scalars";
      }
    }
    else if (vtkDataArray* cs = pd->GetCellData()->GetScalars())
    {
      name = cs->GetName() ? cs->GetName() : "";
      if (name.empty())
      {
        cs->SetName("CellScalars");
        name = "CellScalars";
      }
    }
  }
  if (name.empty())
  {
    return c;
  }
  int association = 0;
  vtkDataArray* array = FindArray(pd, name, association);
  if (!array)
  {
    return c;
  }
  c.Array = name;
  c.Association = association;
  c.Direct = vtkUnsignedCharArray::SafeDownCast(array) &&
    (array->GetNumberOfComponents() == 3 || array->GetNumberOfComponents() == 4) &&
    opt.ColorBy.empty();
  return c;
}

void AddAnnotations(vtkRenderer* ren, const Options& opt, const SceneAnnotations& info,
  const std::map<std::string, vtkSmartPointer<vtkColorTransferFunction>>& maps)
{
  if (opt.NoAnnotations)
  {
    return;
  }
  const double luminance =
    0.299 * opt.Background[0] + 0.587 * opt.Background[1] + 0.114 * opt.Background[2];
  const double ink = luminance > 0.5 ? 0.1 : 0.95;
  // Text is drawn in pixels of the final image: a magnified (tiled) screenshot scales it with
  // the image, as it does the 3D scene (vtkWindowToImageFilter does not scale 2D text).
  const int magnify = std::max(1, opt.Magnify);
  const int fontSize = std::max(8, std::min(opt.Width, opt.Height) / 28) * magnify;

  // A line of text in the ink, its top at 97% of the height, from the left or the right edge.
  auto addText = [&](const std::string& text, bool right)
  {
    vtkNew<vtkTextActor> actor;
    actor->SetInput(text.c_str());
    actor->GetTextProperty()->SetFontSize(fontSize);
    actor->GetTextProperty()->SetColor(ink, ink, ink);
    actor->GetTextProperty()->SetJustification(right ? VTK_TEXT_RIGHT : VTK_TEXT_LEFT);
    actor->GetTextProperty()->SetVerticalJustificationToTop();
    actor->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    actor->GetPositionCoordinate()->SetValue(right ? 0.98 : 0.02, 0.97);
    ren->AddActor2D(actor);
  };
  addText(info.Title, false);

  // Black-and-white output (comic or sketch with --tint off; line art) shows no colours: no
  // colour legend unless --scalar-bar asks for one (ParaView's view hides it there too).
  bool blackAndWhite = false;
  if (opt.Style == "comic")
  {
    vtkNew<vtkComicPass> comic;
    opt.Passes.ApplyTo(comic.Get());
    blackAndWhite = !comic->GetTinted();
  }
  else if (opt.Style == "sketch")
  {
    vtkNew<vtkSketchPass> sketch;
    opt.Passes.ApplyTo(sketch.Get());
    blackAndWhite = !sketch->GetTinted();
  }
  else if (opt.Style == "lines")
  {
    blackAndWhite = true;
  }
  const auto it = maps.find(info.ScalarBarArray);
  const auto constant = info.ConstantArrays.find(info.ScalarBarArray);
  if (!info.ScalarBarArray.empty() && it != maps.end() && (!blackAndWhite || opt.ScalarBar) &&
    constant != info.ConstantArrays.end())
  {
    addText(info.ScalarBarArray + " = " + FormatNumber(constant->second) + " (constant)", true);
  }
  else if (!info.ScalarBarArray.empty() && it != maps.end() && (!blackAndWhite || opt.ScalarBar))
  {
    vtkNew<vtkScalarBarActor> bar;
    bar->SetLookupTable(it->second);
    bar->SetTitle(info.ScalarBarArray.c_str());
    bar->SetNumberOfLabels(4);
    bar->SetOrientationToVertical();
    bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    bar->GetPositionCoordinate()->SetValue(0.88, 0.1);
    bar->SetWidth(0.1);
    bar->SetHeight(0.8);
    for (vtkTextProperty* tp : { bar->GetTitleTextProperty(), bar->GetLabelTextProperty() })
    {
      tp->SetColor(ink, ink, ink);
      tp->ShadowOff();
      tp->ItalicOff();
    }
    bar->SetVerticalTitleSeparation(std::max(2, fontSize / 3));
    bar->SetMaximumWidthInPixels(std::max(40, opt.Width / 8) * magnify);
    ren->AddActor2D(bar);
  }
}
}

namespace
{
/** Colour-map ranges: per array name, the [min, max] of its finite values over all parts. */
using Ranges = std::map<std::string, std::array<double, 2>>;

/**
 * Each part's colouring (ChooseColoring()), and the finite range of each mapped array over all
 * parts. An array with no finite value falls back to the solid colour, and non-finite values
 * are reported, in info.Warnings. Returns whether any part is coloured by an array.
 */
bool ChooseColorings(const std::vector<Part>& parts, const Options& opt, bool builtIn,
  SceneAnnotations& info, const std::string& what, std::vector<Coloring>& colorings, Ranges& ranges)
{
  bool anyColored = false;
  for (const Part& p : parts)
  {
    Coloring c = ChooseColoring(p, opt, builtIn);
    colorings.push_back(c);
    if (c.Array.empty() || c.Direct)
    {
      anyColored = anyColored || c.Direct;
      continue;
    }
    anyColored = true;
    int association = 0;
    vtkDataArray* array = FindArray(p.Surface, c.Array, association);
    // The colour map spans the finite values: NaN takes the map's NaN colour, an infinity the
    // end of the map, and neither reaches the scalar bar's labels.
    const int component = array->GetNumberOfComponents() > 1 ? -1 : 0;
    double r[2];
    array->GetFiniteRange(r, component);
    vtkIdType nonFinite = 0;
    for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
    {
      for (int k = 0; k < array->GetNumberOfComponents(); ++k)
      {
        if (!std::isfinite(array->GetComponent(t, k)))
        {
          ++nonFinite;
          break;
        }
      }
    }
    if (nonFinite > 0 && !(r[0] <= r[1]))
    {
      info.Warnings.push_back(what + ": " + Quote(c.Array) +
        " holds no finite value (NaN or infinity): drawn in one colour");
      colorings.back().Array.clear();
      continue;
    }
    if (nonFinite > 0)
    {
      info.Warnings.push_back(what + ": " + std::to_string(static_cast<long long>(nonFinite)) +
        " of " + std::to_string(static_cast<long long>(array->GetNumberOfTuples())) +
        " values of " + Quote(c.Array) + " are not finite (NaN or infinity): NaN is drawn dark " +
        "red, an infinity in the colour of its end of the map");
    }
    auto found = ranges.find(c.Array);
    if (found == ranges.end())
    {
      ranges[c.Array][0] = r[0];
      ranges[c.Array][1] = r[1];
    }
    else
    {
      found->second[0] = std::min(found->second[0], r[0]);
      found->second[1] = std::max(found->second[1], r[1]);
    }
  }
  return anyColored;
}

/** Fails for a --color-by array that no part has, listing the arrays there are. */
[[noreturn]] void FailNoSuchArray(
  const std::vector<Part>& parts, const Options& opt, const std::string& what)
{
  // List what there is, so that the next try can succeed.
  std::set<std::string> names;
  for (const Part& p : parts)
  {
    for (vtkFieldData* fd : { static_cast<vtkFieldData*>(p.Surface->GetPointData()),
           static_cast<vtkFieldData*>(p.Surface->GetCellData()) })
    {
      for (int a = 0; a < fd->GetNumberOfArrays(); ++a)
      {
        if (fd->GetArray(a) && fd->GetArray(a)->GetName())
        {
          names.insert(fd->GetArray(a)->GetName());
        }
      }
    }
  }
  std::string list;
  for (const std::string& n : names)
  {
    list += (list.empty() ? "" : ", ") + Quote(n);
  }
  Fail(what + ": no point or cell array named " + Quote(opt.ColorBy) + " (see --color-by); " +
    (list.empty() ? std::string("the data has no arrays") : "the arrays are: " + list));
}

/**
 * One colour map per array over its range (Viridis for the built-in scene's speed, else
 * cool-to-warm), and the array the scalar bar shows (the built-in speed, else the first).
 */
std::map<std::string, vtkSmartPointer<vtkColorTransferFunction>> MakeColorMaps(
  const Ranges& ranges, bool builtIn, SceneAnnotations& info)
{
  std::map<std::string, vtkSmartPointer<vtkColorTransferFunction>> maps;
  for (auto& r : ranges)
  {
    double lo = r.second[0], hi = r.second[1];
    // A constant array (up to float rounding): centre it in a unit range (one colour, the map's
    // middle), and label it with its value instead of a bar of four equal labels.
    if (!(hi - lo > 1e-6 * std::max({ 1.0, std::abs(lo), std::abs(hi) })))
    {
      info.ConstantArrays[r.first] = 0.5 * (lo + hi);
      lo -= 0.5;
      hi += 0.5;
    }
    maps[r.first] = (builtIn && r.first == "Speed") ? Viridis(lo, hi) : CoolWarm(lo, hi);
    if (info.ScalarBarArray.empty() || (builtIn && r.first == "Speed"))
    {
      info.ScalarBarArray = r.first;
    }
  }
  return maps;
}

/** The actor of one part: its colouring through its array's map, or the solid colour. */
void AddActor(vtkRenderer* ren, vtkPolyData* surface, const Coloring& c,
  std::map<std::string, vtkSmartPointer<vtkColorTransferFunction>>& maps)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  if (c.Array.empty())
  {
    mapper->ScalarVisibilityOff();
  }
  else
  {
    mapper->ScalarVisibilityOn();
    mapper->SetScalarMode(c.Association == vtkDataObject::FIELD_ASSOCIATION_CELLS
        ? VTK_SCALAR_MODE_USE_CELL_FIELD_DATA
        : VTK_SCALAR_MODE_USE_POINT_FIELD_DATA);
    mapper->SelectColorArray(c.Array.c_str());
    if (c.Direct)
    {
      mapper->SetColorModeToDirectScalars();
    }
    else
    {
      vtkColorTransferFunction* ctf = maps[c.Array];
      int association = 0;
      vtkDataArray* array = FindArray(surface, c.Array, association);
      if (array->GetNumberOfComponents() > 1)
      {
        ctf->SetVectorModeToMagnitude();
      }
      mapper->SetColorModeToMapScalars();
      mapper->SetLookupTable(ctf);
      mapper->UseLookupTableScalarRangeOn();
      mapper->InterpolateScalarsBeforeMappingOn();
    }
  }
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkProperty* prop = actor->GetProperty();
  prop->SetColor(SolidColor[0], SolidColor[1], SolidColor[2]);
  // At most 0.1 + 0.75 + 0.15 = 1: a face seen head-on under the headlight is not saturated.
  prop->SetAmbient(0.1);
  prop->SetDiffuse(0.75);
  prop->SetSpecular(0.15);
  prop->SetSpecularPower(30.0);
  ren->AddActor(actor);
}
}

/** Adds one actor per part, coloured as ChooseColoring() says, and the annotations. */
void AddParts(vtkRenderer* ren, const std::vector<Part>& parts, const Options& opt, bool builtIn,
  SceneAnnotations& info, const std::string& what)
{
  // Colour maps: one per array name, over the range of that array across all parts.
  std::vector<Coloring> colorings;
  Ranges ranges;
  const bool anyColored = ChooseColorings(parts, opt, builtIn, info, what, colorings, ranges);
  if (!opt.ColorBy.empty() && !anyColored)
  {
    FailNoSuchArray(parts, opt, what);
  }
  auto maps = MakeColorMaps(ranges, builtIn, info);
  const auto constant = info.ConstantArrays.find(info.ScalarBarArray);
  if (constant != info.ConstantArrays.end())
  {
    Note(what + ": " + Quote(constant->first) + " holds one value, " +
      FormatNumber(constant->second) + ": drawn in one colour, labelled with its value");
  }
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    AddActor(ren, parts[i].Surface, colorings[i], maps);
  }
  AddAnnotations(ren, opt, info, maps);
}

/**
 * Lights: 0 none; 1 the headlight; N > 1 white scene lights on a Fibonacci sphere around the
 * scene (1.5 times its diagonal from its centre), alternately directional and positional (point
 * lights), each of intensity min(1, 3/N) so that the summed diffuse light (about N/4 lights face
 * a point) stays below 1 (vtkStylizeSceneLights).
 */
void AddLights(vtkRenderer* ren, int count, const double bounds[6])
{
  const double center[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  const double radius = 1.5 * std::max(diagonal, 1e-6);
  vtkStylizeSceneLights::AddLights(
    ren, count, center, radius, 3.0, vtkStylizeSceneLights::DIRECTIONAL_POINT, 90.0);
}

namespace
{
/**
 * The normalized device coordinate box (x0, x1, y0, y1) of every point of the renderer's
 * visible actors' data, as the active camera projects them; false when there is none.
 */
bool ProjectedBox(vtkRenderer* ren, double box[4])
{
  vtkCamera* camera = ren->GetActiveCamera();
  double aspect[2];
  ren->GetAspect(aspect);
  vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(aspect[0] / aspect[1], -1, 1);
  box[0] = box[2] = VTK_DOUBLE_MAX;
  box[1] = box[3] = -VTK_DOUBLE_MAX;
  bool any = false;
  vtkActorCollection* actors = ren->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    auto* pd = actor->GetVisibility() && actor->GetMapper()
      ? vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0))
      : nullptr;
    vtkPoints* points = pd ? pd->GetPoints() : nullptr;
    if (!points)
    {
      continue;
    }
    vtkMatrix4x4* actorMatrix = actor->GetMatrix();
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      double p[4] = { 0, 0, 0, 1 };
      points->GetPoint(i, p);
      actorMatrix->MultiplyPoint(p, p);
      m->MultiplyPoint(p, p);
      if (!(p[3] > 0.0))
      {
        continue;
      }
      const double x = p[0] / p[3], y = p[1] / p[3];
      box[0] = std::min(box[0], x);
      box[1] = std::max(box[1], x);
      box[2] = std::min(box[2], y);
      box[3] = std::max(box[3], y);
      any = true;
    }
  }
  return any && box[1] > box[0] && box[3] > box[2];
}

/**
 * Centres the data in the view and zooms so that its projected box fills `fill` of the
 * image's width or height, whichever it reaches first. A few rounds, since under perspective
 * moving the camera changes the projection.
 */
void FitView(vtkRenderer* ren, double fill)
{
  vtkCamera* camera = ren->GetActiveCamera();
  for (int round = 0; round < 3; ++round)
  {
    double box[4];
    if (!ProjectedBox(ren, box))
    {
      return;
    }
    // Centre: move the camera and its focal point across the view by the box's offset.
    const double cx = 0.5 * (box[0] + box[1]), cy = 0.5 * (box[2] + box[3]);
    double aspect[2];
    ren->GetAspect(aspect);
    const double halfHeight = camera->GetParallelProjection()
      ? camera->GetParallelScale()
      : camera->GetDistance() * std::tan(vtkMath::RadiansFromDegrees(0.5 * camera->GetViewAngle()));
    const double halfWidth = halfHeight * aspect[0] / aspect[1];
    double up[3], dop[3], right[3];
    camera->GetViewUp(up);
    camera->GetDirectionOfProjection(dop);
    vtkMath::Cross(dop, up, right);
    vtkMath::Normalize(right);
    double shift[3];
    for (int i = 0; i < 3; ++i)
    {
      shift[i] = cx * halfWidth * right[i] + cy * halfHeight * up[i];
    }
    double position[3], focal[3];
    camera->GetPosition(position);
    camera->GetFocalPoint(focal);
    camera->SetPosition(position[0] + shift[0], position[1] + shift[1], position[2] + shift[2]);
    camera->SetFocalPoint(focal[0] + shift[0], focal[1] + shift[1], focal[2] + shift[2]);
    // Zoom: the larger of the box's width and height fractions becomes `fill`.
    const double extent = std::max(0.5 * (box[1] - box[0]), 0.5 * (box[3] - box[2]));
    if (extent > 1e-12 && std::isfinite(extent))
    {
      camera->Zoom(std::min(1e6, fill / extent));
    }
    ren->ResetCameraClippingRange();
  }
}
}

void SetUpCamera(vtkRenderer* ren, const Options& opt)
{
  vtkCamera* camera = ren->GetActiveCamera();
  // --up: the up axis u drawn upward; the front view from +X x u (+Z when u is an X axis).
  const int axis = opt.Up.size() == 2 && opt.Up[1] >= 'x' && opt.Up[1] <= 'z' ? opt.Up[1] - 'x' : 1;
  const double sign = opt.Up[0] == '-' ? -1.0 : 1.0;
  double up[3] = { 0.0, 0.0, 0.0 };
  up[axis] = sign;
  const double x[3] = { 1.0, 0.0, 0.0 };
  double back[3] = { 0.0, 0.0, 1.0 };
  if (axis != 0)
  {
    vtkMath::Cross(x, up, back);
  }
  camera->SetPosition(back);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(up);
  camera->SetParallelProjection(opt.Parallel);
  ren->ResetCamera();
  // A three-quarter view by default, as for the built-in scene.
  camera->Azimuth(opt.Azimuth ? *opt.Azimuth : SceneAzimuth);
  double before[3];
  camera->GetDirectionOfProjection(before);
  camera->Elevation(opt.Elevation ? *opt.Elevation : SceneElevation);
  // Looking straight up or down: the old view-up is parallel to the view; use the old forward
  // direction instead so that the view transform stays well defined.
  double dop[3], viewUp[3];
  camera->GetDirectionOfProjection(dop);
  camera->GetViewUp(viewUp);
  if (std::abs(vtkMath::Dot(dop, viewUp)) > 0.999)
  {
    const double s = vtkMath::Dot(dop, viewUp) > 0 ? -1.0 : 1.0;
    camera->SetViewUp(s * before[0], s * before[1], s * before[2]);
  }
  camera->OrthogonalizeViewUp();
  ren->ResetCameraClippingRange();
  // The scene fills the frame, the built-in one as a file's.
  FitView(ren, FrameFill);
  camera->Zoom(opt.Zoom);
  ren->ResetCameraClippingRange();
}
}
