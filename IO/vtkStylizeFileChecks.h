/**
 * Structural checks of input files whose VTK readers (9.1, and ParaView 5.11's) crash, hang,
 * allocate what a header claims or silently read garbage on malformed input, run by
 * vtkStylizeReader before the reader sees the file (a private header of the IO module):
 *
 * - PLY (vtkPLYReader crashes on a malformed header, and on face indices out of range, e.g. in
 *   a truncated file): the header is parsed, the body walked element by element (ASCII or
 *   binary), and every face index checked against the number of vertices.
 * - OBJ (vtkOBJReader crashes on texture-coordinate or normal indices out of range): every
 *   index of the f, l and p statements is checked against the v, vt and vn counts.
 * - STL (vtkSTLReader reads truncated or garbage binary files without complaint): the size of a
 *   binary file must hold the number of triangles its header announces.
 *
 * - VTK legacy: the first line must be the "# vtk DataFile Version" header (so that garbage is
 *   reported as such rather than quoted back).
 * - VTK XML: the sizes the pieces claim; unstructured grids' polyhedron face streams; image
 *   data's origin, spacing and direction (below).
 * - EnSight case files and Exodus II headers (below).
 *
 * Each function returns an empty string when the file passes, else a one-line reason.
 */

#ifndef vtkStylizeFileChecks_h
#define vtkStylizeFileChecks_h

#include <string>

namespace vtkStylizeFileChecks
{
std::string CheckPLYFile(const std::string& path);
std::string CheckOBJFile(const std::string& path);
std::string CheckSTLFile(const std::string& path);
std::string CheckLegacyVTKFile(const std::string& path);
/**
 * VTK XML unstructured grid (.vtu): the polyhedron face streams ("faces", "faceoffsets"), which
 * VTK 9.1's reader walks without bounds checks (a face or point count larger than the stream
 * reads past it and crashes): every count must stay within the stream, and every point id
 * within the piece's points. The arrays are read with the reader's own decoding (inline,
 * appended, binary, compressed); a file without polyhedra costs a parse of its XML header.
 */
std::string CheckUnstructuredGridFaces(const std::string& path);
/**
 * VTK XML serial data (.vtp, .vtu, .vts, .vtr, .vti): the sizes the pieces claim (NumberOfPoints,
 * NumberOfCells, the polygonal counts, extents), which VTK's reader allocates before it reads a
 * value. The arrays they imply (tuples x components x type size) must fit in the memory the
 * process may use (the machine's, or a lower RLIMIT_AS or RLIMIT_DATA), and a file without a
 * compressor must hold at least one byte per value. The header is scanned as text, tags only
 * (inline data is skipped, appended data not read).
 */
std::string CheckXMLClaims(const std::string& path);
/**
 * VTK XML image data (.vti, .pvti): the Origin, Spacing and Direction attributes of the
 * (P)ImageData element must be finite numbers, 3, 3 and 9 of them (VTK's reader silently
 * replaces a "nan" or "inf" with the default). Only the file's first 64 KiB are read.
 */
std::string CheckImageDataFile(const std::string& path);
/**
 * EnSight case file (.case), on which VTK 9.1's reader loops forever when it is cut short or
 * followed by other bytes: at most 1 MiB of text (printable characters and white space), with
 * a FORMAT section and a GEOMETRY section whose "model:" names an existing file (unless it
 * holds the wildcard '*' of a time series).
 */
std::string CheckEnSightCaseFile(const std::string& path);
/**
 * Exodus II (.ex2, .exo, .e, .g) in netCDF's classic formats (CDF-1, 2 and 5): the header is
 * walked and every count it claims (dimensions, attributes, variables, name lengths, values)
 * must fit in the rest of the file, and every variable's data in the file (netCDF allocates
 * what the header claims before it reads the data: docs/command-line.md). netCDF-4
 * (HDF5) files are left to their library.
 */
std::string CheckExodusFile(const std::string& path);
}

#endif
