/**
 * The input stage of vtkstylize: reads a file with vtkStylizeReader (the IO module's
 * checked reader, which the Python package offers too) and turns it into renderable surfaces
 * ("parts").
 *
 * Broken input never reaches a filter or a mapper: vtkStylizeReader checks the file before VTK's
 * reader sees it, captures the reader's errors and validates the data (connectivity within the
 * points, cell types and sizes, structured dimensions, array lengths, finite coordinates).
 * Every failure is thrown as a CliError.
 */

#ifndef vtkstylizeInput_h
#define vtkstylizeInput_h

#include "vtkSmartPointer.h"

#include <optional>
#include <string>
#include <vector>

class vtkDataObject;
class vtkPolyData;

namespace vtkstylize
{
/** One renderable piece of the scene: a leaf of the input (named after its block) as a surface. */
struct Part
{
  std::string Name;
  vtkSmartPointer<vtkPolyData> Surface;
  std::optional<double> Contour; // image data: the contour value it was drawn at
};

/** The supported extensions, space-separated (".obj .ply ..."). */
std::string SupportedExtensions();

/** Whether the extension of the path (case-insensitive) has a reader. */
bool IsSupportedInput(const std::string& path);

/**
 * Checks and reads the file at the given time step (an index into the reader's time steps, or
 * into the data set files of a .pvd collection; 0 for files without time): vtkStylizeReader,
 * isolated in a child process, its error thrown as a failure, its warnings passed to Warn().
 * memoryMiB: the child's memory (as --memory-limit: < 0 the reader's automatic bound, 0 none);
 * seconds: its processor time (0: automatic).
 */
vtkSmartPointer<vtkDataObject> ReadInput(
  const std::string& path, int timeStep = 0, double memoryMiB = -1.0, double seconds = 0.0);

/**
 * Appends the surfaces of a dataset or of every leaf of a composite dataset to parts: polydata
 * as is, 3D image data with a point scalar array as its contour at isoValue (default: Otsu's
 * threshold of the scalars, the value that best separates their two main populations, noted
 * with Note()), anything else as its outer surface. what names the input in messages.
 */
void CollectParts(vtkDataObject* data, const std::optional<double>& isoValue,
  const std::string& what, std::vector<Part>& parts);

/**
 * Drops empty parts and fails when nothing is left (no points, or no cells); computes point
 * normals for the surfaces that have none.
 */
void FinishParts(std::vector<Part>& parts, const std::string& what);

/**
 * Adds the principal curvatures and directions (vtkStylizePrincipalCurvatures: point arrays
 * "PrincipalDirectionMinAbs" and the others) to every part that has polygons or strips, for the
 * sketch pass's model-space directions, the tensors averaged over smoothingRadius times the
 * part's diagonal. Parts of lines or vertices are left as they are.
 */
void AddPrincipalDirections(
  std::vector<Part>& parts, const std::string& what, double smoothingRadius);
}

#endif
