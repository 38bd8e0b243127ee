// libFuzzer target: vtkStylizeReader on any bytes, as the vtkstylize program reads them (the
// checks, VTK's reader and the validation in an isolated child process; the data handed back
// through memory files). The reader may refuse with one line or give data; neither it nor the
// caller's side of the isolation may crash, hang or leak, whatever the child does.
#include "vtkStylizeFuzzInput.h"
#include "vtkStylizeReader.h"

#include "vtkDataObject.h"
#include "vtkNew.h"
#include "vtkObject.h"

#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string path = vtkStylizeFuzz::WriteInput(data, size);
  if (path.empty())
  {
    return 0;
  }
  vtkObject::GlobalWarningDisplayOff();
  vtkNew<vtkStylizeReader> reader;
  reader->SetFileName(path.c_str());
  reader->SetTimeLimit(5.0);
  reader->Update();
  const std::string error = reader->GetErrorMessage();
  if (error.empty() && !reader->GetOutputDataObject(0))
  {
    std::fprintf(stderr, "neither data nor an error\n");
    std::abort();
  }
  if (error.find('\n') != std::string::npos)
  {
    std::fprintf(stderr, "the error is more than one line: %s\n", error.c_str());
    std::abort();
  }
  return 0;
}
