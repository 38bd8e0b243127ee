#include "vtkStylizeAtomicFile.h"

#include "vtkObjectFactory.h"
#include "vtkUnsignedCharArray.h"

#include <cerrno>
#include <cstdio>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

vtkStandardNewMacro(vtkStylizeAtomicFile);

namespace
{
// The named temporary file being written, for RemovePendingFile() (a fixed buffer: read from
// signal handlers).
char PendingPath[4096] = { 0 };

/**
 * The folder of a path ("." when it has none, "/" for a file in the root) and the mkstemp()
 * template of a hidden temporary file beside it, "FOLDER/.NAME.XXXXXX".
 */
std::string HiddenTemplate(const std::string& path, std::string& folder)
{
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos)
  {
    folder = ".";
    return "./." + path + ".XXXXXX";
  }
  folder = slash == 0 ? "/" : path.substr(0, slash);
  return folder + "/." + path.substr(slash + 1) + ".XXXXXX";
}

/** Writes all the bytes to fd, resuming after signals; false (errno set) on failure. */
bool WriteAll(int fd, const unsigned char* bytes, std::size_t size)
{
  for (std::size_t done = 0; done < size;)
  {
    const ssize_t n = ::write(fd, bytes + done, size - done);
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0)
    {
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

/** errno, or EIO when a failed call left it 0 (so that a failure never reads as success). */
int LastError()
{
  return errno != 0 ? errno : EIO;
}

/** The named temporary file: recorded in PendingPath while it exists, removed unless released. */
class TemporaryFile
{
public:
  TemporaryFile() = default;
  ~TemporaryFile() { this->Remove(); }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  void Set(const std::string& path)
  {
    this->Path = path;
    std::snprintf(PendingPath, sizeof(PendingPath), "%s", path.c_str());
  }
  void Release()
  {
    this->Path.clear();
    PendingPath[0] = 0;
  }
  void Remove()
  {
    if (!this->Path.empty())
    {
      ::unlink(this->Path.c_str());
    }
    this->Release();
  }
  const std::string& Get() const { return this->Path; }

private:
  std::string Path;
};

/**
 * Gives the unnamed (O_TMPFILE) file fd a unique name from the mkstemp() template `hidden`
 * (linkat cannot replace an existing file): false when there is no /proc or no link.
 */
bool NameUnnamedFile(int fd, const std::string& hidden, TemporaryFile& temporary)
{
  const std::string self = "/proc/self/fd/" + std::to_string(fd);
  for (int attempt = 0; attempt < 100; ++attempt)
  {
    std::vector<char> name(hidden.begin(), hidden.end());
    name.push_back(0);
    const int probe = ::mkstemp(name.data()); // a unique name, given back at once
    if (probe < 0)
    {
      return false;
    }
    ::close(probe);
    ::unlink(name.data());
    if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, name.data(), AT_SYMLINK_FOLLOW) == 0)
    {
      temporary.Set(name.data());
      return true;
    }
    if (errno != EEXIST)
    {
      return false;
    }
  }
  return false;
}
}

//------------------------------------------------------------------------------
void vtkStylizeAtomicFile::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

//------------------------------------------------------------------------------
int vtkStylizeAtomicFile::Write(const char* path, const void* data, std::size_t size)
{
  if (!path || !*path || (!data && size > 0))
  {
    return EINVAL;
  }
  const auto* bytes = static_cast<const unsigned char*>(data);
  const std::string output = path;
  std::string dir;
  const std::string hidden = HiddenTemplate(output, dir);
  TemporaryFile temporary;
  bool named = false;
  int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
  if (fd >= 0)
  {
    if (!WriteAll(fd, bytes, size))
    {
      const int error = LastError();
      ::close(fd);
      return error;
    }
    named = NameUnnamedFile(fd, hidden, temporary);
    ::close(fd);
  }
  if (!named)
  {
    // No O_TMPFILE, or no way to name it: a hidden named file from the start.
    std::vector<char> name(hidden.begin(), hidden.end());
    name.push_back(0);
    fd = ::mkstemp(name.data());
    if (fd < 0)
    {
      return LastError();
    }
    temporary.Set(name.data());
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    const bool written = WriteAll(fd, bytes, size);
    const int error = LastError();
    ::close(fd);
    if (!written)
    {
      return error;
    }
  }
  if (std::rename(temporary.Get().c_str(), output.c_str()) != 0)
  {
    return LastError(); // the temporary file is removed as it goes out of scope
  }
  temporary.Release();
  return 0;
}

//------------------------------------------------------------------------------
int vtkStylizeAtomicFile::Write(const char* path, vtkUnsignedCharArray* data)
{
  if (!data)
  {
    return EINVAL;
  }
  return vtkStylizeAtomicFile::Write(
    path, data->GetPointer(0), static_cast<std::size_t>(data->GetNumberOfValues()));
}

//------------------------------------------------------------------------------
void vtkStylizeAtomicFile::RemovePendingFile()
{
  if (PendingPath[0])
  {
    ::unlink(PendingPath);
  }
}
