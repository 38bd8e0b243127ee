// EnSight case files (.case), on which VTK 9.1's reader loops forever when they are cut short or
// followed by other bytes: text, a FORMAT section, and a GEOMETRY section naming its model file.

#include "vtkStylizeFileChecks.h"
#include "vtkStylizeFileChecksInternal.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <iterator>
#include <string>
#include <vector>

namespace vtkStylizeFileChecks
{
namespace
{
std::string CheckEnSightCase(FileReader& in, const std::string& path)
{
  if (in.Size() > (1 << 20))
  {
    return "larger than 1 MiB: not an EnSight case file";
  }
  std::string line;
  long long lineNumber = 0;
  bool format = false, geometry = false;
  std::string section, model;
  while (in.GetLine(line))
  {
    ++lineNumber;
    for (char c : line)
    {
      const auto u = static_cast<unsigned char>(c);
      if (u < 32 ? (u != '\t' && u != '\r') : u > 126)
      {
        return "line " + std::to_string(lineNumber) +
          " holds a byte that is not text: not an EnSight case file";
      }
    }
    const std::vector<std::string> w = Words(line);
    if (w.empty() || w[0][0] == '#')
    {
      continue;
    }
    if (Upper(w[0]) == w[0] && w.size() == 1 && line.find(':') == std::string::npos)
    {
      static const char* const sections[] = { "FORMAT", "GEOMETRY", "VARIABLE", "TIME", "FILE",
        "MATERIAL", "BLOCK_CONTINUATION", "SCRIPTS" };
      if (std::find(std::begin(sections), std::end(sections), w[0]) == std::end(sections))
      {
        return "line " + std::to_string(lineNumber) + ": unknown section " + Quote(w[0]);
      }
      section = w[0];
      format = format || section == "FORMAT";
      geometry = geometry || section == "GEOMETRY";
      continue;
    }
    if (section == "GEOMETRY" && w[0] == "model:" && w.size() >= 2)
    {
      model = w.back();
    }
  }
  if (!format)
  {
    return "no FORMAT section: not an EnSight case file";
  }
  if (!geometry || model.empty())
  {
    return "no GEOMETRY section with a \"model:\" file";
  }
  if (model.find('*') == std::string::npos)
  {
    const auto slash = path.find_last_of('/');
    const std::string file =
      model[0] == '/' || slash == std::string::npos ? model : path.substr(0, slash + 1) + model;
    FileReader geometryFile(file);
    if (!geometryFile.IsOpen())
    {
      return "its geometry file " + Quote(model) + " cannot be read: " + std::strerror(errno);
    }
  }
  return std::string();
}
} // namespace

//------------------------------------------------------------------------------
std::string CheckEnSightCaseFile(const std::string& path)
{
  return CheckOpenFile(path, CheckEnSightCase);
}
} // namespace vtkStylizeFileChecks
