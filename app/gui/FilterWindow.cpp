#include "app/gui/FilterWindow.h"

#include "app/gui/QtVtkWidget.h"
#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"
#include "render/export/Figure.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QStackedWidget>
#include <QVBoxLayout>
#include <fstream>

namespace rv {

namespace {
/// A save dialog for a figure (and `extra` filters): the name gets the chosen filter's extension when it has
/// none of its own.
QString askFigurePath(QWidget* parent, const QString& title, const QString& name, const QString& extra) {
  QString filters = "PNG picture (*.png);;SVG vector figure (*.svg);;PDF vector figure (*.pdf)";
  if (!extra.isEmpty()) filters += ";;" + extra;
  QString chosen;
  QString path = QFileDialog::getSaveFileName(
      parent, title, proposedPath(QStandardPaths::PicturesLocation, name + ".png"), filters, &chosen);
  if (path.isEmpty() || !QFileInfo(path).suffix().isEmpty()) return path;
  const auto star = chosen.indexOf("*."), close = chosen.indexOf(')', star);
  return star < 0 ? path : path + chosen.mid(star + 1, close - star - 1);
}
} // namespace

FilterWindow::FilterWindow(const QString& title, const QString& fileName, QWidget* parent)
    : QWidget(parent, Qt::Window), fileName_(fileName) {
  setWindowTitle("rollviz — " + title);
  view_ = new QtVtkWidget(this);
  placeholder_ = new QLabel(this);
  placeholder_->setObjectName("placeholder");
  placeholder_->setAlignment(Qt::AlignCenter);
  placeholder_->setWordWrap(true);
  placeholder_->setMargin(24);
  placeholder_->setStyleSheet("background: white; color: #555; font-size: 15pt");
  stack_ = new QStackedWidget(this);
  stack_->addWidget(view_);
  stack_->addWidget(placeholder_);
  status_ = new QLabel(this);
  status_->setWordWrap(true);
  status_->setTextInteractionFlags(Qt::TextSelectableByMouse); // a result or a reason can be copied
  auto* save = save_ = new QPushButton("Save figure…", this);
  save->setObjectName("save_figure");
  save->setToolTip("PNG (the pixels), or SVG or PDF (vectors, text as text: for papers)");
  connect(save, &QPushButton::clicked, this, [this] {
    const QString path = askFigurePath(this, "Save chart", fileName_, {});
    if (!path.isEmpty()) saveFigure(path);
  });
  auto* csv = csv_ = new QPushButton("Save CSV…", this);
  csv->setObjectName("save_csv");
  connect(csv, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(
        this, "Save chart data", proposedPath(QStandardPaths::DocumentsLocation, fileName_ + ".csv"),
        "CSV (*.csv)");
    if (!path.isEmpty() && !saveCsv(path)) setStatus("cannot write " + path);
  });
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(stack_, 1);
  bar_ = new QHBoxLayout;
  bar_->addWidget(status_, 1);
  bar_->addWidget(save);
  bar_->addWidget(csv);
  layout->addLayout(bar_);
  resize(640, 640);
}

void FilterWindow::addProgress(const QString& stopText, const QString& stopTip,
                               const std::function<void()>& stop) {
  progressBar_ = new QProgressBar(this);
  progressBar_->setRange(0, 1000);
  progressBar_->setTextVisible(false);
  stop_ = new QPushButton(stopText, this);
  stop_->setToolTip(stopTip);
  connect(stop_, &QPushButton::clicked, this, stop);
  bar_->insertWidget(1, progressBar_);
  bar_->insertWidget(2, stop_);
}

void FilterWindow::showProgress(bool running, double fraction) {
  if (!progressBar_) return;
  progressBar_->setVisible(running);
  stop_->setVisible(running);
  stop_->setEnabled(running);
  if (running) progressBar_->setValue(static_cast<int>(1000 * fraction));
}

void FilterWindow::setStatus(const QString& text) {
  status_->setText(text);
}

QString FilterWindow::status() const {
  return status_->text();
}

bool saveChartCsv(const Chart& chart, const QString& path) {
  try {
    AtomicFile file(path.toStdString(), "csv");
    std::ofstream out(file.tempPath());
    chart.writeCsv(out);
    out.close();
    if (!out) return false;
    file.commit();
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

void FilterWindow::replaceView() {
  auto* fresh = new QtVtkWidget(this);
  const bool shown = stack_->currentWidget() == view_;
  stack_->insertWidget(stack_->indexOf(view_), fresh);
  stack_->removeWidget(view_);
  delete view_;
  view_ = fresh;
  if (shown) stack_->setCurrentWidget(view_);
}

void FilterWindow::showPlaceholder(const QString& text) {
  placeholder_->setText(text);
  stack_->setCurrentWidget(placeholder_);
}

void FilterWindow::showView() {
  stack_->setCurrentWidget(view_);
}

QString FilterWindow::placeholder() const {
  return stack_->currentWidget() == placeholder_ ? placeholder_->text() : QString();
}

void FilterWindow::setSavable(bool savable, const QString& why) {
  for (QPushButton* b : {save_, csv_}) {
    b->setEnabled(savable);
    b->setToolTip(savable ? QString() : why);
  }
}

QString proposedPath(QStandardPaths::StandardLocation where, const QString& name) {
  QString folder = QStandardPaths::writableLocation(where);
  if (folder.isEmpty() || !QDir(folder).exists()) folder = QDir::homePath();
  return QDir(folder).filePath(name);
}

bool saveChartFigure(QtVtkWidget* view, const QString& path, QString* why) {
  try {
    if (figureFormat(path.toStdString(), "file") == FigureFormat::Png) {
      if (savePicture(view, path)) return true; // at File > Picture size
      throw ComputationError("cannot write " + path.toStdString());
    }
    view->makeCurrent(); // the exporter draws the chart again, in the widget's context
    try {
      writeFigure(view->renderWindow(), path.toStdString(), "file");
    } catch (...) {
      view->doneCurrent();
      throw;
    }
    view->doneCurrent();
    view->update();
    return true;
  } catch (const std::exception& e) {
    if (why) *why = QString::fromStdString(e.what());
    return false;
  }
}

void exportChartDialog(QWidget* parent, QtVtkWidget* view, const Chart& chart, const QString& name,
                       const std::function<void(const QString&)>& failed) {
  const QString path = askFigurePath(parent, "Export chart", name, "CSV data (*.csv)");
  if (path.isEmpty()) return;
  QString why = "cannot write " + path;
  const bool ok = path.endsWith(".csv", Qt::CaseInsensitive) ? saveChartCsv(chart, path)
                                                             : saveChartFigure(view, path, &why);
  if (!ok) failed(why);
}

bool FilterWindow::saveCsv(const QString& path) {
  const Chart* c = chart();
  return c && saveChartCsv(*c, path);
}

bool FilterWindow::saveFigure(const QString& path) {
  QString why;
  if (saveChartFigure(view_, path, &why)) return true;
  setStatus(why);
  return false;
}

} // namespace rv
