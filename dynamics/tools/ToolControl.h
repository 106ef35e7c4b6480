// ToolControl.h -- how a running tool learns that it should stop, reports how far it got, and hands on what
// it computes as it goes to a front end that draws it meanwhile (the GUI's map window draws a family's points
// as they are found).
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace rv {

/// A row of what a run computes, handed on as it is computed: its columns' names and numbers, and its text
/// columns' (a fixed point's type).
struct StreamedRow {
  std::vector<std::string> names;
  std::vector<double> values;
  std::vector<std::string> textNames, text;
};

struct ToolControl {
  std::function<bool()> stopRequested = [] { return false; }; ///< polled often (at least once per step)
  std::function<void(double)> progress = [](double) {};       ///< fraction done in [0, 1]
  /// Each row as the run computes it -- its table's rows, or points it draws before their table is known (a
  /// separatrix's, level by level); called on the run's thread. Empty: nobody listens.
  std::function<void(const StreamedRow&)> row = {};
  /// Each note the run says (ToolResult::notes), as it says it. Empty: nobody listens.
  std::function<void(const std::string&)> note = {};
};

} // namespace rv
