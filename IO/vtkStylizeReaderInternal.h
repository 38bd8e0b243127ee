/**
 * What the parts of vtkStylizeReader share (a private header of the IO module): the failure
 * every check throws, the state of one read (its warnings, the window capturing VTK's messages),
 * the isolated read through the helper program vtkstylize-read, the PLY triangle-strip reading
 * (vtkStylizeReaderPLY.cxx) and the validation of what was read (vtkStylizeReaderValidate.cxx).
 */

#ifndef vtkStylizeReaderInternal_h
#define vtkStylizeReaderInternal_h

#include "vtkSmartPointer.h"
#include "vtkStylizeIOModule.h" // for export macro

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

class vtkDataObject;
class vtkDataSet;
class vtkStylizeOutputWindow;

namespace vtkStylizeReaderInternal
{
/** Thrown by every check; vtkStylizeReader::Read turns it into the reader's error. */
struct ReadFailure
{
  std::string Message;
};

[[noreturn]] void Fail(const std::string& message);

/**
 * The state of one read, handed to every part of it (no part keeps state of its own between
 * calls): the warnings so far, and the window that captures VTK's messages (none: null).
 */
struct ReadContext
{
  std::vector<std::string> Warnings;
  vtkStylizeOutputWindow* Capture = nullptr;

  /** Adds a warning to the read. */
  void Warn(const std::string& message);

  /** Forgets the messages VTK's readers reported so far. */
  void ClearVTKErrors();

  /** Fails with what + ": " + the first failure VTK reported since ClearVTKErrors(). */
  void CheckVTKErrors(const std::string& what);
};

/** text in single quotes, as the messages name files, blocks and arrays. */
std::string Quote(const std::string& text);

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

/**
 * Checks, reads and validates the file in this process (what vtkStylizeReader does with
 * Isolated off, and what the helper program does for an isolated read).
 */
ReadResult ReadChecked(const std::string& path, int timeStep);

/**
 * The class of the data the file holds, as far as it is known without reading it: from the
 * extension, from the header of a legacy .vtk file (its first lines), from the data set file a
 * .pvd collection names for timeStep. Empty when unknown (the read then says why).
 */
std::string OutputClass(const std::string& path, int timeStep);

#if defined(__SANITIZE_ADDRESS__)
#define VTKSTYLIZE_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define VTKSTYLIZE_ASAN 1
#endif
#endif

/** Bytes per MiB. */
constexpr double MiB = 1024.0 * 1024.0;

/** The longest text of a record of the helper's protocol (messages are one line). */
constexpr std::size_t MaxRecord = 8192;

/** A value of the form "Name:   123 kB" from /proc/self/status, in bytes (0 if absent). */
double StatusBytes(const char* name);

/** The bounds of an isolated read: the helper's memory (MiB), its processor time (s). */
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
 * The helper program an isolated read runs: the environment variable VTKSTYLIZE_READ_HELPER
 * when set, else vtkstylize-read in the folder of the IO library (or of the program it is
 * linked into). Empty when it is not there: why is then the reason, one line.
 */
std::string HelperPath(std::string& why);

/**
 * Reads the file in the helper program (posix_spawn: no code of the calling process runs in the
 * new one, so no lock held by another of its threads is inherited), with a clean environment, no
 * inherited descriptor but the socket, the default action for every signal, under the limits,
 * and returns what it gave: the data comes back through memory files in VTK's XML format, read
 * here with context's capture of VTK's messages. A
 * crash, a limit or a hang of the helper, or a helper that cannot be found or started, is the
 * result's Error, one line naming path and the cause. The helper bounds its own processor time
 * (RLIMIT_CPU) and heap (RLIMIT_DATA, except under AddressSanitizer) before it opens the file;
 * the caller bounds its resident size and wall-clock time, and kills it past 2 x Seconds + 5 s.
 */
ReadResult ReadIsolated(
  ReadContext& context, const std::string& path, int timeStep, const IsolationLimits& limits);

/**
 * The helper program's main (vtkstylize-read PARENT_PID MEMORY_MIB SECONDS TIME_STEP PATH, the
 * socket on descriptor 3): sets its limits, reads with ReadChecked and sends the result.
 */
VTKSTYLIZEIO_EXPORT int ReadHelperMain(int argc, char* argv[]);

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
vtkSmartPointer<vtkDataObject> ReadPLYStrips(
  ReadContext& context, const std::string& path, const std::string& what);

//------------------------------------------------------------------------------
// Validation of what was read (vtkStylizeReaderValidate.cxx)

/**
 * Rejects datasets whose structure would make the filters or the mapper read out of bounds, and
 * repairs, with a warning, what can still be drawn: the cells of a polydata with too few points
 * are left out, a linear cell of an unstructured grid that lists more points than its type has
 * keeps its corners. ds is changed in place (it is the reader's copy).
 */
void ValidateDataSet(ReadContext& context, vtkDataSet* ds, const std::string& what);

/**
 * The point set without its points whose coordinates are not finite (NaN or infinity) and the
 * cells that use them, with a warning; ds itself when all are finite. Fails when no point is
 * finite, or when no cell is left of a dataset that had cells. The connectivity is checked first
 * (a cell may not name a point that does not exist).
 */
vtkSmartPointer<vtkDataSet> WithoutNonFinitePoints(
  ReadContext& context, vtkDataSet* ds, const std::string& what);

/**
 * Every dataset of a composite (every leaf, named as the vtkstylize command names its
 * parts: the block's name, else "block N"), without its non-finite points and validated.
 */
void ValidateBlocks(ReadContext& context, vtkDataObject* data, const std::string& what);
}

#endif
