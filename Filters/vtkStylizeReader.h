/**
 * @class   vtkStylizeReader
 * @brief   Reads any dataset file VTK Stylize renders, checked so that broken or hostile files
 *          give one clear error instead of a crash, a hang or a huge allocation.
 *
 * The reader is chosen by the file's extension (GetSupportedExtensions(): VTK XML serial and
 * parallel, .pvd collections, .vtm, legacy .vtk, Exodus II, EnSight, OpenFOAM, STL, OBJ and
 * PLY). VTK 9.1's readers crash, loop forever or allocate what a header claims on malformed
 * files, so before a reader opens the file it is checked:
 *
 * - the file (and every file a .vtm, .pvt* or .pvd names) must be a readable, non-empty regular
 *   file (a FIFO or a device would block a reader), and multiblock files may not name
 *   themselves through any chain;
 * - the format is walked where its reader does not check it: PLY and OBJ indices, binary STL
 *   sizes, every legacy .vtk header claim against the bytes left, .vtu polyhedron face streams,
 *   .vti origin, spacing and direction, EnSight case files, Exodus (netCDF classic) headers.
 *
 * After reading, every dataset (every leaf of a multiblock) is validated: cell connectivity
 * within the points, cell types and their sizes, structured dimensions, array lengths and
 * finite coordinates. Points whose coordinates are NaN or infinite are left out with the cells
 * that use them (a warning, GetWarning()); a dataset with no finite point fails.
 *
 * The file is read when the pipeline asks for the output's type (RequestDataObject: the type is
 * the file's), again only after a setting changed. On failure the output is an empty
 * vtkPolyData, GetErrorMessage() holds one line ("cannot read 'FILE':
 * REASON"), the error code is set, and the line is reported as an error (vtkErrorMacro, an
 * ErrorEvent). The messages of the readers run inside are captured while they read (a
 * vtkStylizeOutputWindow is installed for the time of the read and the previous window
 * restored, and vtkLogger's stderr output turned off), so that the one line is all a caller
 * sees; with a vtkStylizeOutputWindow already installed, its echo descriptor is kept.
 *
 * Memory: no check here makes a reader allocate more than the file holds; a process limit
 * (setrlimit) turns what remains into an "out of memory" error, which this reader reports
 * rather than letting the allocation's exception escape.
 *
 * Not thread-safe: VTK's output window is process-wide, and the reader installs its own while
 * it reads.
 */

#ifndef vtkStylizeReader_h
#define vtkStylizeReader_h

#include "vtkDataObjectAlgorithm.h"
#include "vtkStylizeFiltersModule.h" // for export macro

#include "vtkSmartPointer.h" // for vtkSmartPointer
#include "vtkTimeStamp.h"    // for vtkTimeStamp

#include <string> // for std::string
#include <vector> // for std::vector

class vtkCompositeDataIterator;

class VTKSTYLIZEFILTERS_EXPORT vtkStylizeReader : public vtkDataObjectAlgorithm
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
   * The name this reader's messages give the leaf an iterator over a composite dataset is at:
   * its NAME metadata, else "block INDEX" (index: the leaf's position among the non-empty
   * leaves, from 0).
   */
  static std::string GetBlockName(vtkCompositeDataIterator* iterator, int index);

protected:
  vtkStylizeReader();
  ~vtkStylizeReader() override;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /** Checks and reads the file: Data, or ErrorMessage; Warnings. */
  void Read();

  char* FileName = nullptr;
  int TimeStep = 0;
  std::string ErrorMessage;
  std::vector<std::string> Warnings;
  vtkSmartPointer<vtkDataObject> Data; // what the last Read() gave (null after a failure)
  vtkTimeStamp ReadTime;

private:
  vtkStylizeReader(const vtkStylizeReader&) = delete;
  void operator=(const vtkStylizeReader&) = delete;
};

#endif
