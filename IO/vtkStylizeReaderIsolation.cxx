// The isolated read of vtkStylizeReader: the file is read in a child process under limits and
// the data comes back through memory files. VTK's readers crash, loop or allocate without bound
// on damaged files along paths no check before reading can reach (issue 39); in a child process
// such a failure ends the child and becomes one line, and the caller's process is untouched.
//
// The protocol, over a socket pair of type SOCK_SEQPACKET (one record per message, in order):
//   'W' text          a warning
//   'E' text          the read failed (then 'D')
//   'M' count name    a multiblock dataset with count children, which follow (pre-order)
//   'P' count name    a multipiece dataset, likewise
//   '0' name          an empty block
//   'L' class name    a dataset, written in VTK's XML format (raw appended binary) to a memory
//                     file (memfd) whose descriptor travels with the record (SCM_RIGHTS)
//   'G' class name    other data (a table), likewise in VTK's legacy binary format
//   'D'               done: the child exits
// A count or class is followed by a newline, the name (possibly empty) is the rest of the
// message. The child writes nothing else: its standard error goes to /dev/null, its core dumps
// are off, it dies with its parent.
#include "vtkStylizeReaderInternal.h"

#include "vtkAlgorithm.h"
#include "vtkDataObjectTypes.h"
#include "vtkDataSet.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkGenericDataObjectWriter.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiPieceDataSet.h"
#include "vtkNew.h"
#include "vtkSMPTools.h"
#include "vtkStylizeOutputWindow.h"
#include "vtkXMLDataSetWriter.h"
#include "vtkXMLGenericDataObjectReader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <new>
#include <string>
#include <vector>

#include <dirent.h>
#include <fcntl.h>
#include <poll.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define VTKSTYLIZE_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define VTKSTYLIZE_ASAN 1
#endif
#endif

namespace vtkStylizeReaderInternal
{
namespace
{
constexpr double MiB = 1024.0 * 1024.0;
constexpr std::size_t MaxRecord = 8192; // (a record's longest text; messages are one line)

//------------------------------------------------------------------------------
// Limits

/** A value of the form "Name:   123 kB" from /proc/self/status, in bytes (0 if absent). */
double StatusBytes(const char* name)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::string key = std::string(name) + ":";
  while (std::getline(status, line))
  {
    if (line.compare(0, key.size(), key) == 0)
    {
      return std::strtod(line.c_str() + key.size(), nullptr) * 1024.0;
    }
  }
  return 0.0;
}

/**
 * The anonymous resident size of process pid in bytes (0 when it cannot be read): resident less
 * shared (file and shared-memory pages). A forked child has the parent's anonymous pages from its
 * start but maps the parent's files again as it touches them, so only the anonymous part compares
 * with what the parent had.
 */
double ResidentBytes(pid_t pid)
{
  char path[64];
  std::snprintf(path, sizeof(path), "/proc/%d/statm", static_cast<int>(pid));
  const int fd = ::open(path, O_RDONLY | O_CLOEXEC);
  if (fd < 0)
  {
    return 0.0;
  }
  char text[128] = { 0 };
  const ssize_t n = ::read(fd, text, sizeof(text) - 1);
  ::close(fd);
  unsigned long size = 0, resident = 0, shared = 0;
  if (n <= 0 || std::sscanf(text, "%lu %lu %lu", &size, &resident, &shared) != 3)
  {
    return 0.0;
  }
  return static_cast<double>(resident > shared ? resident - shared : 0) *
    static_cast<double>(::sysconf(_SC_PAGESIZE));
}

/** The total size of the regular files under folder (at most depth levels, 100000 entries). */
double FolderBytes(const std::string& folder, int depth, int& budget)
{
  double total = 0.0;
  DIR* dir = ::opendir(folder.c_str());
  if (!dir)
  {
    return 0.0;
  }
  while (dirent* entry = ::readdir(dir))
  {
    if (--budget < 0)
    {
      break;
    }
    const std::string name = entry->d_name;
    if (name == "." || name == "..")
    {
      continue;
    }
    const std::string path = folder + "/" + name;
    struct stat st;
    if (::lstat(path.c_str(), &st) != 0)
    {
      continue;
    }
    if (S_ISREG(st.st_mode))
    {
      total += static_cast<double>(st.st_size);
    }
    else if (S_ISDIR(st.st_mode) && depth > 0)
    {
      total += FolderBytes(path, depth - 1, budget);
    }
  }
  ::closedir(dir);
  return total;
}
} // namespace

//------------------------------------------------------------------------------
double InputBytes(const std::string& path)
{
  struct stat st;
  double bytes =
    ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) ? static_cast<double>(st.st_size) : 0.0;
  // A file that names others (or an OpenFOAM case) counts the files beside and below it.
  const auto dot = path.find_last_of('.');
  const std::string extension = dot == std::string::npos ? std::string() : Lower(path.substr(dot));
  if (extension == ".vtm" || extension.compare(0, 4, ".pvt") == 0 || extension == ".pvd" ||
    extension == ".case" || extension == ".foam")
  {
    const auto slash = path.find_last_of('/');
    int budget = 100000;
    bytes = std::max(
      bytes, FolderBytes(slash == std::string::npos ? "." : path.substr(0, slash), 3, budget));
  }
  return bytes;
}

//------------------------------------------------------------------------------
IsolationLimits AutomaticLimits(double inputBytes)
{
  IsolationLimits limits;
  // Memory: 512 MiB and 16 times the input (compressed formats expand, and the validation
  // copies), at most 3/4 of the machine. Time: 10 s and 1 s per MiB of input.
  const double machine = 0.75 * static_cast<double>(::sysconf(_SC_PHYS_PAGES)) *
    static_cast<double>(::sysconf(_SC_PAGESIZE));
  limits.MemoryMiB = std::min(512.0 + 16.0 * inputBytes / MiB, machine > 0.0 ? machine / MiB : 1e9);
  limits.Seconds = 10.0 + inputBytes / MiB;
#ifdef VTKSTYLIZE_ASAN
  limits.MemoryMiB *= 3.0; // (the sanitizer's shadow memory and quarantine)
  limits.Seconds *= 3.0;
#endif
  return limits;
}

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
  ClearVTKErrors();
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

[[noreturn]] void RunChild(int socket, const std::function<ReadResult()>& read,
  const IsolationLimits& limits, double dataBytes, const std::string& what)
{
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  const int null = ::open("/dev/null", O_WRONLY);
  if (null >= 0)
  {
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    ::close(null);
  }
  // (a sanitizer's report of a fault in VTK's reader would be the caller's stderr otherwise)
  vtkStylizeOutputWindow::ReportSanitizersTo(STDERR_FILENO);
  // The default actions, unblocked: a host that ignores or blocks a signal passes that on through
  // fork(), and an ignored or blocked SIGXCPU turns the time limit into the hard limit's SIGKILL.
  for (int sig : { SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGINT, SIGTERM, SIGPIPE, SIGXCPU })
  {
    std::signal(sig, SIG_DFL);
  }
  sigset_t unblocked;
  sigemptyset(&unblocked);
  ::sigprocmask(SIG_SETMASK, &unblocked, nullptr);
  rlimit none{ 0, 0 };
  ::setrlimit(RLIMIT_CORE, &none);
  const rlim_t seconds = static_cast<rlim_t>(std::ceil(limits.Seconds));
  rlimit cpu{ seconds, seconds + 2 };
  ::setrlimit(RLIMIT_CPU, &cpu);
#ifndef VTKSTYLIZE_ASAN
  // The heap and the private mappings: what the parent had, and the allowance (AddressSanitizer
  // reserves terabytes: there the parent watches the resident size alone).
  rlimit data;
  if (::getrlimit(RLIMIT_DATA, &data) == 0)
  {
    const double wanted = dataBytes + limits.MemoryMiB * MiB;
    if (data.rlim_cur == RLIM_INFINITY || wanted < static_cast<double>(data.rlim_cur))
    {
      data.rlim_cur = static_cast<rlim_t>(wanted);
      ::setrlimit(RLIMIT_DATA, &data);
    }
  }
#else
  (void)dataBytes;
#endif
  // The parent's thread pools do not exist here.
  vtkSMPTools::SetBackend("Sequential");
  ReadResult result;
  try
  {
    result = read();
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
  ::_exit(0);
}

//------------------------------------------------------------------------------
// Parent: receiving

struct Record
{
  char Kind = 0;
  std::string Text;
  int Descriptor = -1;
};

/** Receives one record; false at the end of the stream or on an error. */
bool ReceiveRecord(int socket, Record& record)
{
  std::vector<char> buffer(MaxRecord + 64);
  iovec io{ buffer.data(), buffer.size() };
  msghdr header{};
  header.msg_iov = &io;
  header.msg_iovlen = 1;
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int) * 4)];
  header.msg_control = control;
  header.msg_controllen = sizeof(control);
  ssize_t n;
  do
  {
    n = ::recvmsg(socket, &header, MSG_CMSG_CLOEXEC);
  } while (n < 0 && errno == EINTR);
  if (n <= 0)
  {
    return false;
  }
  record.Kind = buffer[0];
  record.Text.assign(buffer.data() + 1, static_cast<std::size_t>(n - 1));
  record.Descriptor = -1;
  for (cmsghdr* c = CMSG_FIRSTHDR(&header); c; c = CMSG_NXTHDR(&header, c))
  {
    if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SCM_RIGHTS)
    {
      const std::size_t count = (c->cmsg_len - CMSG_LEN(0)) / sizeof(int);
      for (std::size_t i = 0; i < count; ++i)
      {
        int fd;
        std::memcpy(&fd, CMSG_DATA(c) + i * sizeof(int), sizeof(int));
        if (record.Descriptor < 0)
        {
          record.Descriptor = fd;
        }
        else
        {
          ::close(fd);
        }
      }
    }
  }
  return true;
}

/** A record's "head\nrest" split. */
void Split(const std::string& text, std::string& head, std::string& rest)
{
  const auto newline = text.find('\n');
  head = text.substr(0, newline);
  rest = newline == std::string::npos ? std::string() : text.substr(newline + 1);
}

/**
 * Reads the data the child wrote to the memory file fd (closed here): VTK's XML format, or its
 * legacy format when legacy.
 */
vtkSmartPointer<vtkDataObject> ReadMemoryFile(int fd, const std::string& type, bool legacy)
{
  // (closed also when something throws: the memory file holds the whole dataset)
  struct Closer
  {
    int Descriptor;
    void Close()
    {
      if (this->Descriptor >= 0)
      {
        ::close(this->Descriptor);
        this->Descriptor = -1;
      }
    }
    ~Closer() { this->Close(); }
  } closer{ fd };
  vtkSmartPointer<vtkAlgorithm> reader;
  const std::string file = "/proc/self/fd/" + std::to_string(fd);
  if (legacy)
  {
    auto generic = vtkSmartPointer<vtkGenericDataObjectReader>::New();
    generic->SetFileName(file.c_str());
    generic->ReadAllScalarsOn();
    generic->ReadAllVectorsOn();
    generic->ReadAllNormalsOn();
    generic->ReadAllTCoordsOn();
    generic->ReadAllTensorsOn();
    generic->ReadAllColorScalarsOn();
    generic->ReadAllFieldsOn();
    reader = generic;
  }
  else
  {
    auto xml = vtkSmartPointer<vtkXMLGenericDataObjectReader>::New();
    xml->SetFileName(file.c_str());
    reader = xml;
  }
  ClearVTKErrors();
  reader->Update();
  closer.Close();
  CheckVTKErrors("the data read cannot be handed over");
  // The XML format keeps the class, or its superclass (vtkStructuredPoints is written as image
  // data): the data is given the class it was read as.
  vtkDataObject* output = reader->GetOutputDataObject(0);
  vtkSmartPointer<vtkDataObject> data;
  data.TakeReference(vtkDataObjectTypes::NewDataObject(type.c_str()));
  if (!output || !data || !data->IsA(output->GetClassName()))
  {
    Fail("the data read cannot be handed over");
  }
  data->ShallowCopy(output);
  return data;
}

/** The composite datasets being filled, the root, and where the next node goes. */
struct TreeBuilder
{
  struct Open
  {
    vtkSmartPointer<vtkDataObject> Node;
    unsigned int Count;
    unsigned int Next;
  };
  vtkSmartPointer<vtkDataObject> Root;
  bool HasRoot = false;
  std::vector<Open> Stack;

  bool Complete() const { return this->HasRoot && this->Stack.empty(); }

  void Add(vtkSmartPointer<vtkDataObject> node, const std::string& name, unsigned int children)
  {
    if (!this->HasRoot)
    {
      this->Root = node;
      this->HasRoot = true;
    }
    else
    {
      if (this->Stack.empty())
      {
        Fail("the data read cannot be handed over");
      }
      Open& parent = this->Stack.back();
      const unsigned int index = parent.Next++;
      if (auto* mb = vtkMultiBlockDataSet::SafeDownCast(parent.Node))
      {
        mb->SetBlock(index, node);
        if (!name.empty())
        {
          mb->GetMetaData(index)->Set(vtkCompositeDataSet::NAME(), name.c_str());
        }
      }
      else if (auto* mp = vtkMultiPieceDataSet::SafeDownCast(parent.Node))
      {
        mp->SetPiece(index, node);
        if (!name.empty())
        {
          mp->GetMetaData(index)->Set(vtkCompositeDataSet::NAME(), name.c_str());
        }
      }
    }
    if (children > 0)
    {
      this->Stack.push_back(Open{ node, children, 0 });
    }
    while (!this->Stack.empty() && this->Stack.back().Next == this->Stack.back().Count)
    {
      this->Stack.pop_back();
    }
  }
};

std::string SignalText(int sig)
{
  const char* text = ::strsignal(sig);
  return text ? Lower(text) : "signal " + std::to_string(sig);
}

/** What the parent received from the child, and why it stopped listening. */
struct Reception
{
  TreeBuilder Tree;
  std::vector<std::string> Warnings;
  std::string Failure;      // the child's failure (a whole line), or the hand-over's
  bool ChildFailed = false; // Failure is the child's
  std::string Killed;       // the limit the parent killed the child for
  bool Done = false;        // 'D' received
};

/** Handles one record; throws ReadFailure on what does not follow the protocol. */
void Handle(const Record& record, Reception& in)
{
  std::string head, rest;
  Split(record.Text, head, rest);
  switch (record.Kind)
  {
    case 'W':
      in.Warnings.push_back(record.Text);
      break;
    case 'E':
      in.Failure = record.Text;
      in.ChildFailed = true;
      break;
    case 'D':
      in.Done = true;
      break;
    case '0':
      in.Tree.Add(nullptr, record.Text, 0);
      break;
    case 'M':
    case 'P':
    {
      const unsigned int count = static_cast<unsigned int>(std::stoul(head));
      vtkSmartPointer<vtkCompositeDataSet> node;
      if (record.Kind == 'M')
      {
        auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
        blocks->SetNumberOfBlocks(count);
        node = blocks;
      }
      else
      {
        auto pieces = vtkSmartPointer<vtkMultiPieceDataSet>::New();
        pieces->SetNumberOfPieces(count);
        node = pieces;
      }
      in.Tree.Add(node, rest, count);
      break;
    }
    case 'L':
    case 'G':
      if (record.Descriptor < 0)
      {
        Fail("the data read cannot be handed over");
      }
      in.Tree.Add(ReadMemoryFile(record.Descriptor, head, record.Kind == 'G'), rest, 0);
      break;
    default:
      Fail("the data read cannot be handed over");
  }
}

/**
 * Receives the child's records until 'D', the end of the stream, or a limit: the resident size
 * (checked every 20 ms) or the wall-clock time.
 */
void Receive(
  int socket, pid_t pid, const IsolationLimits& limits, double residentLimit, Reception& in)
{
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const double wallSeconds = 2.0 * limits.Seconds + 5.0;
  try
  {
    while (!in.Done)
    {
      pollfd p{ socket, POLLIN, 0 };
      const int ready = ::poll(&p, 1, 20);
      if (ResidentBytes(pid) > residentLimit)
      {
        in.Killed = "needs more than " + std::to_string(static_cast<long>(limits.MemoryMiB)) +
          " MiB of memory to read (the reader's limit)";
        return;
      }
      if (std::chrono::duration<double>(Clock::now() - start).count() > wallSeconds)
      {
        in.Killed = "takes more than " + std::to_string(static_cast<long>(wallSeconds)) +
          " s to read (the reader's time limit)";
        return;
      }
      Record record;
      if (ready > 0 && !ReceiveRecord(socket, record))
      {
        return; // (the child ended without 'D')
      }
      if (ready > 0)
      {
        Handle(record, in);
      }
    }
  }
  catch (const ReadFailure& f)
  {
    in.Failure = f.Message;
    in.Done = true;
  }
  catch (const std::bad_alloc&)
  {
    in.Failure = "out of memory";
    in.Done = true;
  }
  catch (const std::exception&)
  {
    in.Failure = "the data read cannot be handed over";
    in.Done = true;
  }
}

/** Why a child that did not finish ended, from its wait status. */
std::string ChildFailure(int status, const IsolationLimits& limits)
{
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU)
  {
    return "it takes more than " + std::to_string(static_cast<long>(std::ceil(limits.Seconds))) +
      " s of processor time to read (the reader's time limit)";
  }
  if (WIFSIGNALED(status))
  {
    return "VTK's reader crashed on it (" + SignalText(WTERMSIG(status)) +
      "): the file is damaged or not what its extension says";
  }
  return "VTK's reader stopped on it (exit status " +
    std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
    "): the file is damaged or not what its extension says";
}
} // namespace

//------------------------------------------------------------------------------
std::string Lower(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

//------------------------------------------------------------------------------
ReadResult ReadIsolated(
  const std::string& path, const std::function<ReadResult()>& read, const IsolationLimits& limits)
{
  const std::string what = "cannot read " + Quote(path);
  ReadResult result;
  int sockets[2];
  if (::socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, sockets) != 0)
  {
    result.Error = what + ": cannot start the reading process: " + std::strerror(errno);
    return result;
  }
  const double dataBytes = StatusBytes("VmData");
  const double residentLimit = ResidentBytes(::getpid()) + limits.MemoryMiB * MiB;
  std::fflush(nullptr); // (the child must not print what the parent buffered)
  const pid_t pid = ::fork();
  if (pid < 0)
  {
    result.Error = what + ": cannot start the reading process: " + std::strerror(errno);
    ::close(sockets[0]);
    ::close(sockets[1]);
    return result;
  }
  if (pid == 0)
  {
    ::close(sockets[0]);
    RunChild(sockets[1], read, limits, dataBytes, what);
  }
  ::close(sockets[1]);
  Reception in;
  Receive(sockets[0], pid, limits, residentLimit, in);
  ::close(sockets[0]);
  if (!in.Done)
  {
    ::kill(pid, SIGKILL);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
  {
  }
  result.Warnings = in.Warnings;
  if (!in.Killed.empty())
  {
    result.Error = what + ": it " + in.Killed;
  }
  else if (!in.Done)
  {
    result.Error = what + ": " + ChildFailure(status, limits);
  }
  else if (!in.Failure.empty())
  {
    result.Error = in.ChildFailed ? in.Failure : what + ": " + in.Failure;
    if (in.Failure.find("out of memory") != std::string::npos)
    {
      result.Error +=
        " (the reader's limit: " + std::to_string(static_cast<long>(limits.MemoryMiB)) + " MiB)";
    }
  }
  else if (!in.Tree.Complete())
  {
    result.Error = what + ": the data read cannot be handed over";
  }
  else
  {
    result.Data = in.Tree.Root;
  }
  if (!result.Error.empty())
  {
    result.Data = nullptr;
  }
  return result;
}
} // namespace vtkStylizeReaderInternal
