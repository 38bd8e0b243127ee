// The pixel-art tests' shared helpers: the scene through a pixel-art pass, art-pixel colours read
// back from the pixelated layer, exact dither set-ups.
#ifndef PixelArtTestHelpers_h
#define PixelArtTestHelpers_h

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkPixelArtPass.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkStylizeGBufferPass.h"
#include "vtkStylizeTestUtilities.h"
#include "vtkUnsignedCharArray.h"
#include <algorithm>
#include <array>
#include <functional>

namespace stylizetest
{
constexpr int W = 400, H = 300;

using Configure = std::function<void(vtkRenderer*, vtkPixelArtPass*)>;

/** RGB (0..255) of pixel (x, y) of an 8-bit image. */
inline std::array<double, 3> Pixel(vtkImageData* img, int x, int y)
{
  int d[3];
  img->GetDimensions(d);
  vtkDataArray* s = img->GetPointData()->GetScalars();
  const vtkIdType i = static_cast<vtkIdType>(y) * d[0] + x;
  return { s->GetComponent(i, 0), s->GetComponent(i, 1), s->GetComponent(i, 2) };
}

/** One sample per art pixel (its centre pixel) of a w x h image with the given block size. */
inline vtkSmartPointer<vtkImageData> ArtPixels(vtkImageData* img, int block)
{
  int d[3];
  img->GetDimensions(d);
  const int nx = (d[0] + block - 1) / block, ny = (d[1] + block - 1) / block;
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->SetDimensions(nx, ny, 1);
  out->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  vtkDataArray* o = out->GetPointData()->GetScalars();
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const auto p = Pixel(
        img, std::min(i * block + block / 2, d[0] - 1), std::min(j * block + block / 2, d[1] - 1));
      for (int c = 0; c < 3; ++c)
      {
        o->SetComponent(static_cast<vtkIdType>(j) * nx + i, c, p[c]);
      }
    }
  }
  return out;
}

/**
 * A flat picture for exact tests: nx x ny cells of `block` x `block` window pixels with the
 * given 8-bit colours, seen by a parallel camera so that each cell covers its block exactly
 * (world unit = one pixel), lit by its ambient term alone (colour = cell colour exactly). The
 * world origin lies `originCells` cells from the lower-left corner.
 */
inline void AddCellPicture(vtkRenderer* ren, int nx, int ny, int block,
  const std::function<std::array<unsigned char, 3>(int, int)>& colour,
  const int originCells[2] = nullptr)
{
  const double x0 = originCells ? -originCells[0] * block : 0.0;
  const double y0 = originCells ? -originCells[1] * block : 0.0;
  vtkNew<vtkPoints> points;
  for (int j = 0; j <= ny; ++j)
  {
    for (int i = 0; i <= nx; ++i)
    {
      points->InsertNextPoint(x0 + i * block, y0 + j * block, 0.0);
    }
  }
  vtkNew<vtkCellArray> quads;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const vtkIdType a = static_cast<vtkIdType>(j) * (nx + 1) + i;
      const vtkIdType ids[4] = { a, a + 1, a + nx + 2, a + nx + 1 };
      quads->InsertNextCell(4, ids);
      const auto c = colour(i, j);
      colours->InsertNextTypedTuple(c.data());
    }
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(points);
  pd->SetPolys(quads);
  pd->GetCellData()->SetScalars(colours);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(pd);
  mapper->SetColorModeToDirectScalars();
  mapper->SetScalarModeToUseCellData();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  actor->GetProperty()->SetSpecular(0.0);
  ren->AddActor(actor);
  SetupLights(ren, "none");
  const double w = nx * block, h = ny * block;
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetParallelProjection(true);
  cam->SetFocalPoint(x0 + w / 2, y0 + h / 2, 0);
  cam->SetPosition(x0 + w / 2, y0 + h / 2, 1000);
  cam->SetViewUp(0, 1, 0);
  cam->SetParallelScale(h / 2);
  cam->SetClippingRange(500, 1500);
}

/** A pass set up for the exact tests: full-precision G-buffer, no edges. */
inline void ExactSetup(vtkPixelArtPass* p, int block)
{
  p->GetGBufferPass()->SetPrecision(vtkStylizeGBufferPass::FULL);
  p->SetPixelSize(block);
  p->SetEdgeDetector(vtkPixelArtPass::NO_EDGES);
  p->DepthEdgesOff();
}

inline bool Differs(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return std::abs(a[0] - b[0]) > 8 || std::abs(a[1] - b[1]) > 8 || std::abs(a[2] - b[2]) > 8;
}
}

#endif
