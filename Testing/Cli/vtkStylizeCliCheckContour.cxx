/**
 * Checks the contour of an image data file at a value, for the tests of vtkstylize's contour
 * value choice:
 *
 *   vtkStylizeCliCheckContour FILE.vti VALUE|mid
 *
 * Contours the active point scalars at VALUE (mid: the middle of their range) and counts the
 * connected regions of the surface and its boundary edges. Prints one line; exits 0 when the
 * surface is one closed piece (one region, no boundary edge), 1 when it is not (empty, several
 * pieces or open), 2 on a usage or read error.
 */

#include "vtkContourFilter.h"
#include "vtkDataArray.h"
#include "vtkFeatureEdges.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataConnectivityFilter.h"
#include "vtkXMLImageDataReader.h"

#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::cerr << "usage: vtkStylizeCliCheckContour FILE.vti VALUE|mid\n";
    return 2;
  }
  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName(argv[1]);
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (!scalars)
  {
    std::cout << "FAIL: " << argv[1] << " has no point scalars\n";
    return 2;
  }
  double range[2];
  scalars->GetRange(range, 0);
  const std::string v = argv[2];
  char* end = nullptr;
  const double value = v == "mid" ? 0.5 * (range[0] + range[1]) : std::strtod(v.c_str(), &end);
  if (v != "mid" && (end == v.c_str() || *end))
  {
    std::cout << "FAIL: bad value '" << v << "'\n";
    return 2;
  }
  vtkNew<vtkContourFilter> contour;
  contour->SetInputData(image);
  contour->SetValue(0, value);
  vtkNew<vtkPolyDataConnectivityFilter> regions;
  regions->SetInputConnection(contour->GetOutputPort());
  regions->SetExtractionModeToAllRegions();
  regions->Update();
  const int count = regions->GetNumberOfExtractedRegions();
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputConnection(contour->GetOutputPort());
  edges->BoundaryEdgesOn();
  edges->FeatureEdgesOff();
  edges->NonManifoldEdgesOn();
  edges->ManifoldEdgesOff();
  edges->Update();
  const vtkIdType open = edges->GetOutput()->GetNumberOfCells();
  const vtkIdType cells = contour->GetOutput()->GetNumberOfCells();
  const bool closed = cells > 0 && count == 1 && open == 0;
  std::cout << (closed ? "OK" : "NOT CLOSED") << ": the contour at " << value << " (range ["
            << range[0] << ", " << range[1] << "]) has " << cells << " cells, " << count
            << " region(s), " << open << " boundary or non-manifold edge(s)\n";
  return closed ? 0 : 1;
}
