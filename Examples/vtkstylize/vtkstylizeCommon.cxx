#include "vtkstylizeCommon.h"

#include <cmath>
#include <sys/resource.h>

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"

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
  rlim_t wanted = bytes >= static_cast<double>(RLIM_INFINITY) ? RLIM_INFINITY
                                                              : static_cast<rlim_t>(bytes);
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

/** Collapses a message to a single line of reasonable length. */
std::string OneLine(const std::string& text, std::size_t maxLength)
{
  std::string out;
  bool space = false;
  for (char c : text)
  {
    if (std::isspace(static_cast<unsigned char>(c)))
    {
      space = !out.empty();
      continue;
    }
    if (space)
    {
      out += ' ';
      space = false;
    }
    out += c;
  }
  if (out.size() > maxLength)
  {
    out = out.substr(0, maxLength - 3) + "...";
  }
  return out;
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
/** Replaces bytes that are not printable ASCII (garbage quoted by a reader) with '?'. */
std::string Printable(const std::string& text)
{
  std::string out = text;
  for (char& c : out)
  {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 127 || (u < 32 && !std::isspace(u)))
    {
      c = '?';
    }
  }
  return out;
}

/**
 * Output window that records VTK's messages instead of printing them, so that the caller can
 * turn the first relevant one into its single stderr line.
 *
 * A failure is an error, or a warning that says "error" (vtkDataReader reports truncated legacy
 * files with warnings such as "Error reading binary data!"). The executive's "Algorithm X
 * returned failure for request" error only repeats that a reader failed; the reader's own
 * message, when there is one, is the one reported.
 */
class vtkStylizeCaptureOutputWindow : public vtkOutputWindow
{
public:
  static vtkStylizeCaptureOutputWindow* New();
  vtkTypeMacro(vtkStylizeCaptureOutputWindow, vtkOutputWindow);

  void DisplayText(const char* text) override { this->Record(text, Text); }
  void DisplayErrorText(const char* text) override { this->Record(text, Error); }
  void DisplayWarningText(const char* text) override { this->Record(text, Warning); }
  void DisplayGenericWarningText(const char* text) override { this->Record(text, Warning); }
  void DisplayDebugText(const char* text) override { this->Record(text, Text); }

  void ClearErrors() { this->Messages.clear(); }

  bool HasErrors() const
  {
    for (const Message& m : this->Messages)
    {
      if (IsFailure(m))
      {
        return true;
      }
    }
    return false;
  }

  /** The most telling failure, reduced to one line without file, line and object prefixes. */
  std::string FirstError() const
  {
    const Message* pipeline = nullptr;
    for (const Message& m : this->Messages)
    {
      if (!IsFailure(m))
      {
        continue;
      }
      if (m.Text.find("returned failure for request") != std::string::npos)
      {
        pipeline = pipeline ? pipeline : &m;
        continue;
      }
      return Clean(m.Text);
    }
    if (pipeline)
    {
      const std::string text = Clean(pipeline->Text);
      // "Algorithm vtkPLYReader(0x...) returned failure ..." -> "vtkPLYReader failed"
      const auto a = text.find("Algorithm ");
      const auto paren = text.find('(', a);
      if (a != std::string::npos && paren != std::string::npos)
      {
        return text.substr(a + 10, paren - a - 10) + " failed";
      }
      return "a VTK algorithm failed";
    }
    return std::string();
  }

  /** Echo every message to this descriptor as it arrives (-1: never). */
  int EchoDescriptor = -1;

protected:
  vtkStylizeCaptureOutputWindow() = default;
  ~vtkStylizeCaptureOutputWindow() override = default;

  enum Kind
  {
    Text,
    Warning,
    Error
  };
  struct Message
  {
    Kind Type;
    std::string Text;
  };

  static bool IsFailure(const Message& m)
  {
    return m.Type == Error || (m.Type == Warning && Lower(m.Text).find("error") != std::string::npos);
  }

  /** Drops "ERROR: In file, line N" / "Warning: In ..." lines and "vtkClass (0x...): ". */
  static std::string Clean(const std::string& raw)
  {
    std::istringstream lines(raw);
    std::string line;
    std::string message;
    while (std::getline(lines, line))
    {
      const auto first = line.find_first_not_of(" \t\r");
      if (first == std::string::npos || line.find("ERROR: In ") == 0 ||
        line.find("Warning: In ") == 0 || line.find("Generic Warning: In ") == 0)
      {
        continue;
      }
      message += line + " ";
      // Only the first line of multi-line messages (the rest is a printed vtkInformation).
      break;
    }
    const std::size_t prefix = message.find("): ");
    const std::size_t object = message.find(" (0x");
    if (prefix != std::string::npos && object != std::string::npos && object < prefix)
    {
      message = message.substr(prefix + 3);
    }
    message = OneLine(Printable(message));
    return message.empty() ? OneLine(Printable(raw)) : message;
  }

  void Record(const char* text, Kind type)
  {
    const std::string s = text ? text : "";
    this->Messages.push_back({ type, s });
    if (this->EchoDescriptor >= 0 && !s.empty())
    {
      ssize_t ignored = ::write(this->EchoDescriptor, s.data(), s.size());
      (void)ignored;
    }
  }

  std::vector<Message> Messages;

private:
  vtkStylizeCaptureOutputWindow(const vtkStylizeCaptureOutputWindow&) = delete;
  void operator=(const vtkStylizeCaptureOutputWindow&) = delete;
};
vtkStandardNewMacro(vtkStylizeCaptureOutputWindow);

/** The installed capture window, owned by vtkOutputWindow's singleton. */
vtkStylizeCaptureOutputWindow* Capture = nullptr;
} // namespace

void InstallMessageCapture(int echoDescriptor)
{
  vtkNew<vtkStylizeCaptureOutputWindow> window;
  window->EchoDescriptor = echoDescriptor;
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
    Capture->ClearErrors();
  }
}

void CheckVTKErrors(const std::string& what)
{
  if (Capture && Capture->HasErrors())
  {
    const std::string error = Capture->FirstError();
    const bool memory = error.find("nable to allocate") != std::string::npos ||
      error.find("bad_alloc") != std::string::npos ||
      error.find("out of memory") != std::string::npos;
    Fail(what + ": " + error + (memory ? MemoryLimitText() : std::string()));
  }
}
} // namespace vtkstylize
