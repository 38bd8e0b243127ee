#include "vtkStylizeOutputWindow.h"

#include "vtkObjectFactory.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <sstream>

#include <dlfcn.h>
#include <link.h>
#include <unistd.h>

vtkStandardNewMacro(vtkStylizeOutputWindow);

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

/** Drops "ERROR: In file, line N" / "Warning: In ..." lines and "vtkClass (0x...): ". */
std::string Clean(const std::string& raw)
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
  message = vtkStylizeOutputWindow::OneLine(Printable(message));
  return message.empty() ? vtkStylizeOutputWindow::OneLine(Printable(raw)) : message;
}

bool SaysError(const std::string& text)
{
  std::string lower = text;
  std::transform(lower.begin(), lower.end(), lower.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower.find("error") != std::string::npos;
}
} // namespace

void vtkStylizeOutputWindow::DisplayText(const char* text)
{
  this->Record(text, TEXT_MESSAGE);
}

void vtkStylizeOutputWindow::DisplayErrorText(const char* text)
{
  this->Record(text, ERROR_MESSAGE);
}

void vtkStylizeOutputWindow::DisplayWarningText(const char* text)
{
  this->Record(text, WARNING_MESSAGE);
}

void vtkStylizeOutputWindow::DisplayGenericWarningText(const char* text)
{
  this->Record(text, WARNING_MESSAGE);
}

void vtkStylizeOutputWindow::DisplayDebugText(const char* text)
{
  this->Record(text, TEXT_MESSAGE);
}

void vtkStylizeOutputWindow::Record(const char* text, MessageKind kind)
{
  const std::string s = text ? text : "";
  this->Messages.push_back({ kind, s });
  if (this->EchoDescriptor >= 0 && !s.empty())
  {
    ssize_t ignored = ::write(this->EchoDescriptor, s.data(), s.size());
    (void)ignored;
  }
}

void vtkStylizeOutputWindow::ClearMessages()
{
  this->Messages.clear();
}

bool vtkStylizeOutputWindow::HasFailure() const
{
  return std::any_of(this->Messages.begin(), this->Messages.end(),
    [](const Message& m)
    { return m.Kind == ERROR_MESSAGE || (m.Kind == WARNING_MESSAGE && SaysError(m.Text)); });
}

std::string vtkStylizeOutputWindow::GetFirstFailure() const
{
  const Message* pipeline = nullptr;
  for (const Message& m : this->Messages)
  {
    if (!(m.Kind == ERROR_MESSAGE || (m.Kind == WARNING_MESSAGE && SaysError(m.Text))))
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

std::string vtkStylizeOutputWindow::OneLine(const std::string& text, std::size_t maxLength)
{
  std::string out;
  bool space = false;
  for (std::size_t i = 0; i < text.size(); ++i)
  {
    const auto c = static_cast<unsigned char>(text[i]);
    if (std::isspace(c))
    {
      space = !out.empty();
      continue;
    }
    if (space)
    {
      out += ' ';
      space = false;
    }
    // A well-formed UTF-8 sequence of a printable character (a file name) is kept; a control
    // character (C0, DEL, C1) or a byte of anything else (garbage a reader quoted from a file:
    // overlong forms, surrogates, code points past U+10FFFF) becomes '?'.
    const std::size_t length = c < 0x80 ? 1
      : (c >> 5) == 0x6                 ? 2
      : (c >> 4) == 0xE                 ? 3
      : (c >> 3) == 0x1E                ? 4
                                        : 0;
    bool valid = length > 0 && i + length <= text.size();
    unsigned long code = length == 1 ? c
      : length == 2                  ? (c & 0x1Fu)
      : length == 3                  ? (c & 0x0Fu)
                                     : (c & 0x07u);
    for (std::size_t k = 1; valid && k < length; ++k)
    {
      const auto next = static_cast<unsigned char>(text[i + k]);
      valid = (next >> 6) == 0x2;
      code = (code << 6) | (next & 0x3Fu);
    }
    static const unsigned long smallest[5] = { 0, 0, 0x80, 0x800, 0x10000 };
    valid = valid && code >= smallest[length] && code <= 0x10FFFF &&
      !(code >= 0xD800 && code <= 0xDFFF) && code >= 32 && !(code >= 0x7F && code <= 0x9F);
    if (!valid)
    {
      out += '?';
      continue;
    }
    out.append(text, i, length);
    i += length - 1;
  }
  if (maxLength >= 3 && out.size() > maxLength)
  {
    std::size_t cut = maxLength - 3;
    while (cut > 0 && (static_cast<unsigned char>(out[cut]) >> 6) == 0x2)
    {
      --cut; // (not inside a UTF-8 sequence)
    }
    out = out.substr(0, cut) + "...";
  }
  return out;
}

void vtkStylizeOutputWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "EchoDescriptor: " << this->EchoDescriptor << "\n";
  os << indent << "Messages: " << this->Messages.size() << "\n";
}

//------------------------------------------------------------------------------
void vtkStylizeOutputWindow::ReportSanitizersTo(int fd)
{
  dl_iterate_phdr(
    [](dl_phdr_info* info, size_t, void* data) -> int
    {
      const std::string name = info->dlpi_name ? info->dlpi_name : "";
      if (name.find("libasan") != std::string::npos || name.find("libubsan") != std::string::npos)
      {
        if (void* library = ::dlopen(name.c_str(), RTLD_LAZY | RTLD_NOLOAD))
        {
          using SetReportFd = void (*)(void*);
          if (auto set =
                reinterpret_cast<SetReportFd>(::dlsym(library, "__sanitizer_set_report_fd")))
          {
            set(reinterpret_cast<void*>(static_cast<std::intptr_t>(*static_cast<int*>(data))));
          }
          ::dlclose(library);
        }
      }
      return 0;
    },
    &fd);
}
