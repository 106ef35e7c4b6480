// PlotFilterDialog.h -- the settings of a 2D / 3D plot filter (manual §2.4.1-§2.4.2) asked when it is
// created: the observables on the axes and the output condition (from the problem's list, with its
// descriptions as tooltips), and the form of the "plot" section's table (period, points, time limit, window).
#pragma once
#include "scenes/Scene.h"

#include <QDialog>
#include <vector>

class QComboBox;

namespace rv {

class ParameterForm;

class PlotFilterDialog : public QDialog {
  Q_OBJECT
public:
  /// `proposed` and `table`: the values shown first (the scene's plot section and its table's values);
  /// `dimensions` 2 or 3.
  PlotFilterDialog(const Model& model, const PlotView& proposed, const ParameterValues& table, int dimensions,
                   QWidget* parent = nullptr);
  /// The settings as chosen.
  PlotView plot() const;

private:
  PlotView proposed_;
  std::vector<QComboBox*> axes_;
  QComboBox* condition_;
  ParameterForm* form_;
};

} // namespace rv
