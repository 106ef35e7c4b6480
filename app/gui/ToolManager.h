// ToolManager.h -- the tool manager (manual §2.1): every running tool instance as a tree (tools under the
// trajectory they study), with its status, progress, where it starts (a trajectory's colour swatch and start
// point) and technical description; stop, continue, restart and delete act on the selected instance, and a
// button is enabled only when its action applies (its tooltip says why not). Delete asks first. It only reads
// the jobs' atomic state: the GUI thread never waits on one except to stop it.
#pragma once
#include "render/ViewOptions.h"
#include <QString>
#include <QWidget>

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <vector>

class QPushButton;
class QTreeWidget;
class QTimer;

namespace rv {

class JobTree;
class Job;

class ToolManager : public QWidget {
  Q_OBJECT
public:
  /// `remove` deletes a job for its owner (which drops what it draws of it first).
  ToolManager(JobTree& jobs, std::function<void(Job&)> remove, QWidget* parent = nullptr);
  /// Rebuilds the tree from the jobs (called by a timer; public for tests).
  void refresh();
  /// The selected job, or nullptr.
  Job* selected() const;
  /// Selects the job with this id (for tests).
  void select(int id);
  void stopSelected();
  void continueSelected();
  void restartSelected();
  /// Deletes the selected job (and those under it) without asking; the Delete button asks first.
  void deleteSelected();
  /// Delete's question: true when the user confirms deleting the selected job (and how many under it).
  bool confirmDelete();
  /// Edit properties (manual §2.1): gives the selected job, which must be stopped, the control panel's
  /// values through `editor` (set by the owner); it then continues from its stop point with them.
  void editSelected();
  void stopAll();
  void deleteAll();
  /// Selects the tool the selected one hangs under (manual: Find parent).
  void selectParent();
  void setEditor(std::function<void(Job&)> editor) { editor_ = std::move(editor); }
  /// Start on a finished trajectory of the map: `more(id)` makes it go on (set by the owner; false when it
  /// cannot).
  void setMore(std::function<bool(int)> more) { more_ = std::move(more); }
  /// Colour of output and Set range act on the selected job through these (set by the owner; they return
  /// false when the job has no such output).
  void setOutputActions(std::function<bool(int, const Rgb&)> colour,
                        std::function<bool(int, long, long)> range) {
    colour_ = std::move(colour), range_ = std::move(range);
  }
  /// What a row shows of a job beside its description: where it starts (empty: nothing) and the colour its
  /// output is drawn in (none: no swatch); set by the owner, which knows what it draws.
  struct RowLook {
    QString start;
    std::optional<Rgb> colour;
  };
  void setRowLook(std::function<RowLook(int)> look) { look_ = std::move(look); }
  /// Enables the buttons that apply to the selected job (called on each refresh and selection change).
  void updateButtons();
  /// Colour of output for the selected job (a colour dialog unless `color` is given).
  void colourSelected(std::optional<Rgb> colour = std::nullopt);
  /// Set range for the selected job (a dialog unless `first` is given; last <= 0: to the end).
  void rangeSelected(std::optional<long> first = std::nullopt, long last = 0);

signals:
  /// Why an action could not be done, for the status bar.
  void message(const QString& text);
  /// The selection changed: the job's id (-1: none), so that every window highlights its graphics.
  void selectedJob(int id);
  /// A job was restarted: what it drew goes.
  void restarted(int id);
  /// Jobs `ids` (with those under them) are about to be deleted by Delete or Delete all (Undo keeps them).
  void aboutToDelete(const std::vector<int>& ids);

public:
  QTreeWidget* tree() const { return tree_; }

private:
  JobTree& jobs_;
  std::function<void(Job&)> remove_;
  std::function<void(Job&)> editor_;
  std::function<bool(int)> more_;
  std::function<bool(int, const Rgb&)> colour_;
  std::function<bool(int, long, long)> range_;
  std::function<RowLook(int)> look_;
  QTreeWidget* tree_;
  /// the buttons by object name, with their tooltips when enabled
  std::map<QString, std::pair<QPushButton*, QString>> buttons_;
  QTimer* timer_;
  std::set<int> failuresSaid_; ///< failed jobs whose reason went to the Results dock (once per failure)
};

} // namespace rv
