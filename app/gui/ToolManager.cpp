#include "app/gui/ToolManager.h"

#include "dynamics/jobs/JobTree.h"

#include <QColorDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLineEdit>
#include <QPushButton>
#include <QTimer>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <map>

namespace rv {

ToolManager::ToolManager(JobTree& jobs, std::function<void(Job&)> remove, QWidget* parent)
    : QWidget(parent), jobs_(jobs), remove_(std::move(remove)) {
  auto* layout = new QVBoxLayout(this);
  tree_ = new QTreeWidget(this);
  tree_->setHeaderLabels({"#", "tool", "status", "progress", "method and problem"});
  tree_->header()->setStretchLastSection(true);
  layout->addWidget(tree_, 1);
  auto* buttons = new QHBoxLayout;
  const auto button = [&](const char* text, const char* tip, void (ToolManager::*slot)()) {
    auto* b = new QPushButton(text, this);
    b->setToolTip(tip);
    b->setObjectName(QString(text).toLower());
    connect(b, &QPushButton::clicked, this, slot);
    buttons->addWidget(b);
  };
  button("Stop", "stop the selected tool (it can continue later)", &ToolManager::stopSelected);
  button("Start", "start the selected tool, or continue it from where it stopped",
         &ToolManager::continueSelected);
  button("Restart", "start the selected tool again from the beginning", &ToolManager::restartSelected);
  button(
      "Edit",
      "give the selected (stopped) tool the control panel's values (problem, method, its settings); Start "
      "then goes on with them: a map or fixed-point search from its stop point, a continuation, separatrix "
      "or bifurcation tree from its beginning",
      &ToolManager::editSelected);
  button("Delete", "stop and delete the selected tool and the tools under it", &ToolManager::deleteSelected);
  button("Find parent", "select the tool the selected one studies", &ToolManager::selectParent);
  auto* colour = new QPushButton("Colour…", this);
  colour->setToolTip("the colour of the selected trajectory's points");
  connect(colour, &QPushButton::clicked, this, [this] { colourSelected(); });
  buttons->addWidget(colour);
  auto* range = new QPushButton("Set range…", this);
  range->setToolTip("which of the selected trajectory's points show (from the first-th to the last-th)");
  connect(range, &QPushButton::clicked, this, [this] { rangeSelected(); });
  buttons->addWidget(range);
  button("Stop all", "stop every tool", &ToolManager::stopAll);
  button("Delete all", "stop and delete every tool", &ToolManager::deleteAll);
  layout->addLayout(buttons);
  connect(tree_, &QTreeWidget::currentItemChanged, this, [this] {
    const Job* j = selected();
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
    QString status = toString(j->status());
    if (j->status() == Job::Status::Failed) status += ": " + QString::fromStdString(j->error());
    it->setText(2, status);
    it->setText(3, QString("%1%").arg(static_cast<int>(100 * j->progress())));
    it->setText(4, QString::fromStdString(j->task().describe())); // the tasks describe their fixed settings
    const QBrush ink = j->running() ? QBrush(QColor(200, 20, 20)) : QBrush(); // manual §2.1: running in red
    for (int c = 0; c < tree_->columnCount(); ++c)
      it->setForeground(c, ink);
  }
  if (keep >= 0) select(keep);
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
  if (Job* j = selected()) j->start();
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
  if (Job* j = selected()) remove_(*j);
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
  for (Job* j : jobs_.jobs()) // parents first: deleting one takes its children with it
    if (jobs_.find(j->id()) == j && !j->parent()) remove_(*j);
  refresh();
}

void ToolManager::selectParent() {
  if (Job* j = selected(); j && j->parent()) select(j->parent()->id());
}

void ToolManager::colourSelected(std::optional<Rgb> color) {
  Job* j = selected();
  if (!j || !colour_) return;
  if (!color) {
    const QColor c = QColorDialog::getColor(Qt::blue, this, "Colour of output");
    if (!c.isValid()) return;
    color = Rgb{c.redF(), c.greenF(), c.blueF()};
  }
  if (!colour_(j->id(), *color)) emit message("only trajectories of the map can be recoloured");
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
