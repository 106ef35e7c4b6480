#include "app/gui/PlotFilterDialog.h"

#include "app/gui/ParameterForm.h"
#include "dynamics/tools/PlotFilter.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <algorithm>

namespace rv {

namespace {
QComboBox* observableBox(const Model& model, const std::string& chosen, QWidget* parent) {
  auto* box = new QComboBox(parent);
  for (const auto& o : model.observables()) {
    box->addItem(QString::fromStdString(o.id));
    box->setItemData(box->count() - 1, QString::fromStdString(o.description), Qt::ToolTipRole);
  }
  box->setCurrentText(QString::fromStdString(chosen));
  return box;
}
} // namespace

PlotFilterDialog::PlotFilterDialog(const Model& model, const PlotView& proposed, const ParameterValues& table,
                                   int dimensions, QWidget* parent)
    : QDialog(parent), proposed_(proposed) {
  setWindowTitle(QString("%1D plot filter").arg(dimensions));
  auto* form = new QFormLayout(this);
  const auto& axes = proposed.settings.axes;
  const char* defaults[3] = {"t", "E", "t"};
  const char* labels[3] = {"Axis X", "Axis Y", "Axis Z"};
  std::vector<std::string> taken; // an axis the scene does not give proposes an observable not yet on one
  for (int i = 0; i < dimensions; ++i) {
    std::string chosen = i < static_cast<int>(axes.size()) ? axes[i] : defaults[i];
    if (i >= static_cast<int>(axes.size()) && std::ranges::find(taken, chosen) != taken.end())
      for (const auto& o : model.observables())
        if (std::ranges::find(taken, o.id) == taken.end()) {
          chosen = o.id;
          break;
        }
    taken.push_back(chosen);
    axes_.push_back(observableBox(model, chosen, this));
    axes_.back()->setObjectName(QString("axis%1").arg(i));
    form->addRow(labels[i], axes_.back());
  }
  condition_ = observableBox(model, proposed.settings.condition, this);
  condition_->setObjectName("condition");
  condition_->setToolTip("a point is output whenever this has changed by the period since the last one");
  form->addRow("Out condition", condition_);
  form_ = new ParameterForm(plotTable(), this);
  form_->setValues(table);
  form->addRow(form_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  form->addRow(buttons);
}

PlotView PlotFilterDialog::plot() const {
  PlotView p = proposed_;
  p.settings.axes.clear();
  for (auto* a : axes_)
    p.settings.axes.push_back(a->currentText().toStdString());
  p.settings.condition = condition_->currentText().toStdString();
  applyPlotTable(form_->values(), p);
  return p;
}

} // namespace rv
