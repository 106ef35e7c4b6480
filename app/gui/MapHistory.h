// MapHistory.h -- Edit > Undo and Redo of the map window: the steps a destructive action leaves (a replaced
// map kept whole as a session -- its scene, trajectories going on where they stood, tool outputs, the user's
// zoom -- or trajectories and tool outputs deleted), newest last, at most kSteps of them. A new change
// forgets what was undone; Redo puts back the map as it stood before the last Undo. The main window makes the
// steps and puts them to use (MainWindowSession.cpp); this class only keeps them in order.
#pragma once
#include "scenes/Session.h"

#include <QString>
#include <functional>
#include <optional>
#include <vector>

namespace rv {

class MapHistory {
public:
  /// What one step brings back.
  struct Step {
    QString what;               ///< in words, after "Undo " in the menu
    std::optional<Session> map; ///< a replaced map (its scene and every trajectory)
    std::vector<SavedTrajectory> deleted;
    std::vector<SavedToolOutput> deletedTools;
  };
  static constexpr std::size_t kSteps = 20;

  /// `changed` is called after every change (the menu's actions show what Undo and Redo would do).
  explicit MapHistory(std::function<void()> changed = {}) : changed_(std::move(changed)) {}
  /// A new destructive change: its step is kept for Undo, the redo steps are forgotten.
  void push(Step step);
  /// The newest Undo step, taken off (nothing when there is none).
  std::optional<Step> takeUndo();
  /// The newest Redo step, taken off (nothing when there is none).
  std::optional<Step> takeRedo();
  /// After an Undo of `what`: the map as it stood before it, for Redo.
  void undone(const QString& what, Session before);
  /// After a Redo of `what`: the map as it stood before it, for Undo (the other redo steps stay).
  void redone(const QString& what, Session before);
  /// What Undo / Redo would bring back, in words ("" when nothing).
  QString undoText() const { return undo_.empty() ? QString() : undo_.back().what; }
  QString redoText() const { return redo_.empty() ? QString() : redo_.back().what; }

private:
  void keepForUndo(Step step);
  void tell() const {
    if (changed_) changed_();
  }
  std::function<void()> changed_;
  std::vector<Step> undo_;
  std::vector<Step> redo_; ///< each the whole map before an undo, newest last
};

} // namespace rv
