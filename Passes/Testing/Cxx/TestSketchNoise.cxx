#include "vtkSketchPass.h"
#include "vtkStylizeTestUtilities.h"

using namespace stylizetest;

// The noise textures: finite values in [0, 1], periodic, with the statistics of their kind.
int TestSketchNoise(int, char*[])
{
  const int n = 32;
  for (int kind :
    { vtkSketchPass::WHITE, vtkSketchPass::PERLIN, vtkSketchPass::WORLEY, vtkSketchPass::SPARSE })
  {
    vtkNew<vtkFloatArray> noise;
    vtkSketchPass::GenerateNoise(kind, n, noise);
    STYLIZE_CHECK(noise->GetNumberOfTuples() == n * n * n, "noise %d: size", kind);
    CheckFinite(noise, "noise " + std::to_string(kind));
    double lo = 1e30, hi = -1e30, sum = 0, sum2 = 0;
    for (vtkIdType i = 0; i < noise->GetNumberOfTuples(); ++i)
    {
      const double v = noise->GetValue(i);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      sum += v;
      sum2 += v * v;
    }
    const double mean = sum / noise->GetNumberOfTuples();
    const double sd = std::sqrt(sum2 / noise->GetNumberOfTuples() - mean * mean);
    // Mean absolute difference of neighbours, inside and across the period's seam (x).
    auto at = [&](int x, int y, int z) { return noise->GetValue((z * n + y) * n + x); };
    double inside = 0, seam = 0;
    for (int z = 0; z < n; ++z)
    {
      for (int y = 0; y < n; ++y)
      {
        inside += std::abs(at(n / 2, y, z) - at(n / 2 - 1, y, z));
        seam += std::abs(at(0, y, z) - at(n - 1, y, z));
      }
    }
    inside /= n * n;
    seam /= n * n;
    std::printf("noise %d: range [%.3f, %.3f], mean %.3f, sd %.3f, neighbour difference %.3f "
                "inside, %.3f across the seam\n",
      kind, lo, hi, mean, sd, inside, seam);
    STYLIZE_CHECK(lo >= 0.0 && hi <= 1.0, "noise %d: out of [0, 1]", kind);
    STYLIZE_CHECK(seam < 1.5 * inside + 0.01, "noise %d: not periodic", kind);
    if (kind == vtkSketchPass::SPARSE)
    {
      // paper (1) with dark dots (0) on 5% of the texels
      long long other = 0;
      for (vtkIdType i = 0; i < noise->GetNumberOfTuples(); ++i)
      {
        const float v = noise->GetValue(i);
        other += (v == 0.0f || v == 1.0f) ? 0 : 1;
      }
      STYLIZE_CHECK(other == 0 && std::abs((1.0 - mean) - 0.05) < 0.005,
        "sparse noise: %lld values neither 0 nor 1, dots on %.4f of the texels", other, 1.0 - mean);
    }
    else if (kind == vtkSketchPass::WHITE)
    {
      STYLIZE_CHECK(std::abs(mean - 0.5) < 0.01 && std::abs(sd - std::sqrt(1.0 / 12.0)) < 0.01,
        "white noise: mean %.3f sd %.3f", mean, sd);
    }
    else
    {
      // smooth noises: neighbours close, compared with white noise (about 1/3)
      STYLIZE_CHECK(inside < 0.15, "noise %d: not smooth (%.3f)", kind, inside);
    }
  }
  return Failures == 0 ? 0 : 1;
}
