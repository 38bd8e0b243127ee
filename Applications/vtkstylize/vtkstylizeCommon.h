/**
 * Shared by the parts of vtkstylize: the error type that carries the exit status and the single
 * stderr line, string helpers, and the capture of VTK's own messages.
 *
 * Every failure is thrown as a CliError; main() prints "vtkstylize: <Message>" and exits with
 * Code. VTK's messages go to a capturing vtkOutputWindow; CheckVTKErrors() turns the first
 * relevant error since ClearVTKErrors() into a failure.
 */

#ifndef vtkstylizeCommon_h
#define vtkstylizeCommon_h

#include <cstddef>
#include <string>
#include <vector>

class vtkObject;

namespace vtkstylize
{
constexpr int ExitUsage = 2;   // bad option, option value or INPUT extension
constexpr int ExitFailure = 1; // input, rendering or output error

/** Thrown for every failure. */
struct CliError
{
  int Code;
  std::string Message;
};

/** Throws a CliError with ExitUsage. */
[[noreturn]] void UsageError(const std::string& message);

/** Throws a CliError with ExitFailure. */
[[noreturn]] void Fail(const std::string& message);

/**
 * Informational lines ("vtkstylize: note: ..."), kept until the image is written: main() prints
 * them on stderr after a success (unless --quiet), so that a failure stays one line.
 */
void Note(const std::string& message);
const std::vector<std::string>& Notes();

/**
 * Warnings about the input ("vtkstylize: warning: ..."): what was left out or drawn otherwise,
 * printed after a success (even with --quiet), like the warnings about options.
 */
void Warn(const std::string& message);
const std::vector<std::string>& Warnings();

/**
 * Limits the memory the process may allocate (RLIMIT_DATA: heap and private mappings) to mib
 * MiB; 0 restores the limit the process started with. Messages about failed allocations then
 * name the limit.
 */
void SetMemoryLimit(double mib);

/** Whether a message reports a failed allocation. */
bool SaysOutOfMemory(const std::string& message);

/** " (the memory limit: N MiB, --memory-limit)", or "" without a limit. */
std::string MemoryLimitText();

/** 'text' */
std::string Quote(const std::string& text);

/** Collapses whitespace runs (newlines included) to single spaces; cuts to maxLength. */
std::string OneLine(const std::string& text, std::size_t maxLength = 240);

std::string Lower(std::string text);

/** %g formatting. */
std::string FormatNumber(double value);

/**
 * Installs the output window that captures VTK's messages. When echoDescriptor >= 0 every
 * message is also written there as it arrives.
 */
void InstallMessageCapture(int echoDescriptor);

/**
 * Where progress bars go: a descriptor of a terminal, or -1 (the default: no bars). main() sets
 * the real stderr when it is a terminal, Run() -1 with --quiet.
 */
void SetProgressDescriptor(int descriptor);
/**
 * Shows the ProgressEvent of `object` (a double in [0, 1]) as a bar on the progress descriptor,
 * "vtkstylize: LABEL [=====     ]  42%", rewritten in place, once a step (from its first event
 * to the event at 1) has taken more than a second; the line is cleared when the step ends.
 */
void ReportProgress(vtkObject* object, const std::string& label);
/** Clears a bar shown on the progress descriptor (before a message; async-signal-safe). */
void ClearProgress();

/** Restores VTK's default output window. */
void RemoveMessageCapture();

/** Forgets the messages captured so far. */
void ClearVTKErrors();

/**
 * Throws Fail(what + ": " + message) when VTK reported a failure since the last
 * ClearVTKErrors(): an error, or a warning that says "error".
 */
void CheckVTKErrors(const std::string& what);
}

#endif
