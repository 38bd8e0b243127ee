// OBJ: every index of the f, l and p statements is checked against the v, vt and vn counts
// (vtkOBJReader crashes on texture-coordinate or normal indices out of range), and every
// coordinate must be a finite number.

#include "vtkStylizeFileChecks.h"
#include "vtkStylizeFileChecksInternal.h"

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace vtkStylizeFileChecks
{
namespace
{
/** The longest OBJ line read (1 MiB): a longer one is not text (a 1 GB line took 2 GB). */
constexpr std::size_t MaxOBJLine = std::size_t(1) << 20;

const char* const Kinds[3] = { "vertex", "texture coordinate", "normal" };
const char* const Plurals[3] = { "vertices", "texture coordinates", "normals" };

/** The first pass: the numbers of v, vt and vn statements (totals). The problem, or "". */
std::string CountOBJElements(FileReader& in, long long totals[3])
{
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
  return std::string();
}

/**
 * The numbers of a v, vt or vn statement: VTK's reader parses numbers itself, and "nan", "inf"
 * or "1e400" became other numbers. The problem, or "".
 */
std::string CheckOBJCoordinates(const std::vector<std::string>& w, long long lineNumber)
{
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
      return "OBJ line " + std::to_string(lineNumber) + ": " + Kinds[kind] + " coordinate '" +
        w[k] + "' is not a finite number";
    }
  }
  return std::string();
}

/**
 * The indices of an f, l or p statement (v, v/vt, v//vn or v/vt/vn), against the totals, or
 * for a negative (relative) index the elements seen so far. The problem, or "".
 */
std::string CheckOBJIndices(const std::vector<std::string>& w, long long lineNumber,
  const long long totals[3], const long long seen[3])
{
  for (std::size_t k = 1; k < w.size(); ++k)
  {
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
        return "OBJ line " + std::to_string(lineNumber) + ": " + Kinds[f] + " index " +
          std::to_string(index) + " is out of range (" + std::to_string(totals[f]) + " " +
          (totals[f] == 1 ? Kinds[f] : Plurals[f]) + ")";
      }
    }
  }
  return std::string();
}

std::string CheckOBJ(FileReader& in, const std::string&)
{
  long long totals[3] = { 0, 0, 0 }; // v, vt, vn
  std::string problem = CountOBJElements(in, totals);
  if (!problem.empty())
  {
    return problem;
  }
  // The second pass: text only, then each statement's numbers or indices.
  in.Rewind();
  long long seen[3] = { 0, 0, 0 };
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
      problem = CheckOBJCoordinates(w, lineNumber);
    }
    else if (w[0] == "f" || w[0] == "l" || w[0] == "p")
    {
      problem = CheckOBJIndices(w, lineNumber, totals, seen);
    }
    if (!problem.empty())
    {
      return problem;
    }
  }
  return std::string();
}
} // namespace

//------------------------------------------------------------------------------
std::string CheckOBJFile(const std::string& path)
{
  return CheckOpenFile(path, CheckOBJ);
}
} // namespace vtkStylizeFileChecks
