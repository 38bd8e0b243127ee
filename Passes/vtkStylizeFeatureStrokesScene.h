/**
 * The scene side of vtkStylizeFeatureStrokes (private to the module): which datasets of a
 * renderer have lines drawn, each one's cached surface, lines and visibility, and the settings
 * taken from its actor (the iso-lines of the array its mapper colours it by).
 */
#ifndef vtkStylizeFeatureStrokesScene_h
#define vtkStylizeFeatureStrokesScene_h

#include "vtkCellData.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkExtractEdges.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStylizeFeatureLines.h"
#include "vtkStylizeFeatureStrokes.h"
#include "vtkStylizeLineVisibility.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"

#include <vector>

class vtkActor;
class vtkDataObject;
class vtkDataSet;
class vtkMatrix4x4;
class vtkRenderer;

namespace vtkStylizeFeatureStrokesScene
{
/**
 * A dataset of the scene (an actor's, or a leaf of its composite data) and its lines, kept
 * between frames: its surface (itself, or vtkDataSetSurfaceFilter's of another dataset), the
 * feature lines of the surface or, for an actor drawn as wireframe, the surface's edges (as
 * creases), and their visibility.
 */
struct Surface
{
  vtkWeakPointer<vtkDataSet> Data;
  bool Wireframe = false;
  vtkNew<vtkDataSetSurfaceFilter> Geometry;
  vtkNew<vtkStylizeFeatureLines> Lines;
  vtkNew<vtkExtractEdges> Edges;
  vtkNew<vtkPolyData> KindedEdges;
  vtkMTimeType EdgesTime = 0;
  vtkNew<vtkStylizeLineVisibility> Visibility;
  bool Seen = false;    // drawn by this frame
  int UnseenStills = 0; // still frames in a row that did not draw it
  /** The mean edge length of the surface's polygons, and the surface's time when measured. */
  double MeanEdge = 0.0;
  vtkMTimeType EdgeTime = 0;

  Surface(vtkDataSet* data, bool wireframe)
    : Data(data)
    , Wireframe(wireframe)
  {
    this->Geometry->SetInputData(data);
    this->Lines->SetInputConnection(this->Geometry->GetOutputPort());
    this->Edges->SetInputConnection(this->Geometry->GetOutputPort());
    if (auto* pd = vtkPolyData::SafeDownCast(data))
    {
      this->Lines->SetInputData(pd);
      this->Edges->SetInputData(pd);
    }
    if (wireframe)
    {
      this->Visibility->SetInputData(this->KindedEdges);
    }
    else
    {
      this->Visibility->SetInputConnection(this->Lines->GetOutputPort());
    }
    this->Visibility->VisibleOnlyOn();
    this->Visibility->SetDepthKind(vtkStylizeLineVisibility::VIEW_DEPTH);
  }

  /** The surface the lines are on (updated). */
  vtkPolyData* SurfaceOf()
  {
    if (auto* pd = vtkPolyData::SafeDownCast(this->Data))
    {
      return pd;
    }
    this->Geometry->Update();
    return this->Geometry->GetOutput();
  }

  /** A wireframe's edges as creases (their FeatureKind), updated when the data changes. */
  void UpdateEdges()
  {
    this->Edges->Update();
    vtkPolyData* edges = this->Edges->GetOutput();
    if (edges->GetMTime() <= this->EdgesTime)
    {
      return;
    }
    this->EdgesTime = edges->GetMTime();
    this->KindedEdges->Initialize();
    this->KindedEdges->SetPoints(edges->GetPoints());
    this->KindedEdges->SetLines(edges->GetLines());
    vtkNew<vtkUnsignedCharArray> kinds;
    kinds->SetName("FeatureKind");
    kinds->SetNumberOfTuples(edges->GetNumberOfLines());
    kinds->Fill(vtkStylizeFeatureLines::CREASE);
    this->KindedEdges->GetCellData()->AddArray(kinds);
  }
};

/**
 * A dataset to draw this frame, the matrix from its coordinates to the world, its look, and the
 * index of its actor among the frame's (LineActors()).
 */
struct Item
{
  vtkDataSet* Data;
  vtkMatrix4x4* Matrix;
  bool Wireframe;
  size_t Actor;
};

/** The mean edge length of (up to 10000 of) the surface's polygons. */
double MeanEdgeLength(vtkPolyData* pd);

/** How much a matrix scales lengths (the cube root of its 3 x 3 part's determinant). */
double ScaleOf(vtkMatrix4x4* m);

/**
 * The actors whose lines are drawn: visible, drawn as surfaces or wireframe, and opaque (or,
 * `translucent`, those with an opacity below 1: a translucent layer's).
 */
std::vector<vtkActor*> LineActors(vtkRenderer* ren, bool translucent = false);

/** Appends the datasets of `data` with cells (itself, or every leaf of composite data). */
void AddSurface(
  vtkDataObject* data, vtkMatrix4x4* matrix, bool wireframe, size_t actor, std::vector<Item>& out);

/** The datasets of the actors (or those that replace them: View::Surfaces). */
std::vector<Item> SurfacesOf(
  const std::vector<vtkActor*>& actors, const vtkStylizeFeatureStrokes::View& view);

/** The polygonal data of an actor's input (every leaf of a composite), ghost cells left out. */
vtkSmartPointer<vtkPolyData> PolygonsOf(vtkDataObject* data);

/**
 * The iso-lines of an actor's dataset (Settings::IsoLines): the point-data array its mapper
 * colours it by through a colour map, the component or magnitude the map shows, the levels
 * placed in the map's range on its scale; none for an actor without mapped point colours.
 */
void SetIsoLines(vtkStylizeFeatureLines* fl, vtkActor* actor, vtkDataSet* data,
  const vtkStylizeFeatureStrokes::Settings& settings);
}

#endif
