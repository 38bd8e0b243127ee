#include "vtkStylizeFeatureStrokesScene.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDiscretizableColorTransferFunction.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkLookupTable.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkPointData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkStylizeVolumeSurfaces.h"

#include <algorithm>
#include <cmath>

namespace vtkStylizeFeatureStrokesScene
{
/** The mean edge length of (up to 10000 of) the surface's polygons. */
double MeanEdgeLength(vtkPolyData* pd)
{
  vtkCellArray* polys = pd->GetPolys();
  const vtkIdType cells = polys->GetNumberOfCells();
  const vtkIdType stride = std::max<vtkIdType>(1, cells / 10000);
  double sum = 0.0;
  vtkIdType count = 0;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < cells; c += stride)
  {
    polys->GetCellAtId(c, ids);
    const vtkIdType n = ids->GetNumberOfIds();
    for (vtkIdType k = 0; k < n; ++k)
    {
      double a[3], b[3];
      pd->GetPoint(ids->GetId(k), a);
      pd->GetPoint(ids->GetId((k + 1) % n), b);
      const double d = std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
      if (std::isfinite(d))
      {
        sum += d;
        ++count;
      }
    }
  }
  return count > 0 ? sum / count : 0.0;
}

/** How much a matrix scales lengths (the cube root of its 3 x 3 part's determinant). */
double ScaleOf(vtkMatrix4x4* m)
{
  if (!m)
  {
    return 1.0;
  }
  const double det =
    vtkMatrix4x4::Determinant(m->GetData()) / std::max(1e-300, std::fabs(m->GetElement(3, 3)));
  const double s = std::cbrt(std::fabs(det));
  return std::isfinite(s) ? s : 1.0;
}

void AddSurface(
  vtkDataObject* data, vtkMatrix4x4* matrix, bool wireframe, size_t actor, std::vector<Item>& out)
{
  if (auto* ds = vtkDataSet::SafeDownCast(data))
  {
    if (ds->GetNumberOfCells() > 0)
    {
      out.push_back({ ds, matrix, wireframe, actor });
    }
  }
  else if (auto* cd = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(cd->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      AddSurface(it->GetCurrentDataObject(), matrix, wireframe, actor, out);
    }
  }
}

/** The actors whose lines are drawn: visible, opaque, drawn as surfaces or wireframe. */
std::vector<vtkActor*> LineActors(vtkRenderer* ren, bool translucent)
{
  std::vector<vtkActor*> actors;
  vtkPropCollection* props = ren->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    auto* actor = vtkActor::SafeDownCast(prop);
    // (a fog's shell whose outline is drawn as the fog's: not its own)
    vtkInformation* keys = actor ? actor->GetPropertyKeys() : nullptr;
    const bool fog = keys && keys->Get(vtkStylizeVolumeSurfaces::FOG_SHELL()) == 1;
    if (actor && actor->GetVisibility() && actor->GetMapper() &&
      (actor->HasTranslucentPolygonalGeometry() != 0) == translucent &&
      actor->GetProperty()->GetRepresentation() != VTK_POINTS && !(translucent && fog))
    {
      actors.push_back(actor);
    }
  }
  return actors;
}

/** The datasets of the actors (or those that replace them: View::Surfaces). */
std::vector<Item> SurfacesOf(
  const std::vector<vtkActor*>& actors, const vtkStylizeFeatureStrokes::View& view)
{
  std::vector<Item> items;
  for (size_t a = 0; a < actors.size(); ++a)
  {
    vtkActor* actor = actors[a];
    vtkDataObject* data = a < view.Surfaces.size() && view.Surfaces[a]
      ? view.Surfaces[a].GetPointer()
      : actor->GetMapper()->GetInputDataObject(0, 0);
    AddSurface(data, actor->GetMatrix(), actor->GetProperty()->GetRepresentation() == VTK_WIREFRAME,
      a, items);
  }
  return items;
}

/** The polygonal data of an actor's input (every leaf of a composite), ghost cells left out. */
vtkSmartPointer<vtkPolyData> PolygonsOf(vtkDataObject* data)
{
  std::vector<Item> leaves;
  AddSurface(data, nullptr, false, 0, leaves);
  vtkNew<vtkAppendPolyData> append;
  for (const Item& leaf : leaves)
  {
    vtkSmartPointer<vtkPolyData> pd = vtkPolyData::SafeDownCast(leaf.Data);
    if (!pd)
    {
      vtkNew<vtkDataSetSurfaceFilter> surface;
      surface->SetInputData(leaf.Data);
      surface->Update();
      pd = surface->GetOutput();
    }
    auto copy = vtkSmartPointer<vtkPolyData>::New();
    copy->ShallowCopy(pd);
    copy->RemoveGhostCells();
    append->AddInputData(copy);
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  if (!leaves.empty())
  {
    append->Update();
    out->ShallowCopy(append->GetOutput());
  }
  return out;
}
/**
 * The iso-lines of an actor's dataset (Settings::IsoLines): the point-data array its mapper
 * colours it by through a colour map, the component or magnitude the map shows, the levels
 * placed in the map's range on its scale; none for an actor without mapped point colours.
 */
void SetIsoLines(vtkStylizeFeatureLines* fl, vtkActor* actor, vtkDataSet* data,
  const vtkStylizeFeatureStrokes::Settings& settings)
{
  fl->SetIsoLineCount(0);
  vtkMapper* m = actor->GetMapper();
  const double width = settings.Widths[vtkStylizeFeatureLines::ISOLINE];
  if (settings.IsoLines <= 0 || !(width > 0.0) || !m->GetScalarVisibility())
  {
    return;
  }
  int cellFlag = 0;
  auto* array = vtkDataArray::SafeDownCast(vtkAbstractMapper::GetAbstractScalars(data,
    m->GetScalarMode(), m->GetArrayAccessMode(), m->GetArrayId(), m->GetArrayName(), cellFlag));
  // Cell colours are constant per cell; direct colours (and unsigned chars in the default
  // colour mode) are not mapped.
  const bool direct = m->GetColorMode() == VTK_COLOR_MODE_DIRECT_SCALARS ||
    (m->GetColorMode() == VTK_COLOR_MODE_DEFAULT && array &&
      array->GetDataType() == VTK_UNSIGNED_CHAR);
  vtkDataArray* active = data->GetPointData()->GetScalars();
  const char* name = array ? array->GetName() : nullptr;
  if (!array || cellFlag != 0 || direct || (!(name && *name) && array != active) ||
    (name && *name && data->GetPointData()->GetArray(name) != array))
  {
    return;
  }
  vtkScalarsToColors* lut = m->GetLookupTable();
  if (lut->GetIndexedLookup() || lut->GetVectorMode() == vtkScalarsToColors::RGBCOLORS)
  {
    return; // categories, or the array's own colours: no levels
  }
  const double* range = m->GetUseLookupTableScalarRange() ? lut->GetRange() : m->GetScalarRange();
  bool log = false;
  int bands = 0;
  if (auto* table = vtkLookupTable::SafeDownCast(lut))
  {
    log = table->GetScale() == VTK_SCALE_LOG10;
    bands = static_cast<int>(table->GetNumberOfTableValues());
  }
  else if (auto* ctf = vtkColorTransferFunction::SafeDownCast(lut))
  {
    log = ctf->GetScale() == VTK_CTF_LOG10;
    auto* discrete = vtkDiscretizableColorTransferFunction::SafeDownCast(lut);
    bands =
      discrete && discrete->GetDiscretize() ? static_cast<int>(discrete->GetNumberOfValues()) : 0;
  }
  int spacing = settings.IsoLineSpacing;
  if (spacing == vtkStylizeFeatureLines::BANDS && !(bands >= 2 && bands <= 1000))
  {
    spacing = vtkStylizeFeatureLines::ROUND; // not a banded map
  }
  fl->SetIsoLineArrayName(name && *name ? name : "");
  fl->SetIsoLineComponent(
    lut->GetVectorMode() == vtkScalarsToColors::COMPONENT ? lut->GetVectorComponent() : -1);
  fl->SetIsoLineRange(range[0], range[1]);
  fl->SetIsoLineSpacing(spacing);
  fl->SetIsoLineBands(std::max(1, bands));
  fl->SetIsoLineLogScale(log);
  fl->SetIsoLineCount(settings.IsoLines);
}
}
