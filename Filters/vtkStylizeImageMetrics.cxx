#include "vtkStylizeImageMetrics.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <cmath>
#include <limits>

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
