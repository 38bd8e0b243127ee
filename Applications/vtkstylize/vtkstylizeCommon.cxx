#include "vtkstylizeCommon.h"

#include <cmath>
#include <sys/resource.h>

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkStylizeOutputWindow.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <sstream>
#include <vector>

#include <unistd.h>

namespace vtkstylize
{
void UsageError(const std::string& message)
{
  throw CliError{ ExitUsage, message };
}

void Fail(const std::string& message)
{
  throw CliError{ ExitFailure, message };
}

namespace
{
std::vector<std::string>& NoteList()
{
  static std::vector<std::string> notes;
  return notes;
}
}

double& MemoryLimitMiB()
{
  static double limit = 0.0;
  return limit;
}

std::vector<std::string>& WarningList()
{
  static std::vector<std::string> warnings;
  return warnings;
}

void SetMemoryLimit(double mib)
{
  // The soft limit the process started with, restored by SetMemoryLimit(0).
  static struct rlimit original;
  static const bool known = ::getrlimit(RLIMIT_DATA, &original) == 0;
  MemoryLimitMiB() = 0.0;
  if (!known)
  {
    return;
  }
  struct rlimit limit = original;
  if (!(mib > 0.0))
  {
    ::setrlimit(RLIMIT_DATA, &original);
    return;
  }
#if defined(__SANITIZE_ADDRESS__)
  // (AddressSanitizer's shadow memory and allocator count as data: no limit under it)
  return;
#endif
  const double bytes = mib * 1024.0 * 1024.0;
  rlim_t wanted =
    bytes >= static_cast<double>(RLIM_INFINITY) ? RLIM_INFINITY : static_cast<rlim_t>(bytes);
  if (limit.rlim_max != RLIM_INFINITY && wanted > limit.rlim_max)
  {
    wanted = limit.rlim_max;
  }
  limit.rlim_cur = wanted;
  if (::setrlimit(RLIMIT_DATA, &limit) == 0)
  {
    MemoryLimitMiB() = static_cast<double>(wanted) / (1024.0 * 1024.0);
  }
}

bool SaysOutOfMemory(const std::string& message)
{
  return message.find("nable to allocate") != std::string::npos ||
    message.find("bad_alloc") != std::string::npos ||
    message.find("out of memory") != std::string::npos;
}

std::string MemoryLimitText()
{
  return MemoryLimitMiB() > 0.0
    ? " (the memory limit: " + FormatNumber(std::floor(MemoryLimitMiB())) + " MiB, --memory-limit)"
    : std::string();
}

void Warn(const std::string& message)
{
  WarningList().push_back(message);
}

const std::vector<std::string>& Warnings()
{
  return WarningList();
}

void Note(const std::string& message)
{
  NoteList().push_back(message);
}

const std::vector<std::string>& Notes()
{
  return NoteList();
}

std::string Quote(const std::string& text)
{
  return "'" + text + "'";
}

std::string OneLine(const std::string& text, std::size_t maxLength)
{
  return vtkStylizeOutputWindow::OneLine(text, maxLength);
}

std::string Lower(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::string FormatNumber(double value)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%g", value);
  return buf;
}

namespace
{
/** The installed capture window, owned by vtkOutputWindow's singleton. */
vtkStylizeOutputWindow* Capture = nullptr;
} // namespace

void InstallMessageCapture(int echoDescriptor)
{
  vtkNew<vtkStylizeOutputWindow> window;
  window->SetEchoDescriptor(echoDescriptor);
  vtkOutputWindow::SetInstance(window);
  Capture = window;
}

void RemoveMessageCapture()
{
  vtkOutputWindow::SetInstance(nullptr);
  Capture = nullptr;
}

void ClearVTKErrors()
{
  if (Capture)
  {
    Capture->ClearMessages();
  }
}

void CheckVTKErrors(const std::string& what)
{
  if (Capture && Capture->HasFailure())
  {
    const std::string error = Capture->GetFirstFailure();
    Fail(what + ": " + error + (SaysOutOfMemory(error) ? MemoryLimitText() : std::string()));
  }
}
} // namespace vtkstylize
