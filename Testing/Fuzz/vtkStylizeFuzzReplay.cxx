// Runs a fuzz target's LLVMFuzzerTestOneInput over files and folders of inputs, without
// libFuzzer: the committed corpus (Testing/Fuzz/corpus) replayed by ctest in every build, the
// sanitizer build included, so that every input a fuzzer once found to crash stays fixed.
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <dirent.h>
#include <sys/stat.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace
{
int Replay(const std::string& path)
{
  struct stat st;
  if (::stat(path.c_str(), &st) != 0)
  {
    std::fprintf(stderr, "vtkStylizeFuzzReplay: cannot read '%s'\n", path.c_str());
    return -1;
  }
  if (S_ISDIR(st.st_mode))
  {
    std::vector<std::string> names;
    if (DIR* dir = ::opendir(path.c_str()))
    {
      while (dirent* e = ::readdir(dir))
      {
        if (e->d_name[0] != '.')
        {
          names.emplace_back(e->d_name);
        }
      }
      ::closedir(dir);
    }
    int count = 0;
    for (const std::string& name : names)
    {
      const int n = Replay(path + "/" + name);
      if (n < 0)
      {
        return -1;
      }
      count += n;
    }
    return count;
  }
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> bytes(
    (std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  return 1;
}
}

int main(int argc, char* argv[])
{
  int count = 0;
  for (int i = 1; i < argc; ++i)
  {
    const int n = Replay(argv[i]);
    if (n < 0)
    {
      return 1;
    }
    count += n;
  }
  std::printf("%d inputs replayed\n", count);
  return count > 0 ? 0 : 1;
}
