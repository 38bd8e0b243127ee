/**
 * @class   vtkStylizeOutputWindow
 * @brief   An output window that records VTK's messages instead of printing them.
 *
 * Installed with vtkOutputWindow::SetInstance(), it keeps every error, warning and text VTK
 * reports, so that a program can turn the first relevant one into a single line of its own
 * (VTK's messages span several lines and name source files and object addresses).
 * vtkStylizeReader installs one while it reads; the vtkstylize command installs one for its
 * whole run.
 *
 * A failure is an error, or a warning that says "error" (vtkDataReader reports truncated legacy
 * files with warnings such as "Error reading binary data!"). The executive's "Algorithm X
 * returned failure for request" only repeats that an algorithm failed: the algorithm's own
 * message, when there is one, is the one GetFirstFailure() returns.
 *
 * The window is process-wide, like vtkOutputWindow's instance: messages from every thread go to
 * it.
 */

#ifndef vtkStylizeOutputWindow_h
#define vtkStylizeOutputWindow_h

#include "vtkOutputWindow.h"
#include "vtkStylizeIOModule.h" // for export macro

#include <string> // for std::string
#include <vector> // for std::vector

class VTKSTYLIZEIO_EXPORT vtkStylizeOutputWindow : public vtkOutputWindow
{
public:
  static vtkStylizeOutputWindow* New();
  vtkTypeMacro(vtkStylizeOutputWindow, vtkOutputWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void DisplayText(const char* text) override;
  void DisplayErrorText(const char* text) override;
  void DisplayWarningText(const char* text) override;
  void DisplayGenericWarningText(const char* text) override;
  void DisplayDebugText(const char* text) override;

  /** Forgets the messages recorded so far. */
  void ClearMessages();

  /** The number of messages recorded since the last ClearMessages(). */
  int GetNumberOfMessages() const { return static_cast<int>(this->Messages.size()); }

  /** Whether a failure (see the class description) was recorded. */
  bool HasFailure() const;

  /**
   * The most telling failure reduced to one line of at most 240 characters, without the
   * "ERROR_MESSAGE: In file, line N" line and the "vtkClass (0x...): " prefix, bytes that are not
   * printable ASCII shown as '?'; "vtkXReader failed" when only the executive's message says
   * so; empty without a failure.
   */
  std::string GetFirstFailure() const;

  ///@{
  /**
   * A file descriptor every message is also written to as it arrives (2: standard error), or -1
   * (the default) to keep them silent.
   */
  vtkSetMacro(EchoDescriptor, int);
  vtkGetMacro(EchoDescriptor, int);
  ///@}

  /**
   * Collapses white-space runs (newlines included) to single spaces, replaces control
   * characters and bytes that are not well-formed UTF-8 (garbage a reader quoted from a file)
   * with '?', and cuts the text to maxLength bytes (the last three "..." when cut).
   */
  static std::string OneLine(const std::string& text, std::size_t maxLength = 240);

  /**
   * Sends the reports of every sanitizer runtime loaded in the process (AddressSanitizer's and
   * UndefinedBehaviorSanitizer's each have their own) to the descriptor fd; nothing without
   * them.
   */
  static void ReportSanitizersTo(int fd);

protected:
  vtkStylizeOutputWindow() = default;
  ~vtkStylizeOutputWindow() override = default;

  enum MessageKind
  {
    TEXT_MESSAGE,
    WARNING_MESSAGE,
    ERROR_MESSAGE
  };
  void Record(const char* text, MessageKind kind);

  int EchoDescriptor = -1;
  struct Message
  {
    MessageKind Kind;
    std::string Text;
  };
  std::vector<Message> Messages;

private:
  vtkStylizeOutputWindow(const vtkStylizeOutputWindow&) = delete;
  void operator=(const vtkStylizeOutputWindow&) = delete;
};

#endif
