// VTK XML (.vtp, .vtu, .vts, .vtr, .vti and the parallel .pvti): the sizes the pieces claim,
// unstructured grids' polyhedron face streams, image data's origin, spacing and direction.

#include "vtkStylizeFileChecks.h"
#include "vtkStylizeFileChecksInternal.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace vtkStylizeFileChecks
{
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

/**
 * Scans a VTK XML file's tags as text up to its appended data, adding up the values and bytes
 * of the arrays its pieces claim (inline data is skipped).
 */
class XMLClaimsScanner
{
public:
  explicit XMLClaimsScanner(FileReader& in)
    : In(in)
  {
  }

  /** Scans the tags; false when a tag is too long for a VTK XML header (the reader says why). */
  bool Scan()
  {
    std::string tag;
    bool inTag = false;
    char c;
    while (!this->Done && this->Problem.empty() && this->In.Read(&c, 1))
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
          return false;
        }
        tag += c;
        continue;
      }
      inTag = false;
      this->Tag(tag);
    }
    return true;
  }

  /** The claims against the memory and the file's size: the problem, or "". */
  std::string Verdict(double fileSize) const
  {
    if (!this->Problem.empty())
    {
      return this->Problem;
    }
    const double memory = MemoryAvailable();
    if (this->Bytes > memory)
    {
      return "its pieces claim arrays of " + GiB(this->Bytes) + " (" +
        std::to_string(this->Piece + 1) + " piece" + (this->Piece == 0 ? "" : "s") +
        "), more than the memory this process may use (" + GiB(memory) + ")";
    }
    if (!this->Compressed && this->Values > fileSize)
    {
      char text[160];
      std::snprintf(text, sizeof(text),
        "its pieces claim %.0f values, more than an uncompressed file of %.0f bytes can hold",
        this->Values, fileSize);
      return text;
    }
    return std::string();
  }

private:
  /** One tag's text between '<' and '>': an opening, closing or empty-element tag. */
  void Tag(std::string& tag)
  {
    if (tag.empty() || tag[0] == '?' || tag[0] == '!')
    {
      return;
    }
    if (tag[0] == '/')
    {
      const std::string name = Words(tag.substr(1)).empty() ? "" : Words(tag.substr(1))[0];
      if (!this->Sections.empty() && this->Sections.back() == name)
      {
        this->Sections.pop_back();
      }
      return;
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
      this->Compressed = a.count("compressor") && !a.at("compressor").empty();
    }
    else if (name == "AppendedData")
    {
      this->Done = true;
    }
    else if (name == "Piece")
    {
      this->StartPiece(a);
      if (this->Problem.empty() && !closed)
      {
        this->Sections.push_back(name);
      }
    }
    else if (name == "DataArray" || name == "Array")
    {
      this->AddArray(a);
      if (!closed)
      {
        this->Sections.push_back(name);
      }
    }
    else if (!closed)
    {
      this->Sections.push_back(name);
    }
  }

  /** A Piece's numbers of points and cells (from its counts, or its extent). */
  void StartPiece(const std::map<std::string, std::string>& a)
  {
    ++this->Piece;
    this->Points = XMLNumber(a, "NumberOfPoints");
    this->Cells = XMLNumber(a, "NumberOfCells");
    const char* keys[4] = { "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys" };
    for (int k = 0; k < 4; ++k)
    {
      this->Lists[k] = XMLNumber(a, keys[k]);
      this->Cells += this->Lists[k];
    }
    const auto extent = a.find("Extent");
    if (extent != a.end())
    {
      const std::vector<std::string> e = Words(extent->second);
      if (e.size() == 6)
      {
        this->Points = this->Cells = 1.0;
        for (int d = 0; d < 3; ++d)
        {
          const double n = std::strtod(e[2 * d + 1].c_str(), nullptr) -
            std::strtod(e[2 * d].c_str(), nullptr) + 1.0;
          this->Points *= n;
          this->Cells *= n > 1.0 ? n - 1.0 : 1.0;
        }
      }
    }
    if (!(this->Points >= 0.0) || !(this->Cells >= 0.0))
    {
      this->Problem = "piece " + std::to_string(this->Piece) +
        " claims a negative or unreadable number " + "of points or cells";
    }
  }

  /** A DataArray's (or field data Array's) values: its tuples are its section's. */
  void AddArray(const std::map<std::string, std::string>& a)
  {
    const std::string section = this->Sections.empty() ? std::string() : this->Sections.back();
    double tuples = 0.0;
    if (section == "Points" || section == "PointData")
    {
      tuples = this->Points;
    }
    else if (section == "CellData" || section == "Cells")
    {
      const auto name = a.find("Name");
      const bool faces =
        name != a.end() && (name->second == "faces" || name->second == "faceoffsets");
      tuples = faces ? 0.0 : this->Cells;
    }
    else if (section == "Verts" || section == "Lines" || section == "Strips" || section == "Polys")
    {
      const int k = section == "Verts" ? 0 : section == "Lines" ? 1 : section == "Strips" ? 2 : 3;
      tuples = this->Lists[k];
    }
    else if (section == "FieldData")
    {
      tuples = XMLNumber(a, "NumberOfTuples");
    }
    double components = a.count("NumberOfComponents") ? XMLNumber(a, "NumberOfComponents") : 1.0;
    if (!(tuples >= 0.0) || !(components >= 0.0))
    {
      this->Problem = "piece " + std::to_string(this->Piece) +
        ": a data array claims a negative or " + "unreadable size";
      return;
    }
    this->Values += tuples * components;
    const auto type = a.find("type");
    this->Bytes +=
      tuples * components * XMLTypeSize(type == a.end() ? std::string() : type->second);
  }

  FileReader& In;
  bool Compressed = false;
  bool Done = false;
  double Values = 0.0, Bytes = 0.0;
  double Points = 0.0, Cells = 0.0;
  double Lists[4] = { 0.0, 0.0, 0.0, 0.0 }; // Verts, Lines, Strips, Polys
  int Piece = -1;
  std::vector<std::string> Sections;
  std::string Problem;
};

std::string CheckXMLClaimsOf(FileReader& in, const std::string& path)
{
  struct stat st;
  if (::stat(path.c_str(), &st) != 0)
  {
    return std::strerror(errno);
  }
  XMLClaimsScanner scanner(in);
  if (!scanner.Scan())
  {
    return std::string(); // not a VTK XML header: the reader says what it is
  }
  return scanner.Verdict(static_cast<double>(st.st_size));
}

std::string CheckImageData(FileReader& in, const std::string&)
{
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
  const std::string element =
    head.substr(tag, close == std::string::npos ? std::string::npos : close - tag);
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
    const std::string text =
      element.substr(start, end == std::string::npos ? std::string::npos : end - start);
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
} // namespace

//------------------------------------------------------------------------------
std::string CheckXMLClaims(const std::string& path)
{
  return CheckOpenFile(path, CheckXMLClaimsOf);
}

//------------------------------------------------------------------------------
std::string CheckUnstructuredGridFaces(const std::string& path)
{
  vtkNew<FaceStreamChecker> checker;
  checker->SetFileName(path.c_str());
  checker->Update();
  return checker->Problem;
}

//------------------------------------------------------------------------------
std::string CheckImageDataFile(const std::string& path)
{
  return CheckOpenFile(path, CheckImageData);
}
} // namespace vtkStylizeFileChecks
