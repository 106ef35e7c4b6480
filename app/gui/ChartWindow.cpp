#include "app/gui/ChartWindow.h"

#include "app/gui/QtVtkWidget.h"
#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"
#include "dynamics/tools/ReturnMap.h"
#include "scenes/SceneCharts.h"
#include "scenes/SceneLoader.h"

#include <QFileDialog>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>
#include <fstream>

namespace rv {

ChartWindow::ChartWindow(const nlohmann::json& document, const std::string& source, const std::string& view,
                         QWidget* parent)
    : QWidget(parent, Qt::Window), viewName_(view) {
  setWindowTitle(QString("rollviz — %1").arg(QString::fromStdString(view)));
  view_ = new QtVtkWidget(this);
  status_ = new QLabel("computing…", this);
  auto* save = new QPushButton("Save PNG…", this);
  connect(save, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(
        this, "Save chart", QString::fromStdString(viewName_) + ".png", "PNG (*.png)");
    if (!path.isEmpty() && !savePng(path)) status_->setText("cannot write " + path);
  });
  auto* csv = new QPushButton("Save CSV…", this);
  connect(csv, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(
        this, "Save chart data", QString::fromStdString(viewName_) + ".csv", "CSV (*.csv)");
    if (!path.isEmpty() && !saveCsv(path)) status_->setText("cannot write " + path);
  });
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(view_, 1);
  auto* bottom = new QHBoxLayout;
  bottom->addWidget(status_, 1);
  bottom->addWidget(save);
  bottom->addWidget(csv);
  layout->addLayout(bottom);
  resize(640, 640);

  worker_ = std::thread([this, document, source, view] {
    std::unique_ptr<Chart> chart;
    QString failure;
    try {
      const Scene scene = sceneFromJson(document, source);
      ToolControl control;
      control.stopRequested = [this] { return stop_.load(); };
      chart = sceneChart(scene, view, control);
    } catch (const Stopped&) {
      failure = "stopped";
    } catch (const std::exception& e) {
      failure = e.what();
    }
    if (stop_) return; // the window is going away: it joins this thread
    // shared: if the window goes before the call is delivered, the discarded call frees the chart
    QMetaObject::invokeMethod(
        this, [this, c = std::shared_ptr<Chart>(std::move(chart)), failure] { deliver(c, failure); },
        Qt::QueuedConnection);
  });
}

ChartWindow::~ChartWindow() {
  stop_ = true;
  if (worker_.joinable()) worker_.join();
}

void ChartWindow::deliver(std::shared_ptr<Chart> chart, const QString& failure) {
  if (worker_.joinable()) worker_.join();
  failure_ = failure;
  if (chart) {
    chart_ = std::move(chart);
    chart_->attach(view_->renderWindow());
    status_->setText(QString::fromStdString(viewName_));
    view_->update();
  } else {
    status_->setText("failed: " + failure);
  }
  emit finished();
}

bool ChartWindow::saveCsv(const QString& path) {
  if (!chart_) return false;
  try {
    AtomicFile file(path.toStdString(), "csv");
    std::ofstream out(file.tempPath());
    chart_->writeCsv(out);
    out.close();
    if (!out) return false;
    file.commit();
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

bool ChartWindow::savePng(const QString& path) {
  return view_->grabFramebuffer().save(path, "PNG");
}

} // namespace rv
