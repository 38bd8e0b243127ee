// STL: vtkSTLReader reads truncated or garbage binary files without complaint, so the size of a
// binary file must hold the number of triangles its header announces.

#include "vtkStylizeFileChecks.h"
#include "vtkStylizeFileChecksInternal.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <string>

namespace vtkStylizeFileChecks
{
namespace
{
std::string CheckSTL(FileReader& in, const std::string&)
{
  const long long size = in.Size();
  unsigned char head[256];
  const std::size_t n = static_cast<std::size_t>(std::min<long long>(size, 256));
  if (!in.Read(head, n))
  {
    return "cannot read the STL header";
  }
  // ASCII when it starts with "solid" and the first bytes are all text (as vtkSTLReader decides).
  std::size_t start = 0;
  while (start < n && std::isspace(head[start]))
  {
    ++start;
  }
  bool text = n - start >= 5 && std::memcmp(head + start, "solid", 5) == 0;
  for (std::size_t i = 0; text && i < n; ++i)
  {
    text = head[i] < 128 && (head[i] >= 32 || std::isspace(head[i]));
  }
  if (text)
  {
    return std::string();
  }
  if (size < 84)
  {
    return "the binary STL file is truncated (" + std::to_string(size) +
      " bytes, less than its 84-byte header)";
  }
  const std::uint32_t triangles = static_cast<std::uint32_t>(head[80]) |
    (static_cast<std::uint32_t>(head[81]) << 8) | (static_cast<std::uint32_t>(head[82]) << 16) |
    (static_cast<std::uint32_t>(head[83]) << 24);
  const long long expected = 84 + 50LL * triangles;
  if (size < expected)
  {
    return "the binary STL file is truncated or corrupt (its header announces " +
      std::to_string(triangles) + " triangles, " + std::to_string(expected) +
      " bytes, but the file has " + std::to_string(size) + " bytes)";
  }
  return std::string();
}
} // namespace

//------------------------------------------------------------------------------
std::string CheckSTLFile(const std::string& path)
{
  return CheckOpenFile(path, CheckSTL);
}
} // namespace vtkStylizeFileChecks
