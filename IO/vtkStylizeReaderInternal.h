/**
 * What the parts of vtkStylizeReader share (a private header of the IO module): the failure
 * every check throws, the warnings and VTK messages of the read in progress, the PLY
 * triangle-strip reading (vtkStylizeReaderPLY.cxx) and the validation of what was read
 * (vtkStylizeReaderValidate.cxx).
 */

#ifndef vtkStylizeReaderInternal_h
#define vtkStylizeReaderInternal_h

#include "vtkSmartPointer.h"

#include <functional>
#include <string>
#include <vector>

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

/** text in lower case (ASCII). */
std::string Lower(std::string text);

//------------------------------------------------------------------------------
// The isolated read (vtkStylizeReaderIsolation.cxx)

/** What a read gives: the data (null after a failure), the failure, the warnings. */
struct ReadResult
{
  vtkSmartPointer<vtkDataObject> Data;
  std::string Error;
  std::vector<std::string> Warnings;
};

/** The bounds of an isolated read: memory above what the caller holds (MiB), time (s). */
struct IsolationLimits
{
  double MemoryMiB = 512.0;
  double Seconds = 10.0;
};

/**
 * The size of the input in bytes: the file's, or for a file that names others (.vtm, .pvt*,
 * .pvd, .case) and an OpenFOAM case, that of the files in its folder and below.
 */
double InputBytes(const std::string& path);

/**
 * The automatic bounds for an input of the given size: memory 512 MiB + 16 times the input, at
 * most 3/4 of the machine's memory; processor time 10 s + 1 s per MiB (three times both under
 * AddressSanitizer).
 */
IsolationLimits AutomaticLimits(double inputBytes);

/**
 * Runs read() in a child process (fork) under the limits and returns what it gave: the data
 * comes back through memory files in VTK's XML format. A crash, a limit or a hang of the child
 * is the result's Error, one line naming path and the cause. The child's processor time is
 * bounded by RLIMIT_CPU, its heap by RLIMIT_DATA (except under AddressSanitizer), its resident
 * size and its wall-clock time by the caller, which kills it past 2 x Seconds + 5 s.
 */
ReadResult ReadIsolated(
  const std::string& path, const std::function<ReadResult()>& read, const IsolationLimits& limits);

//------------------------------------------------------------------------------
// PLY (vtkStylizeReaderPLY.cxx)

/** Whether path is an ASCII PLY file whose last byte is not a newline. */
bool ASCIIPLYWithoutLastNewline(const std::string& path);

/** The file's content with a newline added (for the ASCII PLY files that lack it). */
std::string ContentWithLastNewline(const std::string& path);

/**
 * Whether the file is a PLY whose header (read in its first 64 KiB) declares "element tristrips
 * N" with N > 0.
 */
bool HasPLYStrips(const std::string& path);

/**
 * Reads a PLY file whose surface is stored as triangle strips, which VTK 9.1's vtkPLYReader does
 * not read, as a polydata of triangles. what: the start of the failure's message.
 */
vtkSmartPointer<vtkDataObject> ReadPLYStrips(const std::string& path, const std::string& what);

//------------------------------------------------------------------------------
// Validation of what was read (vtkStylizeReaderValidate.cxx)

/**
 * Rejects datasets whose structure would make the filters or the mapper read out of bounds, and
 * repairs, with a warning, what can still be drawn: the cells of a polydata with too few points
 * are left out, a linear cell of an unstructured grid that lists more points than its type has
 * keeps its corners. ds is changed in place (it is the reader's copy).
 */
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
