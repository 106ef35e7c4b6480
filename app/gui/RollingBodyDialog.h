// RollingBodyDialog.h -- File > New rolling body: a body on the plane described by what it is (its shape and
// sizes, where its centre of mass lies, its mass and principal moments, how it touches the plane), written as
// a rolling model file (scenes/RollingModel.h, docs/rolling.md) whose equations rollviz derives, and opened.
#pragma once
#include "scenes/RollingModel.h"

#include <QDialog>
#include <array>
#include <functional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;

namespace rv {

class RollingBodyDialog : public QDialog {
public:
  /// `open` opens the model file written (the main window's openModel).
  RollingBodyDialog(QWidget* parent, std::function<void(const QString&)> open);
  /// The form as filled in.
  RollingBodyForm form() const;
  /// Checks the body (the model it makes must load), writes the file and opens it; false, with the reason
  /// shown in the dialog, when it cannot.
  bool create();

private:
  void showShape();
  QLineEdit *id_, *surface_, *file_;
  QComboBox *shape_, *contact_;
  std::array<QDoubleSpinBox*, 3> sizes_{}, centre_{}, inertia_{};
  std::array<QLabel*, 3> sizeLabels_{};
  QDoubleSpinBox *bound_, *mass_, *friction_, *gravity_;
  QCheckBox* axis_;
  QLabel* error_;
  std::function<void(const QString&)> open_;
};

} // namespace rv
