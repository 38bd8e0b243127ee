/**
 * What the parts of vtkStylizeReader share (a private header of the IO module): the failure
 * every check throws, the warnings and VTK messages of the read in progress, the PLY
 * triangle-strip reading (vtkStylizeReaderPLY.cxx) and the validation of what was read
 * (vtkStylizeReaderValidate.cxx).
 */

#ifndef vtkStylizeReaderInternal_h
#define vtkStylizeReaderInternal_h

#include "vtkSmartPointer.h"

#include <string>

class vtkDataObject;
class vtkDataSet;

namespace vtkStylizeReaderInternal
{
/** Thrown by every check; vtkStylizeReader::Read turns it into the reader's error. */
struct ReadFailure
{
  std::string Message;
};

[[noreturn]] void Fail(const std::string& message);

/** Adds a warning to the read in progress. */
void Warn(const std::string& message);

/** text in single quotes, as the messages name files, blocks and arrays. */
std::string Quote(const std::string& text);

/** Forgets the messages VTK's readers reported so far. */
void ClearVTKErrors();

/** Fails with what + ": " + the first failure VTK reported since ClearVTKErrors(). */
void CheckVTKErrors(const std::string& what);

//------------------------------------------------------------------------------
// PLY (vtkStylizeReaderPLY.cxx)

/** Whether path is an ASCII PLY file whose last byte is not a newline. */
bool ASCIIPLYWithoutLastNewline(const std::string& path);

/** The file's content with a newline added (for the ASCII PLY files that lack it). */
std::string ContentWithLastNewline(const std::string& path);

/** Whether the PLY file's header declares an element "tristrips". */
bool HasPLYStrips(const std::string& path);

/**
 * Reads a PLY file whose surface is stored as triangle strips, which VTK 9.1's vtkPLYReader does
 * not read, as a polydata of triangles. what: the start of the failure's message.
 */
vtkSmartPointer<vtkDataObject> ReadPLYStrips(const std::string& path, const std::string& what);

//------------------------------------------------------------------------------
// Validation of what was read (vtkStylizeReaderValidate.cxx)

/** Rejects datasets whose structure would make the filters or the mapper read out of bounds. */
void ValidateDataSet(vtkDataSet* ds, const std::string& what);

/**
 * The point set without its points whose coordinates are not finite (NaN or infinity) and the
 * cells that use them, with a warning; ds itself when all are finite. Fails when no point is
 * finite, or when no cell is left of a dataset that had cells. The connectivity is checked first
 * (a cell may not name a point that does not exist).
 */
vtkSmartPointer<vtkDataSet> WithoutNonFinitePoints(vtkDataSet* ds, const std::string& what);

/**
 * Every dataset of a composite (every leaf, named as the vtkstylize command names its
 * parts: the block's name, else "block N"), without its non-finite points and validated.
 */
void ValidateBlocks(vtkDataObject* data, const std::string& what);
}

#endif
