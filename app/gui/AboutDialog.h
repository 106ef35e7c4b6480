// AboutDialog.h -- Help > About: the version, the libraries, and the renderers behind the pictures (the
// on-screen view's GL and, from `rollviz info --json` run beside the GUI, the headless one), with the
// software-GL warning.
#pragma once
#include <QDialog>

class QLabel;
class QProcess;

namespace rv {

class QtVtkWidget;

class AboutDialog : public QDialog {
  Q_OBJECT
public:
  /// `view` is asked for its GL strings; the headless renderer is filled in when `rollviz info` answers.
  AboutDialog(QtVtkWidget* view, QWidget* parent);

signals:
  /// The headless renderer's section is filled (or says why it could not be).
  void headlessKnown();

private:
  void showHeadless(const QString& html);
  QLabel* text_;
  QString head_;
  QProcess* info_ = nullptr;
};

} // namespace rv
