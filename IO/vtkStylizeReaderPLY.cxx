// The PLY files VTK 9.1's vtkPLYReader cannot read as they are: surfaces stored as triangle
// strips (read here with VTK's low-level vtkPLY API), and ASCII files without a last newline.

#include "vtkStylizeReaderInternal.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPLY.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace vtkStylizeReaderInternal
{
namespace
{
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
 * Reads the count records of the element name (tristrips or face), each a list "vertex_indices":
 * the strips (split at -1) into strips, the faces into polys. The problem (an index outside the
 * pointCount vertices), or "". Every record is read, so that vtkPLY frees each list.
 */
std::string ReadPLYIndexLists(
  PlyFile* ply, char* name, int count, int pointCount, vtkCellArray* strips, vtkCellArray* polys)
{
  PlyProperty listProp = { "vertex_indices", PLY_INT, PLY_INT,
    static_cast<int>(offsetof(PLYIndexList, Indices)), 1, PLY_INT, PLY_INT,
    static_cast<int>(offsetof(PLYIndexList, Count)) };
  std::string problem;
  vtkPLY::ply_get_element_setup(ply, name, 1, &listProp);
  const bool isStrips = std::string(name) == "tristrips";
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
  return problem;
}
} // namespace

//------------------------------------------------------------------------------
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

//------------------------------------------------------------------------------
std::string ContentWithLastNewline(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  content += '\n';
  return content;
}

//------------------------------------------------------------------------------
bool HasPLYStrips(const std::string& path)
{
  // The header alone, at most 64 KiB of it (a PLY header is a few hundred bytes): ParaView asks
  // this of every .ply that File > Open sees.
  std::ifstream in(path, std::ios::binary);
  std::vector<char> head(1 << 16);
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  std::istringstream header(std::string(head.data(), static_cast<size_t>(in.gcount())));
  std::string line;
  if (!std::getline(header, line) || line.compare(0, 3, "ply") != 0)
  {
    return false;
  }
  while (std::getline(header, line) && line.compare(0, 10, "end_header") != 0)
  {
    std::istringstream words(line);
    std::string keyword, name;
    long long count = 0;
    if (words >> keyword >> name >> count && keyword == "element" && name == "tristrips" &&
      count > 0)
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
/**
 * Reads a PLY file whose surface is stored as triangle strips, which VTK 9.1's vtkPLYReader does
 * not read: with VTK's own low-level PLY API (vtkPLY, as vtkPLYReader uses it for faces), the
 * vertices (x, y, z), the strips (element "tristrips", list "vertex_indices", -1 between two
 * strips) and any faces (element "face"), as a polydata of triangles (vtkTriangleFilter). Indices
 * outside the vertices fail with one line.
 */
vtkSmartPointer<vtkDataObject> ReadPLYStrips(
  ReadContext& context, const std::string& path, const std::string& what)
{
  int elementCount = 0;
  char** elementNames = nullptr;
  PlyFile* ply = nullptr;
  if (ASCIIPLYWithoutLastNewline(path))
  {
    // (vtkPLY's ASCII reader needs a newline after the last line: read from memory with one)
    ply = vtkPLY::ply_open_for_reading_from_string(
      ContentWithLastNewline(path), &elementCount, &elementNames);
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
    problem = ReadPLYIndexLists(ply, name, count, pointCount, strips, polys);
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
  context.ClearVTKErrors();
  triangles->Update();
  context.CheckVTKErrors(what + ": triangulating the strips failed");
  vtkSmartPointer<vtkPolyData> result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(triangles->GetOutput());
  return result;
}
} // namespace vtkStylizeReaderInternal
