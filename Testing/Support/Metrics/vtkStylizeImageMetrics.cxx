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

vtkIdType vtkStylizeImageMetrics::CountDifferences(
  vtkImageData* a, vtkImageData* b, double tolerance)
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
  auto luminance = [](vtkDataArray* s, vtkIdType i)
  {
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

namespace
{
/** An image as planes of doubles: width, height and the first three (or one) components. */
struct Planes
{
  int W = 0;
  int H = 0;
  std::vector<double> R, G, B;

  bool Read(vtkImageData* image)
  {
    vtkDataArray* s = image ? image->GetPointData()->GetScalars() : nullptr;
    if (!s)
    {
      return false;
    }
    int d[3];
    image->GetDimensions(d);
    if (d[2] != 1)
    {
      return false;
    }
    this->W = d[0];
    this->H = d[1];
    const size_t n = static_cast<size_t>(this->W) * this->H;
    const int nc = s->GetNumberOfComponents();
    this->R.resize(n);
    this->G.resize(n);
    this->B.resize(n);
    for (size_t i = 0; i < n; ++i)
    {
      const vtkIdType t = static_cast<vtkIdType>(i);
      this->R[i] = s->GetComponent(t, 0);
      this->G[i] = s->GetComponent(t, nc >= 3 ? 1 : 0);
      this->B[i] = s->GetComponent(t, nc >= 3 ? 2 : 0);
    }
    return true;
  }

  /** Rec. 709 luminance in [0, 1] (8-bit components). */
  std::vector<double> Luminance() const
  {
    std::vector<double> l(this->R.size());
    for (size_t i = 0; i < l.size(); ++i)
    {
      l[i] = (0.2126 * this->R[i] + 0.7152 * this->G[i] + 0.0722 * this->B[i]) / 255.0;
    }
    return l;
  }

  bool SameSize(const Planes& o) const { return this->W == o.W && this->H == o.H; }
};

/** The surface pixels of a key-coloured mask image (empty when the image is unusable). */
std::vector<char> SurfaceMask(vtkImageData* image, const double key[3], int& w, int& h)
{
  Planes p;
  if (!p.Read(image))
  {
    return {};
  }
  w = p.W;
  h = p.H;
  std::vector<char> m(p.R.size());
  for (size_t i = 0; i < m.size(); ++i)
  {
    m[i] = std::abs(p.R[i] - key[0]) > 1.0 || std::abs(p.G[i] - key[1]) > 1.0 ||
      std::abs(p.B[i] - key[2]) > 1.0;
  }
  return m;
}

/** Separable Gaussian blur of a plane (edges clamped). */
std::vector<double> Blur(const std::vector<double>& v, int w, int h, double sigma)
{
  if (sigma <= 0.0)
  {
    return v;
  }
  const int r = static_cast<int>(std::ceil(3.0 * sigma));
  std::vector<double> k(2 * r + 1);
  double ks = 0.0;
  for (int i = -r; i <= r; ++i)
  {
    ks += k[i + r] = std::exp(-0.5 * i * i / (sigma * sigma));
  }
  for (double& x : k)
  {
    x /= ks;
  }
  std::vector<double> t(v.size()), o(v.size());
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      double s = 0.0;
      for (int i = -r; i <= r; ++i)
      {
        s += k[i + r] * v[static_cast<size_t>(y) * w + std::min(w - 1, std::max(0, x + i))];
      }
      t[static_cast<size_t>(y) * w + x] = s;
    }
  }
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      double s = 0.0;
      for (int i = -r; i <= r; ++i)
      {
        s += k[i + r] * t[static_cast<size_t>(std::min(h - 1, std::max(0, y + i))) * w + x];
      }
      o[static_cast<size_t>(y) * w + x] = s;
    }
  }
  return o;
}
}

double vtkStylizeImageMetrics::ToneCorrelation(vtkImageData* styled, vtkImageData* reference,
  vtkImageData* mask, const double key[3], double sigma)
{
  Planes a, b;
  int w = 0, h = 0;
  const std::vector<char> m = SurfaceMask(mask, key, w, h);
  if (!a.Read(styled) || !b.Read(reference) || !a.SameSize(b) || a.W != w || a.H != h)
  {
    return -2.0;
  }
  // The blur averages the surface only (normalized convolution): the background's paper would
  // otherwise brighten every thin part and silhouette, and a pencil that reproduced the lit
  // tone exactly would score 0.81 on the cow.
  std::vector<double> l = a.Luminance(), weight(m.size());
  for (size_t i = 0; i < m.size(); ++i)
  {
    weight[i] = m[i] ? 1.0 : 0.0;
    l[i] *= weight[i];
  }
  std::vector<double> x = Blur(l, w, h, sigma);
  const std::vector<double> cover = Blur(weight, w, h, sigma);
  for (size_t i = 0; i < m.size(); ++i)
  {
    x[i] = cover[i] > 0.0 ? x[i] / cover[i] : 0.0;
  }
  const std::vector<double> y = b.Luminance();
  double n = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
  for (size_t i = 0; i < m.size(); ++i)
  {
    if (m[i])
    {
      n += 1;
      sx += x[i];
      sy += y[i];
      sxx += x[i] * x[i];
      syy += y[i] * y[i];
      sxy += x[i] * y[i];
    }
  }
  if (n < 2)
  {
    return -2.0;
  }
  const double vx = sxx - sx * sx / n, vy = syy - sy * sy / n, cxy = sxy - sx * sy / n;
  return vx > 0 && vy > 0 ? cxy / std::sqrt(vx * vy) : 0.0;
}

double vtkStylizeImageMetrics::PaperShare(
  vtkImageData* styled, vtkImageData* mask, const double key[3], double threshold)
{
  Planes a;
  int w = 0, h = 0;
  const std::vector<char> m = SurfaceMask(mask, key, w, h);
  if (!a.Read(styled) || a.W != w || a.H != h)
  {
    return -2.0;
  }
  const std::vector<double> l = a.Luminance();
  double n = 0, paper = 0;
  for (size_t i = 0; i < m.size(); ++i)
  {
    if (m[i])
    {
      n += 1;
      paper += l[i] >= threshold ? 1 : 0;
    }
  }
  return n > 0 ? paper / n : -2.0;
}

double vtkStylizeImageMetrics::BandShare(vtkImageData* styled, vtkImageData* reference,
  vtkImageData* mask, const double key[3], double lo, double hi, double level, bool dark)
{
  Planes a, b;
  int w = 0, h = 0;
  const std::vector<char> m = SurfaceMask(mask, key, w, h);
  if (!a.Read(styled) || !b.Read(reference) || !a.SameSize(b) || a.W != w || a.H != h)
  {
    return -2.0;
  }
  const std::vector<double> x = a.Luminance();
  const std::vector<double> y = b.Luminance();
  std::vector<double> lit;
  for (size_t i = 0; i < m.size(); ++i)
  {
    if (m[i])
    {
      lit.push_back(y[i]);
    }
  }
  if (lit.empty() || !(lo <= hi))
  {
    return -2.0;
  }
  std::sort(lit.begin(), lit.end());
  auto at = [&lit](double q)
  {
    const double c = std::min(std::max(q, 0.0), 1.0) * static_cast<double>(lit.size() - 1);
    return lit[static_cast<size_t>(std::lround(c))];
  };
  const double ylo = at(lo), yhi = at(hi);
  double n = 0, count = 0;
  for (size_t i = 0; i < m.size(); ++i)
  {
    if (m[i] && y[i] >= ylo && y[i] <= yhi)
    {
      n += 1;
      count += (dark ? x[i] < level : x[i] >= level) ? 1 : 0;
    }
  }
  return n > 0 ? count / n : -2.0;
}

double vtkStylizeImageMetrics::DirectionAgreement(
  vtkImageData* directions, vtkImageData* mask, const double key[3], int window)
{
  Planes a;
  int w = 0, h = 0;
  const std::vector<char> m = SurfaceMask(mask, key, w, h);
  if (!a.Read(directions) || a.W != w || a.H != h || window < 1)
  {
    return -2.0;
  }
  // Summed-area tables of cos 2theta, sin 2theta and the mask (one extra row and column).
  const size_t W1 = static_cast<size_t>(w) + 1;
  std::vector<double> sc(W1 * (h + 1), 0.0), ss(sc.size(), 0.0), sm(sc.size(), 0.0);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const size_t i = static_cast<size_t>(y) * w + x;
      double c = 0.0, s = 0.0;
      if (m[i])
      {
        // r = 0.5 + 0.5 cos a, g - b = sin(a) sqrt(3) / 2 (0-255 components)
        c = 2.0 * a.R[i] / 255.0 - 1.0;
        s = (a.G[i] - a.B[i]) / 255.0 * 2.0 / std::sqrt(3.0);
        const double len = std::sqrt(c * c + s * s);
        c = len > 0 ? c / len : 0.0;
        s = len > 0 ? s / len : 0.0;
      }
      const size_t j = (y + 1) * W1 + x + 1;
      sc[j] = c + sc[j - 1] + sc[j - W1] - sc[j - W1 - 1];
      ss[j] = s + ss[j - 1] + ss[j - W1] - ss[j - W1 - 1];
      sm[j] = (m[i] ? 1.0 : 0.0) + sm[j - 1] + sm[j - W1] - sm[j - W1 - 1];
    }
  }
  auto box = [&](const std::vector<double>& t, int x0, int y0, int x1, int y1)
  { return t[y1 * W1 + x1] - t[y0 * W1 + x1] - t[y1 * W1 + x0] + t[y0 * W1 + x0]; };
  const int r = window / 2;
  const double area = static_cast<double>(2 * r + 1) * (2 * r + 1);
  double sum = 0.0, n = 0.0;
  for (int y = r; y < h - r; ++y)
  {
    for (int x = r; x < w - r; ++x)
    {
      if (!m[static_cast<size_t>(y) * w + x] || box(sm, x - r, y - r, x + r + 1, y + r + 1) < area)
      {
        continue;
      }
      const double c = box(sc, x - r, y - r, x + r + 1, y + r + 1) / area;
      const double s = box(ss, x - r, y - r, x + r + 1, y + r + 1) / area;
      sum += std::sqrt(c * c + s * s);
      n += 1;
    }
  }
  return n > 0 ? sum / n : -2.0;
}

double vtkStylizeImageMetrics::FramingExtent(vtkImageData* mask, const double key[3])
{
  int w = 0, h = 0;
  const std::vector<char> m = SurfaceMask(mask, key, w, h);
  int x0 = w, x1 = -1, y0 = h, y1 = -1;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      if (m[static_cast<size_t>(y) * w + x])
      {
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
      }
    }
  }
  if (x1 < 0)
  {
    return -2.0;
  }
  return std::max(static_cast<double>(x1 - x0 + 1) / w, static_cast<double>(y1 - y0 + 1) / h);
}
