// vtkstylize: Xvfb started for the run when no X display is set.
#include "VirtualDisplay.h"

#include "vtkstylizeCommon.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace vtkstylize
{
namespace
{
volatile pid_t ServerPid = 0;

/** The path of an executable named name on PATH, or an empty string. */
std::string FindOnPath(const std::string& name)
{
  const char* path = std::getenv("PATH");
  std::string entries = path && *path ? path : "/usr/local/bin:/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= entries.size())
  {
    const std::size_t end = std::min(entries.find(':', start), entries.size());
    const std::string dir = end > start ? entries.substr(start, end - start) : ".";
    const std::string candidate = dir + "/" + name;
    struct stat st;
    if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
      ::access(candidate.c_str(), X_OK) == 0)
    {
      return candidate;
    }
    start = end + 1;
  }
  return std::string();
}
} // namespace

void StartVirtualDisplayIfNeeded(int width, int height)
{
  const char* display = std::getenv("DISPLAY");
  if ((display && *display) || ServerPid > 0)
  {
    return;
  }
  const std::string xvfb = FindOnPath("Xvfb");
  if (xvfb.empty())
  {
    Fail("cannot render: there is no X display (DISPLAY is not set) and Xvfb, which vtkstylize "
         "starts then, is not installed (Debian, Ubuntu: apt install xvfb; Fedora: dnf install "
         "xorg-x11-server-Xvfb); or set DISPLAY to an X server");
  }
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0)
  {
    Fail(std::string("cannot start Xvfb: ") + std::strerror(errno));
  }
  const std::string screen = std::to_string(std::max(1920, std::min(width, 16384))) + "x" +
    std::to_string(std::max(1080, std::min(height, 16384))) + "x24";
  const std::string displayFd = std::to_string(fds[1]);
  const pid_t pid = ::fork();
  if (pid < 0)
  {
    Fail(std::string("cannot start Xvfb: ") + std::strerror(errno));
  }
  if (pid == 0)
  {
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    ::fcntl(fds[1], F_SETFD, 0); // (the server writes its display number to this descriptor)
    const int null = ::open("/dev/null", O_RDWR);
    for (int fd = 0; fd < 3 && null >= 0; ++fd)
    {
      ::dup2(null, fd);
    }
    for (int sig : { SIGINT, SIGTERM, SIGHUP, SIGSEGV, SIGBUS, SIGFPE, SIGABRT })
    {
      std::signal(sig, SIG_DFL);
    }
    ::execl(xvfb.c_str(), "Xvfb", "-displayfd", displayFd.c_str(), "-screen", "0", screen.c_str(),
      "-nolisten", "tcp", "-noreset", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(fds[1]);
  ServerPid = pid;
  // The server writes "N\n" once it accepts connections.
  std::string number;
  const auto start = std::chrono::steady_clock::now();
  while (number.empty() || number.back() != '\n')
  {
    const double left =
      30.0 - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    pollfd p{ fds[0], POLLIN, 0 };
    if (left <= 0.0 || ::poll(&p, 1, static_cast<int>(left * 1000.0) + 1) <= 0)
    {
      if (errno == EINTR && left > 0.0)
      {
        continue;
      }
      break;
    }
    char c;
    const ssize_t n = ::read(fds[0], &c, 1);
    if (n <= 0)
    {
      break;
    }
    number += c;
  }
  ::close(fds[0]);
  if (number.empty() || number.back() != '\n' ||
    number.find_first_not_of("0123456789\n") != std::string::npos)
  {
    StopVirtualDisplay();
    Fail("cannot render: there is no X display (DISPLAY is not set) and " + xvfb +
      " did not start one");
  }
  number.pop_back();
  ::setenv("DISPLAY", (":" + number).c_str(), 1);
}

void StopVirtualDisplay()
{
  const pid_t pid = ServerPid;
  if (pid > 0)
  {
    ServerPid = 0;
    ::kill(pid, SIGTERM);
    int status;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
    {
    }
  }
}
}
