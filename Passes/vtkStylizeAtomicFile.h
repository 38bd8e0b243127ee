/**
 * @class   vtkStylizeAtomicFile
 * @brief   Writes a file atomically: the whole new content or the old file, never a partial one.
 *
 * Write() puts the bytes into a file that has no name until it is complete, then renames it over
 * the destination (rename(2) replaces it atomically). Where the file system allows it, that file
 * is an unnamed O_TMPFILE file in the destination's folder, which vanishes with the process even
 * when it is killed (SIGKILL); it gets a unique hidden name (".NAME.XXXXXX" beside the
 * destination) only for the rename. Elsewhere the bytes go to such a hidden named file from the
 * start. On failure the temporary file is removed and the destination is untouched. A file
 * created new has the mode 0666 less the umask, as open(2) gives.
 *
 * A program that handles fatal signals can call RemovePendingFile() from its handler, so that
 * not even the hidden named file stays behind a crash during a write.
 *
 * @code
 * const int error = vtkStylizeAtomicFile::Write("out.png", bytes, size);
 * if (error != 0)
 * {
 *   std::cerr << "cannot write out.png: " << std::strerror(error) << "\n";
 * }
 * @endcode
 */

#ifndef vtkStylizeAtomicFile_h
#define vtkStylizeAtomicFile_h

#include "vtkObject.h"
#include "vtkStylizePassesModule.h" // for export macro
#include "vtkWrappingHints.h"       // for VTK_WRAPEXCLUDE

#include <cstddef> // for std::size_t

class vtkUnsignedCharArray;

class VTKSTYLIZEPASSES_EXPORT vtkStylizeAtomicFile : public vtkObject
{
public:
  static vtkStylizeAtomicFile* New();
  vtkTypeMacro(vtkStylizeAtomicFile, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Writes `size` bytes from `data` to the file `path` (relative to the working directory or
   * absolute; its folder must exist and be writable), replacing the file atomically. Returns 0
   * on success, else the errno value of the step that failed (std::strerror() tells it; EINVAL
   * for a null or empty path, or null data with a size above 0), the destination then untouched
   * and no temporary file left. Not for two threads writing the same path at once.
   */
  VTK_WRAPEXCLUDE static int Write(const char* path, const void* data, std::size_t size);

  /** Write() of the values of an array (all its components); 0 or an errno value. */
  static int Write(const char* path, vtkUnsignedCharArray* data);

  /**
   * Removes the named temporary file of the Write() in progress, if there is one. Only
   * async-signal-safe calls: for a fatal-signal handler. (It tracks the last Write() that
   * named a temporary file: one writing thread at a time.)
   */
  static void RemovePendingFile();

protected:
  vtkStylizeAtomicFile() = default;
  ~vtkStylizeAtomicFile() override = default;

private:
  vtkStylizeAtomicFile(const vtkStylizeAtomicFile&) = delete;
  void operator=(const vtkStylizeAtomicFile&) = delete;
};

#endif
