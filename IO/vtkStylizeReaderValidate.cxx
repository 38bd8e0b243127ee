// The validation of what vtkStylizeReader read: cell connectivity within the points, cell types
// and their sizes, structured dimensions, array lengths and finite coordinates (the filters and
// the mapper would read out of bounds, or draw nothing, otherwise).

#include "vtkStylizeReaderInternal.h"

#include "vtkStylizeReader.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCleanPolyData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkExtractCells.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRectilinearGrid.h"
#include "vtkStructuredGrid.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace vtkStylizeReaderInternal
{
namespace
{
/** Checks that every cell of the cell array references existing points. */
void CheckCells(vtkCellArray* cells, vtkIdType numberOfPoints, const std::string& what)
{
  if (!cells || cells->GetNumberOfCells() == 0)
  {
    return;
  }
  if (!cells->IsValid())
  {
    Fail(what + ": corrupt cell connectivity");
  }
  vtkDataArray* connectivity = cells->GetConnectivityArray();
  double range[2];
  connectivity->GetRange(range, 0);
  if (connectivity->GetNumberOfTuples() > 0 &&
    (range[0] < 0 || range[1] >= static_cast<double>(numberOfPoints)))
  {
    Fail(what + ": a cell references point " +
      std::to_string(static_cast<long long>(range[0] < 0 ? range[0] : range[1])) +
      " but there are " + std::to_string(static_cast<long long>(numberOfPoints)) + " points");
  }
}

/**
 * Number of points a cell type needs: exactly Size, or at least Size when AtLeast. Types not
 * listed (and VTK_POLYHEDRON without faces) are rejected, since the surface filter would read
 * outside the connectivity for them.
 */
struct CellSize
{
  int Size;
  bool AtLeast;
};

bool CellTypeSize(int type, CellSize& size)
{
  static const std::map<int, CellSize> sizes = { { VTK_EMPTY_CELL, { 0, false } },
    { VTK_VERTEX, { 1, false } }, { VTK_POLY_VERTEX, { 1, true } }, { VTK_LINE, { 2, false } },
    { VTK_POLY_LINE, { 2, true } }, { VTK_TRIANGLE, { 3, false } },
    { VTK_TRIANGLE_STRIP, { 3, true } }, { VTK_POLYGON, { 3, true } }, { VTK_PIXEL, { 4, false } },
    { VTK_QUAD, { 4, false } }, { VTK_TETRA, { 4, false } }, { VTK_VOXEL, { 8, false } },
    { VTK_HEXAHEDRON, { 8, false } }, { VTK_WEDGE, { 6, false } }, { VTK_PYRAMID, { 5, false } },
    { VTK_PENTAGONAL_PRISM, { 10, false } }, { VTK_HEXAGONAL_PRISM, { 12, false } },
    { VTK_QUADRATIC_EDGE, { 3, false } }, { VTK_QUADRATIC_TRIANGLE, { 6, false } },
    { VTK_QUADRATIC_QUAD, { 8, false } }, { VTK_QUADRATIC_TETRA, { 10, false } },
    { VTK_QUADRATIC_HEXAHEDRON, { 20, false } }, { VTK_QUADRATIC_WEDGE, { 15, false } },
    { VTK_QUADRATIC_PYRAMID, { 13, false } }, { VTK_BIQUADRATIC_QUAD, { 9, false } },
    { VTK_TRIQUADRATIC_HEXAHEDRON, { 27, false } }, { VTK_QUADRATIC_LINEAR_QUAD, { 6, false } },
    { VTK_QUADRATIC_LINEAR_WEDGE, { 12, false } },
    { VTK_BIQUADRATIC_QUADRATIC_WEDGE, { 18, false } },
    { VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON, { 24, false } },
    { VTK_BIQUADRATIC_TRIANGLE, { 7, false } }, { VTK_CUBIC_LINE, { 4, false } },
    { VTK_QUADRATIC_POLYGON, { 6, true } }, { VTK_TRIQUADRATIC_PYRAMID, { 19, false } },
    { VTK_CONVEX_POINT_SET, { 1, true } }, { VTK_POLYHEDRON, { 1, true } },
    { VTK_LAGRANGE_CURVE, { 2, true } }, { VTK_LAGRANGE_TRIANGLE, { 3, true } },
    { VTK_LAGRANGE_QUADRILATERAL, { 4, true } }, { VTK_LAGRANGE_TETRAHEDRON, { 4, true } },
    { VTK_LAGRANGE_HEXAHEDRON, { 8, true } }, { VTK_LAGRANGE_WEDGE, { 6, true } },
    { VTK_LAGRANGE_PYRAMID, { 5, true } }, { VTK_BEZIER_CURVE, { 2, true } },
    { VTK_BEZIER_TRIANGLE, { 3, true } }, { VTK_BEZIER_QUADRILATERAL, { 4, true } },
    { VTK_BEZIER_TETRAHEDRON, { 4, true } }, { VTK_BEZIER_HEXAHEDRON, { 8, true } },
    { VTK_BEZIER_WEDGE, { 6, true } }, { VTK_BEZIER_PYRAMID, { 5, true } } };
  const auto it = sizes.find(type);
  if (it == sizes.end())
  {
    return false;
  }
  size = it->second;
  return true;
}

/**
 * Whether npts is a number of points a Lagrange or Bezier cell of the type has at some order
 * (VTK infers the order from it; a count no order gives, say an 11-point wedge, made
 * vtkUnstructuredGridGeometryFilter read outside its arrays). Types that are not higher-order
 * pass.
 */
bool HigherOrderSizeValid(int type, vtkIdType npts)
{
  const bool curve = type == VTK_LAGRANGE_CURVE || type == VTK_BEZIER_CURVE;
  const bool triangle = type == VTK_LAGRANGE_TRIANGLE || type == VTK_BEZIER_TRIANGLE;
  const bool quad = type == VTK_LAGRANGE_QUADRILATERAL || type == VTK_BEZIER_QUADRILATERAL;
  const bool tetra = type == VTK_LAGRANGE_TETRAHEDRON || type == VTK_BEZIER_TETRAHEDRON;
  const bool hexahedron = type == VTK_LAGRANGE_HEXAHEDRON || type == VTK_BEZIER_HEXAHEDRON;
  const bool wedge = type == VTK_LAGRANGE_WEDGE || type == VTK_BEZIER_WEDGE;
  const bool pyramid = type == VTK_LAGRANGE_PYRAMID || type == VTK_BEZIER_PYRAMID;
  if (curve || !(triangle || quad || tetra || hexahedron || wedge || pyramid))
  {
    return true; // (a curve of n points is of order n - 1)
  }
  // VTK's special cases: a quadratic triangle, tetrahedron or wedge with face (and body) points.
  if ((triangle && npts == 7) || (tetra && npts == 15) || (wedge && npts == 21))
  {
    return true;
  }
  for (vtkIdType p = 1; p <= 64; ++p)
  {
    const vtkIdType count = triangle ? (p + 1) * (p + 2) / 2
      : quad                         ? (p + 1) * (p + 1)
      : tetra                        ? (p + 1) * (p + 2) * (p + 3) / 6
      : hexahedron                   ? (p + 1) * (p + 1) * (p + 1)
      : wedge                        ? (p + 1) * (p + 1) * (p + 2) / 2
                                     : (p + 1) * (p + 2) * (2 * p + 3) / 6;
    if (count == npts)
    {
      return true;
    }
    if (count > npts)
    {
      return false;
    }
  }
  return false;
}

/** The name of a linear cell type that quadratic cells are written with by mistake. */
const char* LinearCellName(int type)
{
  switch (type)
  {
    case VTK_LINE:
      return "line";
    case VTK_TRIANGLE:
      return "triangle";
    case VTK_QUAD:
      return "quadrilateral";
    case VTK_TETRA:
      return "tetrahedron";
    case VTK_HEXAHEDRON:
      return "hexahedron";
    case VTK_WEDGE:
      return "wedge";
    case VTK_PYRAMID:
      return "pyramid";
    default:
      return nullptr;
  }
}

/**
 * Checks the cell types of an unstructured grid and their numbers of points. A linear cell
 * (line, triangle, quadrilateral, tetrahedron, hexahedron, wedge, pyramid) that lists more
 * points than its type has, as FEM solvers write quadratic cells with the linear type (a
 * hexahedron of 20 points), keeps its first points, its corners, with a warning: VTK's and
 * ParaView's filters draw such a cell by its corners too.
 */
void CheckCellTypes(ReadContext& context, vtkUnstructuredGrid* ug, const std::string& what)
{
  vtkCellArray* cells = ug->GetCells();
  vtkUnsignedCharArray* types = ug->GetCellTypesArray();
  const vtkIdType numberOfCells = cells ? cells->GetNumberOfCells() : 0;
  if (numberOfCells == 0)
  {
    return;
  }
  if (!types || types->GetNumberOfTuples() != numberOfCells)
  {
    Fail(what + ": the numbers of cells and cell types differ");
  }
  const bool degrees = ug->GetCellData()->GetArray("HigherOrderDegrees") != nullptr;
  vtkIdType longCells = 0, firstLong = -1;
  for (vtkIdType i = 0; i < numberOfCells; ++i)
  {
    const int type = types->GetValue(i);
    const vtkIdType npts = cells->GetCellSize(i);
    CellSize size{ 0, false };
    if (!CellTypeSize(type, size) || (type == VTK_POLYHEDRON && !ug->GetFaces()))
    {
      Fail(what + ": cell " + std::to_string(static_cast<long long>(i)) + " has an invalid or " +
        "unsupported cell type " + std::to_string(type));
    }
    if (!size.AtLeast && npts > size.Size && LinearCellName(type))
    {
      firstLong = longCells++ == 0 ? i : firstLong;
      continue;
    }
    // (a cell array "HigherOrderDegrees" gives the orders instead: VTK reads them from it)
    if ((size.AtLeast ? npts < size.Size : npts != size.Size) ||
      (!degrees && !HigherOrderSizeValid(type, npts)))
    {
      const bool tooFew = size.AtLeast ? npts < size.Size : npts != size.Size;
      Fail(what + ": cell " + std::to_string(static_cast<long long>(i)) + " of type " +
        std::to_string(type) + " has " + std::to_string(static_cast<long long>(npts)) +
        " points, " +
        (tooFew
            ? "expected " + std::string(size.AtLeast ? "at least " : "") + std::to_string(size.Size)
            : std::string("a number no order of a cell of its type has")));
    }
  }
  if (longCells == 0)
  {
    return;
  }
  const int type = types->GetValue(firstLong);
  const vtkIdType npts = cells->GetCellSize(firstLong);
  CellSize size{ 0, false };
  CellTypeSize(type, size);
  // The corners only: a new cell array (the dataset is the reader's copy).
  vtkNew<vtkCellArray> corners;
  corners->AllocateExact(numberOfCells, cells->GetNumberOfConnectivityIds());
  vtkNew<vtkIdList> ids;
  for (vtkIdType i = 0; i < numberOfCells; ++i)
  {
    cells->GetCellAtId(i, ids);
    CellSize cellSize{ 0, false };
    CellTypeSize(types->GetValue(i), cellSize);
    const bool linear = !cellSize.AtLeast && LinearCellName(types->GetValue(i));
    corners->InsertNextCell(
      linear ? std::min<vtkIdType>(cellSize.Size, ids->GetNumberOfIds()) : ids->GetNumberOfIds(),
      ids->GetPointer(0));
  }
  vtkSmartPointer<vtkIdTypeArray> faceLocations = ug->GetFaceLocations();
  vtkSmartPointer<vtkIdTypeArray> faces = ug->GetFaces();
  vtkSmartPointer<vtkUnsignedCharArray> keptTypes = types;
  if (faces)
  {
    ug->SetCells(keptTypes, corners, faceLocations, faces);
  }
  else
  {
    ug->SetCells(keptTypes, corners);
  }
  context.Warn(what + ": " + std::to_string(static_cast<long long>(longCells)) +
    (longCells == 1 ? " cell lists" : " cells list") +
    " more points than a cell of its linear type has (cell " +
    std::to_string(static_cast<long long>(firstLong)) + ": a " + LinearCellName(type) + ", type " +
    std::to_string(type) + ", of " + std::to_string(static_cast<long long>(npts)) +
    " points, a quadratic cell written with the linear type): drawn by the corners (the first " +
    std::to_string(size.Size) + " points), as VTK and ParaView draw it");
}

/**
 * Leaves out, with a warning, the cells of a polydata with fewer points than their kind needs
 * (a vertex 1, a line 2, a polygon or a strip 3), and their cell data: a reader gives them for a
 * file whose lists were shifted (a PLY face that lists 0 vertices), and VTK's filters read
 * outside the connectivity for them (vtkPolyDataNormals crashed in vtkCellLinks::BuildLinks).
 */
void DropDegenerateCells(ReadContext& context, vtkPolyData* pd, const std::string& what)
{
  vtkCellArray* arrays[4] = { pd->GetVerts(), pd->GetLines(), pd->GetPolys(), pd->GetStrips() };
  const vtkIdType minimum[4] = { 1, 2, 3, 3 };
  vtkIdType dropped = 0, first = -1, firstSize = 0, offset = 0;
  for (int k = 0; k < 4; ++k)
  {
    const vtkIdType cells = arrays[k] ? arrays[k]->GetNumberOfCells() : 0;
    for (vtkIdType c = 0; c < cells; ++c)
    {
      const vtkIdType size = arrays[k]->GetCellSize(c);
      if (size < minimum[k])
      {
        if (dropped++ == 0)
        {
          first = offset + c;
          firstSize = size;
        }
      }
    }
    offset += cells;
  }
  if (dropped == 0)
  {
    return;
  }
  vtkNew<vtkCellData> kept;
  kept->CopyAllocate(pd->GetCellData(), pd->GetNumberOfCells() - dropped);
  vtkNew<vtkIdList> ids;
  vtkIdType from = 0, to = 0;
  for (int k = 0; k < 4; ++k)
  {
    if (!arrays[k] || arrays[k]->GetNumberOfCells() == 0)
    {
      continue;
    }
    vtkNew<vtkCellArray> cleaned;
    for (vtkIdType c = 0; c < arrays[k]->GetNumberOfCells(); ++c, ++from)
    {
      arrays[k]->GetCellAtId(c, ids);
      if (ids->GetNumberOfIds() >= minimum[k])
      {
        cleaned->InsertNextCell(ids);
        kept->CopyData(pd->GetCellData(), from, to++);
      }
    }
    vtkCellArray* replaced = cleaned;
    switch (k)
    {
      case 0:
        pd->SetVerts(replaced);
        break;
      case 1:
        pd->SetLines(replaced);
        break;
      case 2:
        pd->SetPolys(replaced);
        break;
      default:
        pd->SetStrips(replaced);
        break;
    }
  }
  pd->GetCellData()->ShallowCopy(kept);
  context.Warn(what + ": " + std::to_string(static_cast<long long>(dropped)) + " cell" +
    (dropped == 1 ? " has" : "s have") + " fewer points than a cell of " +
    (dropped == 1 ? "its" : "their") + " kind needs (cell " +
    std::to_string(static_cast<long long>(first)) + " lists " +
    std::to_string(static_cast<long long>(firstSize)) + "): left out");
}

/** True when every component of the array is a finite number. */
bool AllFinite(vtkDataArray* array)
{
  const vtkIdType count = array->GetNumberOfValues();
  if (auto* f = vtkFloatArray::FastDownCast(array))
  {
    const float* p = f->GetPointer(0);
    return std::all_of(p, p + count, [](float v) { return std::isfinite(v); });
  }
  if (auto* d = vtkDoubleArray::FastDownCast(array))
  {
    const double* p = d->GetPointer(0);
    return std::all_of(p, p + count, [](double v) { return std::isfinite(v); });
  }
  const int nc = array->GetNumberOfComponents();
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < nc; ++c)
    {
      if (!std::isfinite(array->GetComponent(i, c)))
      {
        return false;
      }
    }
  }
  return true;
}

} // namespace

//------------------------------------------------------------------------------
void ValidateDataSet(ReadContext& context, vtkDataSet* ds, const std::string& what)
{
  const vtkIdType n = ds->GetNumberOfPoints();
  if (auto* pd = vtkPolyData::SafeDownCast(ds))
  {
    CheckCells(pd->GetVerts(), n, what);
    CheckCells(pd->GetLines(), n, what);
    CheckCells(pd->GetPolys(), n, what);
    CheckCells(pd->GetStrips(), n, what);
    DropDegenerateCells(context, pd, what);
  }
  else if (auto* ug = vtkUnstructuredGrid::SafeDownCast(ds))
  {
    CheckCells(ug->GetCells(), n, what);
    CheckCellTypes(context, ug, what);
  }
  else if (auto* image = vtkImageData::SafeDownCast(ds))
  {
    // An inverted extent (a header number made huge) gives a negative number of points, with
    // which the surface filter reads far outside the arrays.
    int extent[6];
    image->GetExtent(extent);
    double count = 1.0;
    for (int a = 0; a < 3; ++a)
    {
      const double size = static_cast<double>(extent[2 * a + 1]) - extent[2 * a] + 1.0;
      if (size < 0.0)
      {
        Fail(what + ": the image's extent along " + std::string(1, static_cast<char>('x' + a)) +
          " runs backwards (from " + std::to_string(extent[2 * a]) + " to " +
          std::to_string(extent[2 * a + 1]) + ")");
      }
      count *= size;
    }
    if (count != static_cast<double>(n))
    {
      Fail(what + ": the image's extent does not give its number of points");
    }
  }
  else if (auto* sg = vtkStructuredGrid::SafeDownCast(ds))
  {
    int dims[3];
    sg->GetDimensions(dims);
    if (static_cast<double>(dims[0]) * dims[1] * dims[2] != static_cast<double>(n))
    {
      Fail(what + ": the structured grid has " + std::to_string(static_cast<long long>(n)) +
        " points but its dimensions are " + std::to_string(dims[0]) + "x" +
        std::to_string(dims[1]) + "x" + std::to_string(dims[2]));
    }
  }
  else if (auto* rg = vtkRectilinearGrid::SafeDownCast(ds))
  {
    int dims[3];
    rg->GetDimensions(dims);
    vtkDataArray* coordinates[3] = { rg->GetXCoordinates(), rg->GetYCoordinates(),
      rg->GetZCoordinates() };
    for (int i = 0; i < 3; ++i)
    {
      if (!coordinates[i] || coordinates[i]->GetNumberOfTuples() != dims[i])
      {
        Fail(what + ": the rectilinear grid's " + std::string(1, static_cast<char>('x' + i)) +
          " coordinates do not match its dimensions");
      }
    }
  }
  // Array sizes: a point or cell array shorter than the dataset is corrupt.
  for (int a = 0; a < ds->GetPointData()->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = ds->GetPointData()->GetAbstractArray(a);
    if (array && array->GetNumberOfTuples() < n)
    {
      Fail(what + ": point array " + Quote(array->GetName() ? array->GetName() : "") +
        " is shorter than the number of points");
    }
  }
  for (int a = 0; a < ds->GetCellData()->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = ds->GetCellData()->GetAbstractArray(a);
    if (array && array->GetNumberOfTuples() < ds->GetNumberOfCells())
    {
      Fail(what + ": cell array " + Quote(array->GetName() ? array->GetName() : "") +
        " is shorter than the number of cells");
    }
  }
  // Coordinates: GetBounds() skips NaN, so look at every explicit point (the points that are not
  // finite were dropped with their cells before: see WithoutNonFinitePoints()).
  if (auto* ps = vtkPointSet::SafeDownCast(ds))
  {
    if (ps->GetPoints() && !AllFinite(ps->GetPoints()->GetData()))
    {
      Fail(what + ": point coordinates are not finite (NaN or infinity)");
    }
  }
  if (n > 0)
  {
    double bounds[6];
    ds->GetBounds(bounds);
    for (double b : bounds)
    {
      if (!std::isfinite(b))
      {
        Fail(what + ": point coordinates are not finite");
      }
    }
  }
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkDataSet> WithoutNonFinitePoints(
  ReadContext& context, vtkDataSet* ds, const std::string& what)
{
  auto* ps = vtkPointSet::SafeDownCast(ds);
  vtkDataArray* coordinates = ps && ps->GetPoints() ? ps->GetPoints()->GetData() : nullptr;
  if (!coordinates || AllFinite(coordinates))
  {
    return ds;
  }
  const vtkIdType n = ds->GetNumberOfPoints();
  std::vector<char> bad(static_cast<std::size_t>(n), 0);
  vtkIdType badPoints = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    coordinates->GetTuple(i, p);
    bad[i] = !(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
    badPoints += bad[i];
  }
  if (badPoints == n)
  {
    Fail(what + ": no point has finite coordinates (all are NaN or infinity)");
  }
  if (auto* pd = vtkPolyData::SafeDownCast(ds))
  {
    for (vtkCellArray* cells : { pd->GetVerts(), pd->GetLines(), pd->GetPolys(), pd->GetStrips() })
    {
      CheckCells(cells, n, what);
    }
  }
  else if (auto* ug = vtkUnstructuredGrid::SafeDownCast(ds))
  {
    CheckCells(ug->GetCells(), n, what);
  }
  vtkNew<vtkIdList> keep;
  vtkNew<vtkIdList> ids;
  const vtkIdType cells = ds->GetNumberOfCells();
  for (vtkIdType c = 0; c < cells; ++c)
  {
    ds->GetCellPoints(c, ids);
    bool finite = true;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds() && finite; ++k)
    {
      finite = !bad[ids->GetId(k)];
    }
    if (finite)
    {
      keep->InsertNextId(c);
    }
  }
  if (cells > 0 && keep->GetNumberOfIds() == 0)
  {
    Fail(what + ": every cell uses a point whose coordinates are not finite (NaN or infinity)");
  }
  vtkSmartPointer<vtkDataSet> kept;
  if (auto* pd = vtkPolyData::SafeDownCast(ds))
  {
    // A polydata stays one (vtkExtractCells makes an unstructured grid): its other cells
    // deleted, then the points no cell uses (the non-finite ones among them) dropped.
    vtkNew<vtkPolyData> copy;
    copy->DeepCopy(pd);
    copy->BuildCells();
    vtkIdType next = 0;
    for (vtkIdType c = 0; c < cells; ++c)
    {
      if (next < keep->GetNumberOfIds() && keep->GetId(next) == c)
      {
        ++next;
      }
      else
      {
        copy->DeleteCell(c);
      }
    }
    copy->RemoveDeletedCells();
    vtkNew<vtkCleanPolyData> clean;
    clean->SetInputData(copy);
    clean->PointMergingOff();
    clean->ConvertLinesToPointsOff();
    clean->ConvertPolysToLinesOff();
    clean->ConvertStripsToPolysOff();
    clean->SetOutputPointsPrecision(vtkAlgorithm::DEFAULT_PRECISION);
    clean->Update();
    kept = clean->GetOutput();
  }
  else
  {
    vtkNew<vtkExtractCells> extract;
    extract->SetInputData(ds);
    extract->SetCellList(keep);
    extract->Update();
    kept = extract->GetOutput();
  }
  const vtkIdType dropped = cells - keep->GetNumberOfIds();
  context.Warn(what + ": " + std::to_string(static_cast<long long>(badPoints)) + " of " +
    std::to_string(static_cast<long long>(n)) + " points " + (badPoints == 1 ? "has" : "have") +
    " coordinates that are not finite (NaN or infinity): " + (badPoints == 1 ? "it" : "they") +
    " and the " + std::to_string(static_cast<long long>(dropped)) + " cell" +
    (dropped == 1 ? "" : "s") + " that use " + (badPoints == 1 ? "it" : "them") + " are left out");
  return kept;
}

//------------------------------------------------------------------------------
void ValidateBlocks(ReadContext& context, vtkDataObject* data, const std::string& what)
{
  auto* composite = vtkCompositeDataSet::SafeDownCast(data);
  if (!composite)
  {
    return;
  }
  vtkStylizeReader::ForEachBlock(composite,
    [&](vtkCompositeDataIterator* it, const std::string& name)
    {
      auto* ds = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
      if (!ds)
      {
        return; // (not a dataset: the caller decides what to do with it)
      }
      const std::string leafWhat = what + " (block " + Quote(name) + ")";
      vtkSmartPointer<vtkDataSet> kept = WithoutNonFinitePoints(context, ds, leafWhat);
      ValidateDataSet(context, kept, leafWhat);
      if (kept.GetPointer() != ds)
      {
        composite->SetDataSet(it, kept);
      }
    });
}
} // namespace vtkStylizeReaderInternal
