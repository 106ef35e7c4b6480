// MapHistory.cpp -- the Undo and Redo steps of the map window, in order and bounded.
#include "app/gui/MapHistory.h"

namespace rv {

void MapHistory::keepForUndo(Step step) {
  undo_.push_back(std::move(step));
  if (undo_.size() > kSteps) undo_.erase(undo_.begin());
}

void MapHistory::push(Step step) {
  keepForUndo(std::move(step));
  redo_.clear(); // a new change: what was undone stays undone
  tell();
}

std::optional<MapHistory::Step> MapHistory::takeUndo() {
  if (undo_.empty()) return std::nullopt;
  Step step = std::move(undo_.back());
  undo_.pop_back();
  tell();
  return step;
}

std::optional<MapHistory::Step> MapHistory::takeRedo() {
  if (redo_.empty()) return std::nullopt;
  Step step = std::move(redo_.back());
  redo_.pop_back();
  tell();
  return step;
}

void MapHistory::undone(const QString& what, Session before) {
  redo_.push_back({what, std::move(before), {}, {}});
  tell();
}

void MapHistory::redone(const QString& what, Session before) {
  keepForUndo({what, std::move(before), {}, {}});
  tell();
}

} // namespace rv
