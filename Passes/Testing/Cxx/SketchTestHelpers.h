// The sketch tests' shared helpers: the direction field checked finite and unit length.
#ifndef SketchTestHelpers_h
#define SketchTestHelpers_h

#include "vtkSketchPass.h"
#include "vtkStylizeTestUtilities.h"

namespace stylizetest
{
using Configure = std::function<void(vtkRenderer*, vtkSketchPass*)>;

/** Surface pixels whose resolved direction is missing or not unit length; all non-finite. */
inline void CheckField(vtkSketchPass* pass, const std::string& tag, bool expectSurface)
{
  vtkNew<vtkFloatArray> field;
  STYLIZE_CHECK(pass->DownloadDirections(field), "%s: no direction field", tag.c_str());
  CheckFinite(field, tag + " direction field");
  vtkIdType surface = 0, undefined = 0;
  for (vtkIdType i = 0; i < field->GetNumberOfTuples(); ++i)
  {
    const float* v = field->GetPointer(4 * i);
    if (v[3] > 0.0f)
    {
      ++surface;
      const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      undefined += std::abs(len - 1.0) < 1e-2 ? 0 : 1;
    }
  }
  std::printf("%-52s %lld surface pixels, %lld without a direction\n", tag.c_str(),
    static_cast<long long>(surface), static_cast<long long>(undefined));
  STYLIZE_CHECK(undefined == 0, "%s: %lld surface pixels without a direction", tag.c_str(),
    static_cast<long long>(undefined));
  STYLIZE_CHECK(!expectSurface || surface > 0, "%s: no surface pixels", tag.c_str());
}
}

#endif
