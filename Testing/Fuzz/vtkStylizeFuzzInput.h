// The input of the VTK Stylize fuzz targets: the first byte picks the file's extension (the
// format), the rest is the file's content, written to a file in a private folder.
#ifndef vtkStylizeFuzzInput_h
#define vtkStylizeFuzzInput_h

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace vtkStylizeFuzz
{
/** The extensions the first byte picks from (its value modulo their number). */
const std::vector<std::string>& Extensions();

/** Writes the input's content to FOLDER/input.EXT and returns the path ("" for no input). */
std::string WriteInput(const std::uint8_t* data, std::size_t size);
}

#endif
