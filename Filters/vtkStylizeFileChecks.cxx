#include "vtkStylizeFileChecks.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace vtkStylizeFileChecks
{
namespace
{
/** Sequential reader over a FILE* with a large buffer, for binary and line-oriented parsing. */
class FileReader
{
public:
  explicit FileReader(const std::string& path)
    : File(std::fopen(path.c_str(), "rb"))
  {
  }
  ~FileReader()
  {
    if (this->File)
    {
      std::fclose(this->File);
    }
  }
  FileReader(const FileReader&) = delete;
  FileReader& operator=(const FileReader&) = delete;

  bool IsOpen() const { return this->File != nullptr; }

  long long Size()
  {
    const long pos = std::ftell(this->File);
    std::fseek(this->File, 0, SEEK_END);
    const long long size = std::ftell(this->File);
    std::fseek(this->File, pos, SEEK_SET);
    return size;
  }

  /** Reads n bytes; false at end of file. */
  bool Read(void* out, std::size_t n)
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

  /** Skips n bytes; false when the file ends first. */
  bool Skip(long long n)
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

  /**
   * Reads one line without its end-of-line characters; false at end of file. At most keep
   * characters are kept (the rest of the line is consumed): LineCut() says whether it was cut.
   */
  bool GetLine(std::string& line, std::size_t keep = std::string::npos)
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

  long long GetOffset() const { return this->Offset; }

  /** Whether the last GetLine() cut its line. */
  bool LineCut() const { return this->Cut; }

private:
  bool Fill()
  {
    this->Buffer.resize(1 << 20);
    this->Pos = 0;
    this->End = std::fread(this->Buffer.data(), 1, this->Buffer.size(), this->File);
    return this->End > 0;
  }

  std::FILE* File;
  std::vector<char> Buffer;
  std::size_t Pos = 0;
  std::size_t End = 0;
  long long Offset = 0;
  bool Cut = false;
};

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

bool ParseReal(const std::string& s)
{
  if (s.empty())
  {
    return false;
  }
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

//------------------------------------------------------------------------------
// PLY
//------------------------------------------------------------------------------

/** Size in bytes of a PLY scalar type, 0 when unknown. */
int PLYTypeSize(const std::string& t)
{
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8")
  {
    return 1;
  }
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16")
  {
    return 2;
  }
  if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" ||
    t == "float32")
  {
    return 4;
  }
  if (t == "double" || t == "float64")
  {
    return 8;
  }
  return 0;
}

bool PLYTypeIsReal(const std::string& t)
{
  return t == "float" || t == "float32" || t == "double" || t == "float64";
}

struct PLYProperty
{
  std::string Name;
  std::string Type;      // scalar type, or item type of a list
  std::string CountType; // empty: not a list
};

struct PLYElement
{
  std::string Name;
  long long Count = 0;
  std::vector<PLYProperty> Properties;
};

/** Reads a binary PLY value of the given type as a double. */
bool ReadBinaryValue(FileReader& in, const std::string& type, bool bigEndian, double& value)
{
  const int size = PLYTypeSize(type);
  unsigned char bytes[8];
  if (!in.Read(bytes, static_cast<std::size_t>(size)))
  {
    return false;
  }
  const std::uint16_t one = 1;
  const bool hostBig = *reinterpret_cast<const unsigned char*>(&one) == 0;
  if (hostBig != bigEndian)
  {
    for (int i = 0; i < size / 2; ++i)
    {
      std::swap(bytes[i], bytes[size - 1 - i]);
    }
  }
  if (type == "char" || type == "int8")
  {
    value = static_cast<std::int8_t>(bytes[0]);
  }
  else if (type == "uchar" || type == "uint8")
  {
    value = bytes[0];
  }
  else if (type == "short" || type == "int16")
  {
    std::int16_t v;
    std::memcpy(&v, bytes, 2);
    value = v;
  }
  else if (type == "ushort" || type == "uint16")
  {
    std::uint16_t v;
    std::memcpy(&v, bytes, 2);
    value = v;
  }
  else if (type == "int" || type == "int32")
  {
    std::int32_t v;
    std::memcpy(&v, bytes, 4);
    value = v;
  }
  else if (type == "uint" || type == "uint32")
  {
    std::uint32_t v;
    std::memcpy(&v, bytes, 4);
    value = v;
  }
  else if (type == "float" || type == "float32")
  {
    float v;
    std::memcpy(&v, bytes, 4);
    value = v;
  }
  else
  {
    double v;
    std::memcpy(&v, bytes, 8);
    value = v;
  }
  return true;
}

bool IsFaceIndexList(const PLYElement& e, const PLYProperty& p)
{
  return e.Name == "face" && !p.CountType.empty() &&
    (p.Name == "vertex_indices" || p.Name == "vertex_index");
}

/** The index list of triangle strips: vertex indices, -1 between two strips. */
bool IsStripIndexList(const PLYElement& e, const PLYProperty& p)
{
  return e.Name == "tristrips" && !p.CountType.empty() && p.Name == "vertex_indices";
}
} // namespace

std::string CheckPLYFile(const std::string& path)
{
  FileReader in(path);
  if (!in.IsOpen())
  {
    return std::strerror(errno);
  }
  std::string line;
  if (!in.GetLine(line) || line != "ply")
  {
    return "not a PLY file (it does not start with 'ply')";
  }
  // Header.
  std::string format;
  std::vector<PLYElement> elements;
  int lineNumber = 1;
  bool endHeader = false;
  while (in.GetLine(line))
  {
    ++lineNumber;
    const std::vector<std::string> w = Words(line);
    const std::string where = "PLY header line " + std::to_string(lineNumber);
    if (w.empty())
    {
      return where + " is empty";
    }
    if (w[0] == "comment" || w[0] == "obj_info")
    {
      continue;
    }
    if (w[0] == "end_header")
    {
      endHeader = true;
      break;
    }
    if (w[0] == "format")
    {
      if (w.size() != 3 ||
        (w[1] != "ascii" && w[1] != "binary_little_endian" && w[1] != "binary_big_endian"))
      {
        return where + ": invalid format line";
      }
      format = w[1];
    }
    else if (w[0] == "element")
    {
      long long count = 0;
      if (w.size() != 3 || !ParseInteger(w[2], count) || count < 0)
      {
        return where + ": invalid element line";
      }
      elements.push_back({ w[1], count, {} });
    }
    else if (w[0] == "property")
    {
      if (elements.empty())
      {
        return where + ": property before any element";
      }
      if (w.size() == 3 && PLYTypeSize(w[1]) > 0)
      {
        elements.back().Properties.push_back({ w[2], w[1], "" });
      }
      else if (w.size() == 5 && w[1] == "list" && PLYTypeSize(w[2]) > 0 && PLYTypeSize(w[3]) > 0 &&
        !PLYTypeIsReal(w[2]))
      {
        elements.back().Properties.push_back({ w[4], w[3], w[2] });
      }
      else
      {
        return where + ": invalid property line";
      }
    }
    else
    {
      return where + ": unknown keyword '" + w[0] + "'";
    }
  }
  if (!endHeader)
  {
    return "the PLY header has no end_header line";
  }
  if (format.empty())
  {
    return "the PLY header has no format line";
  }
  long long vertices = -1;
  for (const PLYElement& e : elements)
  {
    if (e.Name == "vertex")
    {
      int xyz = 0;
      for (const PLYProperty& p : e.Properties)
      {
        xyz += (p.CountType.empty() && (p.Name == "x" || p.Name == "y" || p.Name == "z")) ? 1 : 0;
      }
      if (xyz != 3)
      {
        return "the PLY vertex element lacks x, y and z properties";
      }
      vertices = e.Count;
    }
  }
  if (vertices < 0)
  {
    return "the PLY file has no vertex element";
  }

  // Body.
  if (format == "ascii")
  {
    for (const PLYElement& e : elements)
    {
      for (long long i = 0; i < e.Count; ++i)
      {
        if (!in.GetLine(line))
        {
          return "the PLY file is truncated (element '" + e.Name + "' " + std::to_string(i) +
            " of " + std::to_string(e.Count) + " is missing)";
        }
        ++lineNumber;
        const std::vector<std::string> w = Words(line);
        const std::string where = "PLY line " + std::to_string(lineNumber);
        std::size_t k = 0;
        for (const PLYProperty& p : e.Properties)
        {
          long long count = 1;
          if (!p.CountType.empty())
          {
            if (k >= w.size() || !ParseInteger(w[k], count) || count < 0)
            {
              return where + ": invalid list count";
            }
            ++k;
          }
          for (long long j = 0; j < count; ++j, ++k)
          {
            if (k >= w.size())
            {
              return where + ": too few values for element '" + e.Name + "'";
            }
            if (PLYTypeIsReal(p.Type))
            {
              if (!ParseReal(w[k]))
              {
                return where + ": invalid number '" + w[k] + "'";
              }
              continue;
            }
            long long index = 0;
            if (!ParseInteger(w[k], index))
            {
              return where + ": invalid integer '" + w[k] + "'";
            }
            if (IsFaceIndexList(e, p) && (index < 0 || index >= vertices))
            {
              return where + ": face references vertex " + std::to_string(index) + " but there are " +
                std::to_string(vertices) + " vertices";
            }
            if (IsStripIndexList(e, p) && (index < -1 || index >= vertices))
            {
              return where + ": a triangle strip references vertex " + std::to_string(index) +
                " but there are " + std::to_string(vertices) + " vertices";
            }
          }
        }
      }
    }
    return std::string();
  }

  const bool bigEndian = format == "binary_big_endian";
  const long long fileSize = in.Size();
  for (const PLYElement& e : elements)
  {
    bool hasList = false;
    long long size = 0;
    for (const PLYProperty& p : e.Properties)
    {
      hasList = hasList || !p.CountType.empty();
      size += PLYTypeSize(p.Type);
    }
    const std::string truncated = "the PLY file is truncated (in element '" + e.Name + "')";
    if (!hasList)
    {
      // Fixed-size records: check the size and skip them at once.
      if (size > 0 && e.Count > (fileSize - in.GetOffset()) / size)
      {
        return truncated;
      }
      if (!in.Skip(size * e.Count))
      {
        return truncated;
      }
      continue;
    }
    for (long long i = 0; i < e.Count; ++i)
    {
      for (const PLYProperty& p : e.Properties)
      {
        if (p.CountType.empty())
        {
          if (!in.Skip(PLYTypeSize(p.Type)))
          {
            return truncated;
          }
          continue;
        }
        double count = 0;
        if (!ReadBinaryValue(in, p.CountType, bigEndian, count))
        {
          return truncated;
        }
        if (count < 0)
        {
          return "invalid PLY list count " + std::to_string(static_cast<long long>(count)) +
            " in element '" + e.Name + "'";
        }
        const auto n = static_cast<long long>(count);
        const bool strip = IsStripIndexList(e, p);
        if (!IsFaceIndexList(e, p) && !strip)
        {
          if (!in.Skip(n * PLYTypeSize(p.Type)))
          {
            return truncated;
          }
          continue;
        }
        for (long long j = 0; j < n; ++j)
        {
          double index = 0;
          if (!ReadBinaryValue(in, p.Type, bigEndian, index))
          {
            return truncated;
          }
          if (!((index >= 0 || (strip && index == -1)) && index < static_cast<double>(vertices)))
          {
            return std::string(strip ? "a PLY triangle strip" : "a PLY face") + " references vertex " + std::to_string(static_cast<long long>(index)) +
              " but there are " + std::to_string(vertices) + " vertices";
          }
        }
      }
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
// OBJ
//------------------------------------------------------------------------------

namespace
{
/** The longest OBJ line read (1 MiB): a longer one is not text (a 1 GB line took 2 GB). */
constexpr std::size_t MaxOBJLine = std::size_t(1) << 20;
}

std::string CheckOBJFile(const std::string& path)
{
  long long totals[3] = { 0, 0, 0 }; // v, vt, vn
  {
    FileReader in(path);
    if (!in.IsOpen())
    {
      return std::strerror(errno);
    }
    std::string line;
    long long lineNumber = 0;
    while (in.GetLine(line, MaxOBJLine))
    {
      ++lineNumber;
      if (in.LineCut())
      {
        return "OBJ line " + std::to_string(lineNumber) + " is longer than " +
          std::to_string(MaxOBJLine >> 20) + " MiB (not an OBJ text file)";
      }
      const std::size_t start = line.find_first_not_of(" \t");
      if (start == std::string::npos)
      {
        continue;
      }
      if (line.compare(start, 2, "v ") == 0 || line.compare(start, 2, "v\t") == 0)
      {
        ++totals[0];
      }
      else if (line.compare(start, 3, "vt ") == 0 || line.compare(start, 3, "vt\t") == 0)
      {
        ++totals[1];
      }
      else if (line.compare(start, 3, "vn ") == 0 || line.compare(start, 3, "vn\t") == 0)
      {
        ++totals[2];
      }
    }
  }
  static const char* const kinds[3] = { "vertex", "texture coordinate", "normal" };
  static const char* const plurals[3] = { "vertices", "texture coordinates", "normals" };
  long long seen[3] = { 0, 0, 0 };
  FileReader in(path);
  if (!in.IsOpen())
  {
    return std::strerror(errno);
  }
  std::string line;
  long long lineNumber = 0;
  while (in.GetLine(line, MaxOBJLine))
  {
    ++lineNumber;
    for (char c : line)
    {
      const auto u = static_cast<unsigned char>(c);
      if (u == 0 || (u < 32 && u != '\t' && u != '\f' && u != '\v'))
      {
        return "OBJ line " + std::to_string(lineNumber) + " contains binary data (not an OBJ file)";
      }
    }
    const std::vector<std::string> w = Words(line);
    if (w.empty())
    {
      continue;
    }
    if (w[0] == "v" || w[0] == "vt" || w[0] == "vn")
    {
      ++seen[w[0] == "v" ? 0 : w[0] == "vt" ? 1 : 2];
      // VTK's reader parses numbers itself: "nan", "inf" or "1e400" became other numbers
      for (std::size_t k = 1; k < w.size(); ++k)
      {
        char* end = nullptr;
        const double value = std::strtod(w[k].c_str(), &end);
        if (end == w[k].c_str() || *end != '\0')
        {
          return "OBJ line " + std::to_string(lineNumber) + ": '" + w[k] + "' is not a number";
        }
        if (!std::isfinite(value))
        {
          const int kind = w[0] == "v" ? 0 : w[0] == "vt" ? 1 : 2;
          return "OBJ line " + std::to_string(lineNumber) + ": " + kinds[kind] + " coordinate '" +
            w[k] + "' is not a finite number";
        }
      }
      continue;
    }
    if (w[0] != "f" && w[0] != "l" && w[0] != "p")
    {
      continue;
    }
    for (std::size_t k = 1; k < w.size(); ++k)
    {
      // v, v/vt, v//vn or v/vt/vn
      std::vector<std::string> fields;
      std::string::size_type s = 0;
      while (true)
      {
        const auto slash = w[k].find('/', s);
        fields.push_back(w[k].substr(s, slash - s));
        if (slash == std::string::npos)
        {
          break;
        }
        s = slash + 1;
      }
      if (fields.size() > 3)
      {
        return "OBJ line " + std::to_string(lineNumber) + ": invalid index '" + w[k] + "'";
      }
      for (std::size_t f = 0; f < fields.size(); ++f)
      {
        if (fields[f].empty() && f > 0)
        {
          continue; // v//vn
        }
        long long index = 0;
        if (!ParseInteger(fields[f], index) || index == 0)
        {
          return "OBJ line " + std::to_string(lineNumber) + ": invalid index '" + w[k] + "'";
        }
        const bool ok = index > 0 ? index <= totals[f] : -index <= seen[f];
        if (!ok)
        {
          return "OBJ line " + std::to_string(lineNumber) + ": " + kinds[f] + " index " +
            std::to_string(index) + " is out of range (" + std::to_string(totals[f]) + " " +
            (totals[f] == 1 ? kinds[f] : plurals[f]) + ")";
        }
      }
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
// VTK legacy
//------------------------------------------------------------------------------

namespace
{
/** A count as an integer, or in %g form beyond 1e15 (a header's claim can be any number). */
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

std::string Upper(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return text;
}

std::string Quote(const std::string& text)
{
  return "'" + text + "'";
}

/** Bytes of one value of a legacy VTK data type in a BINARY file (0: unknown). */
double LegacyTypeBytes(std::string type)
{
  std::transform(type.begin(), type.end(), type.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (type == "bit")
  {
    return 0.125;
  }
  if (type == "char" || type == "unsigned_char" || type == "signed_char")
  {
    return 1.0;
  }
  if (type == "short" || type == "unsigned_short")
  {
    return 2.0;
  }
  if (type == "int" || type == "unsigned_int" || type == "float")
  {
    return 4.0;
  }
  if (type == "long" || type == "unsigned_long" || type == "double" || type == "vtktypeint64" ||
    type == "vtktypeuint64" || type == "vtkidtype")
  {
    return 8.0;
  }
  return 0.0;
}

/** "nan", "-inf", "Infinity"...: a token VTK's legacy ASCII reader cannot read. */
bool NonFiniteToken(std::string token)
{
  std::transform(token.begin(), token.end(), token.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (!token.empty() && (token[0] == '-' || token[0] == '+'))
  {
    token.erase(0, 1);
  }
  return token == "nan" || token == "inf" || token == "infinity" || token.compare(0, 4, "nan(") == 0;
}
} // namespace

std::string CheckLegacyVTKFile(const std::string& path)
{
  FileReader in(path);
  if (!in.IsOpen())
  {
    return std::strerror(errno);
  }
  const long long size = in.Size();
  std::string line;
  if (!in.GetLine(line, 256) || line.compare(0, 22, "# vtk DataFile Version") != 0)
  {
    return "not a VTK legacy file (it does not start with '# vtk DataFile Version')";
  }
  const double version = line.size() > 23 ? std::strtod(line.c_str() + 23, nullptr) : 0.0;
  if (!std::isfinite(version) || version < 1.0 || version > 100.0)
  {
    return "the version on line 1 is not a number a VTK legacy file has";
  }
  const bool version5 = version >= 5.0;
  if (!in.GetLine(line, 256)) // the title
  {
    return "the file ends after its first line";
  }
  if (!in.GetLine(line, 256))
  {
    return "the file ends before its ASCII or BINARY line";
  }
  std::vector<std::string> w = Words(line);
  std::string mode = w.empty() ? std::string() : w[0];
  std::transform(mode.begin(), mode.end(), mode.begin(),
    [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  if (mode != "ASCII" && mode != "BINARY")
  {
    return "line 3 must say ASCII or BINARY";
  }
  const bool binary = mode == "BINARY";

  // Each section's size, checked against the bytes left before the reader allocates for it (a
  // header that claims a billion cells would have it allocate tens of GB), and the counts that
  // must agree (a short CELL_TYPES section leaves cell types the reader never fills).
  long long lineNumber = 3;
  double points = -1.0, cells = 0.0, attribute = -1.0, pendingValues = -1.0, pendingBytes = 0.0;
  double lastOffsets = 0.0, lastCells = 0.0, lastSize = 0.0;
  bool unstructured = false;
  int fieldArrays = 0;
  std::string problem;
  const auto claim = [&](double values, double bytes, const std::string& what) {
    const double left = static_cast<double>(size - in.GetOffset());
    const double needed = binary ? values * bytes : 2.0 * values - 1.0;
    if (!(values >= 0.0) || needed > left)
    {
      problem = "line " + std::to_string(lineNumber) + ": " + what + " claims " +
        FormatCount(values) + " values, more than the rest of the file (" +
        std::to_string(static_cast<long long>(left)) + " bytes) can hold";
      return false;
    }
    if (binary && !in.Skip(static_cast<long long>(std::ceil(values * bytes))))
    {
      problem = "line " + std::to_string(lineNumber) + ": the file ends inside " + what;
      return false;
    }
    return true;
  };
  const auto number = [&w](std::size_t i) {
    return i < w.size() ? std::strtod(w[i].c_str(), nullptr) : -1.0;
  };
  while (in.GetLine(line, 4096))
  {
    ++lineNumber;
    w = Words(line);
    if (w.empty())
    {
      continue;
    }
    std::string key = w[0];
    std::transform(key.begin(), key.end(), key.begin(),
      [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    const std::string section = w[0];
    bool ok = true;
    bool known = true;
    if (key == "SPACING" || key == "ORIGIN" || key == "ASPECT_RATIO")
    {
    }
    else if (key == "METADATA")
    {
      // (component names and information keys, up to an empty line)
      while (in.GetLine(line, 4096) && !Words(line).empty())
      {
        ++lineNumber;
      }
      ++lineNumber;
    }
    else if (key == "DATASET")
    {
      unstructured = w.size() > 1 && Upper(w[1]) == "UNSTRUCTURED_GRID";
    }
    else if (key == "POINTS" && w.size() >= 3)
    {
      points = number(1);
      ok = claim(3.0 * points, LegacyTypeBytes(w[2]), section);
    }
    else if ((key == "VERTICES" || key == "LINES" || key == "POLYGONS" || key == "TRIANGLE_STRIPS" ||
               key == "CELLS") && w.size() >= 3)
    {
      // (version 5: the count of offsets, one more than the cells, and of connectivity values)
      lastOffsets = number(1);
      lastCells = version5 ? lastOffsets - 1.0 : lastOffsets;
      lastSize = number(2);
      cells += std::max(lastCells, 0.0);
      // (version 5: the values follow in OFFSETS and CONNECTIVITY, checked there; the counts
      // must still fit in the file)
      const double left = static_cast<double>(size - in.GetOffset());
      ok = version5 ? lastOffsets >= 0.0 && lastSize >= 0.0 &&
          (binary ? 4.0 : 2.0) * (lastOffsets + lastSize) <= left + 2.0
                    : claim(lastSize, 4.0, section);
      if (version5 && !ok)
      {
        problem = "line " + std::to_string(lineNumber) + ": " + section + " claims " +
          FormatCount(lastOffsets) + " offsets and " + FormatCount(lastSize) +
          " connectivity values, which the rest of the file cannot hold";
      }
    }
    else if (key == "OFFSETS" && w.size() >= 2)
    {
      ok = claim(lastOffsets, LegacyTypeBytes(w[1]), section);
    }
    else if (key == "CONNECTIVITY" && w.size() >= 2)
    {
      ok = claim(lastSize, LegacyTypeBytes(w[1]), section);
    }
    else if (key == "CELL_TYPES" && w.size() >= 2)
    {
      if (unstructured && number(1) != lastCells)
      {
        problem = "line " + std::to_string(lineNumber) + ": CELL_TYPES lists " +
          FormatCount(number(1)) + " types for " + FormatCount(lastCells) + " cells";
        return problem;
      }
      ok = claim(number(1), 4.0, section);
    }
    else if ((key == "X_COORDINATES" || key == "Y_COORDINATES" || key == "Z_COORDINATES") &&
      w.size() >= 3)
    {
      ok = claim(number(1), LegacyTypeBytes(w[2]), section);
    }
    else if (key == "DIMENSIONS" && w.size() >= 4)
    {
      points = number(1) * number(2) * number(3);
    }
    else if (key == "POINT_DATA" || key == "CELL_DATA")
    {
      attribute = number(1);
      if (key == "POINT_DATA" && points >= 0.0 && attribute != points)
      {
        return "line " + std::to_string(lineNumber) + ": POINT_DATA holds " +
          FormatCount(attribute) + " values for " + FormatCount(points) + " points";
      }
      if (key == "CELL_DATA" && cells > 0.0 && attribute != cells)
      {
        return "line " + std::to_string(lineNumber) + ": CELL_DATA holds " +
          FormatCount(attribute) + " values for " + FormatCount(cells) + " cells";
      }
    }
    else if (key == "SCALARS" && w.size() >= 3)
    {
      // the values follow the LOOKUP_TABLE line
      pendingValues = attribute * (w.size() >= 4 ? number(3) : 1.0);
      pendingBytes = LegacyTypeBytes(w[2]);
    }
    else if (key == "LOOKUP_TABLE" && w.size() == 2 && pendingValues >= 0.0)
    {
      ok = claim(pendingValues, pendingBytes, "SCALARS");
      pendingValues = -1.0;
    }
    else if (key == "LOOKUP_TABLE" && w.size() >= 3)
    {
      ok = claim(4.0 * number(2), 1.0, section);
    }
    else if (key == "COLOR_SCALARS" && w.size() >= 3)
    {
      ok = claim(attribute * number(2), 1.0, section);
    }
    else if ((key == "VECTORS" || key == "NORMALS") && w.size() >= 3)
    {
      ok = claim(3.0 * attribute, LegacyTypeBytes(w[2]), section);
    }
    else if ((key == "TENSORS" || key == "TENSORS6") && w.size() >= 3)
    {
      ok = claim((key == "TENSORS" ? 9.0 : 6.0) * attribute, LegacyTypeBytes(w[2]), section);
    }
    else if (key == "TEXTURE_COORDINATES" && w.size() >= 4)
    {
      ok = claim(number(2) * attribute, LegacyTypeBytes(w[3]), section);
    }
    else if ((key == "GLOBAL_IDS" || key == "PEDIGREE_IDS") && w.size() >= 3)
    {
      ok = claim(attribute, LegacyTypeBytes(w[2]), section);
    }
    else if (key == "FIELD" && w.size() >= 3)
    {
      fieldArrays = static_cast<int>(std::max(0.0, std::min(number(2), 1e9)));
    }
    else if (fieldArrays > 0 && w.size() == 4 && LegacyTypeBytes(w[3]) > 0.0)
    {
      // a field array: name, components, tuples, type
      --fieldArrays;
      ok = claim(number(1) * number(2), LegacyTypeBytes(w[3]), "field array " + Quote(w[0]));
    }
    else
    {
      known = false;
    }
    if (!ok)
    {
      return problem;
    }
    if (!known)
    {
      if (binary)
      {
        return std::string(); // out of step with a binary file: the reader takes over
      }
      // ASCII values: VTK's reader stops at a token it cannot read, with a misleading message
      if (line.find_first_of("nNiI") != std::string::npos)
      {
        for (const std::string& token : w)
        {
          if (NonFiniteToken(token))
          {
            return "line " + std::to_string(lineNumber) + " holds '" + token +
              "': VTK's legacy reader reads no non-finite ASCII values (save the data as VTK XML)";
          }
        }
      }
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
// STL
//------------------------------------------------------------------------------

std::string CheckSTLFile(const std::string& path)
{
  FileReader in(path);
  if (!in.IsOpen())
  {
    return std::strerror(errno);
  }
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
namespace
{
/**
 * A reader that reads nothing but the polyhedron face streams of each piece, with the reader's
 * own array decoding, and walks them with bounds checks (VTK 9.1's ReadFaceArray does not).
 */
class FaceStreamChecker : public vtkXMLUnstructuredGridReader
{
public:
  static FaceStreamChecker* New();
  vtkTypeMacro(FaceStreamChecker, vtkXMLUnstructuredGridReader);
  std::string Problem;

protected:
  FaceStreamChecker() = default;
  ~FaceStreamChecker() override = default;

  int ReadPieceData() override
  {
    if (this->Problem.empty())
    {
      this->Problem = this->CheckPiece();
    }
    return 1; // nothing else is read
  }

  /** The values of the named 1-component array of the Cells element, count of them, or none. */
  vtkSmartPointer<vtkDataArray> Values(vtkXMLDataElement* cells, const char* name, vtkIdType count)
  {
    vtkXMLDataElement* element = cells ? this->FindDataArrayWithName(cells, name) : nullptr;
    if (!element || count <= 0)
    {
      return nullptr;
    }
    vtkSmartPointer<vtkAbstractArray> array;
    array.TakeReference(this->CreateArray(element));
    vtkSmartPointer<vtkDataArray> values = vtkDataArray::SafeDownCast(array);
    if (!values || values->GetNumberOfComponents() != 1)
    {
      return nullptr;
    }
    values->SetNumberOfTuples(count);
    if (!this->ReadArrayValues(element, 0, values, 0, count))
    {
      return nullptr;
    }
    return values;
  }

  std::string CheckPiece()
  {
    vtkXMLDataElement* cells = this->CellElements ? this->CellElements[this->Piece] : nullptr;
    const vtkIdType numberOfCells = this->NumberOfCells ? this->NumberOfCells[this->Piece] : 0;
    const vtkIdType numberOfPoints = this->GetNumberOfPointsInPiece(this->Piece);
    const std::string piece = "piece " + std::to_string(this->Piece);
    vtkSmartPointer<vtkDataArray> offsets = this->Values(cells, "faceoffsets", numberOfCells);
    if (!offsets)
    {
      return std::string(); // no polyhedra (or an array the reader itself refuses)
    }
    // The stream's length: the last polyhedron's end (the reader's rule; -1 marks other cells).
    vtkIdType length = -1;
    for (vtkIdType i = numberOfCells - 1; i >= 0 && length < 0; --i)
    {
      const double end = offsets->GetComponent(i, 0);
      if (end > -1.0)
      {
        length = static_cast<vtkIdType>(end);
      }
    }
    if (length <= 0)
    {
      return std::string();
    }
    vtkSmartPointer<vtkDataArray> faces = this->Values(cells, "faces", length);
    if (!faces)
    {
      return std::string(); // too short: the reader says so itself
    }
    const auto text = [](double v) { return std::to_string(static_cast<long long>(v)); };
    vtkIdType at = 0;
    for (vtkIdType cell = 0; cell < numberOfCells; ++cell)
    {
      if (offsets->GetComponent(cell, 0) < 0.0)
      {
        continue;
      }
      const std::string where = piece + ", cell " + text(static_cast<double>(cell));
      if (at >= length)
      {
        return where + ": its polyhedron faces lie past the end of the \"faces\" array";
      }
      const double numberOfFaces = faces->GetComponent(at++, 0);
      if (!(numberOfFaces >= 1.0) || numberOfFaces > static_cast<double>(length - at))
      {
        return where + ": the polyhedron claims " + text(numberOfFaces) +
          " faces, more than the \"faces\" array holds";
      }
      for (vtkIdType f = 0; f < static_cast<vtkIdType>(numberOfFaces); ++f)
      {
        const double size = at < length ? faces->GetComponent(at, 0) : -1.0;
        if (!(size >= 3.0) || size > static_cast<double>(length - at - 1))
        {
          return where + ": face " + text(static_cast<double>(f)) + " of the polyhedron has " +
            text(size) + " points, which the \"faces\" array does not hold";
        }
        ++at;
        for (vtkIdType k = 0; k < static_cast<vtkIdType>(size); ++k, ++at)
        {
          const double id = faces->GetComponent(at, 0);
          if (!(id >= 0.0) || id >= static_cast<double>(numberOfPoints))
          {
            return where + ": a polyhedron face names point " + text(id) + " but the piece has " +
              text(static_cast<double>(numberOfPoints)) + " points";
          }
        }
      }
    }
    if (at != length)
    {
      return piece + ": the \"faces\" array does not match its polyhedra";
    }
    return std::string();
  }
};
vtkStandardNewMacro(FaceStreamChecker);
} // namespace

namespace
{
/** Bytes of one value of a VTK XML DataArray type. */
double XMLTypeSize(const std::string& type)
{
  if (type == "Int8" || type == "UInt8" || type == "Bit" || type == "String" || type == "Char")
  {
    return 1.0;
  }
  if (type == "Int16" || type == "UInt16")
  {
    return 2.0;
  }
  if (type == "Int64" || type == "UInt64" || type == "Float64" || type == "IdType")
  {
    return 8.0;
  }
  return 4.0;
}

/** The attributes of a tag's text ("Name a=\"1\" b=\"x\""). */
std::map<std::string, std::string> XMLAttributes(const std::string& tag)
{
  std::map<std::string, std::string> attributes;
  std::size_t at = tag.find_first_of(" \t\r\n");
  while (at != std::string::npos && at < tag.size())
  {
    const std::size_t eq = tag.find('=', at);
    if (eq == std::string::npos)
    {
      break;
    }
    const std::size_t open = tag.find_first_of("\"'", eq);
    if (open == std::string::npos)
    {
      break;
    }
    const std::size_t close = tag.find(tag[open], open + 1);
    if (close == std::string::npos)
    {
      break;
    }
    std::string key = tag.substr(at, eq - at);
    key.erase(0, key.find_first_not_of(" \t\r\n"));
    key.erase(key.find_last_not_of(" \t\r\n") + 1);
    attributes[key] = tag.substr(open + 1, close - open - 1);
    at = close + 1;
  }
  return attributes;
}

/** The number in an attribute (0 when absent); NaN when it is not a number. */
double XMLNumber(const std::map<std::string, std::string>& attributes, const char* key)
{
  const auto it = attributes.find(key);
  if (it == attributes.end())
  {
    return 0.0;
  }
  char* end = nullptr;
  const double value = std::strtod(it->second.c_str(), &end);
  return end == it->second.c_str() ? std::nan("") : value;
}

/** The memory this process may allocate: the machine's, or a lower resource limit. */
double MemoryAvailable()
{
  double bytes = static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * ::sysconf(_SC_PAGE_SIZE);
  for (int resource : { RLIMIT_AS, RLIMIT_DATA })
  {
    struct rlimit limit;
    if (::getrlimit(resource, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    {
      bytes = std::min(bytes, static_cast<double>(limit.rlim_cur));
    }
  }
  return bytes;
}

std::string GiB(double bytes)
{
  char text[64];
  std::snprintf(text, sizeof(text), "%.3g GiB", bytes / (1024.0 * 1024.0 * 1024.0));
  return text;
}
} // namespace

std::string CheckXMLClaims(const std::string& path)
{
  FileReader in(path);
  if (!in.IsOpen())
  {
    return std::strerror(errno);
  }
  struct stat st;
  if (::stat(path.c_str(), &st) != 0)
  {
    return std::strerror(errno);
  }
  const double fileSize = static_cast<double>(st.st_size);
  bool compressed = false;
  double values = 0.0, bytes = 0.0;
  double points = 0.0, cells = 0.0;
  double lists[4] = { 0.0, 0.0, 0.0, 0.0 }; // Verts, Lines, Strips, Polys
  int piece = -1;
  std::vector<std::string> sections;
  std::string problem;
  const auto addArray = [&](const std::map<std::string, std::string>& a) {
    const std::string section = sections.empty() ? std::string() : sections.back();
    double tuples = 0.0;
    if (section == "Points" || section == "PointData")
    {
      tuples = points;
    }
    else if (section == "CellData" || section == "Cells")
    {
      const auto name = a.find("Name");
      const bool faces = name != a.end() && (name->second == "faces" || name->second == "faceoffsets");
      tuples = faces ? 0.0 : cells;
    }
    else if (section == "Verts" || section == "Lines" || section == "Strips" || section == "Polys")
    {
      const int k = section == "Verts" ? 0 : section == "Lines" ? 1 : section == "Strips" ? 2 : 3;
      tuples = lists[k];
    }
    else if (section == "FieldData")
    {
      tuples = XMLNumber(a, "NumberOfTuples");
    }
    double components = a.count("NumberOfComponents") ? XMLNumber(a, "NumberOfComponents") : 1.0;
    if (!(tuples >= 0.0) || !(components >= 0.0))
    {
      problem = "piece " + std::to_string(piece) + ": a data array claims a negative or " +
        "unreadable size";
      return;
    }
    values += tuples * components;
    const auto type = a.find("type");
    bytes += tuples * components * XMLTypeSize(type == a.end() ? std::string() : type->second);
  };
  std::string tag;
  bool inTag = false, done = false;
  char c;
  while (!done && problem.empty() && in.Read(&c, 1))
  {
    if (!inTag)
    {
      if (c == '<')
      {
        inTag = true;
        tag.clear();
      }
      continue;
    }
    if (c != '>')
    {
      if (tag.size() > (1u << 16))
      {
        return std::string(); // not a VTK XML header: the reader says what it is
      }
      tag += c;
      continue;
    }
    inTag = false;
    if (tag.empty() || tag[0] == '?' || tag[0] == '!')
    {
      continue;
    }
    if (tag[0] == '/')
    {
      const std::string name = Words(tag.substr(1)).empty() ? "" : Words(tag.substr(1))[0];
      if (!sections.empty() && sections.back() == name)
      {
        sections.pop_back();
      }
      continue;
    }
    const bool closed = tag.back() == '/';
    if (closed)
    {
      tag.pop_back();
    }
    const std::string name = tag.substr(0, tag.find_first_of(" \t\r\n"));
    const std::map<std::string, std::string> a = XMLAttributes(tag);
    if (name == "VTKFile")
    {
      compressed = a.count("compressor") && !a.at("compressor").empty();
    }
    else if (name == "AppendedData")
    {
      done = true;
    }
    else if (name == "Piece")
    {
      ++piece;
      points = XMLNumber(a, "NumberOfPoints");
      cells = XMLNumber(a, "NumberOfCells");
      const char* keys[4] = { "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys" };
      for (int k = 0; k < 4; ++k)
      {
        lists[k] = XMLNumber(a, keys[k]);
        cells += lists[k];
      }
      const auto extent = a.find("Extent");
      if (extent != a.end())
      {
        const std::vector<std::string> e = Words(extent->second);
        if (e.size() == 6)
        {
          points = cells = 1.0;
          for (int d = 0; d < 3; ++d)
          {
            const double n = std::strtod(e[2 * d + 1].c_str(), nullptr) -
              std::strtod(e[2 * d].c_str(), nullptr) + 1.0;
            points *= n;
            cells *= n > 1.0 ? n - 1.0 : 1.0;
          }
        }
      }
      if (!(points >= 0.0) || !(cells >= 0.0))
      {
        problem = "piece " + std::to_string(piece) + " claims a negative or unreadable number " +
          "of points or cells";
      }
      else if (!closed)
      {
        sections.push_back(name);
      }
    }
    else if (name == "DataArray" || name == "Array")
    {
      addArray(a);
      if (!closed)
      {
        sections.push_back(name);
      }
    }
    else if (!closed)
    {
      sections.push_back(name);
    }
  }
  if (!problem.empty())
  {
    return problem;
  }
  const double memory = MemoryAvailable();
  if (bytes > memory)
  {
    return "its pieces claim arrays of " + GiB(bytes) + " (" + std::to_string(piece + 1) +
      " piece" + (piece == 0 ? "" : "s") + "), more than the memory this process may use (" +
      GiB(memory) + ")";
  }
  if (!compressed && values > fileSize)
  {
    char text[160];
    std::snprintf(text, sizeof(text),
      "its pieces claim %.0f values, more than an uncompressed file of %.0f bytes can hold",
      values, fileSize);
    return text;
  }
  return std::string();
}

std::string CheckUnstructuredGridFaces(const std::string& path)
{
  vtkNew<FaceStreamChecker> checker;
  checker->SetFileName(path.c_str());
  checker->Update();
  return checker->Problem;
}

std::string CheckImageDataFile(const std::string& path)
{
  FileReader in(path);
  if (!in.IsOpen())
  {
    return std::strerror(errno);
  }
  std::string head(64 * 1024, '\0');
  std::size_t n = 0;
  while (n < head.size() && in.Read(&head[n], 1))
  {
    ++n;
  }
  head.resize(n);
  std::size_t tag = head.find("<ImageData");
  const std::size_t parallel = head.find("<PImageData");
  tag = std::min(tag, parallel);
  if (tag == std::string::npos)
  {
    return std::string(); // the reader reports what it cannot find
  }
  const std::size_t close = head.find('>', tag);
  const std::string element = head.substr(tag, close == std::string::npos ? std::string::npos : close - tag);
  static const std::pair<const char*, int> attributes[3] = { { "Origin", 3 }, { "Spacing", 3 },
    { "Direction", 9 } };
  for (const auto& a : attributes)
  {
    const std::string key = std::string(" ") + a.first + "=\"";
    const std::size_t at = element.find(key);
    if (at == std::string::npos)
    {
      continue;
    }
    const std::size_t start = at + key.size();
    const std::size_t end = element.find('"', start);
    const std::string text = element.substr(start, end == std::string::npos ? std::string::npos : end - start);
    const std::vector<std::string> words = Words(text);
    if (static_cast<int>(words.size()) != a.second)
    {
      return std::string("the image's ") + a.first + " has " + std::to_string(words.size()) +
        " values, not " + std::to_string(a.second);
    }
    for (const std::string& w : words)
    {
      char* stop = nullptr;
      const double value = std::strtod(w.c_str(), &stop);
      if (stop == w.c_str() || *stop != '\0' || !std::isfinite(value))
      {
        return std::string("the image's ") + a.first + " '" + text + "' holds '" + w +
          "', not a finite number (VTK's reader would put the default in its place)";
      }
    }
  }
  return std::string();
}

std::string CheckEnSightCaseFile(const std::string& path)
{
  FileReader in(path);
  if (!in.IsOpen())
  {
    return std::strerror(errno);
  }
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

namespace
{
/** Walks a netCDF classic header (big-endian) held in memory. */
class NetCDFHeader
{
public:
  NetCDFHeader(const std::vector<unsigned char>& bytes, long long fileSize, int version)
    : Bytes(bytes)
    , FileSize(fileSize)
    , Version(version)
  {
  }

  std::string Check()
  {
    this->Pos = 4;
    unsigned long long records = 0;
    if (!this->Count(records, "the number of records"))
    {
      return this->Problem;
    }
    if (records == (this->Version == 5 ? ~0ULL : 0xFFFFFFFFULL))
    {
      records = 0; // streaming
    }
    std::vector<unsigned long long> dims;
    unsigned long long tag = 0, n = 0;
    // dimensions: each a name (>= 4 bytes with its length) and a length
    if (!this->List(0x0A, tag, n, 8 + this->Width()))
    {
      return this->Problem;
    }
    for (unsigned long long i = 0; i < n; ++i)
    {
      unsigned long long length = 0;
      if (!this->Name() || !this->Count(length, "a dimension's length"))
      {
        return this->Problem;
      }
      dims.push_back(length);
    }
    if (!this->Attributes())
    {
      return this->Problem;
    }
    if (!this->List(0x0B, tag, n, 20))
    {
      return this->Problem;
    }
    for (unsigned long long v = 0; v < n; ++v)
    {
      unsigned long long rank = 0;
      if (!this->Name() || !this->Count(rank, "a variable's rank", this->Width()))
      {
        return this->Problem;
      }
      double values = 1.0;
      bool record = false;
      for (unsigned long long d = 0; d < rank; ++d)
      {
        unsigned long long id = 0;
        if (!this->Count(id, "a dimension id"))
        {
          return this->Problem;
        }
        if (id >= dims.size())
        {
          return "a variable names dimension " + std::to_string(id) + " of " +
            std::to_string(dims.size());
        }
        if (d == 0 && dims[id] == 0)
        {
          record = true;
          continue;
        }
        values *= static_cast<double>(dims[id]);
      }
      unsigned long long type = 0, vsize = 0, begin = 0;
      if (!this->Attributes() || !this->Value(type, 4) || !this->Count(vsize, "a variable's size") ||
        !this->Value(begin, this->Version == 1 ? 4 : 8))
      {
        return this->Problem.empty() ? "the header ends inside a variable" : this->Problem;
      }
      const double bytes = values * TypeSize(type) * (record ? static_cast<double>(records) : 1.0);
      if (TypeSize(type) == 0.0)
      {
        return "a variable has the unknown type " + std::to_string(type);
      }
      if (static_cast<double>(begin) + bytes > static_cast<double>(this->FileSize))
      {
        return "a variable claims " + FormatCount(bytes) + " bytes of data at byte " +
          std::to_string(begin) + ", beyond the file's " + std::to_string(this->FileSize);
      }
    }
    return std::string();
  }

private:
  static double TypeSize(unsigned long long type)
  {
    static const double sizes[12] = { 0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8 };
    return type < 12 ? sizes[type] : 0.0;
  }

  int Width() const { return this->Version == 5 ? 8 : 4; }

  bool Value(unsigned long long& out, int bytes)
  {
    if (this->Pos + bytes > this->Bytes.size())
    {
      this->Problem = "the header is cut short";
      return false;
    }
    out = 0;
    for (int i = 0; i < bytes; ++i)
    {
      out = (out << 8) | this->Bytes[this->Pos++];
    }
    return true;
  }

  /** A count of this format's width; at most what the rest of the file could hold. */
  bool Count(unsigned long long& out, const char* what, int width = 0)
  {
    if (!this->Value(out, width ? width : this->Width()))
    {
      return false;
    }
    if (static_cast<double>(out) > static_cast<double>(this->FileSize) * 1e6)
    {
      this->Problem = std::string("the header claims ") + std::to_string(out) + " for " + what +
        " in a file of " + std::to_string(this->FileSize) + " bytes";
      return false;
    }
    return true;
  }

  /** A list's tag and element count (ABSENT: zeros); each element at least minimum bytes. */
  bool List(unsigned long long expected, unsigned long long& tag, unsigned long long& n,
    double minimum)
  {
    if (!this->Value(tag, 4) || !this->Value(n, this->Width()))
    {
      return false;
    }
    if (tag == 0 && n == 0)
    {
      return true;
    }
    if (tag != expected)
    {
      this->Problem = "the header holds an unexpected list tag " + std::to_string(tag);
      return false;
    }
    const double left = static_cast<double>(this->Bytes.size() - this->Pos);
    if (static_cast<double>(n) * minimum > left)
    {
      this->Problem = "the header claims " + std::to_string(n) + " items in a list, more than " +
        "its " + std::to_string(static_cast<long long>(left)) + " remaining bytes can hold";
      return false;
    }
    return true;
  }

  bool Name()
  {
    unsigned long long length = 0;
    if (!this->Value(length, this->Width()))
    {
      return false;
    }
    const unsigned long long padded = (length + 3) / 4 * 4;
    if (padded > this->Bytes.size() - this->Pos)
    {
      this->Problem = "a name of " + std::to_string(length) + " bytes runs past the header";
      return false;
    }
    this->Pos += padded;
    return true;
  }

  bool Attributes()
  {
    unsigned long long tag = 0, n = 0;
    if (!this->List(0x0C, tag, n, 12 + this->Width()))
    {
      return false;
    }
    for (unsigned long long i = 0; i < n; ++i)
    {
      unsigned long long type = 0, count = 0;
      if (!this->Name() || !this->Value(type, 4) || !this->Value(count, this->Width()))
      {
        return false;
      }
      const double bytes = std::ceil(static_cast<double>(count) * TypeSize(type) / 4.0) * 4.0;
      if (TypeSize(type) == 0.0 || bytes > static_cast<double>(this->Bytes.size() - this->Pos))
      {
        this->Problem = "an attribute claims " + std::to_string(count) + " values, past the header";
        return false;
      }
      this->Pos += static_cast<std::size_t>(bytes);
    }
    return true;
  }

  const std::vector<unsigned char>& Bytes;
  long long FileSize;
  int Version;
  std::size_t Pos = 0;
  std::string Problem;
};
} // namespace

std::string CheckExodusFile(const std::string& path)
{
  FileReader in(path);
  if (!in.IsOpen())
  {
    return std::strerror(errno);
  }
  const long long size = in.Size();
  // The header lies at the start; 16 MiB hold the largest Exodus header one meets.
  std::vector<unsigned char> bytes(static_cast<std::size_t>(std::min<long long>(size, 16 << 20)));
  if (!bytes.empty() && !in.Read(bytes.data(), bytes.size()))
  {
    return "cannot read the file";
  }
  if (bytes.size() >= 8 && bytes[0] == 0x89 && bytes[1] == 'H' && bytes[2] == 'D' && bytes[3] == 'F')
  {
    return std::string(); // netCDF-4: HDF5 checks its own structure
  }
  if (bytes.size() < 8 || bytes[0] != 'C' || bytes[1] != 'D' || bytes[2] != 'F' ||
    (bytes[3] != 1 && bytes[3] != 2 && bytes[3] != 5))
  {
    return "not an Exodus II file (neither netCDF classic nor netCDF-4)";
  }
  return NetCDFHeader(bytes, size, bytes[3]).Check();
}
} // namespace vtkStylizeFileChecks
