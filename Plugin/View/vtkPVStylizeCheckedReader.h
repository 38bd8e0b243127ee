/**
 * @class   vtkPVStylizeCheckedReader
 * @brief   The checked reader (vtkStylizeReader) as ParaView's File > Open offers it.
 *
 * The class of the plugin's "Stylize Checked Reader" source. Its proxy lists, for ParaView's
 * reader factory, every extension vtkStylizeReader reads, so that the reader is in File > Open's
 * file types. CanReadFile() is what the factory asks of each reader that matches a file's
 * extension: this one says yes only where ParaView's own reader loses data (a PLY file stored
 * as triangle strips, whose surface ParaView's PLY Reader reads with no cells), so that File >
 * Open opens such a file with it, and every other file with ParaView's reader as before (this
 * one stays a choice: its file type in the Open dialog, the Sources menu, Python).
 *
 * @sa vtkStylizeReader vtkPVStylizePLYReader
 */
#ifndef vtkPVStylizeCheckedReader_h
#define vtkPVStylizeCheckedReader_h

#include "vtkStylizeParaViewViewModule.h" // for export macro
#include "vtkStylizeReader.h"

class VTKSTYLIZEPARAVIEWVIEW_EXPORT vtkPVStylizeCheckedReader : public vtkStylizeReader
{
public:
  static vtkPVStylizeCheckedReader* New();
  vtkTypeMacro(vtkPVStylizeCheckedReader, vtkStylizeReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * For ParaView's reader factory: 1 when File > Open should pick this reader for the file (a
   * PLY whose header declares triangle strips: vtkStylizeReader::IsPLYWithTriangleStrips), else
   * 0 (ParaView's own reader reads it without loss). Reads the file's header alone.
   */
  int CanReadFile(VTK_FILEPATH const char* fileName);

protected:
  vtkPVStylizeCheckedReader() = default;
  ~vtkPVStylizeCheckedReader() override = default;

private:
  vtkPVStylizeCheckedReader(const vtkPVStylizeCheckedReader&) = delete;
  void operator=(const vtkPVStylizeCheckedReader&) = delete;
};

#endif
