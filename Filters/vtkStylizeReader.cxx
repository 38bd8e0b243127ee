#include "vtkStylizeReader.h"

#include "vtkStylizeFileChecks.h"
#include "vtkStylizeOutputWindow.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkExodusIIReader.h"
#include "vtkExtractCells.h"
#include "vtkGenericEnSightReader.h"
#include "vtkOpenFOAMReader.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"
#include "vtkXMLPImageDataReader.h"
#include "vtkXMLPPolyDataReader.h"
#include "vtkXMLPRectilinearGridReader.h"
#include "vtkXMLPStructuredGridReader.h"
#include "vtkXMLPUnstructuredGridReader.h"
#include "vtkFloatArray.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPLY.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRectilinearGrid.h"
#include "vtkSTLReader.h"
#include "vtkTriangleFilter.h"
#include "vtkStructuredGrid.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLImageDataReader.h"
#include "vtkXMLMultiBlockDataReader.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLRectilinearGridReader.h"
#include "vtkXMLStructuredGridReader.h"
#include "vtkXMLUnstructuredGridReader.h"
#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include "vtkInformationVector.h"
#include "vtkLogger.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <cmath>
#include <cstring>
#include <exception>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <new>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

vtkStandardNewMacro(vtkStylizeReader);

namespace
{
/** Thrown by every check; RequestData turns it into the reader's error. */
struct ReadFailure
{
  std::string Message;
};

[[noreturn]] void Fail(const std::string& message)
{
  throw ReadFailure{ message };
}

/** The warnings of the update in progress, and the window capturing VTK's messages. */
std::vector<std::string>* CurrentWarnings = nullptr;
vtkStylizeOutputWindow* Capture = nullptr;

void Warn(const std::string& message)
{
  if (CurrentWarnings)
  {
    CurrentWarnings->push_back(message);
  }
}

std::string Quote(const std::string& text)
{
  return "'" + text + "'";
}

std::string Lower(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

/** Forgets the messages VTK's readers reported so far. */
void ClearVTKErrors()
{
  if (Capture)
  {
    Capture->ClearMessages();
  }
}

/** Fails with what + ": " + the first failure VTK reported since ClearVTKErrors(). */
void CheckVTKErrors(const std::string& what)
{
  if (Capture && Capture->HasFailure())
  {
    Fail(what + ": " + Capture->GetFirstFailure());
  }
}

/**
 * Installs a vtkStylizeOutputWindow for its lifetime (keeping the echo descriptor of one already
 * installed) and restores the previous window. VTK's logger also writes errors to stderr
 * (vtkOutputWindowDisplayErrorText logs before it hands the text to the window): its stderr
 * level is turned off meanwhile and set back to the cutoff found (vtkLogger has no getter for the
 * stderr level alone; the cutoff is that level unless a log file or callback asks for more).
 */
class CaptureScope
{
public:
  CaptureScope()
  {
    this->Previous = vtkOutputWindow::GetInstance();
    if (auto* outer = vtkStylizeOutputWindow::SafeDownCast(this->Previous))
    {
      this->Window->SetEchoDescriptor(outer->GetEchoDescriptor());
    }
    vtkOutputWindow::SetInstance(this->Window);
    Capture = this->Window;
    this->LoggerLevel = vtkLogger::GetCurrentVerbosityCutoff();
    this->LoggerChanged = this->LoggerLevel >= vtkLogger::VERBOSITY_ERROR;
    if (this->LoggerChanged)
    {
      vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    }
  }
  ~CaptureScope()
  {
    if (this->LoggerChanged)
    {
      vtkLogger::SetStderrVerbosity(this->LoggerLevel);
    }
    Capture = nullptr;
    vtkOutputWindow::SetInstance(this->Previous);
  }
  CaptureScope(const CaptureScope&) = delete;
  CaptureScope& operator=(const CaptureScope&) = delete;

private:
  vtkSmartPointer<vtkOutputWindow> Previous;
  vtkNew<vtkStylizeOutputWindow> Window;
  vtkLogger::Verbosity LoggerLevel = vtkLogger::VERBOSITY_OFF;
  bool LoggerChanged = false;
};

std::string Extension(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash) ||
    dot == (slash == std::string::npos ? 0 : slash + 1))
  {
    return std::string();
  }
  return Lower(path.substr(dot));
}

using ReaderFactory = std::function<vtkSmartPointer<vtkAlgorithm>(const std::string&)>;

template <typename T>
ReaderFactory MakeReader()
{
  return [](const std::string& path) -> vtkSmartPointer<vtkAlgorithm> {
    vtkNew<T> reader;
    reader->SetFileName(path.c_str());
    return reader;
  };
}

/** Exodus II: every element block, with all point and element result arrays. */
vtkSmartPointer<vtkAlgorithm> MakeExodusReader(const std::string& path)
{
  vtkNew<vtkExodusIIReader> reader;
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  reader->SetAllArrayStatus(vtkExodusIIReader::ELEM_BLOCK, 1);
  reader->SetAllArrayStatus(vtkExodusIIReader::NODAL, 1);
  reader->SetAllArrayStatus(vtkExodusIIReader::ELEM_BLOCK_ELEM_CONN, 1);
  reader->SetAllArrayStatus(vtkExodusIIReader::ELEM_BLOCK_ATTRIB, 1);
  return reader;
}

const std::map<std::string, ReaderFactory>& Readers()
{
  static const std::map<std::string, ReaderFactory> readers = {
    { ".vtp", MakeReader<vtkXMLPolyDataReader>() },
    { ".vtu", MakeReader<vtkXMLUnstructuredGridReader>() },
    { ".vts", MakeReader<vtkXMLStructuredGridReader>() },
    { ".vtr", MakeReader<vtkXMLRectilinearGridReader>() },
    { ".vti", MakeReader<vtkXMLImageDataReader>() },
    { ".vtm", MakeReader<vtkXMLMultiBlockDataReader>() },
    { ".vtk",
      [](const std::string& path) -> vtkSmartPointer<vtkAlgorithm> {
        vtkNew<vtkGenericDataObjectReader> reader;
        reader->SetFileName(path.c_str());
        reader->ReadAllScalarsOn();
        reader->ReadAllVectorsOn();
        reader->ReadAllNormalsOn();
        reader->ReadAllColorScalarsOn();
        reader->ReadAllFieldsOn();
        return reader;
      } },
    { ".stl", MakeReader<vtkSTLReader>() },
    { ".obj", MakeReader<vtkOBJReader>() },
    { ".ply", MakeReader<vtkPLYReader>() },
    { ".pvtu", MakeReader<vtkXMLPUnstructuredGridReader>() },
    { ".pvtp", MakeReader<vtkXMLPPolyDataReader>() },
    { ".pvti", MakeReader<vtkXMLPImageDataReader>() },
    { ".pvts", MakeReader<vtkXMLPStructuredGridReader>() },
    { ".pvtr", MakeReader<vtkXMLPRectilinearGridReader>() },
    { ".ex2", MakeExodusReader },
    { ".exo", MakeExodusReader },
    { ".e", MakeExodusReader },
    { ".g", MakeExodusReader },
    { ".case",
      [](const std::string& path) -> vtkSmartPointer<vtkAlgorithm> {
        vtkNew<vtkGenericEnSightReader> reader;
        reader->SetCaseFileName(path.c_str());
        return reader;
      } },
    { ".foam", MakeReader<vtkOpenFOAMReader>() },
    // .pvd: a collection file; ReadInput reads the data set file of the chosen time step.
    { ".pvd", nullptr },
  };
  return readers;
}

std::string SupportedExtensions()
{
  std::string list;
  for (const auto& r : Readers())
  {
    list += (list.empty() ? "" : " ") + r.first;
  }
  return list;
}

bool IsSupportedInput(const std::string& path)
{
  return Readers().count(Extension(path)) > 0;
}

/**
 * Checks that the file is a readable regular file, not empty unless allowEmpty (an OpenFOAM .foam
 * file only names its case directory and is usually empty), before any reader sees it.
 */
void CheckInputFile(const std::string& path, bool allowEmpty = false)
{
  struct stat st;
  if (::stat(path.c_str(), &st) != 0)
  {
    Fail("cannot read " + Quote(path) + ": " + std::strerror(errno));
  }
  if (S_ISDIR(st.st_mode))
  {
    Fail("cannot read " + Quote(path) + ": is a directory");
  }
  if (!S_ISREG(st.st_mode))
  {
    Fail("cannot read " + Quote(path) + ": not a regular file");
  }
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0)
  {
    Fail("cannot read " + Quote(path) + ": " + std::strerror(errno));
  }
  char byte;
  const ssize_t n = ::read(fd, &byte, 1);
  const int readErrno = errno;
  ::close(fd);
  if (n < 0)
  {
    Fail("cannot read " + Quote(path) + ": " + std::strerror(readErrno));
  }
  if ((n == 0 || st.st_size == 0) && !allowEmpty)
  {
    Fail("cannot read " + Quote(path) + ": the file is empty");
  }
}

/**
/** The XML claims check, then the given one. */
template <std::string (*Next)(const std::string&)>
std::string ClaimsThen(const std::string& path)
{
  const std::string problem = vtkStylizeFileChecks::CheckXMLClaims(path);
  return problem.empty() ? Next(path) : problem;
}

/**
 * The structural check of the file's format (vtkStylizeFileChecks.h), for the formats whose
 * readers crash, hang, allocate without bound or read garbage on broken files: the problem, or
 * an empty string.
 */
std::string StructuralCheck(const std::string& path)
{
  using Check = std::string (*)(const std::string&);
  static const std::map<std::string, Check> checks = { { ".ply", vtkStylizeFileChecks::CheckPLYFile },
    { ".obj", vtkStylizeFileChecks::CheckOBJFile }, { ".stl", vtkStylizeFileChecks::CheckSTLFile },
    { ".vtk", vtkStylizeFileChecks::CheckLegacyVTKFile },
    { ".vtu", ClaimsThen<vtkStylizeFileChecks::CheckUnstructuredGridFaces> },
    { ".vti", ClaimsThen<vtkStylizeFileChecks::CheckImageDataFile> },
    { ".vtp", vtkStylizeFileChecks::CheckXMLClaims }, { ".vts", vtkStylizeFileChecks::CheckXMLClaims },
    { ".vtr", vtkStylizeFileChecks::CheckXMLClaims },
    { ".pvti", vtkStylizeFileChecks::CheckImageDataFile }, { ".case", vtkStylizeFileChecks::CheckEnSightCaseFile },
    { ".ex2", vtkStylizeFileChecks::CheckExodusFile }, { ".exo", vtkStylizeFileChecks::CheckExodusFile },
    { ".e", vtkStylizeFileChecks::CheckExodusFile }, { ".g", vtkStylizeFileChecks::CheckExodusFile } };
  const auto check = checks.find(Extension(path));
  if (check == checks.end())
  {
    return std::string();
  }
  const std::string problem = check->second(path);
  ClearVTKErrors(); // (a check that reads with VTK leaves the reader's own complaints)
  return problem;
}

/** Whether path is an ASCII PLY file whose last byte is not a newline. */
bool ASCIIPLYWithoutLastNewline(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  bool ascii = false;
  for (int i = 0; i < 64 && std::getline(in, line); ++i)
  {
    if (line.compare(0, 12, "format ascii") == 0)
    {
      ascii = true;
      break;
    }
    if (line.compare(0, 10, "end_header") == 0)
    {
      break;
    }
  }
  if (!ascii)
  {
    return false;
  }
  in.clear();
  in.seekg(-1, std::ios::end);
  char last = '\n';
  return in.get(last) && last != '\n';
}

/** path's folder with a slash ("" for a bare name). */
std::string Folder(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

/**
 * The files an XML multiblock (.vtm, DataSet's "file") or parallel (.pvt*, Piece's "Source")
 * file names, before VTK's reader opens them: each must be a readable regular file (a FIFO or a
 * device would block the reader forever, a missing one is named here rather than skipped), and a
 * multiblock file may not name itself through any chain of multiblock files. chain: the
 * multiblock files that led here.
 */
void CheckReferencedFiles(const std::string& path, std::vector<std::string> chain = {},
  const std::string& input = std::string())
{
  const std::string& top = input.empty() ? path : input;
  const std::string extension = Extension(path);
  const bool multiblock = extension == ".vtm";
  if (!multiblock && extension.compare(0, 4, ".pvt") != 0)
  {
    return;
  }
  char* canonical = ::realpath(path.c_str(), nullptr);
  const std::string real = canonical ? canonical : path;
  std::free(canonical);
  if (std::find(chain.begin(), chain.end(), real) != chain.end())
  {
    Fail("cannot read " + Quote(top) + ": the multiblock file " + Quote(path) +
      " names itself (a loop of " + std::to_string(chain.size()) + " file" +
      (chain.size() == 1 ? "" : "s") + ")");
  }
  chain.push_back(real);
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(path.c_str());
  ClearVTKErrors();
  if (!parser->Parse() || !parser->GetRootElement())
  {
    ClearVTKErrors();
    Fail("cannot read " + Quote(top) + ": " + (path == top ? std::string() : Quote(path) + " is ") +
      "not a well-formed VTK XML file");
  }
  ClearVTKErrors();
  const char* attribute = multiblock ? "file" : "Source";
  std::vector<vtkXMLDataElement*> pending = { parser->GetRootElement() };
  while (!pending.empty())
  {
    vtkXMLDataElement* e = pending.back();
    pending.pop_back();
    for (int i = 0; i < e->GetNumberOfNestedElements(); ++i)
    {
      pending.push_back(e->GetNestedElement(i));
    }
    const char* name = e->GetAttribute(attribute);
    if (!name || !*name)
    {
      continue;
    }
    std::string file = name;
    if (file[0] != '/')
    {
      file = Folder(path) + file;
    }
    struct stat st;
    if (::stat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
    {
      Fail("cannot read " + Quote(top) + ": " + (path == top ? "it" : Quote(path)) + " names " +
        Quote(file) + ", which " +
        (::stat(file.c_str(), &st) != 0 ? std::string("cannot be read: ") + std::strerror(errno)
                                         : std::string("is not a regular file")));
    }
    CheckInputFile(file);
    const std::string problem = StructuralCheck(file);
    if (!problem.empty())
    {
      Fail("cannot read " + Quote(top) + ": " + Quote(file) + ": " + problem);
    }
    CheckReferencedFiles(file, chain, top);
  }
}

/**
 * The data set files of a ParaView data (.pvd) collection, in time order, read with VTK's XML
 * parser; a relative file is relative to the .pvd's folder.
 */
std::vector<std::string> CollectionFiles(const std::string& path)
{
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(path.c_str());
  ClearVTKErrors();
  if (!parser->Parse() || !parser->GetRootElement())
  {
    Fail("cannot read " + Quote(path) + ": not a well-formed ParaView data (.pvd) file");
  }
  vtkXMLDataElement* collection = parser->GetRootElement()->FindNestedElementWithName("Collection");
  std::vector<std::pair<double, std::string>> entries;
  for (int i = 0; collection && i < collection->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* e = collection->GetNestedElement(i);
    const char* file = e->GetAttribute("file");
    if (!e->GetName() || std::string(e->GetName()) != "DataSet" || !file)
    {
      continue;
    }
    double t = static_cast<double>(entries.size());
    e->GetScalarAttribute("timestep", t);
    std::string f = file;
    const auto slash = path.find_last_of('/');
    if (!f.empty() && f[0] != '/' && slash != std::string::npos)
    {
      f = path.substr(0, slash + 1) + f;
    }
    entries.emplace_back(t, f);
  }
  ClearVTKErrors();
  if (entries.empty())
  {
    Fail("cannot read " + Quote(path) + ": the collection lists no data set file");
  }
  std::stable_sort(entries.begin(), entries.end(),
    [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> files;
  for (const auto& e : entries)
  {
    files.push_back(e.second);
  }
  return files;
}

std::string StepsText(std::size_t n)
{
  return n == 1 ? "1 time step" : std::to_string(n) + " time steps";
}

/** Whether the PLY file's header declares an element "tristrips". */
bool HasPLYStrips(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  while (std::getline(in, line) && line.compare(0, 10, "end_header") != 0)
  {
    if (line.compare(0, 18, "element tristrips ") == 0)
    {
      return true;
    }
  }
  return false;
}

// Records that vtkPLY fills (as vtkPLYReader's own plyVertex and plyFace).
struct PLYStripVertex
{
  float X[3];
};
struct PLYIndexList
{
  int Count;
  int* Indices; // allocated by vtkPLY (malloc), freed here
};

/**
 * Reads a PLY file whose surface is stored as triangle strips, which VTK 9.1's vtkPLYReader does
 * not read: with VTK's own low-level PLY API (vtkPLY, as vtkPLYReader uses it for faces), the
 * vertices (x, y, z), the strips (element "tristrips", list "vertex_indices", -1 between two
 * strips) and any faces (element "face"), as a polydata of triangles (vtkTriangleFilter). Indices
 * outside the vertices fail with one line.
 */
vtkSmartPointer<vtkDataObject> ReadPLYStrips(const std::string& path, const std::string& what)
{
  int elementCount = 0;
  char** elementNames = nullptr;
  PlyFile* ply = nullptr;
  if (ASCIIPLYWithoutLastNewline(path))
  {
    // (vtkPLY's ASCII reader needs a newline after the last line: read from memory with one)
    std::ifstream in(path, std::ios::binary);
    std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    content += '\n';
    ply = vtkPLY::ply_open_for_reading_from_string(content, &elementCount, &elementNames);
  }
  else
  {
    ply = vtkPLY::ply_open_for_reading(path.c_str(), &elementCount, &elementNames);
  }
  if (!ply)
  {
    Fail(what + ": not a readable PLY file");
  }
  PlyProperty vertexProps[] = {
    { "x", PLY_FLOAT, PLY_FLOAT, static_cast<int>(offsetof(PLYStripVertex, X)), 0, 0, 0, 0 },
    { "y", PLY_FLOAT, PLY_FLOAT, static_cast<int>(offsetof(PLYStripVertex, X) + sizeof(float)), 0,
      0, 0, 0 },
    { "z", PLY_FLOAT, PLY_FLOAT, static_cast<int>(offsetof(PLYStripVertex, X) + 2 * sizeof(float)),
      0, 0, 0, 0 },
  };
  PlyProperty listProp = { "vertex_indices", PLY_INT, PLY_INT,
    static_cast<int>(offsetof(PLYIndexList, Indices)), 1, PLY_INT, PLY_INT,
    static_cast<int>(offsetof(PLYIndexList, Count)) };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  vtkNew<vtkCellArray> strips;
  vtkNew<vtkCellArray> polys;
  std::string problem;
  int pointCount = 0;
  for (int e = 0; e < elementCount && problem.empty(); ++e)
  {
    char* name = elementNames[e];
    int count = 0, propertyCount = 0;
    PlyElement* element = vtkPLY::ply_get_element_description(ply, name, &count, &propertyCount);
    if (!element || count < 0)
    {
      problem = "bad element '" + std::string(name ? name : "") + "'";
      break;
    }
    int index = 0;
    const std::string elementName = name;
    const bool vertices = elementName == "vertex";
    const bool lists = (elementName == "tristrips" || elementName == "face") &&
      vtkPLY::find_property(element, "vertex_indices", &index) &&
      element->props[index]->is_list == PLY_LIST;
    if (vertices)
    {
      vtkPLY::ply_get_element_setup(ply, name, 3, vertexProps);
      pointCount = count;
      points->SetNumberOfPoints(count);
      for (int i = 0; i < count; ++i)
      {
        PLYStripVertex v{};
        vtkPLY::ply_get_element(ply, &v);
        points->SetPoint(i, v.X);
      }
      continue;
    }
    if (!lists)
    {
      // Any other element is read and dropped, to get to the next one.
      vtkPLY::ply_get_element_setup(ply, name, 0, nullptr);
      std::vector<char> ignored(1024);
      for (int i = 0; i < count; ++i)
      {
        vtkPLY::ply_get_element(ply, ignored.data());
      }
      continue;
    }
    vtkPLY::ply_get_element_setup(ply, name, 1, &listProp);
    const bool isStrips = elementName == "tristrips";
    std::vector<vtkIdType> ids;
    for (int i = 0; i < count; ++i)
    {
      PLYIndexList list{ 0, nullptr };
      vtkPLY::ply_get_element(ply, &list);
      // One list: strips separated by -1 (tristrips), or one polygon (face).
      ids.clear();
      for (int k = 0; k <= list.Count && problem.empty(); ++k)
      {
        const int id = k < list.Count ? list.Indices[k] : -1;
        if (id == -1 && isStrips)
        {
          if (ids.size() >= 3)
          {
            strips->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
          }
          ids.clear();
        }
        else if (id >= 0 && id < pointCount)
        {
          ids.push_back(id);
        }
        else if (k < list.Count)
        {
          problem = std::string(isStrips ? "a triangle strip" : "a face") + " references vertex " +
            std::to_string(id) + " but there are " + std::to_string(pointCount) + " vertices";
        }
      }
      if (!isStrips && problem.empty() && ids.size() >= 3)
      {
        polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
      }
      std::free(list.Indices); // allocated by vtkPLY's get_element
    }
  }
  for (int e = 0; e < elementCount; ++e)
  {
    std::free(elementNames[e]); // allocated by ply_open_for_reading
  }
  std::free(elementNames);
  vtkPLY::ply_close(ply);
  if (!problem.empty())
  {
    Fail(what + ": " + problem);
  }
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(points);
  surface->SetStrips(strips);
  surface->SetPolys(polys);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(surface);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  ClearVTKErrors();
  triangles->Update();
  CheckVTKErrors(what + ": triangulating the strips failed");
  vtkSmartPointer<vtkPolyData> result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(triangles->GetOutput());
  return result;
}

vtkSmartPointer<vtkDataObject> ReadInput(const std::string& path, int timeStep)
{
  if (Extension(path) == ".pvd")
  {
    CheckInputFile(path);
    const std::vector<std::string> files = CollectionFiles(path);
    if (timeStep < 0 || static_cast<std::size_t>(timeStep) >= files.size())
    {
      Fail("cannot read " + Quote(path) + ": time step " + std::to_string(timeStep) +
        " is out of range (the file has " + StepsText(files.size()) + ")");
    }
    const std::string& file = files[static_cast<std::size_t>(timeStep)];
    if (Extension(file) == ".pvd" || !IsSupportedInput(file))
    {
      Fail("cannot read " + Quote(path) + ": unsupported data set file " + Quote(file));
    }
    return ReadInput(file, 0);
  }
  const auto it = Readers().find(Extension(path));
  if (it == Readers().end())
  {
    Fail("unsupported file type " + Quote(path) + " (supported: " + SupportedExtensions() + ")");
  }
  CheckInputFile(path, it->first == ".foam");
  CheckReferencedFiles(path);
  const std::string problem = StructuralCheck(path);
  if (!problem.empty())
  {
    Fail("cannot read " + Quote(path) + ": " + problem);
  }
  // VTK 9.1's PLY reader reads faces only: a surface stored as triangle strips is read here.
  if (it->first == ".ply" && HasPLYStrips(path))
  {
    if (timeStep != 0)
    {
      Fail("cannot read " + Quote(path) + ": time step " + std::to_string(timeStep) +
        " is out of range (the file has 1 time step)");
    }
    return ReadPLYStrips(path, "cannot read " + Quote(path));
  }
  ClearVTKErrors();
  vtkSmartPointer<vtkAlgorithm> reader = it->second(path);
  if (it->first == ".ply" && ASCIIPLYWithoutLastNewline(path))
  {
    // VTK 9.1's reader frees a line twice (abort) when an ASCII file does not end with a
    // newline: it reads the file from memory with one added.
    std::ifstream in(path, std::ios::binary);
    std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    content += '\n';
    auto* ply = vtkPLYReader::SafeDownCast(reader);
    ply->SetInputString(content);
    ply->ReadFromInputStringOn();
  }
  reader->UpdateInformation();
  // Time: the requested step of the reader's time steps (files without time have one step).
  vtkInformation* info = reader->GetOutputInformation(0);
  const int steps = info && info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS())
    ? info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS())
    : 0;
  if (timeStep < 0 || timeStep >= std::max(steps, 1))
  {
    Fail("cannot read " + Quote(path) + ": time step " + std::to_string(timeStep) +
      " is out of range (the file has " + StepsText(static_cast<std::size_t>(std::max(steps, 1))) +
      ")");
  }
  if (steps > 0)
  {
    reader->UpdateTimeStep(info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS())[timeStep]);
  }
  else
  {
    reader->Update();
  }
  const std::string what = "cannot read " + Quote(path);
  CheckVTKErrors(what);
  if (reader->GetErrorCode() != vtkErrorCode::NoError)
  {
    const char* code = vtkErrorCode::GetStringFromErrorCode(reader->GetErrorCode());
    Fail(what + ": " + (code ? code : "read error"));
  }
  vtkDataObject* output = reader->GetOutputDataObject(0);
  if (!output)
  {
    Fail(what + ": the reader produced no data");
  }
  vtkSmartPointer<vtkDataObject> data;
  data.TakeReference(output->NewInstance());
  data->ShallowCopy(output);
  return data;
}

/** Checks that every cell of the cell array references existing points. */
void CheckCells(vtkCellArray* cells, vtkIdType numberOfPoints, const std::string& what)
{
  if (!cells || cells->GetNumberOfCells() == 0)
  {
    return;
  }
  if (!cells->IsValid())
  {
    Fail(what + ": corrupt cell connectivity");
  }
  vtkDataArray* connectivity = cells->GetConnectivityArray();
  double range[2];
  connectivity->GetRange(range, 0);
  if (connectivity->GetNumberOfTuples() > 0 &&
    (range[0] < 0 || range[1] >= static_cast<double>(numberOfPoints)))
  {
    Fail(what + ": a cell references point " +
      std::to_string(static_cast<long long>(range[0] < 0 ? range[0] : range[1])) + " but there are " +
      std::to_string(static_cast<long long>(numberOfPoints)) + " points");
  }
}

/**
 * Number of points a cell type needs: exactly Size, or at least Size when AtLeast. Types not
 * listed (and VTK_POLYHEDRON without faces) are rejected, since the surface filter would read
 * outside the connectivity for them.
 */
struct CellSize
{
  int Size;
  bool AtLeast;
};

bool CellTypeSize(int type, CellSize& size)
{
  static const std::map<int, CellSize> sizes = { { VTK_EMPTY_CELL, { 0, false } },
    { VTK_VERTEX, { 1, false } }, { VTK_POLY_VERTEX, { 1, true } }, { VTK_LINE, { 2, false } },
    { VTK_POLY_LINE, { 2, true } }, { VTK_TRIANGLE, { 3, false } },
    { VTK_TRIANGLE_STRIP, { 3, true } }, { VTK_POLYGON, { 3, true } },
    { VTK_PIXEL, { 4, false } }, { VTK_QUAD, { 4, false } }, { VTK_TETRA, { 4, false } },
    { VTK_VOXEL, { 8, false } }, { VTK_HEXAHEDRON, { 8, false } }, { VTK_WEDGE, { 6, false } },
    { VTK_PYRAMID, { 5, false } }, { VTK_PENTAGONAL_PRISM, { 10, false } },
    { VTK_HEXAGONAL_PRISM, { 12, false } }, { VTK_QUADRATIC_EDGE, { 3, false } },
    { VTK_QUADRATIC_TRIANGLE, { 6, false } }, { VTK_QUADRATIC_QUAD, { 8, false } },
    { VTK_QUADRATIC_TETRA, { 10, false } }, { VTK_QUADRATIC_HEXAHEDRON, { 20, false } },
    { VTK_QUADRATIC_WEDGE, { 15, false } }, { VTK_QUADRATIC_PYRAMID, { 13, false } },
    { VTK_BIQUADRATIC_QUAD, { 9, false } }, { VTK_TRIQUADRATIC_HEXAHEDRON, { 27, false } },
    { VTK_QUADRATIC_LINEAR_QUAD, { 6, false } }, { VTK_QUADRATIC_LINEAR_WEDGE, { 12, false } },
    { VTK_BIQUADRATIC_QUADRATIC_WEDGE, { 18, false } },
    { VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON, { 24, false } },
    { VTK_BIQUADRATIC_TRIANGLE, { 7, false } }, { VTK_CUBIC_LINE, { 4, false } },
    { VTK_QUADRATIC_POLYGON, { 6, true } }, { VTK_TRIQUADRATIC_PYRAMID, { 19, false } },
    { VTK_CONVEX_POINT_SET, { 1, true } }, { VTK_POLYHEDRON, { 1, true } },
    { VTK_LAGRANGE_CURVE, { 2, true } }, { VTK_LAGRANGE_TRIANGLE, { 3, true } },
    { VTK_LAGRANGE_QUADRILATERAL, { 4, true } }, { VTK_LAGRANGE_TETRAHEDRON, { 4, true } },
    { VTK_LAGRANGE_HEXAHEDRON, { 8, true } }, { VTK_LAGRANGE_WEDGE, { 6, true } },
    { VTK_LAGRANGE_PYRAMID, { 5, true } }, { VTK_BEZIER_CURVE, { 2, true } },
    { VTK_BEZIER_TRIANGLE, { 3, true } }, { VTK_BEZIER_QUADRILATERAL, { 4, true } },
    { VTK_BEZIER_TETRAHEDRON, { 4, true } }, { VTK_BEZIER_HEXAHEDRON, { 8, true } },
    { VTK_BEZIER_WEDGE, { 6, true } }, { VTK_BEZIER_PYRAMID, { 5, true } } };
  const auto it = sizes.find(type);
  if (it == sizes.end())
  {
    return false;
  }
  size = it->second;
  return true;
}

/** Checks the cell types of an unstructured grid and their numbers of points. */
void CheckCellTypes(vtkUnstructuredGrid* ug, const std::string& what)
{
  vtkCellArray* cells = ug->GetCells();
  vtkUnsignedCharArray* types = ug->GetCellTypesArray();
  const vtkIdType numberOfCells = cells ? cells->GetNumberOfCells() : 0;
  if (numberOfCells == 0)
  {
    return;
  }
  if (!types || types->GetNumberOfTuples() != numberOfCells)
  {
    Fail(what + ": the numbers of cells and cell types differ");
  }
  for (vtkIdType i = 0; i < numberOfCells; ++i)
  {
    const int type = types->GetValue(i);
    const vtkIdType npts = cells->GetCellSize(i);
    CellSize size{ 0, false };
    if (!CellTypeSize(type, size) || (type == VTK_POLYHEDRON && !ug->GetFaces()))
    {
      Fail(what + ": cell " + std::to_string(static_cast<long long>(i)) + " has an invalid or " +
        "unsupported cell type " + std::to_string(type));
    }
    if (size.AtLeast ? npts < size.Size : npts != size.Size)
    {
      Fail(what + ": cell " + std::to_string(static_cast<long long>(i)) + " of type " +
        std::to_string(type) + " has " + std::to_string(static_cast<long long>(npts)) +
        " points, expected " + (size.AtLeast ? "at least " : "") + std::to_string(size.Size));
    }
  }
}

/** True when every component of the array is a finite number. */
bool AllFinite(vtkDataArray* array)
{
  const vtkIdType count = array->GetNumberOfValues();
  if (auto* f = vtkFloatArray::FastDownCast(array))
  {
    const float* p = f->GetPointer(0);
    return std::all_of(p, p + count, [](float v) { return std::isfinite(v); });
  }
  if (auto* d = vtkDoubleArray::FastDownCast(array))
  {
    const double* p = d->GetPointer(0);
    return std::all_of(p, p + count, [](double v) { return std::isfinite(v); });
  }
  const int nc = array->GetNumberOfComponents();
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < nc; ++c)
    {
      if (!std::isfinite(array->GetComponent(i, c)))
      {
        return false;
      }
    }
  }
  return true;
}

/** Rejects datasets whose structure would make the filters or the mapper read out of bounds. */
void ValidateDataSet(vtkDataSet* ds, const std::string& what)
{
  const vtkIdType n = ds->GetNumberOfPoints();
  if (auto* pd = vtkPolyData::SafeDownCast(ds))
  {
    CheckCells(pd->GetVerts(), n, what);
    CheckCells(pd->GetLines(), n, what);
    CheckCells(pd->GetPolys(), n, what);
    CheckCells(pd->GetStrips(), n, what);
  }
  else if (auto* ug = vtkUnstructuredGrid::SafeDownCast(ds))
  {
    CheckCells(ug->GetCells(), n, what);
    CheckCellTypes(ug, what);
  }
  else if (auto* sg = vtkStructuredGrid::SafeDownCast(ds))
  {
    int dims[3];
    sg->GetDimensions(dims);
    if (static_cast<double>(dims[0]) * dims[1] * dims[2] != static_cast<double>(n))
    {
      Fail(what + ": the structured grid has " + std::to_string(static_cast<long long>(n)) +
        " points but its dimensions are " + std::to_string(dims[0]) + "x" +
        std::to_string(dims[1]) + "x" + std::to_string(dims[2]));
    }
  }
  else if (auto* rg = vtkRectilinearGrid::SafeDownCast(ds))
  {
    int dims[3];
    rg->GetDimensions(dims);
    vtkDataArray* coordinates[3] = { rg->GetXCoordinates(), rg->GetYCoordinates(),
      rg->GetZCoordinates() };
    for (int i = 0; i < 3; ++i)
    {
      if (!coordinates[i] || coordinates[i]->GetNumberOfTuples() != dims[i])
      {
        Fail(what + ": the rectilinear grid's " + std::string(1, static_cast<char>('x' + i)) +
          " coordinates do not match its dimensions");
      }
    }
  }
  // Array sizes: a point or cell array shorter than the dataset is corrupt.
  for (int a = 0; a < ds->GetPointData()->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = ds->GetPointData()->GetAbstractArray(a);
    if (array && array->GetNumberOfTuples() < n)
    {
      Fail(what + ": point array " + Quote(array->GetName() ? array->GetName() : "") +
        " is shorter than the number of points");
    }
  }
  for (int a = 0; a < ds->GetCellData()->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = ds->GetCellData()->GetAbstractArray(a);
    if (array && array->GetNumberOfTuples() < ds->GetNumberOfCells())
    {
      Fail(what + ": cell array " + Quote(array->GetName() ? array->GetName() : "") +
        " is shorter than the number of cells");
    }
  }
  // Coordinates: GetBounds() skips NaN, so look at every explicit point (the points that are not
  // finite were dropped with their cells before: see WithoutNonFinitePoints()).
  if (auto* ps = vtkPointSet::SafeDownCast(ds))
  {
    if (ps->GetPoints() && !AllFinite(ps->GetPoints()->GetData()))
    {
      Fail(what + ": point coordinates are not finite (NaN or infinity)");
    }
  }
  if (n > 0)
  {
    double bounds[6];
    ds->GetBounds(bounds);
    for (double b : bounds)
    {
      if (!std::isfinite(b))
      {
        Fail(what + ": point coordinates are not finite");
      }
    }
  }
}

/**
 * The point set without its points whose coordinates are not finite (NaN or infinity) and the
 * cells that use them, with a warning; ds itself when all are finite. Fails when no point is
 * finite, or when no cell is left of a dataset that had cells. The connectivity is checked first
 * (a cell may not name a point that does not exist).
 */
vtkSmartPointer<vtkDataSet> WithoutNonFinitePoints(vtkDataSet* ds, const std::string& what)
{
  auto* ps = vtkPointSet::SafeDownCast(ds);
  vtkDataArray* coordinates = ps && ps->GetPoints() ? ps->GetPoints()->GetData() : nullptr;
  if (!coordinates || AllFinite(coordinates))
  {
    return ds;
  }
  const vtkIdType n = ds->GetNumberOfPoints();
  std::vector<char> bad(static_cast<std::size_t>(n), 0);
  vtkIdType badPoints = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    coordinates->GetTuple(i, p);
    bad[i] = !(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
    badPoints += bad[i];
  }
  if (badPoints == n)
  {
    Fail(what + ": no point has finite coordinates (all are NaN or infinity)");
  }
  if (auto* pd = vtkPolyData::SafeDownCast(ds))
  {
    for (vtkCellArray* cells : { pd->GetVerts(), pd->GetLines(), pd->GetPolys(), pd->GetStrips() })
    {
      CheckCells(cells, n, what);
    }
  }
  else if (auto* ug = vtkUnstructuredGrid::SafeDownCast(ds))
  {
    CheckCells(ug->GetCells(), n, what);
  }
  vtkNew<vtkIdList> keep;
  vtkNew<vtkIdList> ids;
  const vtkIdType cells = ds->GetNumberOfCells();
  for (vtkIdType c = 0; c < cells; ++c)
  {
    ds->GetCellPoints(c, ids);
    bool finite = true;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds() && finite; ++k)
    {
      finite = !bad[ids->GetId(k)];
    }
    if (finite)
    {
      keep->InsertNextId(c);
    }
  }
  if (cells > 0 && keep->GetNumberOfIds() == 0)
  {
    Fail(what + ": every cell uses a point whose coordinates are not finite (NaN or infinity)");
  }
  vtkNew<vtkExtractCells> extract;
  extract->SetInputData(ds);
  extract->SetCellList(keep);
  extract->Update();
  const vtkIdType dropped = cells - keep->GetNumberOfIds();
  Warn(what + ": " + std::to_string(static_cast<long long>(badPoints)) + " of " +
    std::to_string(static_cast<long long>(n)) + " points " + (badPoints == 1 ? "has" : "have") +
    " coordinates that are not finite (NaN or infinity): " + (badPoints == 1 ? "it" : "they") +
    " and the " + std::to_string(static_cast<long long>(dropped)) + " cell" +
    (dropped == 1 ? "" : "s") + " that use " + (badPoints == 1 ? "it" : "them") +
    " are left out");
  return extract->GetOutput();
}

/**
 * Every dataset of a composite (every leaf, named as the vtkstylize command names its
 * parts: the block's name, else "block N"), without its non-finite points and validated.
 */
void ValidateBlocks(vtkDataObject* data, const std::string& what)
{
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    it->SkipEmptyNodesOn();
    int index = 0;
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem(), ++index)
    {
      auto* ds = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
      if (!ds)
      {
        continue; // (not a dataset: the caller decides what to do with it)
      }
      const std::string name = vtkStylizeReader::GetBlockName(it, index);
      const std::string leafWhat = what + " (block " + Quote(name) + ")";
      vtkSmartPointer<vtkDataSet> kept = WithoutNonFinitePoints(ds, leafWhat);
      ValidateDataSet(kept, leafWhat);
      if (kept.GetPointer() != ds)
      {
        composite->SetDataSet(it, kept);
      }
    }
  }
}
} // namespace

//------------------------------------------------------------------------------
vtkStylizeReader::vtkStylizeReader()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkStylizeReader::~vtkStylizeReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
std::string vtkStylizeReader::GetSupportedExtensions()
{
  return SupportedExtensions();
}

//------------------------------------------------------------------------------
bool vtkStylizeReader::IsSupportedFile(const std::string& path)
{
  return IsSupportedInput(path);
}

//------------------------------------------------------------------------------
std::string vtkStylizeReader::GetBlockName(vtkCompositeDataIterator* iterator, int index)
{
  if (iterator && iterator->HasCurrentMetaData() &&
    iterator->GetCurrentMetaData()->Has(vtkCompositeDataSet::NAME()))
  {
    return iterator->GetCurrentMetaData()->Get(vtkCompositeDataSet::NAME());
  }
  return "block " + std::to_string(index);
}

//------------------------------------------------------------------------------
const char* vtkStylizeReader::GetWarning(int index) const
{
  return index >= 0 && index < this->GetNumberOfWarnings()
    ? this->Warnings[static_cast<std::size_t>(index)].c_str()
    : nullptr;
}

//------------------------------------------------------------------------------
int vtkStylizeReader::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
  return 1;
}

//------------------------------------------------------------------------------
void vtkStylizeReader::Read()
{
  this->ErrorMessage.clear();
  this->Warnings.clear();
  this->Data = nullptr;
  const std::string path = this->FileName ? this->FileName : "";
  const std::string what = "cannot read " + Quote(path);
  vtkSmartPointer<vtkDataObject> data;
  {
    CaptureScope capture;
    CurrentWarnings = &this->Warnings;
    try
    {
      if (path.empty())
      {
        Fail("no file to read (SetFileName)");
      }
      data = ReadInput(path, this->TimeStep);
      if (auto* ds = vtkDataSet::SafeDownCast(data))
      {
        vtkSmartPointer<vtkDataSet> kept = WithoutNonFinitePoints(ds, Quote(path));
        ValidateDataSet(kept, Quote(path));
        data = kept;
      }
      else
      {
        ValidateBlocks(data, Quote(path));
      }
    }
    catch (const ReadFailure& failure)
    {
      this->ErrorMessage = failure.Message;
    }
    catch (const std::bad_alloc&)
    {
      this->ErrorMessage = what + ": out of memory";
    }
    catch (const std::exception& e)
    {
      // (a library's exception, e.g. std::length_error for a size it cannot hold)
      this->ErrorMessage = what + ": " + vtkStylizeOutputWindow::OneLine(e.what());
    }
    CurrentWarnings = nullptr;
  }
  if (this->ErrorMessage.empty())
  {
    this->Data = data;
  }
  else
  {
    this->ErrorMessage = vtkStylizeOutputWindow::OneLine(this->ErrorMessage, 1000);
  }
}

//------------------------------------------------------------------------------
int vtkStylizeReader::RequestDataObject(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // The output's type is the file's, known once it is read: the file is read here (again only
  // after a change of the settings), and RequestData hands the result on.
  if (this->GetMTime() > this->ReadTime)
  {
    this->Read();
    this->ReadTime.Modified();
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkDataObject* output = vtkDataObject::GetData(outInfo);
  const char* type = this->Data ? this->Data->GetClassName() : "vtkPolyData";
  if (!output || std::strcmp(output->GetClassName(), type) != 0)
  {
    vtkSmartPointer<vtkDataObject> fresh;
    if (this->Data)
    {
      fresh.TakeReference(this->Data->NewInstance());
    }
    else
    {
      fresh = vtkSmartPointer<vtkPolyData>::New();
    }
    outInfo->Set(vtkDataObject::DATA_OBJECT(), fresh);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkStylizeReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkDataObject* output = vtkDataObject::GetData(outputVector->GetInformationObject(0));
  if (!this->Data)
  {
    this->SetErrorCode(vtkErrorCode::FileFormatError);
    vtkErrorMacro(<< this->ErrorMessage);
    return 0;
  }
  this->SetErrorCode(vtkErrorCode::NoError);
  output->ShallowCopy(this->Data);
  return 1;
}

//------------------------------------------------------------------------------
void vtkStylizeReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "TimeStep: " << this->TimeStep << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
  os << indent << "Warnings: " << this->Warnings.size() << "\n";
}
