/**
 * @class   vtkStylizeReader
 * @brief   Reads any dataset file VTK Stylize renders, checked so that broken or hostile files
 *          give one clear error instead of a crash, a hang or a huge allocation.
 *
 * The reader is chosen by the file's extension (GetSupportedExtensions(): VTK XML serial and
 * parallel, .pvd, .vtm, legacy .vtk, Exodus II, EnSight, OpenFOAM, STL, OBJ and PLY). VTK 9.1's
 * readers crash, loop forever or allocate what a header claims on malformed files, so the file
 * (and every file it names) is checked before a reader opens it, and every dataset read is
 * validated; points that are not finite are left out with a warning (GetWarning()). On failure
 * the output is an empty vtkPolyData and GetErrorMessage() holds one line ("cannot read 'FILE':
 * REASON"), also reported as a VTK error; the messages of the readers run inside are captured,
 * so that this line is all a caller sees.
 *
 * The file is read in RequestData: the output's class comes from the extension (or a legacy
 * file's header, or the file a .pvd names) without reading the data, and only the ranks that
 * update piece 0 read it (the reader does not split data into pieces).
 *
 * Not thread-safe: VTK's output window is process-wide, and the reader installs its own
 * (vtkStylizeOutputWindow) while it reads.
 *
 * The checks, the validation and the error reporting: docs/command-line.md.
 *
 * @sa vtkStylizeOutputWindow
 */

#ifndef vtkStylizeReader_h
#define vtkStylizeReader_h

#include "vtkDataObjectAlgorithm.h"
#include "vtkStylizeIOModule.h" // for export macro

#include <functional> // for std::function
#include <string>     // for std::string
#include <vector>     // for std::vector

class vtkCompositeDataIterator;
class vtkCompositeDataSet;

class VTKSTYLIZEIO_EXPORT vtkStylizeReader : public vtkDataObjectAlgorithm
{
public:
  static vtkStylizeReader* New();
  vtkTypeMacro(vtkStylizeReader, vtkDataObjectAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The file to read (its extension chooses the format). Default none (an error on update). */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * The time step to read: an index (a count from 0) into the reader's time steps, or into the
   * data set files of a .pvd collection; 0 for files without time. An index past the file's
   * steps is an error that names their number. Range [0, 2147483647], default 0.
   */
  vtkSetClampMacro(TimeStep, int, 0, VTK_INT_MAX);
  vtkGetMacro(TimeStep, int);
  ///@}

  ///@{
  /**
   * Whether the file is read in the helper program vtkstylize-read (installed beside the IO
   * library; the environment variable VTKSTYLIZE_READ_HELPER names another), started with
   * posix_spawn under limits, and the data handed back through memory files: a crash, a hang or
   * a runaway allocation of VTK's reader on a damaged file then ends the helper, not the caller,
   * and is the reader's error ("VTK's reader crashed on it (segmentation fault)..."). The helper
   * is a new program, not a copy of the caller (fork): no lock another thread of the caller
   * holds (the allocator's, a thread pool's, Python's) can be inherited, so a multithreaded host
   * (ParaView, a Qt application, MPI, TBB) reads safely. Off, the file is read in this process
   * (the checks before reading still run). Default on.
   */
  vtkSetMacro(Isolated, bool);
  vtkGetMacro(Isolated, bool);
  vtkBooleanMacro(Isolated, bool);
  ///@}

  ///@{
  /**
   * The memory the isolated read may take (the helper's heap and resident size beyond what it
   * holds when it starts), in MiB; 0:
   * automatic, 512 MiB + 16 times the size of the input (the file, or the folder of a file that
   * names others), at most 3/4 of the machine's memory. Range [0, 1e9], default 0.
   */
  vtkSetClampMacro(MemoryLimit, double, 0.0, 1e9);
  vtkGetMacro(MemoryLimit, double);
  ///@}

  ///@{
  /**
   * The processor time the isolated read may take, in seconds (wall-clock: twice that and 5 s);
   * 0: automatic, 10 s + 1 s per MiB of input. Range [0, 1e6], default 0.
   */
  vtkSetClampMacro(TimeLimit, double, 0.0, 1e6);
  vtkGetMacro(TimeLimit, double);
  ///@}

  /** The reason of the last update's failure, one line; empty after a success. */
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

  ///@{
  /**
   * What the last update left out or read otherwise (points with non-finite coordinates and
   * their cells), one line each.
   */
  int GetNumberOfWarnings() const { return static_cast<int>(this->Warnings.size()); }
  const char* GetWarning(int index) const;
  ///@}

  /** The extensions read, lower case and space-separated (".case .e .ex2 ..."). */
  static std::string GetSupportedExtensions();

  /** Whether the file's extension (case-insensitive) is one of GetSupportedExtensions(). */
  static bool IsSupportedFile(const std::string& path);

  /**
   * Whether path is a PLY file whose header declares triangle strips (element "tristrips"),
   * which VTK's own vtkPLYReader does not read (it gives their surface no cells) and this
   * reader does. Reads the header alone; false for a file that cannot be opened.
   */
  static bool IsPLYWithTriangleStrips(const std::string& path);

  /**
   * The name this reader's messages give the leaf an iterator over a composite dataset is at:
   * its NAME metadata, else "block INDEX" (index: the leaf's position among the non-empty
   * leaves, from 0).
   */
  static std::string GetBlockName(vtkCompositeDataIterator* iterator, int index);

#ifndef __VTK_WRAP__
  /**
   * Calls visit(iterator, name) for every non-empty leaf of the composite dataset, in order,
   * with the name GetBlockName() gives it (visit may replace the leaf through the iterator).
   */
  static void ForEachBlock(vtkCompositeDataSet* composite,
    const std::function<void(vtkCompositeDataIterator*, const std::string&)>& visit);
#endif

protected:
  vtkStylizeReader();
  ~vtkStylizeReader() override;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  int TimeStep = 0;
  bool Isolated = true;
  double MemoryLimit = 0.0;
  double TimeLimit = 0.0;
  std::string ErrorMessage;
  std::vector<std::string> Warnings;

private:
  vtkStylizeReader(const vtkStylizeReader&) = delete;
  void operator=(const vtkStylizeReader&) = delete;
};

#endif
