// PlotFilterDialog.h -- the settings of a 2D / 3D plot filter (manual §2.4.1-§2.4.2) asked when it is
// created: the observables on the axes and the output condition (from the problem's list, with its
// descriptions as tooltips), the period, the maximum number of points per trajectory and the point type.
#pragma once
#include "scenes/Scene.h"

#include <QDialog>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace rv {

class PlotFilterDialog : public QDialog {
  Q_OBJECT
public:
  /// `proposed`: the values shown first (the scene's plot section); `dimensions` 2 or 3.
  PlotFilterDialog(const Model& model, const PlotView& proposed, int dimensions, QWidget* parent = nullptr);
  /// The settings as chosen.
  PlotView plot() const;

private:
  PlotView proposed_;
  std::vector<QComboBox*> axes_;
  QComboBox* condition_;
  QDoubleSpinBox* period_;
  QSpinBox* maxPoints_;
  QComboBox* pointType_;
};

} // namespace rv
