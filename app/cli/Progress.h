// Progress.h -- progress on stderr when it is a terminal, and Ctrl-C as a request to stop cleanly.
#pragma once
#include "dynamics/tools/ToolControl.h"

#include <chrono>
#include <string>

namespace rv {

/// Installs a SIGINT handler that only sets a flag; long loops poll interrupted().
void installInterruptHandler();
bool interrupted();

/// Prints "label: 42%" on stderr at most a few times a second, only when stderr is a terminal.
class Progress {
public:
  explicit Progress(std::string label);
  ~Progress();
  void update(double fraction);
  /// The same with a note after the percentage (e.g. "1200/3000 points, ETA 1m20s").
  void update(double fraction, const std::string& detail);

private:
  std::string label_;
  bool tty_;
  int last_ = -1;
  std::chrono::steady_clock::time_point shown_{};
};

/// Stops on Ctrl-C and reports into `progress` (which must outlive the control).
ToolControl interruptibleControl(Progress& progress);

} // namespace rv
