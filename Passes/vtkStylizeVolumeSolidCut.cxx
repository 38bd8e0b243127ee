#include "vtkStylizeVolumeSolidCut.h"

#include "vtkCellArray.h"
#include "vtkClipPolyData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticCellLocator.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace
{
/**
 * `fine` cut where `chords` (per point) reaches vtkStylizeVolumeFog::LooksSolid, the part at or
 * above it as `clip`'s output (`copy`: `fine` with the chords and `reach` or null, its input), with
 * `fine`'s scalars active again (the surface's colours). (VTK 9.1's vtkClipPolyData clips by the
 * active scalars alone.)
 */
void ClipByChords(vtkPolyData* fine, vtkFloatArray* chords, vtkFloatArray* reach, vtkPolyData* copy,
  vtkClipPolyData* clip)
{
  vtkDataArray* values = fine->GetPointData()->GetScalars();
  copy->ShallowCopy(fine);
  vtkPointData* data = copy->GetPointData();
  if (reach)
  {
    data->AddArray(reach);
  }
  data->SetActiveAttribute(data->AddArray(chords), vtkDataSetAttributes::SCALARS);
  clip->SetValue(vtkStylizeVolumeFog::LooksSolid);
  clip->SetInputData(copy);
  clip->Update();
  vtkPointData* out = clip->GetOutput()->GetPointData();
  for (int i = 0; values && i < out->GetNumberOfArrays(); ++i)
  {
    const char* name = out->GetArrayName(i);
    if (out->GetArray(i) != nullptr &&
      out->GetArray(i)->GetNumberOfComponents() == values->GetNumberOfComponents() &&
      (name && values->GetName() ? std::string(name) == values->GetName()
                                 : !name && !values->GetName()))
    {
      out->SetActiveAttribute(i, vtkDataSetAttributes::SCALARS);
      break;
    }
  }
}
}

//------------------------------------------------------------------------------
vtkStylizeVolumeSolidCut::vtkStylizeVolumeSolidCut() = default;

//------------------------------------------------------------------------------
vtkStylizeVolumeSolidCut::~vtkStylizeVolumeSolidCut() = default;

//------------------------------------------------------------------------------
bool vtkStylizeVolumeSolidCut::Cut(vtkPolyData* solid, vtkDataSet* data, vtkStylizeVolumeFog& fog,
  const vtkStylizeVolumeFog::Volume& volume, double level, const double eye[3], const double dop[3],
  bool parallel, bool reach)
{
  if (solid->GetNumberOfPolys() == 0)
  {
    return false;
  }
  vtkPolyData* fine = FogSurface(solid, data, volume.Image, this->Fine, this->FineTime);
  vtkNew<vtkFloatArray> chords;
  chords->SetName("StylizeSolidChord");
  vtkNew<vtkFloatArray> reached;
  reached->SetName(LooksSolidAt);
  if (!fog.SolidOpacity(
        fine, volume, level, eye, dop, parallel, chords, reach ? reached.GetPointer() : nullptr))
  {
    return false;
  }
  ClipByChords(fine, chords, reach ? reached.GetPointer() : nullptr, this->Chords, this->Looks);
  this->Drawn->SetDataSet(this->Looks->GetOutput());
  if (this->Looks->GetOutput()->GetNumberOfCells() > 0)
  {
    this->Drawn->BuildLocator(); // (the fog's rays then only read it)
  }
  return true;
}

//------------------------------------------------------------------------------
vtkAlgorithmOutput* vtkStylizeVolumeSolidCut::GetOutputPort()
{
  return this->Looks->GetOutputPort();
}

//------------------------------------------------------------------------------
vtkAbstractCellLocator* vtkStylizeVolumeSolidCut::GetLocator()
{
  return this->Drawn;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkStylizeVolumeSolidCut::Refined(
  vtkPolyData* surface, double length, vtkIdType most)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(surface);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  vtkSmartPointer<vtkPolyData> current = triangles->GetOutput();
  for (int round = 0; round < 12; ++round)
  {
    vtkPoints* points = current->GetPoints();
    const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
    std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> middles;
    vtkNew<vtkPoints> more;
    more->SetDataTypeToDouble(); // (kept by DeepCopy: the middles of middles in double)
    more->DeepCopy(points);
    auto out = vtkSmartPointer<vtkPolyData>::New();
    vtkPointData* from = current->GetPointData();
    vtkPointData* to = out->GetPointData();
    to->InterpolateAllocate(from, n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      to->CopyData(from, i, i);
    }
    // the middle of edge (a, b), made once, or -1 when it is short enough
    auto middle = [&](vtkIdType a, vtkIdType b) -> vtkIdType
    {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto found = middles.find(key);
      if (found != middles.end())
      {
        return found->second;
      }
      double x[3], y[3];
      points->GetPoint(a, x);
      points->GetPoint(b, y);
      vtkIdType id = -1;
      if (vtkMath::Distance2BetweenPoints(x, y) > length * length &&
        more->GetNumberOfPoints() < most)
      {
        id = more->InsertNextPoint(0.5 * (x[0] + y[0]), 0.5 * (x[1] + y[1]), 0.5 * (x[2] + y[2]));
        to->InterpolateEdge(from, id, key.first, key.second, 0.5);
      }
      middles[key] = id;
      return id;
    };
    vtkNew<vtkCellArray> split;
    vtkCellArray* polys = current->GetPolys();
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    bool any = false;
    for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
    {
      if (count != 3)
      {
        continue;
      }
      vtkIdType t[3] = { ids[0], ids[1], ids[2] }, m[3];
      for (int e = 0; e < 3; ++e)
      {
        m[e] = middle(t[e], t[(e + 1) % 3]); // (edge e: from corner e to the next)
      }
      const int splits = (m[0] >= 0) + (m[1] >= 0) + (m[2] >= 0);
      any = any || splits > 0;
      // turned so that the split edges come first: one split, edge 0; two, edges 0 and 1
      int r = 0;
      while ((splits == 1 && m[r] < 0) || (splits == 2 && m[(r + 2) % 3] >= 0))
      {
        ++r;
      }
      const vtkIdType a = t[r], b = t[(r + 1) % 3], c = t[(r + 2) % 3];
      const vtkIdType ab = m[r], bc = m[(r + 1) % 3], ca = m[(r + 2) % 3];
      const std::array<std::array<vtkIdType, 3>, 4> pieces[4] = {
        { { { a, b, c } } },
        { { { a, ab, c }, { ab, b, c } } },
        { { { ab, b, bc }, { a, ab, bc }, { a, bc, c } } },
        { { { a, ab, ca }, { ab, b, bc }, { ca, bc, c }, { ab, bc, ca } } },
      };
      for (int i = 0; i <= splits; ++i) // (splits + 1 triangles)
      {
        split->InsertNextCell(3, pieces[splits][i].data());
      }
    }
    out->SetPoints(more);
    out->SetPolys(split);
    current = out;
    if (!any)
    {
      break;
    }
  }
  return current;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkStylizeVolumeSolidCut::FogSurface(vtkPolyData* surface, vtkDataSet* data,
  vtkImageData* image, vtkSmartPointer<vtkPolyData>& kept, vtkMTimeType& time)
{
  if (vtkImageData::SafeDownCast(data))
  {
    kept = nullptr;
    return surface;
  }
  if (!kept || time < surface->GetMTime())
  {
    const double* spacing = image->GetSpacing();
    kept = Refined(surface,
      2.0 * std::min({ std::abs(spacing[0]), std::abs(spacing[1]), std::abs(spacing[2]) }),
      4 * surface->GetNumberOfPoints() + 100000);
    time = surface->GetMTime();
  }
  return kept;
}
