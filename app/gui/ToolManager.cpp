#include "app/gui/ToolManager.h"

#include "app/gui/ChartWindow.h"

#include "dynamics/jobs/JobTree.h"

#include <QColorDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QIcon>
#include <QInputDialog>
#include <QLineEdit>
#include <QMessageBox>
#include <QPixmap>
#include <QPushButton>
#include <QTimer>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <map>

namespace rv {

ToolManager::ToolManager(JobTree& jobs, std::function<void(Job&)> remove, QWidget* parent)
    : QWidget(parent), jobs_(jobs), remove_(std::move(remove)) {
  auto* layout = new QVBoxLayout(this);
  tree_ = new QTreeWidget(this);
  tree_->setHeaderLabels({"#", "tool", "status", "progress", "start", "method and problem"});
  tree_->header()->setStretchLastSection(true);
  tree_->setColumnWidth(0, 60);
  tree_->setColumnWidth(1, 150);
  tree_->setColumnWidth(4, 170);
  layout->addWidget(tree_, 1);
  auto* buttons = new QHBoxLayout;
  const auto add = [&](const char* text, const char* tip) {
    auto* b = new QPushButton(text, this);
    b->setToolTip(tip);
    b->setObjectName(QString(text).toLower());
    buttons->addWidget(b);
    buttons_[b->objectName()] = {b, tip};
    return b;
  };
  const auto button = [&](const char* text, const char* tip, void (ToolManager::*slot)()) {
    connect(add(text, tip), &QPushButton::clicked, this, slot);
  };
  button("Stop", "stop the selected tool (it can continue later)", &ToolManager::stopSelected);
  button("Start",
         "start the selected tool, or continue it from where it stopped; a finished trajectory of the map "
         "goes on for as many points again (the control panel's poincare.points)",
         &ToolManager::continueSelected);
  button("Restart", "start the selected tool again from the beginning", &ToolManager::restartSelected);
  button(
      "Edit",
      "give the selected (stopped) tool the control panel's values (problem, method, its settings); Start "
      "then goes on with them: a map or fixed-point search from its stop point, a continuation, separatrix "
      "or bifurcation tree from its beginning",
      &ToolManager::editSelected);
  connect(add("Delete", "stop and delete the selected tool and the tools under it (asks first)"),
          &QPushButton::clicked, this, [this] {
            if (confirmDelete()) deleteSelected();
          });
  button("Find parent", "select the tool the selected one studies", &ToolManager::selectParent);
  connect(add("Colour…", "the colour of the selected trajectory's points"), &QPushButton::clicked, this,
          [this] { colourSelected(); });
  connect(
      add("Set range…", "which of the selected trajectory's points show (from the first-th to the last-th)"),
      &QPushButton::clicked, this, [this] { rangeSelected(); });
  button("Stop all", "stop every tool", &ToolManager::stopAll);
  connect(
      add("Delete all", "stop and delete every tool (asks first; Edit > Undo brings the trajectories back)"),
      &QPushButton::clicked, this, [this] {
        if (QMessageBox::question(this, "Delete all",
                                  QString("Delete all %1 tools? Edit > Undo brings the trajectories back.")
                                      .arg(jobs_.jobs().size()),
                                  QMessageBox::Yes | QMessageBox::No, QMessageBox::No) == QMessageBox::Yes)
          deleteAll();
      });
  layout->addLayout(buttons);
  connect(tree_, &QTreeWidget::currentItemChanged, this, [this] {
    const Job* j = selected();
    updateButtons();
    emit selectedJob(j ? j->id() : -1);
  });
  timer_ = new QTimer(this);
  connect(timer_, &QTimer::timeout, this, &ToolManager::refresh);
  timer_->start(250);
}

void ToolManager::refresh() {
  const int keep = selected() ? selected()->id() : -1;
  // the tree's items follow the jobs: rebuilt when the set changes, texts updated otherwise
  std::map<int, QTreeWidgetItem*> items;
  for (int i = 0; i < tree_->topLevelItemCount(); ++i) {
    std::vector<QTreeWidgetItem*> stack{tree_->topLevelItem(i)};
    while (!stack.empty()) {
      QTreeWidgetItem* it = stack.back();
      stack.pop_back();
      items[it->data(0, Qt::UserRole).toInt()] = it;
      for (int c = 0; c < it->childCount(); ++c)
        stack.push_back(it->child(c));
    }
  }
  const std::vector<Job*> jobs = jobs_.jobs();
  bool same = items.size() == jobs.size();
  for (Job* j : jobs)
    same = same && items.count(j->id());
  if (!same) {
    tree_->clear();
    items.clear();
    for (Job* j : jobs) { // parents come before their children
      auto* it = j->parent() && items.count(j->parent()->id()) ? new QTreeWidgetItem(items[j->parent()->id()])
                                                               : new QTreeWidgetItem(tree_);
      it->setData(0, Qt::UserRole, j->id());
      items[j->id()] = it;
    }
    tree_->expandAll();
  }
  for (Job* j : jobs) {
    QTreeWidgetItem* it = items[j->id()];
    it->setText(0, QString::number(j->id()));
    it->setText(1, QString::fromStdString(j->task().name()));
    QString status = statusName(j->status());
    if (j->status() == Job::Status::Failed) {
      const QString why = inGuiWords(j->error());
      status += ": " + why;
      // every outcome reaches the Results dock, a failure with why (a record's was said when it failed)
      if (failuresSaid_.insert(j->id()).second && !j->task().isRecord())
        emit message(QString("tool %1 (%2) failed: %3")
                         .arg(j->id())
                         .arg(QString::fromStdString(j->task().name()), why));
    } else {
      failuresSaid_.erase(j->id());
    }
    it->setText(2, status);
    it->setToolTip(2, status); // whole, where the column cuts it
    it->setText(3, QString("%1%").arg(static_cast<int>(100 * j->progress())));
    const QString description = QString::fromStdString(j->task().describe()); // their fixed settings
    it->setText(5, description);
    it->setToolTip(5, description); // whole, where the column cuts it
    const RowLook look = look_ ? look_(j->id()) : RowLook{};
    it->setText(4, look.start);
    if (look.colour) { // the swatch of the colour its output is drawn in
      const Rgb& c = *look.colour;
      QPixmap swatch(12, 12);
      swatch.fill(
          QColor::fromRgbF(static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])));
      it->setIcon(1, QIcon(swatch));
    } else {
      it->setIcon(1, QIcon());
    }
    const QBrush ink = j->running() ? QBrush(QColor(200, 20, 20)) : QBrush(); // manual §2.1: running in red
    for (int c = 0; c < tree_->columnCount(); ++c)
      it->setForeground(c, ink);
  }
  if (keep >= 0) select(keep);
  updateButtons();
}

void ToolManager::updateButtons() {
  const Job* j = selected();
  const std::vector<Job*> all = jobs_.jobs();
  const bool any = !all.empty();
  const bool anyRunning = std::any_of(all.begin(), all.end(), [](const Job* k) { return k->running(); });
  const bool running = j && j->running(), finished = j && j->status() == Job::Status::Finished;
  const bool drawsPoints = j && look_ && look_(j->id()).colour; // a colour: a trajectory of the map
  const auto enable = [&](const char* name, bool on, const char* whyNot) {
    auto& [b, tip] = buttons_.at(name);
    b->setEnabled(on);
    b->setToolTip(on ? tip : tip + "\n(now: " + whyNot + ")");
  };
  const char* none = "select a tool first";
  enable("stop", running, j ? "the tool is not running" : none);
  const bool more = finished && more_ && drawsPoints; // a finished trajectory goes on (more_ says if it can)
  enable("start", j && !running && (!finished || more),
         !j        ? none
         : running ? "it runs"
                   : "it has finished: Restart");
  enable("restart", j != nullptr, none);
  enable("edit", j && !running && editor_, !j ? none : "stop the tool first");
  enable("delete", j != nullptr, none);
  enable("find parent", j && j->parent(), j ? "the tool has no parent" : none);
  enable("colour…", drawsPoints, j ? "only a trajectory of the map has a colour" : none);
  enable("set range…", drawsPoints, j ? "only a trajectory of the map has a range of points" : none);
  enable("stop all", anyRunning, "no tool runs");
  enable("delete all", any, "no tools");
}

bool ToolManager::confirmDelete() {
  Job* j = selected();
  if (!j) return false;
  const std::size_t under = jobs_.subtree(*j).size() - 1;
  QString text = QString("Delete tool %1 (%2)").arg(j->id()).arg(QString::fromStdString(j->task().name()));
  if (under > 0) text += QString(" and the %1 tool%2 under it").arg(under).arg(under > 1 ? "s" : "");
  text += "? What it computed and drew goes with it.";
  return QMessageBox::question(this, "Delete tool", text, QMessageBox::Yes | QMessageBox::No,
                               QMessageBox::No) == QMessageBox::Yes;
}

Job* ToolManager::selected() const {
  const QTreeWidgetItem* it = tree_->currentItem();
  return it ? jobs_.find(it->data(0, Qt::UserRole).toInt()) : nullptr;
}

void ToolManager::select(int id) {
  for (QTreeWidgetItemIterator it(tree_); *it; ++it)
    if ((*it)->data(0, Qt::UserRole).toInt() == id) tree_->setCurrentItem(*it);
}

void ToolManager::stopSelected() {
  if (Job* j = selected()) j->stop();
  refresh();
}

void ToolManager::continueSelected() {
  if (Job* j = selected()) {
    if (j->status() == Job::Status::Finished && more_)
      more_(j->id());
    else
      j->start();
  }
  refresh();
}

void ToolManager::restartSelected() {
  if (Job* j = selected()) {
    j->restart();
    emit restarted(j->id());
  }
  refresh();
}

void ToolManager::deleteSelected() {
  if (Job* j = selected()) {
    emit aboutToDelete({j->id()});
    remove_(*j);
  }
  refresh();
}

void ToolManager::editSelected() {
  Job* job = selected();
  if (!job || !editor_) return;
  if (job->running()) {
    emit message("stop the tool before editing it");
    return;
  }
  try {
    editor_(*job);
    emit message(QString("tool %1 edited: Start goes on with the new values").arg(job->id()));
  } catch (const std::exception& e) {
    emit message(QString("cannot edit tool %1: %2").arg(job->id()).arg(e.what()));
  }
  refresh();
}

void ToolManager::stopAll() {
  for (Job* j : jobs_.jobs())
    j->stop();
  refresh();
}

void ToolManager::deleteAll() {
  std::vector<int> roots;
  for (const Job* j : jobs_.jobs())
    if (!j->parent()) roots.push_back(j->id());
  if (!roots.empty()) emit aboutToDelete(roots);
  for (Job* j : jobs_.jobs()) // parents first: deleting one takes its children with it
    if (jobs_.find(j->id()) == j && !j->parent()) remove_(*j);
  refresh();
}

void ToolManager::selectParent() {
  if (Job* j = selected(); j && j->parent()) select(j->parent()->id());
}

void ToolManager::colourSelected(std::optional<Rgb> colour) {
  Job* j = selected();
  if (!j || !colour_) return;
  if (!colour) {
    // the dialog starts at the colour the trajectory has now
    const auto now = look_ ? look_(j->id()).colour : std::nullopt;
    const QColor start = now ? QColor::fromRgbF(static_cast<float>((*now)[0]), static_cast<float>((*now)[1]),
                                                static_cast<float>((*now)[2]))
                             : QColor(Qt::blue);
    const QColor c = QColorDialog::getColor(start, this, "Colour of output");
    if (!c.isValid()) return;
    colour = Rgb{c.redF(), c.greenF(), c.blueF()};
  }
  if (!colour_(j->id(), *colour)) emit message("only trajectories of the map can be recoloured");
}

void ToolManager::rangeSelected(std::optional<long> first, long last) {
  Job* j = selected();
  if (!j || !range_) return;
  if (!first) {
    bool ok = false;
    const QString text =
        QInputDialog::getText(this, "Set range", "points to show, FIRST-LAST (LAST empty: to the end)",
                              QLineEdit::Normal, "1-", &ok);
    if (!ok) return;
    const QStringList parts = text.split('-');
    first = parts.value(0).trimmed().toLong();
    last = parts.value(1).trimmed().toLong();
    if (*first < 1 || (last > 0 && last < *first)) {
      emit message("Set range: give FIRST-LAST with 1 <= FIRST <= LAST, e.g. 100-500 or 100-");
      return;
    }
  }
  if (!range_(j->id(), *first, last)) emit message("only trajectories of the map have a range of points");
}

} // namespace rv
