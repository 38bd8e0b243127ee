#include "vtkStylizeMeshGeometry.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

#include <algorithm>

//------------------------------------------------------------------------------
std::vector<std::array<vtkIdType, 3>> vtkStylizeMesh::Triangles(vtkPolyData* input)
{
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(input->GetPoints());
  surface->SetPolys(input->GetPolys());
  surface->SetStrips(input->GetStrips());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(surface);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  if (input->GetNumberOfPoints() > 0 &&
    (input->GetNumberOfPolys() > 0 || input->GetNumberOfStrips() > 0))
  {
    triangles->Update();
  }
  vtkPolyData* tri = triangles->GetOutput();
  std::vector<std::array<vtkIdType, 3>> faces;
  if (tri && tri->GetPolys())
  {
    vtkCellArray* polys = tri->GetPolys();
    vtkIdType n;
    const vtkIdType* ids;
    for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
    {
      if (n == 3 && ids[0] != ids[1] && ids[1] != ids[2] && ids[0] != ids[2])
      {
        faces.push_back({ ids[0], ids[1], ids[2] });
      }
    }
  }
  return faces;
}

//------------------------------------------------------------------------------
std::vector<vtkStylizeMesh::Vec> vtkStylizeMesh::AngleWeightedNormals(
  const std::vector<Vec>& p, const std::vector<std::array<vtkIdType, 3>>& faces)
{
  std::vector<Vec> normal(p.size(), Vec{ 0, 0, 0 });
  for (const auto& f : faces)
  {
    Vec fn = Cross(Sub(p[f[1]], p[f[0]]), Sub(p[f[2]], p[f[0]]));
    if (!Normalize(fn))
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      Vec a = Sub(p[f[(k + 1) % 3]], p[f[k]]);
      Vec b = Sub(p[f[(k + 2) % 3]], p[f[k]]);
      if (!Normalize(a) || !Normalize(b))
      {
        continue;
      }
      const double angle = std::acos(std::max(-1.0, std::min(1.0, Dot(a, b))));
      normal[f[k]] = Add(normal[f[k]], Scale(fn, angle));
    }
  }
  return normal;
}
