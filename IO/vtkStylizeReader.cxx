#include "vtkStylizeReader.h"
#include "vtkStylizeReaderInternal.h"

#include "vtkStylizeFileChecks.h"
#include "vtkStylizeOutputWindow.h"

#include "vtkAlgorithm.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObjectTypes.h"
#include "vtkDataSet.h"
#include "vtkErrorCode.h"
#include "vtkExodusIIReader.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkGenericEnSightReader.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkObjectFactory.h"
#include "vtkOpenFOAMReader.h"
#include "vtkPLYReader.h"
#include "vtkPolyData.h"
#include "vtkSTLReader.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"
#include "vtkXMLImageDataReader.h"
#include "vtkXMLMultiBlockDataReader.h"
#include "vtkXMLPImageDataReader.h"
#include "vtkXMLPPolyDataReader.h"
#include "vtkXMLPRectilinearGridReader.h"
#include "vtkXMLPStructuredGridReader.h"
#include "vtkXMLPUnstructuredGridReader.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLRectilinearGridReader.h"
#include "vtkXMLStructuredGridReader.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <functional>
#include <map>
#include <new>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

vtkStandardNewMacro(vtkStylizeReader);

namespace vtkStylizeReaderInternal
{
//------------------------------------------------------------------------------
void Fail(const std::string& message)
{
  throw ReadFailure{ message };
}

//------------------------------------------------------------------------------
void ReadContext::Warn(const std::string& message)
{
  this->Warnings.push_back(message);
}

//------------------------------------------------------------------------------
std::string Quote(const std::string& text)
{
  return "'" + text + "'";
}

//------------------------------------------------------------------------------
void ReadContext::ClearVTKErrors()
{
  if (this->Capture)
  {
    this->Capture->ClearMessages();
  }
}

//------------------------------------------------------------------------------
void ReadContext::CheckVTKErrors(const std::string& what)
{
  if (this->Capture && this->Capture->HasFailure())
  {
    Fail(what + ": " + this->Capture->GetFirstFailure());
  }
}
} // namespace vtkStylizeReaderInternal

namespace
{
using namespace vtkStylizeReaderInternal;

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
  explicit CaptureScope(ReadContext& context)
    : Context(context)
  {
    this->Previous = vtkOutputWindow::GetInstance();
    if (auto* outer = vtkStylizeOutputWindow::SafeDownCast(this->Previous))
    {
      this->Window->SetEchoDescriptor(outer->GetEchoDescriptor());
    }
    vtkOutputWindow::SetInstance(this->Window);
    this->OuterCapture = context.Capture;
    context.Capture = this->Window;
    // (VTK's readers report failures only through their error macros, which say nothing while
    // a host has turned the messages off: the captured window needs them on)
    this->WarningDisplay = vtkObject::GetGlobalWarningDisplay();
    vtkObject::GlobalWarningDisplayOn();
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
    vtkObject::SetGlobalWarningDisplay(this->WarningDisplay);
    this->Context.Capture = this->OuterCapture; // (an enclosing scope's window captures again)
    vtkOutputWindow::SetInstance(this->Previous);
  }
  CaptureScope(const CaptureScope&) = delete;
  CaptureScope& operator=(const CaptureScope&) = delete;

private:
  ReadContext& Context;
  vtkSmartPointer<vtkOutputWindow> Previous;
  vtkStylizeOutputWindow* OuterCapture = nullptr;
  vtkNew<vtkStylizeOutputWindow> Window;
  vtkLogger::Verbosity LoggerLevel = vtkLogger::VERBOSITY_OFF;
  bool LoggerChanged = false;
  int WarningDisplay = 1;
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
  return [](const std::string& path) -> vtkSmartPointer<vtkAlgorithm>
  {
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
      [](const std::string& path) -> vtkSmartPointer<vtkAlgorithm>
      {
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
      [](const std::string& path) -> vtkSmartPointer<vtkAlgorithm>
      {
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
std::string StructuralCheck(ReadContext& context, const std::string& path)
{
  using Check = std::string (*)(const std::string&);
  static const std::map<std::string, Check> checks = {
    { ".ply", vtkStylizeFileChecks::CheckPLYFile }, { ".obj", vtkStylizeFileChecks::CheckOBJFile },
    { ".stl", vtkStylizeFileChecks::CheckSTLFile },
    { ".vtk", vtkStylizeFileChecks::CheckLegacyVTKFile },
    { ".vtu", ClaimsThen<vtkStylizeFileChecks::CheckUnstructuredGridFaces> },
    { ".vti", ClaimsThen<vtkStylizeFileChecks::CheckImageDataFile> },
    { ".vtp", vtkStylizeFileChecks::CheckXMLClaims },
    { ".vts", vtkStylizeFileChecks::CheckXMLClaims },
    { ".vtr", vtkStylizeFileChecks::CheckXMLClaims },
    { ".pvti", vtkStylizeFileChecks::CheckImageDataFile },
    { ".case", vtkStylizeFileChecks::CheckEnSightCaseFile },
    { ".ex2", vtkStylizeFileChecks::CheckExodusFile },
    { ".exo", vtkStylizeFileChecks::CheckExodusFile },
    { ".e", vtkStylizeFileChecks::CheckExodusFile }, { ".g", vtkStylizeFileChecks::CheckExodusFile }
  };
  const auto check = checks.find(Extension(path));
  if (check == checks.end())
  {
    return std::string();
  }
  const std::string problem = check->second(path);
  context.ClearVTKErrors(); // (a check that reads with VTK leaves the reader's own complaints)
  return problem;
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
void CheckReferencedFiles(ReadContext& context, const std::string& path,
  std::vector<std::string> chain = {}, const std::string& input = std::string())
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
  context.ClearVTKErrors();
  if (!parser->Parse() || !parser->GetRootElement())
  {
    context.ClearVTKErrors();
    Fail("cannot read " + Quote(top) + ": " + (path == top ? std::string() : Quote(path) + " is ") +
      "not a well-formed VTK XML file");
  }
  context.ClearVTKErrors();
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
    const std::string problem = StructuralCheck(context, file);
    if (!problem.empty())
    {
      Fail("cannot read " + Quote(top) + ": " + Quote(file) + ": " + problem);
    }
    CheckReferencedFiles(context, file, chain, top);
  }
}

/**
 * The data set files of a ParaView data (.pvd) collection, in time order, read with VTK's XML
 * parser; a relative file is relative to the .pvd's folder.
 */
std::vector<std::string> CollectionFiles(ReadContext& context, const std::string& path)
{
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(path.c_str());
  context.ClearVTKErrors();
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
  context.ClearVTKErrors();
  if (entries.empty())
  {
    Fail("cannot read " + Quote(path) + ": the collection lists no data set file");
  }
  std::stable_sort(
    entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
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

vtkSmartPointer<vtkDataObject> ReadInput(
  ReadContext& context, const std::string& path, int timeStep)
{
  if (Extension(path) == ".pvd")
  {
    CheckInputFile(path);
    const std::vector<std::string> files = CollectionFiles(context, path);
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
    return ReadInput(context, file, 0);
  }
  const auto it = Readers().find(Extension(path));
  if (it == Readers().end())
  {
    Fail("unsupported file type " + Quote(path) + " (supported: " + SupportedExtensions() + ")");
  }
  CheckInputFile(path, it->first == ".foam");
  CheckReferencedFiles(context, path);
  const std::string problem = StructuralCheck(context, path);
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
    return ReadPLYStrips(context, path, "cannot read " + Quote(path));
  }
  context.ClearVTKErrors();
  vtkSmartPointer<vtkAlgorithm> reader = it->second(path);
  if (it->first == ".ply" && ASCIIPLYWithoutLastNewline(path))
  {
    // VTK 9.1's reader frees a line twice (abort) when an ASCII file does not end with a
    // newline: it reads the file from memory with one added.
    auto* ply = vtkPLYReader::SafeDownCast(reader);
    ply->SetInputString(ContentWithLastNewline(path));
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
  context.CheckVTKErrors(what);
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
/**
 * The class a legacy .vtk file's header announces (its DATASET line, after the version, title
 * and format lines, read in its first 8 KiB); empty when it announces none.
 */
std::string LegacyOutputClass(const std::string& path)
{
  static const std::map<std::string, std::string> classes = { { "POLYDATA", "vtkPolyData" },
    { "STRUCTURED_POINTS", "vtkStructuredPoints" }, { "STRUCTURED_GRID", "vtkStructuredGrid" },
    { "RECTILINEAR_GRID", "vtkRectilinearGrid" }, { "UNSTRUCTURED_GRID", "vtkUnstructuredGrid" },
    { "TABLE", "vtkTable" }, { "DIRECTED_GRAPH", "vtkDirectedGraph" },
    { "UNDIRECTED_GRAPH", "vtkUndirectedGraph" }, { "MOLECULE", "vtkMolecule" },
    { "TREE", "vtkTree" } };
  std::ifstream in(path, std::ios::binary);
  std::string head(8192, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  std::istringstream lines(head);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number)
  {
    if (number <= 3)
    {
      continue; // (the version, the title, ASCII or BINARY)
    }
    std::istringstream words(line);
    std::string key, type;
    if (!(words >> key))
    {
      continue;
    }
    words >> type;
    std::transform(type.begin(), type.end(), type.begin(),
      [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    const auto found = classes.find(type);
    return Lower(key) == "dataset" && found != classes.end() ? found->second : std::string();
  }
  return std::string();
}
} // namespace

namespace vtkStylizeReaderInternal
{
//------------------------------------------------------------------------------
ReadResult ReadChecked(const std::string& path, int timeStep)
{
  ReadResult result;
  const std::string what = "cannot read " + Quote(path);
  ReadContext context;
  CaptureScope capture(context);
  try
  {
    vtkSmartPointer<vtkDataObject> data = ReadInput(context, path, timeStep);
    if (auto* ds = vtkDataSet::SafeDownCast(data))
    {
      vtkSmartPointer<vtkDataSet> kept = WithoutNonFinitePoints(context, ds, Quote(path));
      ValidateDataSet(context, kept, Quote(path));
      data = kept;
    }
    else
    {
      ValidateBlocks(context, data, Quote(path));
    }
    result.Data = data;
  }
  catch (const ReadFailure& failure)
  {
    result.Error = failure.Message;
  }
  catch (const std::bad_alloc&)
  {
    result.Error = what + ": out of memory";
  }
  catch (const std::exception& e)
  {
    // (a library's exception, e.g. std::length_error for a size it cannot hold)
    result.Error = what + ": " + vtkStylizeOutputWindow::OneLine(e.what());
  }
  result.Warnings = std::move(context.Warnings);
  if (!result.Error.empty())
  {
    result.Data = nullptr;
  }
  return result;
}

//------------------------------------------------------------------------------
std::string OutputClass(const std::string& path, int timeStep)
{
  static const std::map<std::string, std::string> classes = { { ".vtp", "vtkPolyData" },
    { ".pvtp", "vtkPolyData" }, { ".stl", "vtkPolyData" }, { ".obj", "vtkPolyData" },
    { ".ply", "vtkPolyData" }, { ".vtu", "vtkUnstructuredGrid" },
    { ".pvtu", "vtkUnstructuredGrid" }, { ".vts", "vtkStructuredGrid" },
    { ".pvts", "vtkStructuredGrid" }, { ".vtr", "vtkRectilinearGrid" },
    { ".pvtr", "vtkRectilinearGrid" }, { ".vti", "vtkImageData" }, { ".pvti", "vtkImageData" },
    { ".vtm", "vtkMultiBlockDataSet" }, { ".ex2", "vtkMultiBlockDataSet" },
    { ".exo", "vtkMultiBlockDataSet" }, { ".e", "vtkMultiBlockDataSet" },
    { ".g", "vtkMultiBlockDataSet" }, { ".case", "vtkMultiBlockDataSet" },
    { ".foam", "vtkMultiBlockDataSet" } };
  const std::string extension = Extension(path);
  if (extension == ".vtk")
  {
    return LegacyOutputClass(path);
  }
  if (extension == ".pvd")
  {
    // (the collection's XML, parsed by VTK's expat-based parser; the data set file itself is
    // read later, in the helper)
    ReadContext context;
    CaptureScope capture(context);
    struct stat st;
    try
    {
      if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode) || st.st_size > (64 << 20))
      {
        return std::string();
      }
      const std::vector<std::string> files = CollectionFiles(context, path);
      if (timeStep < 0 || static_cast<std::size_t>(timeStep) >= files.size() ||
        Extension(files[static_cast<std::size_t>(timeStep)]) == ".pvd")
      {
        return std::string();
      }
      return OutputClass(files[static_cast<std::size_t>(timeStep)], 0);
    }
    catch (const ReadFailure&)
    {
      return std::string();
    }
  }
  const auto found = classes.find(extension);
  return found == classes.end() ? std::string() : found->second;
}
} // namespace vtkStylizeReaderInternal

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
bool vtkStylizeReader::IsPLYWithTriangleStrips(const std::string& path)
{
  return HasPLYStrips(path);
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
void vtkStylizeReader::ForEachBlock(vtkCompositeDataSet* composite,
  const std::function<void(vtkCompositeDataIterator*, const std::string&)>& visit)
{
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(composite->NewIterator());
  it->SkipEmptyNodesOn();
  int index = 0;
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem(), ++index)
  {
    visit(it, vtkStylizeReader::GetBlockName(it, index));
  }
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
int vtkStylizeReader::RequestDataObject(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // The output's class is the file's, known here without reading the file (OutputClass): the
  // file is read in RequestData, on the ranks that need the data only (this reader does not
  // handle piece requests: the pipeline runs it for piece 0).
  const std::string path = this->FileName ? this->FileName : "";
  std::string type = path.empty() ? std::string() : OutputClass(path, this->TimeStep);
  vtkSmartPointer<vtkDataObject> fresh;
  if (!type.empty())
  {
    fresh.TakeReference(vtkDataObjectTypes::NewDataObject(type.c_str()));
  }
  if (!fresh)
  {
    type = "vtkPolyData"; // (the read says why it fails, or that the data is not this)
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkDataObject* output = vtkDataObject::GetData(outInfo);
  if (!output || type != output->GetClassName())
  {
    if (!fresh)
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
  this->ErrorMessage.clear();
  this->Warnings.clear();
  const std::string path = this->FileName ? this->FileName : "";
  ReadResult result;
  if (path.empty())
  {
    result.Error = "no file to read (SetFileName)";
  }
  else if (this->Isolated)
  {
    IsolationLimits limits = AutomaticLimits(InputBytes(path));
    if (this->MemoryLimit > 0.0)
    {
      limits.MemoryMiB = this->MemoryLimit;
    }
    if (this->TimeLimit > 0.0)
    {
      limits.Seconds = this->TimeLimit;
    }
    ReadContext context;
    CaptureScope capture(context); // (VTK's messages while the data is handed back)
    result = ReadIsolated(context, path, this->TimeStep, limits);
  }
  else
  {
    result = ReadChecked(path, this->TimeStep);
  }
  this->Warnings = result.Warnings;
  if (result.Error.empty() && !result.Data->IsA(output->GetClassName()))
  {
    result.Error = "cannot read " + Quote(path) + ": it holds a " + result.Data->GetClassName() +
      ", not the " + output->GetClassName() + " its " +
      (Extension(path) == ".vtk" ? "header" : "extension") + " announces";
  }
  if (!result.Error.empty())
  {
    this->ErrorMessage = vtkStylizeOutputWindow::OneLine(result.Error, 1000);
    this->SetErrorCode(vtkErrorCode::FileFormatError);
    output->Initialize();
    vtkErrorMacro(<< this->ErrorMessage);
    return 0;
  }
  this->SetErrorCode(vtkErrorCode::NoError);
  output->ShallowCopy(result.Data);
  return 1;
}

//------------------------------------------------------------------------------
void vtkStylizeReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "TimeStep: " << this->TimeStep << "\n";
  os << indent << "Isolated: " << this->Isolated << "\n";
  os << indent << "MemoryLimit: " << this->MemoryLimit << "\n";
  os << indent << "TimeLimit: " << this->TimeLimit << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
  os << indent << "Warnings: " << this->Warnings.size() << "\n";
}
