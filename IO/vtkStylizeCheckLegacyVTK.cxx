// Legacy VTK: the "# vtk DataFile Version" header, then every section's size against the bytes
// left before the reader allocates for it, the counts that must agree, and the ASCII values VTK's
// legacy reader cannot read.

#include "vtkStylizeFileChecks.h"
#include "vtkStylizeFileChecksInternal.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace vtkStylizeFileChecks
{
namespace
{
std::string Lower(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

/** Bytes of one value of a legacy VTK data type in a BINARY file (0: unknown). */
double LegacyTypeBytes(std::string type)
{
  type = Lower(type);
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
  token = Lower(token);
  if (!token.empty() && (token[0] == '-' || token[0] == '+'))
  {
    token.erase(0, 1);
  }
  return token == "nan" || token == "inf" || token == "infinity" ||
    token.compare(0, 4, "nan(") == 0;
}

/**
 * Walks a legacy VTK file's header lines. Each section's size is checked against the bytes left
 * before the reader allocates for it (a header that claims a billion cells would have it
 * allocate tens of GB), and the counts that must agree (a short CELL_TYPES section leaves cell
 * types the reader never fills). In a BINARY file the values are skipped; in an ASCII file the
 * value lines are scanned for non-finite numbers.
 */
class LegacyVTKChecker
{
public:
  explicit LegacyVTKChecker(FileReader& in)
    : In(in)
    , Size(in.Size())
  {
  }

  std::string Check()
  {
    std::string problem = this->ReadHead();
    if (!problem.empty())
    {
      return problem;
    }
    while (this->In.GetLine(this->Line, 4096))
    {
      ++this->LineNumber;
      this->W = Words(this->Line);
      if (this->W.empty())
      {
        continue;
      }
      const std::string key = Upper(this->W[0]);
      bool ok = true;
      const bool known = this->StructureLine(key, ok) || this->AttributeLine(key, ok);
      if (!ok)
      {
        return this->Problem;
      }
      if (!known)
      {
        if (this->Binary)
        {
          return std::string(); // out of step with a binary file: the reader takes over
        }
        problem = this->NonFiniteValue();
        if (!problem.empty())
        {
          return problem;
        }
      }
    }
    return std::string();
  }

private:
  /** Lines 1 to 3: the version, the title, ASCII or BINARY. The problem, or "". */
  std::string ReadHead()
  {
    std::string& line = this->Line;
    if (!this->In.GetLine(line, 256) || line.compare(0, 22, "# vtk DataFile Version") != 0)
    {
      return "not a VTK legacy file (it does not start with '# vtk DataFile Version')";
    }
    const double version = line.size() > 23 ? std::strtod(line.c_str() + 23, nullptr) : 0.0;
    if (!std::isfinite(version) || version < 1.0 || version > 100.0)
    {
      return "the version on line 1 is not a number a VTK legacy file has";
    }
    this->Version5 = version >= 5.0;
    if (!this->In.GetLine(line, 256)) // the title
    {
      return "the file ends after its first line";
    }
    if (!this->In.GetLine(line, 256))
    {
      return "the file ends before its ASCII or BINARY line";
    }
    const std::vector<std::string> w = Words(line);
    const std::string mode = w.empty() ? std::string() : Upper(w[0]);
    if (mode != "ASCII" && mode != "BINARY")
    {
      return "line 3 must say ASCII or BINARY";
    }
    this->Binary = mode == "BINARY";
    return std::string();
  }

  /**
   * A section of values of the given bytes each (in a BINARY file): it must fit in the rest of
   * the file, where it is skipped. False with the Problem otherwise.
   */
  bool Claim(double values, double bytes, const std::string& what)
  {
    const double left = static_cast<double>(this->Size - this->In.GetOffset());
    const double needed = this->Binary ? values * bytes : 2.0 * values - 1.0;
    if (!(values >= 0.0) || needed > left)
    {
      this->Problem = "line " + std::to_string(this->LineNumber) + ": " + what + " claims " +
        FormatCount(values) + " values, more than the rest of the file (" +
        std::to_string(static_cast<long long>(left)) + " bytes) can hold";
      return false;
    }
    if (this->Binary && !this->In.Skip(static_cast<long long>(std::ceil(values * bytes))))
    {
      this->Problem = "line " + std::to_string(this->LineNumber) + ": the file ends inside " + what;
      return false;
    }
    return true;
  }

  /** The line's word i as a number (-1 when the line is shorter). */
  double Number(std::size_t i) const
  {
    return i < this->W.size() ? std::strtod(this->W[i].c_str(), nullptr) : -1.0;
  }

  /**
   * The lines of the data set's structure (points, cells, coordinates, dimensions): false when
   * key is none of them. ok: false with the Problem when the section does not fit.
   */
  bool StructureLine(const std::string& key, bool& ok)
  {
    const std::vector<std::string>& w = this->W;
    const std::string& section = w[0];
    if (key == "SPACING" || key == "ORIGIN" || key == "ASPECT_RATIO")
    {
    }
    else if (key == "METADATA")
    {
      // (component names and information keys, up to an empty line)
      while (this->In.GetLine(this->Line, 4096) && !Words(this->Line).empty())
      {
        ++this->LineNumber;
      }
      ++this->LineNumber;
    }
    else if (key == "DATASET")
    {
      this->Unstructured = w.size() > 1 && Upper(w[1]) == "UNSTRUCTURED_GRID";
    }
    else if (key == "POINTS" && w.size() >= 3)
    {
      this->Points = this->Number(1);
      ok = this->Claim(3.0 * this->Points, LegacyTypeBytes(w[2]), section);
    }
    else if ((key == "VERTICES" || key == "LINES" || key == "POLYGONS" ||
               key == "TRIANGLE_STRIPS" || key == "CELLS") &&
      w.size() >= 3)
    {
      ok = this->CellsLine(section);
    }
    else if (key == "OFFSETS" && w.size() >= 2)
    {
      ok = this->Claim(this->LastOffsets, LegacyTypeBytes(w[1]), section);
    }
    else if (key == "CONNECTIVITY" && w.size() >= 2)
    {
      ok = this->Claim(this->LastSize, LegacyTypeBytes(w[1]), section);
    }
    else if (key == "CELL_TYPES" && w.size() >= 2)
    {
      if (this->Unstructured && this->Number(1) != this->LastCells)
      {
        this->Problem = "line " + std::to_string(this->LineNumber) + ": CELL_TYPES lists " +
          FormatCount(this->Number(1)) + " types for " + FormatCount(this->LastCells) + " cells";
        ok = false;
        return true;
      }
      ok = this->Claim(this->Number(1), 4.0, section);
    }
    else if ((key == "X_COORDINATES" || key == "Y_COORDINATES" || key == "Z_COORDINATES") &&
      w.size() >= 3)
    {
      ok = this->Claim(this->Number(1), LegacyTypeBytes(w[2]), section);
    }
    else if (key == "DIMENSIONS" && w.size() >= 4)
    {
      this->Points = this->Number(1) * this->Number(2) * this->Number(3);
    }
    else
    {
      return false;
    }
    return true;
  }

  /** A VERTICES, LINES, POLYGONS, TRIANGLE_STRIPS or CELLS line: false with the Problem. */
  bool CellsLine(const std::string& section)
  {
    // (version 5: the count of offsets, one more than the cells, and of connectivity values)
    this->LastOffsets = this->Number(1);
    this->LastCells = this->Version5 ? this->LastOffsets - 1.0 : this->LastOffsets;
    this->LastSize = this->Number(2);
    this->Cells += std::max(this->LastCells, 0.0);
    if (!this->Version5)
    {
      return this->Claim(this->LastSize, 4.0, section);
    }
    // (version 5: the values follow in OFFSETS and CONNECTIVITY, checked there; the counts
    // must still fit in the file)
    const double left = static_cast<double>(this->Size - this->In.GetOffset());
    if (this->LastOffsets >= 0.0 && this->LastSize >= 0.0 &&
      (this->Binary ? 4.0 : 2.0) * (this->LastOffsets + this->LastSize) <= left + 2.0)
    {
      return true;
    }
    this->Problem = "line " + std::to_string(this->LineNumber) + ": " + section + " claims " +
      FormatCount(this->LastOffsets) + " offsets and " + FormatCount(this->LastSize) +
      " connectivity values, which the rest of the file cannot hold";
    return false;
  }

  /**
   * The lines of the point and cell attributes and of field data: false when key is none of
   * them. ok: false with the Problem when the section does not fit or its count disagrees.
   */
  bool AttributeLine(const std::string& key, bool& ok)
  {
    const std::vector<std::string>& w = this->W;
    const std::string& section = w[0];
    const double attribute = this->Attribute;
    if (key == "POINT_DATA" || key == "CELL_DATA")
    {
      ok = this->DataLine(key);
    }
    else if (key == "SCALARS" && w.size() >= 3)
    {
      // the values follow the LOOKUP_TABLE line
      this->PendingValues = attribute * (w.size() >= 4 ? this->Number(3) : 1.0);
      this->PendingBytes = LegacyTypeBytes(w[2]);
    }
    else if (key == "LOOKUP_TABLE" && w.size() == 2 && this->PendingValues >= 0.0)
    {
      ok = this->Claim(this->PendingValues, this->PendingBytes, "SCALARS");
      this->PendingValues = -1.0;
    }
    else if (key == "LOOKUP_TABLE" && w.size() >= 3)
    {
      ok = this->Claim(4.0 * this->Number(2), 1.0, section);
    }
    else if (key == "COLOR_SCALARS" && w.size() >= 3)
    {
      ok = this->Claim(attribute * this->Number(2), 1.0, section);
    }
    else if ((key == "VECTORS" || key == "NORMALS") && w.size() >= 3)
    {
      ok = this->Claim(3.0 * attribute, LegacyTypeBytes(w[2]), section);
    }
    else if ((key == "TENSORS" || key == "TENSORS6") && w.size() >= 3)
    {
      ok = this->Claim((key == "TENSORS" ? 9.0 : 6.0) * attribute, LegacyTypeBytes(w[2]), section);
    }
    else if (key == "TEXTURE_COORDINATES" && w.size() >= 4)
    {
      ok = this->Claim(this->Number(2) * attribute, LegacyTypeBytes(w[3]), section);
    }
    else if ((key == "GLOBAL_IDS" || key == "PEDIGREE_IDS") && w.size() >= 3)
    {
      ok = this->Claim(attribute, LegacyTypeBytes(w[2]), section);
    }
    else if (key == "FIELD" && w.size() >= 3)
    {
      this->FieldArrays = static_cast<int>(std::max(0.0, std::min(this->Number(2), 1e9)));
    }
    else if (this->FieldArrays > 0 && w.size() == 4 && LegacyTypeBytes(w[3]) > 0.0)
    {
      // a field array: name, components, tuples, type
      --this->FieldArrays;
      ok = this->Claim(
        this->Number(1) * this->Number(2), LegacyTypeBytes(w[3]), "field array " + Quote(w[0]));
    }
    else
    {
      return false;
    }
    return true;
  }

  /** A POINT_DATA or CELL_DATA line: its count must be the points' or cells'. */
  bool DataLine(const std::string& key)
  {
    this->Attribute = this->Number(1);
    if (key == "POINT_DATA" && this->Points >= 0.0 && this->Attribute != this->Points)
    {
      this->Problem = "line " + std::to_string(this->LineNumber) + ": POINT_DATA holds " +
        FormatCount(this->Attribute) + " values for " + FormatCount(this->Points) + " points";
      return false;
    }
    if (key == "CELL_DATA" && this->Cells > 0.0 && this->Attribute != this->Cells)
    {
      this->Problem = "line " + std::to_string(this->LineNumber) + ": CELL_DATA holds " +
        FormatCount(this->Attribute) + " values for " + FormatCount(this->Cells) + " cells";
      return false;
    }
    return true;
  }

  /**
   * An ASCII value line's first non-finite token: VTK's reader stops at a token it cannot read,
   * with a misleading message. The problem, or "".
   */
  std::string NonFiniteValue() const
  {
    if (this->Line.find_first_of("nNiI") != std::string::npos)
    {
      for (const std::string& token : this->W)
      {
        if (NonFiniteToken(token))
        {
          return "line " + std::to_string(this->LineNumber) + " holds '" + token +
            "': VTK's legacy reader reads no non-finite ASCII values (save the data as VTK XML)";
        }
      }
    }
    return std::string();
  }

  FileReader& In;
  const long long Size;
  std::string Line;
  std::vector<std::string> W; // the words of Line
  bool Version5 = false;
  bool Binary = false;
  long long LineNumber = 3;
  double Points = -1.0, Cells = 0.0, Attribute = -1.0, PendingValues = -1.0, PendingBytes = 0.0;
  double LastOffsets = 0.0, LastCells = 0.0, LastSize = 0.0;
  bool Unstructured = false;
  int FieldArrays = 0;
  std::string Problem;
};

std::string CheckLegacyVTK(FileReader& in, const std::string&)
{
  return LegacyVTKChecker(in).Check();
}
} // namespace

//------------------------------------------------------------------------------
std::string CheckLegacyVTKFile(const std::string& path)
{
  return CheckOpenFile(path, CheckLegacyVTK);
}
} // namespace vtkStylizeFileChecks
