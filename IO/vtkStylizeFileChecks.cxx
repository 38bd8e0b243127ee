// The helpers shared by the format checkers (vtkStylizeFileChecksInternal.h). The checkers
// themselves, one file per format: vtkStylizeCheckPLY.cxx, vtkStylizeCheckOBJ.cxx,
// vtkStylizeCheckSTL.cxx, vtkStylizeCheckLegacyVTK.cxx, vtkStylizeCheckXML.cxx,
// vtkStylizeCheckEnSight.cxx and vtkStylizeCheckExodus.cxx.

#include "vtkStylizeFileChecks.h"
#include "vtkStylizeFileChecksInternal.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace vtkStylizeFileChecks
{
//------------------------------------------------------------------------------
FileReader::FileReader(const std::string& path)
  : File(std::fopen(path.c_str(), "rb"))
{
}

//------------------------------------------------------------------------------
FileReader::~FileReader()
{
  if (this->File)
  {
    std::fclose(this->File);
  }
}

//------------------------------------------------------------------------------
long long FileReader::Size()
{
  const long pos = std::ftell(this->File);
  std::fseek(this->File, 0, SEEK_END);
  const long long size = std::ftell(this->File);
  std::fseek(this->File, pos, SEEK_SET);
  return size;
}

//------------------------------------------------------------------------------
bool FileReader::Read(void* out, std::size_t n)
{
  char* dst = static_cast<char*>(out);
  while (n > 0)
  {
    if (this->Pos == this->End && !this->Fill())
    {
      return false;
    }
    const std::size_t k = std::min(n, this->End - this->Pos);
    std::memcpy(dst, this->Buffer.data() + this->Pos, k);
    this->Pos += k;
    this->Offset += k;
    dst += k;
    n -= k;
  }
  return true;
}

//------------------------------------------------------------------------------
bool FileReader::Skip(long long n)
{
  const long long buffered = static_cast<long long>(this->End - this->Pos);
  if (n <= buffered)
  {
    this->Pos += static_cast<std::size_t>(n);
    this->Offset += n;
    return true;
  }
  n -= buffered;
  this->Offset += buffered;
  this->Pos = this->End = 0;
  const long long here = std::ftell(this->File);
  if (std::fseek(this->File, 0, SEEK_END) != 0)
  {
    return false;
  }
  const long long size = std::ftell(this->File);
  if (here + n > size)
  {
    return false;
  }
  std::fseek(this->File, here + n, SEEK_SET);
  this->Offset += n;
  return true;
}

//------------------------------------------------------------------------------
void FileReader::Rewind()
{
  std::fseek(this->File, 0, SEEK_SET);
  this->Pos = this->End = 0;
  this->Offset = 0;
  this->Cut = false;
}

//------------------------------------------------------------------------------
bool FileReader::GetLine(std::string& line, std::size_t keep)
{
  line.clear();
  this->Cut = false;
  bool any = false;
  while (true)
  {
    if (this->Pos == this->End && !this->Fill())
    {
      return any;
    }
    any = true;
    const char c = this->Buffer[this->Pos++];
    ++this->Offset;
    if (c == '\n')
    {
      break;
    }
    if (line.size() < keep)
    {
      line += c;
    }
    else
    {
      this->Cut = true;
    }
  }
  if (!line.empty() && line.back() == '\r')
  {
    line.pop_back();
  }
  return true;
}

//------------------------------------------------------------------------------
bool FileReader::Fill()
{
  this->Buffer.resize(1 << 20);
  this->Pos = 0;
  this->End = std::fread(this->Buffer.data(), 1, this->Buffer.size(), this->File);
  return this->End > 0;
}

//------------------------------------------------------------------------------
std::string CheckOpenFile(const std::string& path, OpenFileCheck check)
{
  FileReader in(path);
  if (!in.IsOpen())
  {
    return std::strerror(errno);
  }
  return check(in, path);
}

//------------------------------------------------------------------------------
std::vector<std::string> Words(const std::string& line)
{
  std::vector<std::string> words;
  std::istringstream in(line);
  std::string w;
  while (in >> w)
  {
    words.push_back(w);
  }
  return words;
}

//------------------------------------------------------------------------------
bool ParseInteger(const std::string& s, long long& v)
{
  if (s.empty())
  {
    return false;
  }
  errno = 0;
  char* end = nullptr;
  v = std::strtoll(s.c_str(), &end, 10);
  return errno == 0 && end == s.c_str() + s.size();
}

//------------------------------------------------------------------------------
std::string FormatCount(double value)
{
  if (std::isfinite(value) && std::abs(value) < 1e15 && value == std::floor(value))
  {
    return std::to_string(static_cast<long long>(value));
  }
  char text[32];
  std::snprintf(text, sizeof(text), "%g", value);
  return text;
}

//------------------------------------------------------------------------------
std::string Upper(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return text;
}

//------------------------------------------------------------------------------
std::string Quote(const std::string& text)
{
  return "'" + text + "'";
}
} // namespace vtkStylizeFileChecks
