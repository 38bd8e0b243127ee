#include "vtkPVStylizeCheckedReader.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkPVStylizeCheckedReader);

//------------------------------------------------------------------------------
int vtkPVStylizeCheckedReader::CanReadFile(const char* fileName)
{
  return fileName && vtkStylizeReader::IsPLYWithTriangleStrips(fileName) ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkPVStylizeCheckedReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
