#include "app/gui/FilterWindow.h"

#include "app/gui/QtVtkWidget.h"
#include "dynamics/io/AtomicFile.h"

#include <QFileDialog>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>
#include <fstream>

namespace rv {

FilterWindow::FilterWindow(const QString& title, const QString& fileName, QWidget* parent)
    : QWidget(parent, Qt::Window), fileName_(fileName) {
  setWindowTitle("rollviz — " + title);
  view_ = new QtVtkWidget(this);
  status_ = new QLabel(this);
  auto* save = new QPushButton("Save PNG…", this);
  connect(save, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, "Save chart", fileName_ + ".png", "PNG (*.png)");
    if (!path.isEmpty() && !savePng(path)) setStatus("cannot write " + path);
  });
  auto* csv = new QPushButton("Save CSV…", this);
  connect(csv, &QPushButton::clicked, this, [this] {
    const QString path =
        QFileDialog::getSaveFileName(this, "Save chart data", fileName_ + ".csv", "CSV (*.csv)");
    if (!path.isEmpty() && !saveCsv(path)) setStatus("cannot write " + path);
  });
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(view_, 1);
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
  delete layout()->replaceWidget(view_, fresh);
  delete view_;
  view_ = fresh;
}

void exportChartDialog(QWidget* parent, QtVtkWidget* view, const Chart& chart, const QString& name,
                       const std::function<void(const QString&)>& failed) {
  const QString path = QFileDialog::getSaveFileName(parent, "Export chart", name + ".png",
                                                    "PNG picture (*.png);;CSV data (*.csv)");
  if (path.isEmpty()) return;
  const bool ok = path.endsWith(".csv", Qt::CaseInsensitive) ? saveChartCsv(chart, path)
                                                             : view->grabFramebuffer().save(path, "PNG");
  if (!ok) failed("cannot write " + path);
}

bool FilterWindow::saveCsv(const QString& path) {
  const Chart* c = chart();
  return c && saveChartCsv(*c, path);
}

bool FilterWindow::savePng(const QString& path) {
  return view_->grabFramebuffer().save(path, "PNG");
}

} // namespace rv
