// Exodus II in netCDF's classic formats (CDF-1, 2 and 5): every count the header claims must fit
// in the rest of the file, and every variable's data in the file. netCDF-4 (HDF5) files are left
// to their library.

#include "vtkStylizeFileChecks.h"
#include "vtkStylizeFileChecksInternal.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace vtkStylizeFileChecks
{
namespace
{
/** Walks a netCDF classic header (big-endian) held in memory. */
class NetCDFHeader
{
public:
  NetCDFHeader(const std::vector<unsigned char>& bytes, long long fileSize, int version)
    : Bytes(bytes)
    , FileSize(fileSize)
    , Version(version)
  {
  }

  std::string Check()
  {
    this->Pos = 4;
    unsigned long long records = 0;
    if (!this->Count(records, "the number of records"))
    {
      return this->Problem;
    }
    if (records == (this->Version == 5 ? ~0ULL : 0xFFFFFFFFULL))
    {
      records = 0; // streaming
    }
    std::vector<unsigned long long> dims;
    unsigned long long tag = 0, n = 0;
    // dimensions: each a name (>= 4 bytes with its length) and a length
    if (!this->List(0x0A, tag, n, 8 + this->Width()))
    {
      return this->Problem;
    }
    for (unsigned long long i = 0; i < n; ++i)
    {
      unsigned long long length = 0;
      if (!this->Name() || !this->Count(length, "a dimension's length"))
      {
        return this->Problem;
      }
      dims.push_back(length);
    }
    if (!this->Attributes())
    {
      return this->Problem;
    }
    if (!this->List(0x0B, tag, n, 20))
    {
      return this->Problem;
    }
    for (unsigned long long v = 0; v < n; ++v)
    {
      unsigned long long rank = 0;
      if (!this->Name() || !this->Count(rank, "a variable's rank", this->Width()))
      {
        return this->Problem;
      }
      double values = 1.0;
      bool record = false;
      for (unsigned long long d = 0; d < rank; ++d)
      {
        unsigned long long id = 0;
        if (!this->Count(id, "a dimension id"))
        {
          return this->Problem;
        }
        if (id >= dims.size())
        {
          return "a variable names dimension " + std::to_string(id) + " of " +
            std::to_string(dims.size());
        }
        if (d == 0 && dims[id] == 0)
        {
          record = true;
          continue;
        }
        values *= static_cast<double>(dims[id]);
      }
      unsigned long long type = 0, vsize = 0, begin = 0;
      if (!this->Attributes() || !this->Value(type, 4) ||
        !this->Count(vsize, "a variable's size") || !this->Value(begin, this->Version == 1 ? 4 : 8))
      {
        return this->Problem.empty() ? "the header ends inside a variable" : this->Problem;
      }
      const double bytes = values * TypeSize(type) * (record ? static_cast<double>(records) : 1.0);
      if (TypeSize(type) == 0.0)
      {
        return "a variable has the unknown type " + std::to_string(type);
      }
      if (static_cast<double>(begin) + bytes > static_cast<double>(this->FileSize))
      {
        return "a variable claims " + FormatCount(bytes) + " bytes of data at byte " +
          std::to_string(begin) + ", beyond the file's " + std::to_string(this->FileSize);
      }
    }
    return std::string();
  }

private:
  static double TypeSize(unsigned long long type)
  {
    static const double sizes[12] = { 0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8 };
    return type < 12 ? sizes[type] : 0.0;
  }

  int Width() const { return this->Version == 5 ? 8 : 4; }

  bool Value(unsigned long long& out, int bytes)
  {
    if (this->Pos + bytes > this->Bytes.size())
    {
      this->Problem = "the header is cut short";
      return false;
    }
    out = 0;
    for (int i = 0; i < bytes; ++i)
    {
      out = (out << 8) | this->Bytes[this->Pos++];
    }
    return true;
  }

  /** A count of this format's width; at most what the rest of the file could hold. */
  bool Count(unsigned long long& out, const char* what, int width = 0)
  {
    if (!this->Value(out, width ? width : this->Width()))
    {
      return false;
    }
    if (static_cast<double>(out) > static_cast<double>(this->FileSize) * 1e6)
    {
      this->Problem = std::string("the header claims ") + std::to_string(out) + " for " + what +
        " in a file of " + std::to_string(this->FileSize) + " bytes";
      return false;
    }
    return true;
  }

  /** A list's tag and element count (ABSENT: zeros); each element at least minimum bytes. */
  bool List(
    unsigned long long expected, unsigned long long& tag, unsigned long long& n, double minimum)
  {
    if (!this->Value(tag, 4) || !this->Value(n, this->Width()))
    {
      return false;
    }
    if (tag == 0 && n == 0)
    {
      return true;
    }
    if (tag != expected)
    {
      this->Problem = "the header holds an unexpected list tag " + std::to_string(tag);
      return false;
    }
    const double left = static_cast<double>(this->Bytes.size() - this->Pos);
    if (static_cast<double>(n) * minimum > left)
    {
      this->Problem = "the header claims " + std::to_string(n) + " items in a list, more than " +
        "its " + std::to_string(static_cast<long long>(left)) + " remaining bytes can hold";
      return false;
    }
    return true;
  }

  bool Name()
  {
    unsigned long long length = 0;
    if (!this->Value(length, this->Width()))
    {
      return false;
    }
    const unsigned long long padded = (length + 3) / 4 * 4;
    if (padded > this->Bytes.size() - this->Pos)
    {
      this->Problem = "a name of " + std::to_string(length) + " bytes runs past the header";
      return false;
    }
    this->Pos += padded;
    return true;
  }

  bool Attributes()
  {
    unsigned long long tag = 0, n = 0;
    if (!this->List(0x0C, tag, n, 12 + this->Width()))
    {
      return false;
    }
    for (unsigned long long i = 0; i < n; ++i)
    {
      unsigned long long type = 0, count = 0;
      if (!this->Name() || !this->Value(type, 4) || !this->Value(count, this->Width()))
      {
        return false;
      }
      const double bytes = std::ceil(static_cast<double>(count) * TypeSize(type) / 4.0) * 4.0;
      if (TypeSize(type) == 0.0 || bytes > static_cast<double>(this->Bytes.size() - this->Pos))
      {
        this->Problem = "an attribute claims " + std::to_string(count) + " values, past the header";
        return false;
      }
      this->Pos += static_cast<std::size_t>(bytes);
    }
    return true;
  }

  const std::vector<unsigned char>& Bytes;
  long long FileSize;
  int Version;
  std::size_t Pos = 0;
  std::string Problem;
};

std::string CheckExodus(FileReader& in, const std::string&)
{
  const long long size = in.Size();
  // The header lies at the start; 16 MiB hold the largest Exodus header one meets.
  std::vector<unsigned char> bytes(static_cast<std::size_t>(std::min<long long>(size, 16 << 20)));
  if (!bytes.empty() && !in.Read(bytes.data(), bytes.size()))
  {
    return "cannot read the file";
  }
  if (bytes.size() >= 8 && bytes[0] == 0x89 && bytes[1] == 'H' && bytes[2] == 'D' &&
    bytes[3] == 'F')
  {
    return std::string(); // netCDF-4: HDF5 checks its own structure
  }
  if (bytes.size() < 8 || bytes[0] != 'C' || bytes[1] != 'D' || bytes[2] != 'F' ||
    (bytes[3] != 1 && bytes[3] != 2 && bytes[3] != 5))
  {
    return "not an Exodus II file (neither netCDF classic nor netCDF-4)";
  }
  return NetCDFHeader(bytes, size, bytes[3]).Check();
}
} // namespace

//------------------------------------------------------------------------------
std::string CheckExodusFile(const std::string& path)
{
  return CheckOpenFile(path, CheckExodus);
}
} // namespace vtkStylizeFileChecks
