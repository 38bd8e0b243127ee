/**
 * @class   vtkPVStylizePLYReader
 * @brief   ParaView's PLY reader, declining the PLY files it would read without their surface.
 *
 * VTK's vtkPLYReader reads the faces of a PLY file (element "face") but not its triangle strips
 * (element "tristrips"): a scan stored as strips comes out with no cells, an empty view. The
 * plugin gives ParaView's "PLY Reader" (its inner proxy PLYReaderCore, StylizeReaders.xml) this
 * class: the same reader, whose CanReadFile() answers 0 for such a file, so that ParaView's
 * reader factory leaves it to the plugin's checked reader (vtkPVStylizeCheckedReader), which
 * reads the strips. Every other PLY file is read by vtkPLYReader as before.
 *
 * @sa vtkPLYReader vtkPVStylizeCheckedReader vtkStylizeReader::IsPLYWithTriangleStrips
 */
#ifndef vtkPVStylizePLYReader_h
#define vtkPVStylizePLYReader_h

#include "vtkPLYReader.h"
#include "vtkStylizeParaViewViewModule.h" // for export macro

class VTKSTYLIZEPARAVIEWVIEW_EXPORT vtkPVStylizePLYReader : public vtkPLYReader
{
public:
  static vtkPVStylizePLYReader* New();
  vtkTypeMacro(vtkPVStylizePLYReader, vtkPLYReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * vtkPLYReader::CanReadFile(), but 0 for a PLY file whose header declares triangle strips
   * (read by the checked reader instead).
   */
  static int CanReadFile(VTK_FILEPATH const char* fileName);

protected:
  vtkPVStylizePLYReader() = default;
  ~vtkPVStylizePLYReader() override = default;

private:
  vtkPVStylizePLYReader(const vtkPVStylizePLYReader&) = delete;
  void operator=(const vtkPVStylizePLYReader&) = delete;
};

#endif
