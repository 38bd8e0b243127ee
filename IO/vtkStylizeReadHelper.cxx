// vtkstylize-read: the program vtkStylizeReader's isolated read runs (posix_spawn), installed
// beside the IO library. It sets its limits, reads and validates the file, and hands the data
// back over the socket it was given (vtkStylizeReaderIsolation.cxx describes the protocol).
#include "vtkStylizeReaderInternal.h"

int main(int argc, char* argv[])
{
  return vtkStylizeReaderInternal::ReadHelperMain(argc, argv);
}
