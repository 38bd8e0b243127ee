// The C++ tests' checks: STYLIZE_CHECK counts failures in stylizetest::Failures (a test returns
// non-zero when any failed); CheckFinite reports non-finite values of an array.
#ifndef vtkStylizeTestChecks_h
#define vtkStylizeTestChecks_h

#include "vtkFloatArray.h"
#include "vtkStylizeImageMetrics.h"

#include <cstdio>
#include <string>

namespace stylizetest
{
inline int Failures = 0;

#define STYLIZE_CHECK(cond, ...)                                                                   \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      std::fprintf(stderr, "FAIL %s:%d: %s: ", __FILE__, __LINE__, #cond);                         \
      std::fprintf(stderr, __VA_ARGS__);                                                           \
      std::fprintf(stderr, "\n");                                                                  \
      ++stylizetest::Failures;                                                                     \
    }                                                                                              \
  } while (0)

/** Counts NaN/Inf in a float buffer and reports. */
inline bool CheckFinite(vtkFloatArray* a, const std::string& what)
{
  const vtkIdType bad = vtkStylizeImageMetrics::CountNonFinite(a);
  STYLIZE_CHECK(bad == 0, "%s: %lld non-finite values", what.c_str(), static_cast<long long>(bad));
  return bad == 0;
}
}

#endif
