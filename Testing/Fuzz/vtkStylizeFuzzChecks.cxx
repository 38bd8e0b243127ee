// libFuzzer target: the format checks vtkStylizeReader runs before VTK's readers
// (vtkStylizeFileChecks.h), in this process, on any bytes. A check may refuse (return a reason)
// or accept; it may not crash, hang, leak or read out of bounds.
#include "vtkStylizeFileChecks.h"
#include "vtkStylizeFuzzInput.h"

#include <map>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string path = vtkStylizeFuzz::WriteInput(data, size);
  if (path.empty())
  {
    return 0;
  }
  using Check = std::string (*)(const std::string&);
  static const std::map<std::string, std::vector<Check>> checks = {
    { ".ply", { vtkStylizeFileChecks::CheckPLYFile } },
    { ".obj", { vtkStylizeFileChecks::CheckOBJFile } },
    { ".stl", { vtkStylizeFileChecks::CheckSTLFile } },
    { ".vtk", { vtkStylizeFileChecks::CheckLegacyVTKFile } },
    { ".vtu",
      { vtkStylizeFileChecks::CheckXMLClaims, vtkStylizeFileChecks::CheckUnstructuredGridFaces } },
    { ".vti", { vtkStylizeFileChecks::CheckXMLClaims, vtkStylizeFileChecks::CheckImageDataFile } },
    { ".pvti", { vtkStylizeFileChecks::CheckImageDataFile } },
    { ".vtp", { vtkStylizeFileChecks::CheckXMLClaims } },
    { ".vts", { vtkStylizeFileChecks::CheckXMLClaims } },
    { ".vtr", { vtkStylizeFileChecks::CheckXMLClaims } },
    { ".case", { vtkStylizeFileChecks::CheckEnSightCaseFile } },
    { ".ex2", { vtkStylizeFileChecks::CheckExodusFile } }
  };
  const auto it = checks.find(path.substr(path.find_last_of('.')));
  if (it != checks.end())
  {
    for (Check check : it->second)
    {
      // (as the reader does: the next check only runs on what the first accepted)
      if (!check(path).empty())
      {
        break;
      }
    }
  }
  return 0;
}
