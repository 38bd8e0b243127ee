#include "vtkPVStylizePLYReader.h"

#include "vtkObjectFactory.h"
#include "vtkStylizeReader.h"

vtkStandardNewMacro(vtkPVStylizePLYReader);

//------------------------------------------------------------------------------
int vtkPVStylizePLYReader::CanReadFile(const char* fileName)
{
  if (!fileName || vtkStylizeReader::IsPLYWithTriangleStrips(fileName))
  {
    return 0;
  }
  return vtkPLYReader::CanReadFile(fileName);
}

//------------------------------------------------------------------------------
void vtkPVStylizePLYReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
