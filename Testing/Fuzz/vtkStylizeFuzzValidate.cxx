// libFuzzer target: the validation of what a reader gave (vtkStylizeReaderValidate.cxx), in this
// process. The input builds a small polydata or unstructured grid directly (cells of any size,
// type and point ids, in range or not); what the validation accepts then goes through the
// filters vtkstylize runs on a surface (vtkDataSetSurfaceFilter, vtkPolyDataNormals), which
// must not read out of bounds: the data that reaches the filters is valid.
#include "vtkStylizeReaderInternal.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <cstddef>
#include <cstdint>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size < 2)
  {
    return 0;
  }
  vtkObject::GlobalWarningDisplayOff();
  std::size_t at = 0;
  auto next = [&]() -> std::uint8_t { return at < size ? data[at++] : 0; };
  const bool grid = next() & 1;
  const int numberOfPoints = next() % 40;
  vtkNew<vtkPoints> points;
  for (int i = 0; i < numberOfPoints; ++i)
  {
    points->InsertNextPoint(0.37 * i, 0.11 * ((i * 7) % 13), 0.05 * ((i * 5) % 11));
  }
  vtkNew<vtkCellArray> cells[4];
  std::vector<unsigned char> types;
  while (at + 2 <= size && types.size() < 64)
  {
    const std::uint8_t kind = next();
    const int npts = next() % 24;
    std::vector<vtkIdType> ids;
    for (int k = 0; k < npts; ++k)
    {
      // (mostly in range; now and then one past the points or negative)
      const std::uint8_t b = next();
      ids.push_back(b < 250 ? b % (numberOfPoints ? numberOfPoints : 1) : numberOfPoints + b - 252);
    }
    cells[grid ? 0 : kind % 4]->InsertNextCell(npts, ids.data());
    // (no polyhedron: SetCells reads its face stream from the connectivity, a grid built here
    // cannot have one; the polyhedra of files are checked by vtkStylizeFuzzChecks)
    const int type = kind % 80;
    types.push_back(static_cast<unsigned char>(type == VTK_POLYHEDRON ? 255 : type));
  }
  vtkSmartPointer<vtkDataSet> ds;
  if (grid)
  {
    vtkNew<vtkUnstructuredGrid> ug;
    ug->SetPoints(points);
    std::vector<int> cellTypes(types.begin(), types.end());
    ug->SetCells(cellTypes.data(), cells[0]);
    ds = ug;
  }
  else
  {
    vtkNew<vtkPolyData> pd;
    pd->SetPoints(points);
    pd->SetVerts(cells[0]);
    pd->SetLines(cells[1]);
    pd->SetPolys(cells[2]);
    pd->SetStrips(cells[3]);
    ds = pd;
  }
  try
  {
    vtkStylizeReaderInternal::ReadContext context;
    vtkStylizeReaderInternal::ValidateDataSet(context, ds, "'fuzz'");
  }
  catch (const vtkStylizeReaderInternal::ReadFailure&)
  {
    return 0; // (refused: nothing reaches the filters)
  }
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(ds);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(surface->GetOutputPort());
  normals->Update();
  return 0;
}
