// The isolated read of vtkStylizeReader: the file is read by the helper program vtkstylize-read
// under limits and the data comes back through memory files. VTK's readers crash, loop or
// allocate without bound on damaged files along paths no check before reading can reach (issue
// 39); in another process such a failure ends that process and becomes one line, and the
// caller's process is untouched. The helper is started with posix_spawn, not fork(): a fork of a
// multithreaded host (ParaView, Qt, MPI, TBB's workers) copies locks other threads hold, held
// forever in the child (issue 53); an exec'd program starts with none of the host's state.
//
// The protocol, over a socket pair of type SOCK_SEQPACKET (one record per message, in order;
// the helper's end is its descriptor 3):
//   'H'               the helper started and set its limits
//   'W' text          a warning
//   'E' text          the read failed (then 'D')
//   'M' count name    a multiblock dataset with count children, which follow (pre-order)
//   'P' count name    a multipiece dataset, likewise
//   '0' name          an empty block
//   'L' class name    a dataset, written in VTK's XML format (raw appended binary) to a memory
//                     file (memfd) whose descriptor travels with the record (SCM_RIGHTS)
//   'G' class name    other data (a table), likewise in VTK's legacy binary format
//   'D'               done: the helper exits
// A count or class is followed by a newline, the name (possibly empty) is the rest of the
// message. The helper writes nothing else: its standard streams are /dev/null, its core dumps
// are off, it dies with its parent.
#include "vtkStylizeReaderInternal.h"

#include "vtkAlgorithm.h"
#include "vtkDataObjectTypes.h"
#include "vtkDataSet.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiPieceDataSet.h"
#include "vtkNew.h"
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
#include <dlfcn.h>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace vtkStylizeReaderInternal
{
//------------------------------------------------------------------------------
// Limits

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

namespace
{
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
vtkSmartPointer<vtkDataObject> ReadMemoryFile(
  ReadContext& context, int fd, const std::string& type, bool legacy)
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
  context.ClearVTKErrors();
  reader->Update();
  closer.Close();
  context.CheckVTKErrors("the data read cannot be handed over");
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
  bool Started = false;     // 'H' received
  double Baseline = 0.0;    // the helper's resident size then (bytes)
};

/** Handles one record; throws ReadFailure on what does not follow the protocol. */
void Handle(ReadContext& context, const Record& record, Reception& in)
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
    case 'H':
      in.Started = true;
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
      in.Tree.Add(ReadMemoryFile(context, record.Descriptor, head, record.Kind == 'G'), rest, 0);
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
  ReadContext& context, int socket, pid_t pid, const IsolationLimits& limits, Reception& in)
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
      if (in.Started && ResidentBytes(pid) > in.Baseline + limits.MemoryMiB * MiB)
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
        Handle(context, record, in);
        if (record.Kind == 'H')
        {
          in.Baseline = ResidentBytes(pid); // (the libraries it loaded, before the read)
        }
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
std::string HelperPath(std::string& why)
{
  const char* name = "vtkstylize-read";
  if (const char* given = std::getenv("VTKSTYLIZE_READ_HELPER"))
  {
    if (*given && ::access(given, X_OK) == 0)
    {
      return given;
    }
    why = std::string("the reading helper ") + Quote(given) +
      " (VTKSTYLIZE_READ_HELPER) is not an executable file";
    return std::string();
  }
  // Beside the IO library (or the program it is linked into).
  Dl_info info;
  std::string folder;
  if (::dladdr(reinterpret_cast<void*>(&HelperPath), &info) != 0 && info.dli_fname)
  {
    char* real = ::realpath(info.dli_fname, nullptr);
    folder = real ? real : info.dli_fname;
    std::free(real);
    const auto slash = folder.find_last_of('/');
    folder = slash == std::string::npos ? std::string(".") : folder.substr(0, slash);
  }
  const std::string path = folder + "/" + name;
  if (!folder.empty() && ::access(path.c_str(), X_OK) == 0)
  {
    return path;
  }
  why = std::string("the reading helper ") + name + " is not in " +
    (folder.empty() ? std::string("the IO library's folder") : Quote(folder)) +
    " (install it there, or name it in VTKSTYLIZE_READ_HELPER)";
  return std::string();
}

namespace
{
/**
 * The helper's environment: the sanitizers' settings and nothing else (no LD_PRELOAD, no
 * locale, no Python or ParaView variable of the host reaches VTK's readers).
 */
std::vector<std::string> HelperEnvironment()
{
  std::vector<std::string> kept;
  for (char** e = environ; e && *e; ++e)
  {
    const std::string entry = *e;
    for (const char* prefix :
      { "ASAN_OPTIONS=", "UBSAN_OPTIONS=", "LSAN_OPTIONS=", "TSAN_OPTIONS=" })
    {
      if (entry.compare(0, std::strlen(prefix), prefix) == 0)
      {
        kept.push_back(entry);
      }
    }
  }
  return kept;
}

/** Starts the helper on socket (its descriptor 3); its pid, or -1 with why. */
pid_t SpawnHelper(const std::string& helper, int socket, const std::vector<std::string>& arguments,
  std::string& why)
{
  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attributes;
  ::posix_spawn_file_actions_init(&actions);
  ::posix_spawnattr_init(&attributes);
  ::posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  ::posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  ::posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  ::posix_spawn_file_actions_adddup2(&actions, socket, 3); // (dup2 clears close-on-exec)
  // Every signal's default action, none blocked (a host that ignores SIGXCPU or blocks SIGSEGV
  // would pass that on), and a process group of its own (a terminal's Ctrl-C goes to the caller,
  // which stops the read; the helper dies with it).
  sigset_t all, none;
  sigfillset(&all);
  sigemptyset(&none);
  ::posix_spawnattr_setsigdefault(&attributes, &all);
  ::posix_spawnattr_setsigmask(&attributes, &none);
  ::posix_spawnattr_setpgroup(&attributes, 0);
  ::posix_spawnattr_setflags(&attributes,
    static_cast<short>(POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETPGROUP));
  std::vector<std::string> args = arguments;
  args.insert(args.begin(), helper);
  std::vector<char*> argv;
  for (std::string& a : args)
  {
    argv.push_back(&a[0]);
  }
  argv.push_back(nullptr);
  std::vector<std::string> environment = HelperEnvironment();
  std::vector<char*> envp;
  for (std::string& e : environment)
  {
    envp.push_back(&e[0]);
  }
  envp.push_back(nullptr);
  pid_t pid = -1;
  const int error =
    ::posix_spawn(&pid, helper.c_str(), &actions, &attributes, argv.data(), envp.data());
  ::posix_spawn_file_actions_destroy(&actions);
  ::posix_spawnattr_destroy(&attributes);
  if (error != 0)
  {
    why = "cannot start the reading helper " + Quote(helper) + ": " + std::strerror(error);
    return -1;
  }
  return pid;
}
} // namespace

//------------------------------------------------------------------------------
ReadResult ReadIsolated(
  ReadContext& context, const std::string& path, int timeStep, const IsolationLimits& limits)
{
  const std::string what = "cannot read " + Quote(path);
  ReadResult result;
  std::string why;
  const std::string helper = HelperPath(why);
  if (helper.empty())
  {
    result.Error = what + ": " + why;
    return result;
  }
  int sockets[2];
  if (::socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, sockets) != 0)
  {
    result.Error = what + ": cannot start the reading helper: " + std::strerror(errno);
    return result;
  }
  // (the helper's end must not be descriptor 3 itself: dup2(3, 3) would keep close-on-exec)
  if (sockets[1] == 3)
  {
    const int moved = ::fcntl(sockets[1], F_DUPFD_CLOEXEC, 4);
    ::close(sockets[1]);
    sockets[1] = moved;
  }
  char memory[64], seconds[64];
  std::snprintf(memory, sizeof(memory), "%.17g", limits.MemoryMiB);
  std::snprintf(seconds, sizeof(seconds), "%.17g", limits.Seconds);
  const pid_t pid = sockets[1] < 0
    ? -1
    : SpawnHelper(helper, sockets[1],
        { std::to_string(::getpid()), memory, seconds, std::to_string(timeStep), path }, why);
  if (sockets[1] >= 0)
  {
    ::close(sockets[1]);
  }
  if (pid < 0)
  {
    ::close(sockets[0]);
    result.Error = what + ": " + (why.empty() ? "cannot start the reading helper" : why);
    return result;
  }
  Reception in;
  Receive(context, sockets[0], pid, limits, in);
  ::close(sockets[0]);
  if (!in.Done)
  {
    ::kill(pid, SIGKILL);
  }
  int status = 0;
  bool waited = true;
  while (::waitpid(pid, &status, 0) < 0)
  {
    if (errno != EINTR)
    {
      waited = false; // (a host that reaps every child itself: SIGCHLD ignored)
      break;
    }
  }
  result.Warnings = in.Warnings;
  if (!in.Killed.empty())
  {
    result.Error = what + ": it " + in.Killed;
  }
  else if (!in.Started)
  {
    result.Error = what + ": the reading helper " + Quote(helper) + " did not start" +
      (waited && WIFEXITED(status) ? " (exit status " + std::to_string(WEXITSTATUS(status)) + ")"
          : waited && WIFSIGNALED(status) ? " (" + SignalText(WTERMSIG(status)) + ")"
                                          : "");
  }
  else if (!in.Done)
  {
    result.Error =
      what + ": " + (waited ? ChildFailure(status, limits) : "VTK's reader stopped on it");
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
