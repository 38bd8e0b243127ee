/**
 * Checks an image written by vtkstylize:
 *
 *   vtkStylizeCliCheckPNG FILE.png WIDTH HEIGHT [R,G,B]
 *
 * The file must be a PNG of WIDTH x HEIGHT pixels, and at least 0.5% of its pixels must differ
 * from the background colour R,G,B (in [0, 1], default 1,1,1) by more than 8 levels in some
 * channel, so that an image of the background alone fails. Prints one line and exits 0 on
 * success, 1 otherwise.
 */

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPointData.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  if (argc != 4 && argc != 5)
  {
    std::cerr << "usage: vtkStylizeCliCheckPNG FILE.png WIDTH HEIGHT [R,G,B]\n";
    return 2;
  }
  const int width = std::atoi(argv[2]);
  const int height = std::atoi(argv[3]);
  double background[3] = { 1.0, 1.0, 1.0 };
  if (argc == 5 &&
    std::sscanf(argv[4], "%lf,%lf,%lf", &background[0], &background[1], &background[2]) != 3)
  {
    std::cerr << "bad background " << argv[4] << "\n";
    return 2;
  }
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(argv[1]))
  {
    std::cout << "FAIL: " << argv[1] << " is not a readable PNG file\n";
    return 1;
  }
  reader->SetFileName(argv[1]);
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] != width || dims[1] != height)
  {
    std::cout << "FAIL: " << argv[1] << " is " << dims[0] << "x" << dims[1] << ", expected "
              << width << "x" << height << "\n";
    return 1;
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  const int nc = scalars ? scalars->GetNumberOfComponents() : 0;
  if (nc < 3)
  {
    std::cout << "FAIL: " << argv[1] << " has " << nc << " components, expected RGB\n";
    return 1;
  }
  const vtkIdType n = scalars->GetNumberOfTuples();
  vtkIdType foreground = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (std::abs(scalars->GetComponent(i, c) - 255.0 * background[c]) > 8.0)
      {
        ++foreground;
        break;
      }
    }
  }
  const double fraction = n > 0 ? static_cast<double>(foreground) / n : 0.0;
  if (fraction < 0.005)
  {
    std::cout << "FAIL: " << argv[1] << " shows almost only the background (" << foreground
              << " of " << n << " pixels differ)\n";
    return 1;
  }
  std::cout << "OK: " << argv[1] << " " << width << "x" << height << ", " << 100.0 * fraction
            << "% foreground\n";
  return 0;
}
