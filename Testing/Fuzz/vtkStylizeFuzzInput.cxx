#include "vtkStylizeFuzzInput.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include <unistd.h>

namespace vtkStylizeFuzz
{
const std::vector<std::string>& Extensions()
{
  static const std::vector<std::string> extensions = { ".ply", ".obj", ".stl", ".vtk", ".vtu",
    ".vti", ".vtp", ".vts", ".vtr", ".vtm", ".pvti", ".pvtu", ".pvd", ".case", ".ex2", ".foam" };
  return extensions;
}

std::string WriteInput(const std::uint8_t* data, std::size_t size)
{
  static std::string folder;
  if (folder.empty())
  {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/vtkstylize-fuzz.XXXXXX";
    if (!::mkdtemp(&pattern[0]))
    {
      std::perror("mkdtemp");
      std::abort();
    }
    folder = pattern;
    static const std::string removed = folder;
    std::atexit([] { std::system(("rm -rf '" + removed + "'").c_str()); });
  }
  if (size == 0)
  {
    return std::string();
  }
  const std::string path = folder + "/input" + Extensions()[data[0] % Extensions().size()];
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  return path;
}
}
