#include "vtkStylizeImageMetrics.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkStylizeImageMetrics);

namespace
{
bool Compatible(vtkImageData* a, vtkImageData* b, vtkDataArray*& sa, vtkDataArray*& sb)
{
  if (!a || !b)
  {
    return false;
  }
  int da[3], db[3];
  a->GetDimensions(da);
  b->GetDimensions(db);
  sa = a->GetPointData()->GetScalars();
  sb = b->GetPointData()->GetScalars();
  return da[0] == db[0] && da[1] == db[1] && da[2] == db[2] && sa && sb &&
    sa->GetNumberOfComponents() == sb->GetNumberOfComponents() &&
    sa->GetNumberOfTuples() == sb->GetNumberOfTuples();
}
}

void vtkStylizeImageMetrics::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

double vtkStylizeImageMetrics::MaximumDifference(vtkImageData* a, vtkImageData* b)
{
  vtkDataArray *sa, *sb;
  if (!Compatible(a, b, sa, sb))
  {
    return -1.0;
  }
  double worst = 0.0;
  const int nc = sa->GetNumberOfComponents();
  for (vtkIdType i = 0; i < sa->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < nc; ++c)
    {
      const double d = std::abs(sa->GetComponent(i, c) - sb->GetComponent(i, c));
      worst = (d > worst || std::isnan(d)) ? d : worst;
    }
  }
  return worst;
}

vtkIdType vtkStylizeImageMetrics::CountDifferences(vtkImageData* a, vtkImageData* b, double tolerance)
{
  vtkDataArray *sa, *sb;
  if (!Compatible(a, b, sa, sb))
  {
    return -1;
  }
  vtkIdType count = 0;
  const int nc = sa->GetNumberOfComponents();
  for (vtkIdType i = 0; i < sa->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < nc; ++c)
    {
      const double d = std::abs(sa->GetComponent(i, c) - sb->GetComponent(i, c));
      if (!(d <= tolerance))
      {
        ++count;
        break;
      }
    }
  }
  return count;
}

double vtkStylizeImageMetrics::PSNR(vtkImageData* a, vtkImageData* b, double peak)
{
  vtkDataArray *sa, *sb;
  if (!Compatible(a, b, sa, sb))
  {
    return 0.0;
  }
  double sum = 0.0;
  const int nc = sa->GetNumberOfComponents();
  const vtkIdType n = sa->GetNumberOfTuples() * nc;
  for (vtkIdType i = 0; i < sa->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < nc; ++c)
    {
      const double d = sa->GetComponent(i, c) - sb->GetComponent(i, c);
      sum += d * d;
    }
  }
  if (n == 0 || sum == 0.0)
  {
    return std::numeric_limits<double>::infinity();
  }
  return 10.0 * std::log10(peak * peak / (sum / static_cast<double>(n)));
}

vtkIdType vtkStylizeImageMetrics::CountNonFinite(vtkDataArray* array)
{
  if (!array)
  {
    return 0;
  }
  vtkIdType count = 0;
  const int nc = array->GetNumberOfComponents();
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < nc; ++c)
    {
      count += std::isfinite(array->GetComponent(i, c)) ? 0 : 1;
    }
  }
  return count;
}

//------------------------------------------------------------------------------
double vtkStylizeImageMetrics::SSIM(vtkImageData* a, vtkImageData* b, double peak)
{
  if (!a || !b)
  {
    return -2.0;
  }
  int da[3], db[3];
  a->GetDimensions(da);
  b->GetDimensions(db);
  vtkDataArray* sa = a->GetPointData()->GetScalars();
  vtkDataArray* sb = b->GetPointData()->GetScalars();
  if (!sa || !sb || da[0] != db[0] || da[1] != db[1] || da[2] != 1 || db[2] != 1)
  {
    return -2.0;
  }
  const int w = da[0], h = da[1];
  auto luminance = [](vtkDataArray* s, vtkIdType i) {
    const int n = s->GetNumberOfComponents();
    if (n < 3)
    {
      return s->GetComponent(i, 0);
    }
    return (s->GetComponent(i, 0) + s->GetComponent(i, 1) + s->GetComponent(i, 2)) / 3.0;
  };
  std::vector<double> x(static_cast<size_t>(w) * h), y(x.size());
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(x.size()); ++i)
  {
    x[i] = luminance(sa, i);
    y[i] = luminance(sb, i);
  }
  const int radius = 5;
  double kernel[2 * radius + 1];
  for (int i = -radius; i <= radius; ++i)
  {
    kernel[i + radius] = std::exp(-0.5 * i * i / (1.5 * 1.5));
  }
  const double c1 = (0.01 * peak) * (0.01 * peak);
  const double c2 = (0.03 * peak) * (0.03 * peak);
  // Window centres: inside the image by the radius, or the centre of a small image.
  const int x0 = w > 2 * radius ? radius : w / 2, x1 = w > 2 * radius ? w - radius : w / 2 + 1;
  const int y0 = h > 2 * radius ? radius : h / 2, y1 = h > 2 * radius ? h - radius : h / 2 + 1;
  double sum = 0.0;
  long long count = 0;
  for (int cy = y0; cy < y1; ++cy)
  {
    for (int cx = x0; cx < x1; ++cx)
    {
      double wsum = 0, mx = 0, my = 0, mxx = 0, myy = 0, mxy = 0;
      for (int j = -radius; j <= radius; ++j)
      {
        const int yy = cy + j;
        if (yy < 0 || yy >= h)
        {
          continue;
        }
        for (int i = -radius; i <= radius; ++i)
        {
          const int xx = cx + i;
          if (xx < 0 || xx >= w)
          {
            continue;
          }
          const double k = kernel[i + radius] * kernel[j + radius];
          const size_t p = static_cast<size_t>(yy) * w + xx;
          wsum += k;
          mx += k * x[p];
          my += k * y[p];
          mxx += k * x[p] * x[p];
          myy += k * y[p] * y[p];
          mxy += k * x[p] * y[p];
        }
      }
      mx /= wsum;
      my /= wsum;
      const double vx = std::max(0.0, mxx / wsum - mx * mx);
      const double vy = std::max(0.0, myy / wsum - my * my);
      const double cxy = mxy / wsum - mx * my;
      sum += ((2 * mx * my + c1) * (2 * cxy + c2)) / ((mx * mx + my * my + c1) * (vx + vy + c2));
      ++count;
    }
  }
  return count > 0 ? sum / count : -2.0;
}
