// PLY: the header is parsed, the body walked element by element (ASCII or binary), and every
// face and triangle-strip index checked against the number of vertices (vtkPLYReader crashes on
// a malformed header and on indices out of range, e.g. in a truncated file).

#include "vtkStylizeFileChecks.h"
#include "vtkStylizeFileChecksInternal.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace vtkStylizeFileChecks
{
namespace
{

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
  if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" || t == "float32")
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

/** The value of type T held in bytes (in the host's byte order). */
template <typename T>
double FromBytes(const unsigned char* bytes)
{
  T v;
  std::memcpy(&v, bytes, sizeof(T));
  return static_cast<double>(v);
}

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
    value = FromBytes<std::int16_t>(bytes);
  }
  else if (type == "ushort" || type == "uint16")
  {
    value = FromBytes<std::uint16_t>(bytes);
  }
  else if (type == "int" || type == "int32")
  {
    value = FromBytes<std::int32_t>(bytes);
  }
  else if (type == "uint" || type == "uint32")
  {
    value = FromBytes<std::uint32_t>(bytes);
  }
  else if (type == "float" || type == "float32")
  {
    value = FromBytes<float>(bytes);
  }
  else
  {
    value = FromBytes<double>(bytes);
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

/** What the header declares; LineNumber: the header's last line. */
struct PLYHeader
{
  std::string Format;
  std::vector<PLYElement> Elements;
  int LineNumber = 1;
  long long Vertices = -1;
};

/** One property line of the header, added to the last element: the problem, or "". */
std::string AddPLYProperty(
  const std::vector<std::string>& w, const std::string& where, std::vector<PLYElement>& elements)
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
  return std::string();
}

/** The header's lines up to end_header, after the "ply" line: the problem, or "". */
std::string ReadPLYHeaderLines(FileReader& in, PLYHeader& header)
{
  std::string line;
  bool endHeader = false;
  while (in.GetLine(line))
  {
    ++header.LineNumber;
    const std::vector<std::string> w = Words(line);
    const std::string where = "PLY header line " + std::to_string(header.LineNumber);
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
      header.Format = w[1];
    }
    else if (w[0] == "element")
    {
      long long count = 0;
      if (w.size() != 3 || !ParseInteger(w[2], count) || count < 0)
      {
        return where + ": invalid element line";
      }
      header.Elements.push_back({ w[1], count, {} });
    }
    else if (w[0] == "property")
    {
      const std::string problem = AddPLYProperty(w, where, header.Elements);
      if (!problem.empty())
      {
        return problem;
      }
    }
    else
    {
      return where + ": unknown keyword '" + w[0] + "'";
    }
  }
  return endHeader ? std::string() : "the PLY header has no end_header line";
}

/** The whole header, with the vertex element's x, y and z: the problem, or "". */
std::string ReadPLYHeader(FileReader& in, PLYHeader& header)
{
  std::string line;
  if (!in.GetLine(line) || line != "ply")
  {
    return "not a PLY file (it does not start with 'ply')";
  }
  const std::string problem = ReadPLYHeaderLines(in, header);
  if (!problem.empty())
  {
    return problem;
  }
  if (header.Format.empty())
  {
    return "the PLY header has no format line";
  }
  for (const PLYElement& e : header.Elements)
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
      header.Vertices = e.Count;
    }
  }
  if (header.Vertices < 0)
  {
    return "the PLY file has no vertex element";
  }
  return std::string();
}

/**
 * One value w[k] of an ASCII PLY line, of property p: a number of its type, and a face or strip
 * index within the vertices. The problem, or "".
 */
std::string CheckPLYASCIIValue(const PLYElement& e, const PLYProperty& p,
  const std::vector<std::string>& w, std::size_t k, long long vertices, const std::string& where)
{
  if (PLYTypeIsReal(p.Type))
  {
    return ParseReal(w[k]) ? std::string() : where + ": invalid number '" + w[k] + "'";
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
  return std::string();
}

/** The body of an ASCII PLY file, one line per element: the problem, or "". */
std::string CheckPLYASCIIBody(FileReader& in, PLYHeader& header)
{
  std::string line;
  for (const PLYElement& e : header.Elements)
  {
    for (long long i = 0; i < e.Count; ++i)
    {
      if (!in.GetLine(line))
      {
        return "the PLY file is truncated (element '" + e.Name + "' " + std::to_string(i) + " of " +
          std::to_string(e.Count) + " is missing)";
      }
      ++header.LineNumber;
      const std::vector<std::string> w = Words(line);
      const std::string where = "PLY line " + std::to_string(header.LineNumber);
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
          const std::string problem = CheckPLYASCIIValue(e, p, w, k, header.Vertices, where);
          if (!problem.empty())
          {
            return problem;
          }
        }
      }
    }
  }
  return std::string();
}

/**
 * One list property of a binary PLY element: its count, then its items (skipped, or read and
 * checked against the vertices for face and strip indices). The problem, or "".
 */
std::string CheckPLYBinaryList(FileReader& in, const PLYElement& e, const PLYProperty& p,
  bool bigEndian, long long vertices, const std::string& truncated)
{
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
    return in.Skip(n * PLYTypeSize(p.Type)) ? std::string() : truncated;
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
      return std::string(strip ? "a PLY triangle strip" : "a PLY face") + " references vertex " +
        std::to_string(static_cast<long long>(index)) + " but there are " +
        std::to_string(vertices) + " vertices";
    }
  }
  return std::string();
}

/** The body of a binary PLY file: its size, and the index lists. The problem, or "". */
std::string CheckPLYBinaryBody(FileReader& in, const PLYHeader& header)
{
  const bool bigEndian = header.Format == "binary_big_endian";
  const long long fileSize = in.Size();
  for (const PLYElement& e : header.Elements)
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
        const std::string problem = p.CountType.empty()
          ? (in.Skip(PLYTypeSize(p.Type)) ? std::string() : truncated)
          : CheckPLYBinaryList(in, e, p, bigEndian, header.Vertices, truncated);
        if (!problem.empty())
        {
          return problem;
        }
      }
    }
  }
  return std::string();
}

std::string CheckPLY(FileReader& in, const std::string&)
{
  PLYHeader header;
  const std::string problem = ReadPLYHeader(in, header);
  if (!problem.empty())
  {
    return problem;
  }
  return header.Format == "ascii" ? CheckPLYASCIIBody(in, header) : CheckPLYBinaryBody(in, header);
}
} // namespace

//------------------------------------------------------------------------------
std::string CheckPLYFile(const std::string& path)
{
  return CheckOpenFile(path, CheckPLY);
}
} // namespace vtkStylizeFileChecks
