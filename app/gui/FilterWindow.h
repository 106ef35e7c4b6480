// FilterWindow.h -- what every filter window (manual §2.4) has: a chart view, a status line and Save figure
// (PNG, SVG, PDF) / Save CSV of the chart as drawn. The windows differ in where their chart comes from:
// computed whole on a worker thread (ChartWindow) or fed live by the running tools (PlotWindow,
// MultipliersWindow).
#pragma once
#include "render/charts/Chart.h"

#include <QStandardPaths>
#include <QWidget>
#include <functional>

class QLabel;
class QProgressBar;
class QPushButton;
class QHBoxLayout;
class QStackedWidget;

namespace rv {

class QtVtkWidget;

/// Where a save dialog proposes `name`: in the user's `where` folder (pictures, videos, documents), never the
/// working directory (often the source tree); the home folder when that one does not exist.
QString proposedPath(QStandardPaths::StandardLocation where, const QString& name);

/// Writes a chart's data as CSV through a temporary name; false when it cannot.
bool saveChartCsv(const Chart& chart, const QString& path);
/// Saves the chart as drawn in `view` as a figure in the format the name's extension names: PNG (the pixels),
/// SVG or PDF (vectors, text as text: render/export/Figure.h). False, with the reason in `why`, when it
/// cannot.
bool saveChartFigure(QtVtkWidget* view, const QString& path, QString* why);
/// Asks for a file name and saves the view as PNG, SVG or PDF or the chart as CSV (by the name's extension);
/// says why it could not in `failed`.
void exportChartDialog(QWidget* parent, QtVtkWidget* view, const Chart& chart, const QString& name,
                       const std::function<void(const QString&)>& failed);

class FilterWindow : public QWidget {
  Q_OBJECT
public:
  /// `fileName`: the suggested name of saved files, without extension.
  FilterWindow(const QString& title, const QString& fileName, QWidget* parent);
  QtVtkWidget* view() const { return view_; }
  /// Writes the chart as drawn to a PNG, SVG or PDF (by the extension); false, the reason in the status line,
  /// when it cannot.
  bool saveFigure(const QString& path);
  /// Writes the chart's data as CSV (through a temporary name); false when it cannot or nothing is drawn yet.
  bool saveCsv(const QString& path);

protected:
  /// The chart shown (nullptr while there is none yet).
  virtual const Chart* chart() const = 0;
  void setStatus(const QString& text);
  /// A fresh chart view in place of the old one (a new chart is never attached to a view that drew another).
  void replaceView();
  /// In place of the chart: a message ("computing …", why it failed) on a white page, not a black view.
  void showPlaceholder(const QString& text);
  /// The chart view again.
  void showView();
  /// Save figure / Save CSV enabled or not (`why` their tooltip when not).
  void setSavable(bool savable, const QString& why = {});
  /// The row under the chart, for a window's own controls (left of the save buttons).
  QHBoxLayout* bar() const { return bar_; }
  /// For windows whose chart is computed by a job: a progress bar and a stop button (`stopText`, `stopTip`)
  /// in the bar; a click runs `stop`.
  void addProgress(const QString& stopText, const QString& stopTip, const std::function<void()>& stop);
  /// Shows the progress bar and the stop button at `fraction` while the job runs, hides them otherwise.
  void showProgress(bool running, double fraction);

public:
  /// The placeholder's text while it shows (empty while the view shows).
  QString placeholder() const;
  /// The status line's text.
  QString status() const;

private:
  QtVtkWidget* view_;
  QStackedWidget* stack_;
  QLabel* placeholder_;
  QPushButton *save_, *csv_;
  QLabel* status_;
  QHBoxLayout* bar_;
  QProgressBar* progressBar_ = nullptr;
  QPushButton* stop_ = nullptr;
  QString fileName_;
};

} // namespace rv
