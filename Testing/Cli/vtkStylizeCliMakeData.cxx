/**
 * Writes the small input files of the vtkstylize command-line tests into a directory:
 * valid files in every supported format, and broken ones (truncated, garbage, empty, zero points
 * or cells, out-of-range connectivity, ...).
 *
 *   vtkStylizeCliMakeData OUTDIR
 */

#include "vtkAppendFilter.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkConeSource.h"
#include "vtkDoubleArray.h"
#include "vtkElevationFilter.h"
#include "vtkExodusIIWriter.h"
#include "vtkFloatArray.h"
#include "vtkGenericDataObjectWriter.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkOBJWriter.h"
#include "vtkPLYWriter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRTAnalyticSource.h"
#include "vtkRectilinearGrid.h"
#include "vtkSTLWriter.h"
#include "vtkSphereSource.h"
#include "vtkStructuredGrid.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLImageDataWriter.h"
#include "vtkXMLMultiBlockDataWriter.h"
#include "vtkXMLPUnstructuredGridWriter.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtkXMLRectilinearGridWriter.h"
#include "vtkXMLStructuredGridWriter.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

namespace
{
std::string Dir;

std::string P(const std::string& name)
{
  return Dir + "/" + name;
}

bool Failed = false;

template <typename W>
void Write(W* writer, const std::string& name)
{
  writer->SetFileName(P(name).c_str());
  if (!writer->Write())
  {
    std::cerr << "cannot write " << name << "\n";
    Failed = true;
  }
}

std::vector<char> ReadAll(const std::string& name)
{
  std::ifstream in(P(name), std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void WriteBytes(const std::string& name, const char* data, std::size_t size)
{
  std::ofstream out(P(name), std::ios::binary | std::ios::trunc);
  out.write(data, static_cast<std::streamsize>(size));
  if (!out)
  {
    std::cerr << "cannot write " << name << "\n";
    Failed = true;
  }
}

void WriteText(const std::string& name, const std::string& text)
{
  WriteBytes(name, text.data(), text.size());
}

/** Copies the first fraction of a file. */
void Truncate(const std::string& from, const std::string& to, double fraction)
{
  const std::vector<char> bytes = ReadAll(from);
  WriteBytes(to, bytes.data(), static_cast<std::size_t>(bytes.size() * fraction));
}

/** Deterministic binary garbage. */
std::string Garbage(std::size_t size, unsigned seed)
{
  std::string s(size, '\0');
  unsigned x = seed;
  for (char& c : s)
  {
    x = x * 1664525u + 1013904223u;
    c = static_cast<char>(x >> 24);
  }
  return s;
}

vtkSmartPointer<vtkPolyData> Sphere()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(12);
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(sphere->GetOutputPort());
  elevation->SetLowPoint(0, -0.5, 0);
  elevation->SetHighPoint(0, 0.5, 0);
  elevation->Update();
  vtkSmartPointer<vtkPolyData> pd = vtkSmartPointer<vtkPolyData>::New();
  pd->ShallowCopy(elevation->GetOutput());
  return pd;
}

vtkSmartPointer<vtkImageData> Wavelet(int half)
{
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-half, half, -half, half, -half, half);
  wavelet->Update();
  vtkSmartPointer<vtkImageData> image = vtkSmartPointer<vtkImageData>::New();
  image->ShallowCopy(wavelet->GetOutput());
  return image;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: vtkStylizeCliMakeData OUTDIR\n";
    return 2;
  }
  Dir = argv[1];
  ::mkdir(Dir.c_str(), 0777);
  ::mkdir(P("dir.vtp").c_str(), 0777);       // a directory given as INPUT
  ::mkdir(P("out").c_str(), 0777);           // output directory of the tests
  ::mkdir(P("out/isdir.png").c_str(), 0777); // a directory given as --output
  ::unlink(P("devnull.vtp").c_str());
  if (::symlink("/dev/null", P("devnull.vtp").c_str()) != 0) // not a regular file
  {
    std::cerr << "cannot create devnull.vtp\n";
    Failed = true;
  }

  // ---- Valid files -------------------------------------------------------------------------
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  {
    vtkNew<vtkXMLPolyDataWriter> w;
    w->SetInputData(sphere);
    w->SetDataModeToAppended();
    w->EncodeAppendedDataOff();
    Write(w.Get(), "sphere.vtp");
    Write(w.Get(), "SPHERE_UPPER.VTP");
  }
  {
    // A 3-component point array whose magnitude varies: "Velocity" = (2 x, y, z) on the sphere.
    vtkNew<vtkPolyData> flow;
    flow->DeepCopy(sphere);
    vtkNew<vtkFloatArray> velocity;
    velocity->SetName("Velocity");
    velocity->SetNumberOfComponents(3);
    for (vtkIdType i = 0; i < flow->GetNumberOfPoints(); ++i)
    {
      double p[3];
      flow->GetPoint(i, p);
      velocity->InsertNextTuple3(2.0 * p[0], p[1], p[2]);
    }
    flow->GetPointData()->AddArray(velocity);
    vtkNew<vtkXMLPolyDataWriter> w;
    w->SetInputData(flow);
    Write(w.Get(), "velocity.vtp");
  }
  {
    // Volumetric unstructured grid: hexahedra of a small image, with point scalars.
    vtkNew<vtkAppendFilter> toGrid;
    toGrid->SetInputData(Wavelet(3));
    toGrid->Update();
    vtkNew<vtkXMLUnstructuredGridWriter> w;
    w->SetInputData(toGrid->GetOutput());
    Write(w.Get(), "hexes.vtu");
    vtkNew<vtkGenericDataObjectWriter> legacy;
    legacy->SetInputData(toGrid->GetOutput());
    legacy->SetFileTypeToBinary();
    Write(legacy.Get(), "hexes.vtk");
  }
  {
    vtkNew<vtkXMLImageDataWriter> w;
    w->SetInputData(Wavelet(8));
    Write(w.Get(), "wavelet.vti");
    vtkNew<vtkGenericDataObjectWriter> legacy;
    legacy->SetInputData(Wavelet(8));
    legacy->SetFileTypeToBinary();
    Write(legacy.Get(), "wavelet.vtk");
    // No scalars: drawn as its outer surface.
    vtkNew<vtkImageData> plain;
    plain->SetDimensions(4, 3, 2);
    plain->SetSpacing(1, 1, 1);
    w->SetInputData(plain);
    Write(w.Get(), "noscalars.vti");
    // Constant scalars: the contour is empty.
    vtkNew<vtkImageData> constant;
    constant->SetDimensions(4, 4, 4);
    constant->AllocateScalars(VTK_FLOAT, 1);
    constant->GetPointData()->GetScalars()->Fill(1.0);
    w->SetInputData(constant);
    Write(w.Get(), "constant.vti");
  }
  {
    // A ball of density 100 in a background of 0 (a smooth step of one voxel), with six hot
    // voxels of 1000 inside it: the middle of the range (about 500) contours the hot voxels
    // only, six small pieces; Otsu's threshold (between 0 and 100) gives the ball, one closed
    // surface.
    vtkNew<vtkImageData> ball;
    ball->SetDimensions(25, 25, 25);
    ball->SetOrigin(-12, -12, -12);
    vtkNew<vtkFloatArray> density;
    density->SetName("Density");
    for (int k = -12; k <= 12; ++k)
    {
      for (int j = -12; j <= 12; ++j)
      {
        for (int i = -12; i <= 12; ++i)
        {
          const double r = std::sqrt(double(i * i + j * j + k * k));
          double v = 100.0 / (1.0 + std::exp(r - 8.0));
          if ((std::abs(i) == 4 && j == 0 && k == 0) || (std::abs(j) == 4 && i == 0 && k == 0) ||
            (std::abs(k) == 4 && i == 0 && j == 0))
          {
            v = 1000.0;
          }
          density->InsertNextValue(static_cast<float>(v));
        }
      }
    }
    ball->GetPointData()->SetScalars(density);
    vtkNew<vtkXMLImageDataWriter> w;
    w->SetInputData(ball);
    Write(w.Get(), "otsu.vti");
  }
  {
    // Structured grid: a bent sheet of 6 x 5 x 2 points.
    vtkNew<vtkStructuredGrid> grid;
    grid->SetDimensions(6, 5, 2);
    vtkNew<vtkPoints> points;
    vtkNew<vtkFloatArray> height;
    height->SetName("Bend");
    for (int k = 0; k < 2; ++k)
    {
      for (int j = 0; j < 5; ++j)
      {
        for (int i = 0; i < 6; ++i)
        {
          const double z = 0.3 * std::sin(i * 0.6) + 0.4 * k;
          points->InsertNextPoint(i * 0.4, j * 0.4, z);
          height->InsertNextValue(static_cast<float>(z));
        }
      }
    }
    grid->SetPoints(points);
    grid->GetPointData()->SetScalars(height);
    vtkNew<vtkXMLStructuredGridWriter> w;
    w->SetInputData(grid);
    Write(w.Get(), "sheet.vts");
  }
  {
    vtkNew<vtkRectilinearGrid> grid;
    grid->SetDimensions(4, 3, 3);
    vtkNew<vtkDoubleArray> x, y, z;
    for (double v : { 0.0, 0.5, 1.5, 3.0 })
    {
      x->InsertNextValue(v);
    }
    for (double v : { 0.0, 1.0, 1.5 })
    {
      y->InsertNextValue(v);
      z->InsertNextValue(v * 0.5);
    }
    grid->SetXCoordinates(x);
    grid->SetYCoordinates(y);
    grid->SetZCoordinates(z);
    vtkNew<vtkXMLRectilinearGridWriter> w;
    w->SetInputData(grid);
    Write(w.Get(), "grid.vtr");
  }
  {
    vtkNew<vtkConeSource> cone;
    cone->SetCenter(2, 0, 0);
    cone->SetResolution(12);
    cone->Update();
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetNumberOfBlocks(2);
    blocks->SetBlock(0, sphere);
    blocks->SetBlock(1, cone->GetOutput());
    blocks->GetMetaData(0u)->Set(vtkMultiBlockDataSet::NAME(), "sphere");
    blocks->GetMetaData(1u)->Set(vtkMultiBlockDataSet::NAME(), "cone");
    vtkNew<vtkXMLMultiBlockDataWriter> w;
    w->SetInputData(blocks);
    Write(w.Get(), "blocks.vtm");
  }
  {
    vtkNew<vtkGenericDataObjectWriter> w;
    w->SetInputData(sphere);
    w->SetFileTypeToASCII();
    Write(w.Get(), "sphere_ascii.vtk");
    w->SetFileTypeToBinary();
    Write(w.Get(), "sphere_binary.vtk");
  }
  {
    vtkNew<vtkSTLWriter> w;
    w->SetInputData(sphere);
    w->SetFileTypeToASCII();
    Write(w.Get(), "sphere_ascii.stl");
    w->SetFileTypeToBinary();
    Write(w.Get(), "sphere_binary.stl");
  }
  {
    vtkNew<vtkOBJWriter> w;
    w->SetInputData(sphere);
    Write(w.Get(), "sphere.obj");
  }
  {
    vtkNew<vtkPLYWriter> w;
    w->SetInputData(sphere);
    w->SetFileTypeToBinary();
    Write(w.Get(), "sphere.ply");
    // Per-point RGB colours, drawn directly.
    vtkNew<vtkPolyData> colored;
    colored->ShallowCopy(sphere);
    vtkNew<vtkUnsignedCharArray> rgb;
    rgb->SetName("RGB");
    rgb->SetNumberOfComponents(3);
    for (vtkIdType i = 0; i < colored->GetNumberOfPoints(); ++i)
    {
      double p[3];
      colored->GetPoint(i, p);
      rgb->InsertNextTuple3(127.5 * (p[0] + 1), 127.5 * (p[1] + 1), 127.5 * (p[2] + 1));
    }
    colored->GetPointData()->SetScalars(rgb);
    w->SetInputData(colored);
    w->SetArrayName("RGB");
    w->SetColorModeToDefault();
    w->SetFileTypeToASCII();
    Write(w.Get(), "colored.ply");
  }
  // A tiny hand-written ASCII legacy file, with a cell scalar.
  WriteText("quad.vtk",
    "# vtk DataFile Version 3.0\nquad\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n"
    "0 0 0  1 0 0  1 1 0  0 1 0\nPOLYGONS 2 8\n3 0 1 2\n3 0 2 3\n"
    "CELL_DATA 2\nSCALARS Id int 1\nLOOKUP_TABLE default\n0 1\n");

  // ---- Broken files ------------------------------------------------------------------------
  Truncate("sphere_binary.stl", "truncated.stl", 0.5);
  Truncate("sphere_ascii.stl", "truncated_ascii.stl", 0.3);
  Truncate("sphere.vtp", "truncated.vtp", 0.6);
  Truncate("sphere_binary.vtk", "truncated.vtk", 0.5);
  Truncate("sphere.ply", "truncated.ply", 0.5);
  Truncate("wavelet.vti", "truncated.vti", 0.5);
  Truncate("sphere.obj", "truncated_header.obj", 0.0); // zero bytes
  WriteText("garbage.vtp", Garbage(3000, 1));
  WriteText("garbage.vtk", Garbage(3000, 2));
  WriteText("garbage.ply", Garbage(3000, 3));
  WriteText("garbage.stl", Garbage(3000, 4));
  WriteText("garbage.obj", Garbage(3000, 5));
  WriteText("garbage.vtm", Garbage(3000, 6));
  WriteText("garbage.vti", Garbage(3000, 7));
  WriteText("notxml.vtu", "this is plain text, not a VTK XML file\n");
  WriteText("empty.stl", "");
  WriteText("empty.vtp", "");
  WriteText("unknown.xyz", "1 2 3\n");
  WriteText("noextension", "1 2 3\n");
  // Well-formed but empty.
  {
    vtkNew<vtkPolyData> nothing;
    vtkNew<vtkXMLPolyDataWriter> w;
    w->SetInputData(nothing);
    Write(w.Get(), "nopoints.vtp");
  }
  WriteText("noblocks.vtm",
    "<?xml version=\"1.0\"?>\n<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\">\n"
    "  <vtkMultiBlockDataSet>\n  </vtkMultiBlockDataSet>\n</VTKFile>\n");
  WriteText("missingpiece.vtm",
    "<?xml version=\"1.0\"?>\n<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\">\n"
    "  <vtkMultiBlockDataSet>\n    <DataSet index=\"0\" file=\"does_not_exist.vtp\"/>\n"
    "  </vtkMultiBlockDataSet>\n</VTKFile>\n");
  WriteText("nofaces.obj", "# vertices only\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
  WriteText("nopoints.ply",
    "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
    "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n");
  WriteText("nocells.vtk",
    "# vtk DataFile Version 3.0\nno cells\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n"
    "0 0 0  1 0 0  0 1 0\n");
  WriteText("solid_empty.stl", "solid empty\nendsolid empty\n");
  // Structurally corrupt.
  WriteText("badindex.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n");
  WriteText("badtcoord.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/5 2/6 3/7\n");
  WriteText("badindex.vtk",
    "# vtk DataFile Version 3.0\nbad index\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n"
    "0 0 0  1 0 0  0 1 0\nPOLYGONS 1 4\n3 0 1 99\n");
  WriteText("shortpoints.vtk",
    "# vtk DataFile Version 3.0\nshort\nASCII\nDATASET POLYDATA\nPOINTS 30 float\n"
    "0 0 0  1 0 0  0 1 0\n");
  const std::string ugridHead = "# vtk DataFile Version 3.0\nbad grid\nASCII\n"
                                "DATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n"
                                "0 0 0  1 0 0  0 1 0  0 0 1\nCELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n";
  WriteText("badcelltype.vtk", ugridHead + "99\n");
  WriteText("badcellsize.vtk", ugridHead + "12\n"); // a hexahedron with 3 points
  WriteText("badstructured.vtk",
    "# vtk DataFile Version 3.0\nbad\nASCII\nDATASET STRUCTURED_GRID\nDIMENSIONS 3 3 3\n"
    "POINTS 4 float\n0 0 0  1 0 0  0 1 0  0 0 1\n");
  WriteText("badrectilinear.vtk",
    "# vtk DataFile Version 3.0\nbad\nASCII\nDATASET RECTILINEAR_GRID\nDIMENSIONS 3 3 3\n"
    "X_COORDINATES 2 float\n0 1\nY_COORDINATES 3 float\n0 1 2\nZ_COORDINATES 3 float\n0 1 2\n");
  {
    vtkNew<vtkPolyData> nan;
    nan->DeepCopy(sphere);
    nan->GetPoints()->SetPoint(0, std::nan(""), 0.0, 0.0);
    vtkNew<vtkXMLPolyDataWriter> w;
    w->SetInputData(nan);
    Write(w.Get(), "nonfinite.vtp");
  }
  WriteText("badheader.ply", "ply\nformat ascii 1.0\nelement vertex 3\nthis is not a property\n");
  {
    vtkNew<vtkTable> table;
    vtkNew<vtkFloatArray> column;
    column->SetName("x");
    column->InsertNextValue(1.0f);
    table->AddColumn(column);
    vtkNew<vtkGenericDataObjectWriter> w;
    w->SetInputData(table);
    Write(w.Get(), "table.vtk");
  }
  // ---- Simulation formats (issue 14: files VTK reads are never refused) -----------------
  {
    vtkNew<vtkAppendFilter> toGrid;
    toGrid->SetInputData(Wavelet(3));
    toGrid->Update();
    vtkUnstructuredGrid* grid = toGrid->GetOutput();
    // Parallel XML: two pieces and the .pvtu that lists them.
    vtkNew<vtkXMLPUnstructuredGridWriter> p;
    p->SetInputData(grid);
    p->SetNumberOfPieces(2);
    p->SetStartPiece(0);
    p->SetEndPiece(1);
    Write(p.Get(), "pieces.pvtu");
    // A .pvd collection of three time steps (the third one a sphere).
    vtkNew<vtkXMLUnstructuredGridWriter> u;
    u->SetInputData(grid);
    Write(u.Get(), "series_0.vtu");
    Write(u.Get(), "series_1.vtu");
    vtkNew<vtkXMLPolyDataWriter> v;
    v->SetInputData(sphere);
    Write(v.Get(), "series_2.vtp");
    std::ofstream(P("series.pvd"))
      << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
         "<Collection>\n"
         "<DataSet timestep=\"2\" part=\"0\" file=\"series_2.vtp\"/>\n"
         "<DataSet timestep=\"0\" part=\"0\" file=\"series_0.vtu\"/>\n"
         "<DataSet timestep=\"1\" part=\"0\" file=\"series_1.vtu\"/>\n"
         "</Collection>\n</VTKFile>\n";
    std::ofstream(P("broken.pvd")) << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\"";
    // Exodus II, one element block of hexahedra with a nodal variable.
    vtkNew<vtkUnstructuredGrid> exo;
    exo->DeepCopy(grid);
    vtkNew<vtkIntArray> blocks;
    blocks->SetName("ElementBlockIds");
    blocks->SetNumberOfTuples(exo->GetNumberOfCells());
    blocks->FillValue(1);
    exo->GetCellData()->AddArray(blocks);
    vtkNew<vtkExodusIIWriter> e;
    e->SetInputData(exo);
    e->WriteAllTimeStepsOff();
    Write(e.Get(), "mesh.ex2");
  }
  {
    // Legacy file with one 20-node hexahedron (VTK_QUADRATIC_HEXAHEDRON), as VTK reads it.
    vtkNew<vtkUnstructuredGrid> q;
    vtkNew<vtkPoints> points;
    const double corner[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
      { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
    const int edge[12][2] = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 6 }, { 6, 7 },
      { 7, 4 }, { 0, 4 }, { 1, 5 }, { 2, 6 }, { 3, 7 } };
    for (const auto& c : corner)
    {
      points->InsertNextPoint(c);
    }
    for (const auto& ed : edge)
    {
      points->InsertNextPoint(0.5 * (corner[ed[0]][0] + corner[ed[1]][0]),
        0.5 * (corner[ed[0]][1] + corner[ed[1]][1]), 0.5 * (corner[ed[0]][2] + corner[ed[1]][2]));
    }
    q->SetPoints(points);
    vtkIdType ids[20];
    for (vtkIdType i = 0; i < 20; ++i)
    {
      ids[i] = i;
    }
    q->InsertNextCell(VTK_QUADRATIC_HEXAHEDRON, 20, ids);
    vtkNew<vtkGenericDataObjectWriter> w;
    w->SetInputData(q);
    Write(w.Get(), "hex20.vtk");
    // The same cell as an FEM solver writes it: 20 points with the linear hexahedron's type 12
    // (VTK and ParaView draw it by its 8 corners).
    std::string text = "# vtk DataFile Version 3.0\nquadratic hexahedron typed 12\nASCII\n"
                       "DATASET UNSTRUCTURED_GRID\nPOINTS 20 double\n";
    for (vtkIdType i = 0; i < 20; ++i)
    {
      double p[3];
      points->GetPoint(i, p);
      text += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
    }
    text += "CELLS 1 21\n20";
    for (vtkIdType i = 0; i < 20; ++i)
    {
      text += " " + std::to_string(i);
    }
    text += "\nCELL_TYPES 1\n12\n";
    WriteText("hex20_typed_12.vtk", text);
  }
  // A Lagrange wedge of 11 points, a number no order of a wedge has (6, 18, 21, 40...): VTK's
  // geometry filter read outside its arrays for it (found by vtkStylizeFuzzValidate).
  {
    vtkNew<vtkUnstructuredGrid> ug;
    vtkNew<vtkPoints> points;
    for (int i = 0; i < 11; ++i)
    {
      points->InsertNextPoint(0.1 * i, 0.05 * (i % 3), 0.07 * (i % 4));
    }
    ug->SetPoints(points);
    vtkIdType ids[11] = { 1, 0, 2, 3, 4, 5, 6, 7, 8, 9, 10 };
    ug->InsertNextCell(VTK_LAGRANGE_WEDGE, 11, ids);
    vtkNew<vtkXMLUnstructuredGridWriter> w;
    w->SetInputData(ug);
    Write(w.Get(), "lagrange_wedge_11.vtu");
  }
  // A surface whose point array holds one value (an isosurface of that array).
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->Update();
    vtkNew<vtkPolyData> surface;
    surface->DeepCopy(sphere->GetOutput());
    vtkNew<vtkFloatArray> value;
    value->SetName("temperature");
    value->SetNumberOfTuples(surface->GetNumberOfPoints());
    value->Fill(160.0);
    surface->GetPointData()->SetScalars(value);
    vtkNew<vtkXMLPolyDataWriter> w;
    w->SetInputData(surface);
    Write(w.Get(), "constant_scalars.vtp");
  }
  // EnSight Gold (ASCII): two hexahedra with a nodal scalar; a case file whose geometry file
  // is missing, and one whose geometry file is cut short.
  {
    const char* geoHead = "EnSight Gold geometry\nvtkstylize test\nnode id off\nelement id off\n"
                          "part\n         1\ntwo hexahedra\ncoordinates\n        12\n";
    std::string xyz[3];
    for (int k = 0; k < 2; ++k)
    {
      for (int j = 0; j < 2; ++j)
      {
        for (int i = 0; i < 3; ++i)
        {
          xyz[0] += std::to_string(i) + ".0\n";
          xyz[1] += std::to_string(j) + ".0\n";
          xyz[2] += std::to_string(k) + ".0\n";
        }
      }
    }
    // Points i + 3 j + 6 k, numbered from 1; hexa8: bottom face then top face.
    const std::string cells = "hexa8\n         2\n1 2 5 4 7 8 11 10\n2 3 6 5 8 9 12 11\n";
    WriteText("ensight.geo", geoHead + xyz[0] + xyz[1] + xyz[2] + cells);
    std::string values = "Temperature\npart\n         1\ncoordinates\n";
    for (int n = 0; n < 12; ++n)
    {
      values += std::to_string(300 + 10 * n) + ".0\n";
    }
    WriteText("ensight.Temperature", values);
    const std::string caseText = "FORMAT\ntype: ensight gold\n\nGEOMETRY\nmodel: ensight.geo\n\n"
                                 "VARIABLE\nscalar per node: Temperature ensight.Temperature\n";
    WriteText("ensight.case", caseText);
    WriteText("ensight_missing.case",
      "FORMAT\ntype: ensight gold\n\nGEOMETRY\nmodel: does_not_exist.geo\n");
    WriteText("ensight_truncated.geo", geoHead + xyz[0] + "0.0\n");
    WriteText("ensight_truncated.case",
      "FORMAT\ntype: ensight gold\n\nGEOMETRY\nmodel: ensight_truncated.geo\n");
  }
  // OpenFOAM: a case directory of two hexahedral cells (one internal face, ten boundary faces in
  // one patch) with a cell field T at time 1; the .foam file is empty, as OpenFOAM's are. A
  // second case whose polyMesh has no faces file.
  {
    const auto header = [](const char* cls, const char* object)
    {
      return std::string("FoamFile\n{\n    version 2.0;\n    format ascii;\n    class ") + cls +
        ";\n    object " + object + ";\n}\n";
    };
    for (const std::string& dir : { std::string("foam"), std::string("foam_broken") })
    {
      for (const char* sub : { "", "/system", "/constant", "/constant/polyMesh", "/1" })
      {
        ::mkdir(P(dir + sub).c_str(), 0777);
      }
      WriteText(dir + "/case.foam", "");
      WriteText(dir + "/system/controlDict",
        header("dictionary", "controlDict") +
          "application icoFoam;\nstartFrom startTime;\nstartTime 0;\nstopAt endTime;\n"
          "endTime 1;\ndeltaT 1;\nwriteControl timeStep;\nwriteInterval 1;\n");
      std::string points = header("vectorField", "points") + "12\n(\n";
      for (int k = 0; k < 2; ++k)
      {
        for (int j = 0; j < 2; ++j)
        {
          for (int i = 0; i < 3; ++i)
          {
            points +=
              "(" + std::to_string(i) + " " + std::to_string(j) + " " + std::to_string(k) + ")\n";
          }
        }
      }
      WriteText(dir + "/constant/polyMesh/points", points + ")\n");
      if (dir == "foam")
      {
        // Internal face first (owner 0, neighbour 1, normal +x), then each cell's boundary
        // faces, normals pointing out of their owner.
        WriteText(dir + "/constant/polyMesh/faces",
          header("faceList", "faces") +
            "11\n(\n4(1 4 10 7)\n4(0 6 9 3)\n4(0 3 4 1)\n4(6 7 10 9)\n4(0 1 7 6)\n4(3 9 10 4)\n"
            "4(2 5 11 8)\n4(1 4 5 2)\n4(7 8 11 10)\n4(1 2 8 7)\n4(4 10 11 5)\n)\n");
      }
      WriteText(dir + "/constant/polyMesh/owner",
        header("labelList", "owner") + "11\n(\n0\n0\n0\n0\n0\n0\n1\n1\n1\n1\n1\n)\n");
      WriteText(
        dir + "/constant/polyMesh/neighbour", header("labelList", "neighbour") + "1\n(\n1\n)\n");
      WriteText(dir + "/constant/polyMesh/boundary",
        header("polyBoundaryMesh", "boundary") +
          "1\n(\n    walls\n    {\n        type wall;\n        nFaces 10;\n        startFace 1;\n"
          "    }\n)\n");
      WriteText(dir + "/1/T",
        header("volScalarField", "T") +
          "dimensions [0 0 0 1 0 0 0];\ninternalField nonuniform List<scalar> "
          "2\n(\n300\n400\n)\n;\n"
          "boundaryField\n{\n    walls\n    {\n        type zeroGradient;\n    }\n}\n");
    }
  }
  // PLY stored as triangle strips (element "tristrips", -1 separates strips), and a legacy file
  // with strips and polygons.
  std::ofstream(P("strips.ply"))
    << "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
       "property float z\nelement tristrips 1\nproperty list int int vertex_indices\n"
       "end_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0.2\n0 2 0\n1 2 0\n7 0 1 2 3 4 5 -1\n";
  // The same as binary (little endian) with two strips in one list, and ASCII files whose
  // strips reference a vertex that does not exist, and -2.
  {
    std::string bin = "ply\nformat binary_little_endian 1.0\nelement vertex 6\n"
                      "property float x\nproperty float y\nproperty float z\n"
                      "element tristrips 1\nproperty list int int vertex_indices\nend_header\n";
    const float xyz[18] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0.2f, 0, 2, 0, 1, 2, 0 };
    const int list[10] = { 9, 0, 1, 2, 3, -1, 2, 3, 4, 5 };
    bin.append(reinterpret_cast<const char*>(xyz), sizeof(xyz));
    bin.append(reinterpret_cast<const char*>(list), sizeof(list));
    WriteBytes("strips_binary.ply", bin.data(), bin.size());
  }
  const std::string stripsHead = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                                 "property float y\nproperty float z\nelement tristrips 1\n"
                                 "property list int int vertex_indices\nend_header\n"
                                 "0 0 0\n1 0 0\n0 1 0\n1 1 0\n";
  WriteText("badstrips.ply", stripsHead + "5 0 1 2 3 9\n");
  WriteText("badstrips_negative.ply", stripsHead + "5 0 1 2 -2 3\n");
  std::ofstream(P("strips.vtk"))
    << "# vtk DataFile Version 3.0\nstrips and polygons\nASCII\nDATASET POLYDATA\n"
       "POINTS 8 float\n0 0 0\n1 0 0\n0 1 0\n1 1 0.2\n0 2 0\n1 2 0\n2 0 0\n2 1 0.3\n"
       "POLYGONS 1 5\n4 1 6 7 3\nTRIANGLE_STRIPS 1 7\n6 0 1 2 3 4 5\n";

  // Hostile input (issue 17). Multiblock references: a block that is a FIFO (a reader would block
  // on it forever), a file that names itself, two files that name each other.
  const auto vtm = [](const std::string& file)
  {
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\">\n"
           "  <vtkMultiBlockDataSet>\n    <DataSet index=\"0\" file=\"" +
      file + "\"/>\n  </vtkMultiBlockDataSet>\n</VTKFile>\n";
  };
  ::unlink(P("fifo_block.vtp").c_str());
  if (::mkfifo(P("fifo_block.vtp").c_str(), 0600) != 0)
  {
    std::cerr << "cannot make the FIFO fifo_block.vtp\n";
    Failed = true;
  }
  WriteText("fifo_block.vtm", vtm("fifo_block.vtp"));
  WriteText("self_loop.vtm", vtm("self_loop.vtm"));
  ::mkdir(P("loop").c_str(), 0755);
  WriteText("loop/inner.vtm", vtm("../outer_loop.vtm"));
  WriteText("outer_loop.vtm", vtm("loop/inner.vtm"));
  // Polyhedra whose face streams lie (VTK 9.1's reader or surface filter crashed on them): a
  // face naming point 999999 or -7, a polyhedron claiming 100,000 faces.
  const auto polyhedron = [](const std::string& faces)
  {
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
           "<UnstructuredGrid><Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n"
           "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">"
           "0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points>\n<Cells>\n"
           "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 3</DataArray>\n"
           "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4</DataArray>\n"
           "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">42</DataArray>\n"
           "<DataArray type=\"Int64\" Name=\"faces\" format=\"ascii\">" +
      faces + "</DataArray>\n<DataArray type=\"Int64\" Name=\"faceoffsets\" format=\"ascii\">17" +
      "</DataArray>\n</Cells></Piece></UnstructuredGrid></VTKFile>\n";
  };
  WriteText("polyhedron.vtu", polyhedron("4 3 0 1 2 3 0 1 3 3 0 2 3 3 1 2 3"));
  WriteText("polyhedron_far_id.vtu", polyhedron("4 3 0 1 2 3 0 1 999999 3 0 2 3 3 1 2 3"));
  WriteText("polyhedron_negative_id.vtu", polyhedron("4 3 0 1 2 3 0 1 -7 3 0 2 3 3 1 2 3"));
  WriteText("polyhedron_many_faces.vtu", polyhedron("100000 3 0 1 2 3 0 1 3 3 0 2 3 3 1 2 3"));
  // Legacy files of ~150 bytes whose headers claim a billion points, polygons or cells (the
  // reader allocated 11-19 GB before failing), and a CELL_TYPES section shorter than CELLS (the
  // reader left the other types unset).
  const std::string legacyHead = "# vtk DataFile Version 3.0\nclaims\nASCII\n";
  WriteText("claims_points.vtk",
    legacyHead + "DATASET POLYDATA\nPOINTS 1000000000 float\n0 0 0 1 0 0 0 1 0\n");
  WriteText("claims_polygons.vtk",
    legacyHead +
      "DATASET POLYDATA\nPOINTS 3 float\n"
      "0 0 0 1 0 0 0 1 0\nPOLYGONS 1000000000 4000000000\n3 0 1 2\n");
  WriteText("claims_cells.vtk",
    legacyHead +
      "DATASET UNSTRUCTURED_GRID\nPOINTS 3 float\n"
      "0 0 0 1 0 0 0 1 0\nCELLS 1000000000 4000000000\n3 0 1 2\nCELL_TYPES 1\n5\n");
  WriteText("short_cell_types.vtk",
    legacyHead +
      "DATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n"
      "0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 2 8\n3 0 1 2\n3 1 2 3\nCELL_TYPES 1\n5\n");
  WriteText("nan_scalars.vtk",
    legacyHead +
      "DATASET POLYDATA\nPOINTS 3 float\n"
      "0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\nSCALARS s float 1\n"
      "LOOKUP_TABLE default\n0 nan inf\n");
  // OBJ numbers VTK's reader misreads (nan, inf and 1e400 became other numbers), a word, and a
  // 2 MiB line (a 1 GB one took 2 GB before the binary-data refusal).
  const std::string objTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  WriteText("nan_vertex.obj", "v 0 nan 0\n" + objTriangle);
  WriteText("inf_vertex.obj", "v inf 0 0\n" + objTriangle);
  WriteText("overflow_vertex.obj", "v 1e400 0 0\n" + objTriangle);
  WriteText("word_vertex.obj", "v 0 0 zero\n" + objTriangle);
  WriteText("long_line.obj", "v " + std::string(std::size_t(2) << 20, '1') + "\n" + objTriangle);
  // Pictures of the background alone: three identical points, an image of spacing 0, a vertex
  // at 1e38 beside a unit triangle.
  WriteText("no_extent.obj", "v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n");
  WriteText("far_vertex.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1e38 0 0\nf 1 2 3\nf 2 3 4\n");
  {
    std::string values;
    for (int i = 0; i < 27; ++i)
    {
      values += std::to_string(i % 3) + " ";
    }
    WriteText("spacing_zero.vti",
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"0.1\">\n"
      "<ImageData WholeExtent=\"0 2 0 2 0 2\" Origin=\"0 0 0\" Spacing=\"0 0 0\">\n"
      "<Piece Extent=\"0 2 0 2 0 2\"><PointData Scalars=\"s\">\n"
      "<DataArray type=\"Float32\" Name=\"s\" format=\"ascii\">" +
        values + "</DataArray>\n</PointData></Piece></ImageData></VTKFile>\n");
  }
  // Non-finite values: point scalars with NaN and infinities, an image whose values are all NaN,
  // an image with a NaN spacing or an infinite origin.
  {
    vtkNew<vtkPolyData> scalars;
    scalars->DeepCopy(sphere);
    vtkNew<vtkFloatArray> s;
    s->SetName("s");
    for (vtkIdType i = 0; i < scalars->GetNumberOfPoints(); ++i)
    {
      s->InsertNextValue(i % 7 == 0 ? std::nanf("") : (i % 11 == 0 ? HUGE_VALF : float(i)));
    }
    scalars->GetPointData()->SetScalars(s);
    vtkNew<vtkXMLPolyDataWriter> w;
    w->SetInputData(scalars);
    Write(w.Get(), "non_finite_scalars.vtp");
    vtkNew<vtkImageData> image;
    image->SetDimensions(4, 4, 4);
    vtkNew<vtkFloatArray> nan;
    nan->SetName("s");
    for (int i = 0; i < 64; ++i)
    {
      nan->InsertNextValue(std::nanf(""));
    }
    image->GetPointData()->SetScalars(nan);
    vtkNew<vtkXMLImageDataWriter> iw;
    iw->SetInputData(image);
    Write(iw.Get(), "all_nan.vti");
  }
  {
    std::string values;
    for (int i = 0; i < 27; ++i)
    {
      values += std::to_string(i % 3) + " ";
    }
    const auto vti = [&values](const std::string& origin, const std::string& spacing)
    {
      return "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"0.1\">\n"
             "<ImageData WholeExtent=\"0 2 0 2 0 2\" Origin=\"" +
        origin + "\" Spacing=\"" + spacing +
        "\">\n<Piece Extent=\"0 2 0 2 0 2\"><PointData Scalars=\"s\">\n"
        "<DataArray type=\"Float32\" Name=\"s\" format=\"ascii\">" +
        values + "</DataArray>\n</PointData></Piece></ImageData></VTKFile>\n";
    };
    WriteText("nan_spacing.vti", vti("0 0 0", "nan 1 1"));
    WriteText("inf_origin.vti", vti("inf 0 0", "1 1 1"));
  }
  // A compression bomb: a 300^3 float image (108 MB) that zlib stores in a few hundred KB.
  {
    vtkNew<vtkImageData> image;
    image->SetDimensions(300, 300, 300);
    vtkNew<vtkFloatArray> values;
    values->SetName("s");
    values->SetNumberOfValues(300 * 300 * 300);
    values->FillValue(1.0f);
    image->GetPointData()->SetScalars(values);
    vtkNew<vtkXMLImageDataWriter> w;
    w->SetInputData(image);
    w->SetCompressorTypeToZLib();
    w->SetDataModeToAppended();
    Write(w.Get(), "compressed_300.vti");
  }
  // What the hostile corpus found: an ASCII PLY file without its last newline (VTK's reader
  // freed a line twice and aborted), an EnSight case cut short (the reader looped forever), an
  // Exodus file whose header claims two billion dimensions (netCDF took 1.6 GB before failing).
  {
    std::vector<char> bytes = ReadAll("colored.ply");
    while (!bytes.empty() && (bytes.back() == '\n' || bytes.back() == '\r'))
    {
      bytes.pop_back();
    }
    WriteBytes("no_last_newline.ply", bytes.data(), bytes.size());
    WriteText("cut_short.case", "FORMAT\ntype: ensight gold\n\nG");
    bytes = ReadAll("mesh.ex2");
    if (bytes.size() > 16)
    {
      // the dimension list's count (after the magic, the record count and the list's tag)
      bytes[12] = 0x7f;
      bytes[13] = bytes[14] = bytes[15] = static_cast<char>(0xff);
    }
    WriteBytes("claims_dimensions.ex2", bytes.data(), bytes.size());
  }
  return Failed ? 1 : 0;
}
