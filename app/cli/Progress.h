// Progress.h -- progress on stderr when it is a terminal, and Ctrl-C as a request to stop cleanly.
#pragma once
#include "dynamics/tools/ToolControl.h"

#include <chrono>
#include <mutex>
#include <string>

namespace rv {

/// Installs a SIGINT handler that only sets a flag; long loops poll interrupted().
void installInterruptHandler();
bool interrupted();

/// Whether standard output is a terminal (a command that prints as it goes there shows no progress line:
/// the two would share one line).
bool stdoutIsTerminal();

/// One updating line "label: 42%" on stderr, at most a few times a second, only when stderr is a terminal
/// (and `show`); erased by clear() and at the end. update() may be called from several threads.
class Progress {
public:
  explicit Progress(std::string label, bool show = true);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  void update(double fraction);
  /// The same with a note after the percentage (e.g. "1200/3000 points, ETA 1m20s").
  void update(double fraction, const std::string& detail);
  /// Erases the line, before anything else is printed on the terminal; a later update() shows it again.
  void clear();

private:
  std::string label_;
  bool tty_;
  std::mutex mutex_;
  bool shown_ = false; // the line is on the terminal now
  int last_ = -1;
  std::chrono::steady_clock::time_point at_{};
};

/// Stops on Ctrl-C and reports into `progress` (which must outlive the control).
ToolControl interruptibleControl(Progress& progress);

} // namespace rv
