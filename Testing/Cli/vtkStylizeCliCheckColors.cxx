/**
 * Colour checks of images written by vtkstylize (PNG, RGB):
 *
 *   vtkStylizeCliCheckColors gray FILE.png R,G,B
 *       every pixel that is not the background R,G,B (in [0, 1]) is a neutral gray (r == g == b);
 *       the image must show at least 1% of such pixels.
 *   vtkStylizeCliCheckColors off-levels FILE.png K MIN
 *       at least the share MIN of the pixels has a channel that is none of the K levels
 *       round(255 i / (K - 1)) (so the image is not only colours of the K-level palette).
 *   vtkStylizeCliCheckColors overlay PLAIN.png BARE.png STYLED.png MIN
 *       the overlay pixels (where PLAIN, with annotations, differs from BARE, the same render
 *       without them) must be identical in STYLED for at least the share MIN of them.
 *
 * Prints one line; exits 0 when the check holds, 1 when not, 2 on a usage or read error.
 */

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
struct Image
{
  int Width = 0;
  int Height = 0;
  std::vector<int> RGB; // 3 per pixel
};

bool Read(const char* path, Image& image)
{
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path))
  {
    std::cout << "ERROR: " << path << " is not a readable PNG file\n";
    return false;
  }
  reader->SetFileName(path);
  reader->Update();
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  vtkDataArray* scalars = reader->GetOutput()->GetPointData()->GetScalars();
  if (!scalars || scalars->GetNumberOfComponents() < 3)
  {
    std::cout << "ERROR: " << path << " is not an RGB image\n";
    return false;
  }
  image.Width = dims[0];
  image.Height = dims[1];
  const vtkIdType n = scalars->GetNumberOfTuples();
  image.RGB.resize(3 * n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      image.RGB[3 * i + c] = static_cast<int>(scalars->GetComponent(i, c));
    }
  }
  return true;
}

int Gray(const char* path, const char* background)
{
  double bg[3];
  Image image;
  if (std::sscanf(background, "%lf,%lf,%lf", &bg[0], &bg[1], &bg[2]) != 3 || !Read(path, image))
  {
    return 2;
  }
  const size_t n = image.RGB.size() / 3;
  size_t shown = 0, colored = 0;
  int example[3] = { 0, 0, 0 };
  for (size_t i = 0; i < n; ++i)
  {
    const int* p = &image.RGB[3 * i];
    bool isBackground = true;
    for (int c = 0; c < 3; ++c)
    {
      isBackground =
        isBackground && std::abs(p[c] - static_cast<int>(std::lround(255 * bg[c]))) <= 1;
    }
    if (isBackground)
    {
      continue;
    }
    ++shown;
    if (p[0] != p[1] || p[1] != p[2])
    {
      if (colored++ == 0)
      {
        std::copy(p, p + 3, example);
      }
    }
  }
  if (shown < n / 100)
  {
    std::cout << "FAIL: " << path << " shows almost only the background\n";
    return 1;
  }
  if (colored > 0)
  {
    std::cout << "FAIL: " << path << ": " << colored << " of " << shown
              << " non-background pixels are not gray, e.g. (" << example[0] << ", " << example[1]
              << ", " << example[2] << ")\n";
    return 1;
  }
  std::cout << "OK: " << path << ": all " << shown << " non-background pixels are gray\n";
  return 0;
}

int OffLevels(const char* path, int levels, double minimum)
{
  Image image;
  if (levels < 2 || !Read(path, image))
  {
    return 2;
  }
  std::vector<bool> isLevel(256, false);
  for (int i = 0; i < levels; ++i)
  {
    isLevel[static_cast<size_t>(std::lround(255.0 * i / (levels - 1)))] = true;
  }
  const size_t n = image.RGB.size() / 3;
  size_t off = 0;
  for (size_t i = 0; i < n; ++i)
  {
    const int* p = &image.RGB[3 * i];
    off += (!isLevel[p[0]] || !isLevel[p[1]] || !isLevel[p[2]]) ? 1 : 0;
  }
  const double share = n ? static_cast<double>(off) / n : 0.0;
  const bool ok = share >= minimum;
  std::cout << (ok ? "OK: " : "FAIL: ") << path << ": " << 100.0 * share
            << "% of the pixels are off the " << levels << " levels (minimum " << 100.0 * minimum
            << "%)\n";
  return ok ? 0 : 1;
}

int Overlay(const char* plainPath, const char* barePath, const char* styledPath, double minimum)
{
  Image plain, bare, styled;
  if (!Read(plainPath, plain) || !Read(barePath, bare) || !Read(styledPath, styled))
  {
    return 2;
  }
  if (plain.RGB.size() != bare.RGB.size() || plain.RGB.size() != styled.RGB.size())
  {
    std::cout << "ERROR: the images differ in size\n";
    return 2;
  }
  const size_t n = plain.RGB.size() / 3;
  size_t overlay = 0, same = 0;
  for (size_t i = 0; i < n; ++i)
  {
    bool drawn = false, equal = true;
    for (int c = 0; c < 3; ++c)
    {
      drawn = drawn || plain.RGB[3 * i + c] != bare.RGB[3 * i + c];
      equal = equal && plain.RGB[3 * i + c] == styled.RGB[3 * i + c];
    }
    if (drawn)
    {
      ++overlay;
      same += equal ? 1 : 0;
    }
  }
  if (overlay < 20)
  {
    std::cout << "FAIL: only " << overlay << " overlay pixels: " << plainPath << " and " << barePath
              << " barely differ\n";
    return 1;
  }
  const double share = static_cast<double>(same) / overlay;
  const bool ok = share >= minimum;
  std::cout << (ok ? "OK: " : "FAIL: ") << styledPath << ": " << same << " of " << overlay
            << " overlay pixels (" << 100.0 * share << "%) are as in " << plainPath << " (minimum "
            << 100.0 * minimum << "%)\n";
  return ok ? 0 : 1;
}

/** The number of pixels where `plain` differs from `bare`, or -1 on an error. */
long OverlayCount(const char* plainPath, const char* barePath)
{
  Image plain, bare;
  if (!Read(plainPath, plain) || !Read(barePath, bare) || plain.RGB.size() != bare.RGB.size())
  {
    return -1;
  }
  long overlay = 0;
  for (size_t i = 0; i < plain.RGB.size(); i += 3)
  {
    bool drawn = false;
    for (int c = 0; c < 3; ++c)
    {
      drawn = drawn || plain.RGB[i + c] != bare.RGB[i + c];
    }
    overlay += drawn ? 1 : 0;
  }
  return overlay;
}

int OverlayScale(
  const char* plain1, const char* bare1, const char* plain2, const char* bare2, double tolerance)
{
  const long a = OverlayCount(plain1, bare1), b = OverlayCount(plain2, bare2);
  if (a < 0 || b < 0)
  {
    std::cout << "ERROR: unreadable images, or images of different sizes\n";
    return 2;
  }
  if (a < 20 || b < 20)
  {
    std::cout << "FAIL: too few overlay pixels (" << a << ", " << b << ")\n";
    return 1;
  }
  const double ratio = static_cast<double>(a) / b;
  const bool ok = std::abs(ratio - 1.0) <= tolerance;
  std::cout << (ok ? "OK: " : "FAIL: ") << a << " overlay pixels in " << plain1 << ", " << b
            << " in " << plain2 << ": ratio " << ratio << " (tolerance " << tolerance << ")\n";
  return ok ? 0 : 1;
}
}

int main(int argc, char* argv[])
{
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "gray" && argc == 4)
  {
    return Gray(argv[2], argv[3]);
  }
  if (mode == "off-levels" && argc == 5)
  {
    return OffLevels(argv[2], std::atoi(argv[3]), std::atof(argv[4]));
  }
  if (mode == "overlay" && argc == 6)
  {
    return Overlay(argv[2], argv[3], argv[4], std::atof(argv[5]));
  }
  if (mode == "overlay-scale" && argc == 7)
  {
    return OverlayScale(argv[2], argv[3], argv[4], argv[5], std::atof(argv[6]));
  }
  std::cerr << "usage: vtkStylizeCliCheckColors gray FILE.png R,G,B\n"
               "       vtkStylizeCliCheckColors off-levels FILE.png K MIN\n"
               "       vtkStylizeCliCheckColors overlay PLAIN.png BARE.png STYLED.png MIN\n"
               "       vtkStylizeCliCheckColors overlay-scale PLAIN.png BARE.png PLAIN2.png "
               "BARE2.png TOL\n";
  return 2;
}
