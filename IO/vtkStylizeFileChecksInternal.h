/**
 * The helpers the format checkers of vtkStylizeFileChecks.h share (a private header of the IO
 * module): a buffered file reader, word splitting and number parsing, and the text of the
 * messages. Each format's checker lives in its own vtkStylizeCheck<Format>.cxx; the helpers are
 * defined in vtkStylizeFileChecks.cxx.
 */

#ifndef vtkStylizeFileChecksInternal_h
#define vtkStylizeFileChecksInternal_h

#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace vtkStylizeFileChecks
{
/** Sequential reader over a FILE* with a large buffer, for binary and line-oriented parsing. */
class FileReader
{
public:
  explicit FileReader(const std::string& path);
  ~FileReader();
  FileReader(const FileReader&) = delete;
  FileReader& operator=(const FileReader&) = delete;

  bool IsOpen() const { return this->File != nullptr; }

  /** The file's size in bytes (the read position is kept). */
  long long Size();

  /** Reads n bytes; false at end of file. */
  bool Read(void* out, std::size_t n);

  /** Skips n bytes; false when the file ends first. */
  bool Skip(long long n);

  /** Goes back to the file's first byte (for checks that read the file twice). */
  void Rewind();

  /**
   * Reads one line without its end-of-line characters; false at end of file. At most keep
   * characters are kept (the rest of the line is consumed): LineCut() says whether it was cut.
   */
  bool GetLine(std::string& line, std::size_t keep = std::string::npos);

  long long GetOffset() const { return this->Offset; }

  /** Whether the last GetLine() cut its line. */
  bool LineCut() const { return this->Cut; }

private:
  bool Fill();

  std::FILE* File;
  std::vector<char> Buffer;
  std::size_t Pos = 0;
  std::size_t End = 0;
  long long Offset = 0;
  bool Cut = false;
};

/** A check of an open file: the problem, or an empty string. path: the file's name. */
using OpenFileCheck = std::string (*)(FileReader& in, const std::string& path);

/**
 * Opens path and runs check on it: the system's reason (strerror) when the file cannot be
 * opened, else what the check returns.
 */
std::string CheckOpenFile(const std::string& path, OpenFileCheck check);

/** The white-space separated words of a line. */
std::vector<std::string> Words(const std::string& line);

/** Whether s is a whole decimal integer that fits a long long (then in v). */
bool ParseInteger(const std::string& s, long long& v);

/** A count as an integer, or in %g form beyond 1e15 (a header's claim can be any number). */
std::string FormatCount(double value);

std::string Upper(std::string text);

/** text in single quotes, as the messages name files, sections and arrays. */
std::string Quote(const std::string& text);
}

#endif
