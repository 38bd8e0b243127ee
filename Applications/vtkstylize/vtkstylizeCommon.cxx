#include "vtkstylizeCommon.h"

#include <cmath>
#include <sys/resource.h>

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkStylizeOutputWindow.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
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

namespace
{
int ProgressDescriptor = -1;
volatile std::sig_atomic_t ProgressShown = 0; // a bar is on the terminal's current line

/** One observed object's step: its label, when it started, and what was last drawn. */
struct ProgressStep
{
  std::string Label;
  bool Active = false;
  std::chrono::steady_clock::time_point Start;
  int Drawn = -1; // the percentage on the terminal
};

void WriteProgress(const std::string& text)
{
  if (ProgressDescriptor >= 0)
  {
    ssize_t ignored = ::write(ProgressDescriptor, text.data(), text.size());
    (void)ignored;
  }
}

void OnProgress(vtkObject*, unsigned long, void* self, void* data)
{
  auto* step = static_cast<ProgressStep*>(self);
  const double fraction = data ? *static_cast<double*>(data) : 0.0;
  const auto now = std::chrono::steady_clock::now();
  if (!step->Active)
  {
    step->Active = true;
    step->Start = now;
    step->Drawn = -1;
  }
  if (!(fraction < 1.0))
  {
    step->Active = false;
    if (step->Drawn >= 0)
    {
      ClearProgress();
    }
    return;
  }
  const int percent = static_cast<int>(100.0 * std::max(0.0, fraction));
  // (VTKSTYLIZE_PROGRESS_DELAY: the second before a bar shows, changed by the tests)
  static const double delay = std::getenv("VTKSTYLIZE_PROGRESS_DELAY")
    ? std::max(0.0, std::atof(std::getenv("VTKSTYLIZE_PROGRESS_DELAY")))
    : 1.0;
  if (ProgressDescriptor < 0 || percent == step->Drawn ||
    std::chrono::duration<double>(now - step->Start).count() < delay)
  {
    return;
  }
  step->Drawn = percent;
  const int width = 30, filled = width * percent / 100;
  ProgressShown = 1; // (before the write: an interrupt during it still clears the line)
  WriteProgress("\r\033[Kvtkstylize: " + step->Label + " [" + std::string(filled, '=') +
    std::string(width - filled, ' ') + "] " + std::to_string(percent) + "%");
}
}

void SetProgressDescriptor(int descriptor)
{
  ProgressDescriptor = descriptor;
}

void ReportProgress(vtkObject* object, const std::string& label)
{
  if (!object)
  {
    return;
  }
  // The step lives as long as the observer (deleted with the command).
  auto* step = new ProgressStep;
  step->Label = label;
  vtkNew<vtkCallbackCommand> command;
  command->SetClientData(step);
  command->SetCallback(&OnProgress);
  command->SetClientDataDeleteCallback([](void* self) { delete static_cast<ProgressStep*>(self); });
  object->AddObserver(vtkCommand::ProgressEvent, command);
}

void ClearProgress()
{
  if (ProgressShown && ProgressDescriptor >= 0)
  {
    static const char clear[] = "\r\033[K";
    ssize_t ignored = ::write(ProgressDescriptor, clear, sizeof(clear) - 1);
    (void)ignored;
    ProgressShown = 0;
  }
}

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
