// The helper's side of vtkStylizeReader's isolated read (the program vtkstylize-read,
// vtkStylizeReadHelper.cxx, runs ReadHelperMain): it sets its limits, reads and validates the file
// (ReadChecked) and sends the result over the socket, datasets through memory files.
// vtkStylizeReaderIsolation.cxx describes the protocol and holds the caller's side.
#include "vtkStylizeReaderInternal.h"

#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkGenericDataObjectWriter.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiPieceDataSet.h"
#include "vtkNew.h"
#include "vtkSMPTools.h"
#include "vtkXMLDataSetWriter.h"

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <vector>

#include <dirent.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace vtkStylizeReaderInternal
{
namespace
{
//------------------------------------------------------------------------------
// Child: sending

bool SendRecord(int socket, char kind, const std::string& text, int fd = -1)
{
  std::string message(1, kind);
  message += text.substr(0, MaxRecord);
  iovec io{ &message[0], message.size() };
  msghdr header{};
  header.msg_iov = &io;
  header.msg_iovlen = 1;
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int))];
  if (fd >= 0)
  {
    std::memset(control, 0, sizeof(control));
    header.msg_control = control;
    header.msg_controllen = sizeof(control);
    cmsghdr* c = CMSG_FIRSTHDR(&header);
    c->cmsg_level = SOL_SOCKET;
    c->cmsg_type = SCM_RIGHTS;
    c->cmsg_len = CMSG_LEN(sizeof(int));
    std::memcpy(CMSG_DATA(c), &fd, sizeof(int));
  }
  ssize_t sent;
  do
  {
    sent = ::sendmsg(socket, &header, MSG_NOSIGNAL);
  } while (sent < 0 && errno == EINTR);
  return sent == static_cast<ssize_t>(message.size());
}

std::string BlockName(vtkCompositeDataSet* parent, unsigned int index)
{
  vtkInformation* meta = nullptr;
  if (auto* mb = vtkMultiBlockDataSet::SafeDownCast(parent))
  {
    meta = mb->HasMetaData(index) ? mb->GetMetaData(index) : nullptr;
  }
  else if (auto* mp = vtkMultiPieceDataSet::SafeDownCast(parent))
  {
    meta = mp->HasMetaData(index) ? mp->GetMetaData(index) : nullptr;
  }
  return meta && meta->Has(vtkCompositeDataSet::NAME()) ? meta->Get(vtkCompositeDataSet::NAME())
                                                        : std::string();
}

/** Sends object (and its children); throws ReadFailure on what cannot be sent. */
void SendTree(int socket, vtkDataObject* object, const std::string& name)
{
  if (!object)
  {
    SendRecord(socket, '0', name);
    return;
  }
  auto* mb = vtkMultiBlockDataSet::SafeDownCast(object);
  auto* mp = vtkMultiPieceDataSet::SafeDownCast(object);
  if (mb || mp)
  {
    const unsigned int n = mb ? mb->GetNumberOfBlocks() : mp->GetNumberOfPieces();
    SendRecord(socket, mb ? 'M' : 'P', std::to_string(n) + "\n" + name);
    for (unsigned int i = 0; i < n; ++i)
    {
      auto* composite = static_cast<vtkCompositeDataSet*>(object);
      SendTree(socket, mb ? mb->GetBlock(i) : mp->GetPieceAsDataObject(i), BlockName(composite, i));
    }
    return;
  }
  auto* ds = vtkDataSet::SafeDownCast(object);
  const int fd = ::memfd_create("vtkstylize-read", MFD_CLOEXEC);
  if (fd < 0)
  {
    Fail(std::string("cannot create a memory file: ") + std::strerror(errno));
  }
  const std::string file = "/proc/self/fd/" + std::to_string(fd);
  int written = 0;
  if (ds)
  {
    // Datasets: VTK's XML format, raw binary, which keeps every class and attribute.
    // (without its time step, which the writer would add as a field array "TimeValue")
    vtkSmartPointer<vtkDataSet> copy;
    copy.TakeReference(ds->NewInstance());
    copy->ShallowCopy(ds);
    copy->GetInformation()->Remove(vtkDataObject::DATA_TIME_STEP());
    vtkNew<vtkXMLDataSetWriter> writer;
    writer->SetInputData(copy);
    writer->SetFileName(file.c_str());
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetCompressorTypeToNone();
    writer->SetHeaderTypeToUInt64();
    writer->SetIdTypeToInt64();
    written = writer->Write();
  }
  else
  {
    // Other data (a table, a graph): VTK's legacy format, binary.
    vtkNew<vtkGenericDataObjectWriter> writer;
    writer->SetInputData(object);
    writer->SetFileName(file.c_str());
    writer->SetFileTypeToBinary();
    written = writer->Write();
  }
  if (!written)
  {
    ::close(fd);
    Fail("cannot hand the data over: writing it to memory failed");
  }
  SendRecord(socket, ds ? 'L' : 'G', std::string(object->GetClassName()) + "\n" + name, fd);
  ::close(fd);
}

/** A whole decimal number of argument text, or false. */
bool ParseNumber(const char* text, double& value)
{
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text, &end);
  return errno == 0 && end != text && *end == '\0' && std::isfinite(value) && value >= 0.0;
}

/** Closes every descriptor from first on (close_range, else those /proc/self/fd lists). */
void CloseDescriptorsFrom(int first)
{
  if (::syscall(SYS_close_range, static_cast<unsigned>(first), ~0U, 0U) == 0)
  {
    return;
  }
  std::vector<int> open;
  if (DIR* dir = ::opendir("/proc/self/fd"))
  {
    while (dirent* entry = ::readdir(dir))
    {
      const int fd = std::atoi(entry->d_name);
      if (fd >= first && fd != ::dirfd(dir))
      {
        open.push_back(fd);
      }
    }
    ::closedir(dir);
  }
  for (int fd : open)
  {
    ::close(fd);
  }
}

/** The helper's limits, set before it opens the file. */
void SetLimits(double memoryMiB, double seconds)
{
  rlimit none{ 0, 0 };
  ::setrlimit(RLIMIT_CORE, &none);
  const rlim_t cpuSeconds = static_cast<rlim_t>(std::ceil(seconds));
  rlimit cpu{ cpuSeconds, cpuSeconds + 2 };
  ::setrlimit(RLIMIT_CPU, &cpu);
#ifndef VTKSTYLIZE_ASAN
  // The heap and the private mappings: what the helper has now (its libraries), and the
  // allowance (AddressSanitizer reserves terabytes: there the caller watches the resident size).
  rlimit data;
  if (::getrlimit(RLIMIT_DATA, &data) == 0)
  {
    const double wanted = StatusBytes("VmData") + memoryMiB * MiB;
    if (data.rlim_cur == RLIM_INFINITY || wanted < static_cast<double>(data.rlim_cur))
    {
      data.rlim_cur = static_cast<rlim_t>(wanted);
      ::setrlimit(RLIMIT_DATA, &data);
    }
  }
#else
  (void)memoryMiB;
#endif
}
} // namespace

//------------------------------------------------------------------------------
int ReadHelperMain(int argc, char* argv[])
{
  double parent = 0.0, memoryMiB = 0.0, seconds = 0.0, step = 0.0;
  struct stat st;
  if (argc != 6 || !ParseNumber(argv[1], parent) || !ParseNumber(argv[2], memoryMiB) ||
    !ParseNumber(argv[3], seconds) || !ParseNumber(argv[4], step) || step > 2147483647.0 ||
    ::fstat(3, &st) != 0 || !S_ISSOCK(st.st_mode))
  {
    std::fprintf(stderr,
      "vtkstylize-read: the reading helper of VTK Stylize's checked reader (vtkStylizeReader), "
      "started by it, not by hand\n");
    return 2;
  }
  const int socket = 3;
  // Dies with the caller; a caller gone before this line is noticed by its pid.
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != static_cast<pid_t>(parent))
  {
    return 1;
  }
  // No descriptor of the caller's but the socket (posix_spawn passes on those without
  // close-on-exec).
  CloseDescriptorsFrom(socket + 1);
  // A crash of VTK's reader ends the helper by its signal, which the caller names ("segmentation
  // fault"): the sanitizers' runtimes install handlers of their own at start-up (posix_spawn set
  // the defaults before), which would turn it into their exit status.
  for (int sig : { SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT })
  {
    std::signal(sig, SIG_DFL);
  }
  SetLimits(memoryMiB, seconds);
  if (!SendRecord(socket, 'H', std::string()))
  {
    return 1;
  }
  vtkSMPTools::SetBackend("Sequential"); // (one read, one thread: predictable time and memory)
  const std::string path = argv[5];
  const std::string what = "cannot read " + Quote(path);
  ReadResult result;
  try
  {
    result = ReadChecked(path, static_cast<int>(step));
    for (const std::string& warning : result.Warnings)
    {
      SendRecord(socket, 'W', warning);
    }
    if (result.Error.empty())
    {
      SendTree(socket, result.Data, std::string());
    }
  }
  catch (const ReadFailure& failure)
  {
    result.Error = what + ": " + failure.Message;
  }
  catch (const std::bad_alloc&)
  {
    result.Error = what + ": out of memory";
  }
  catch (...)
  {
    result.Error = what + ": the data cannot be handed over";
  }
  if (!result.Error.empty())
  {
    SendRecord(socket, 'E', result.Error);
  }
  SendRecord(socket, 'D', std::string());
  std::fflush(nullptr);
  ::_exit(0); // (no static destructor of VTK's runs after the data is sent)
}

} // namespace vtkStylizeReaderInternal
