// RollingBodyDialog.h -- File > New rolling body: a body described by what it is (its shape and sizes, where
// its centre of mass lies, its mass and principal moments, what it rolls on -- the plane, a sphere, an
// ellipsoid, a paraboloid bowl -- and how it touches it), written as a rolling model file
// (scenes/RollingModel.h, docs/rolling.md) whose equations rollviz derives, and opened.
#pragma once
#include "scenes/RollingModel.h"

#include <QDialog>
#include <array>
#include <functional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;

namespace rv {

class RollingBodyDialog : public QDialog {
public:
  /// `open` opens the model file written (the main window's openModel).
  RollingBodyDialog(QWidget* parent, std::function<void(const QString&)> open);
  /// The form as filled in.
  RollingBodyForm form() const;
  /// Checks the body (the model it makes must load and roll from its start), writes the file and opens it;
  /// false, with the reason shown in the dialog, when it cannot.
  bool create();

private:
  /// Shows the fields the shape and the support chosen have.
  void showFields();
  /// Shows or hides a row of the form: `field` and its label.
  void showRow(QWidget* field, bool visible);
  QFormLayout* rows_;
  QLineEdit *id_, *surface_, *profile_, *file_, *supportSurface_;
  QComboBox *shape_, *contact_, *support_, *side_;
  std::array<QDoubleSpinBox*, 3> sizes_{}, centre_{}, inertia_{}, supportSizes_{};
  std::array<QDoubleSpinBox*, 2> heights_{};
  std::array<QLabel*, 3> sizeLabels_{}, supportLabels_{};
  QDoubleSpinBox *exponent_, *bulge_, *bound_, *mass_, *friction_, *gravity_;
  QWidget* heightsRow_;
  QCheckBox *profileSquared_, *axis_;
  QLabel* error_;
  std::function<void(const QString&)> open_;
};

} // namespace rv
