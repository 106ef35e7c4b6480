#include "app/gui/ParameterForm.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>
#include <QValidator>
#include <algorithm>
#include <cmath>

namespace rv {

namespace {
// a spin box that shows numbers as %g (0.5, 1e-15) and keeps them exact (no rounding to fixed decimals)
class NumberBox : public QDoubleSpinBox {
public:
  explicit NumberBox(QWidget* parent) : QDoubleSpinBox(parent) { setDecimals(323); }
  QString textFromValue(double v) const override { return QString::number(v, 'g', 15); }
  double valueFromText(const QString& text) const override { return text.toDouble(); }
  QValidator::State validate(QString& text, int&) const override {
    bool ok = false;
    const double v = text.toDouble(&ok);
    if (!ok) return QValidator::Intermediate; // "1e-", "-" while typing
    return v >= minimum() && v <= maximum() ? QValidator::Acceptable : QValidator::Intermediate;
  }
};
} // namespace

ParameterForm::ParameterForm(const ParameterTable& table, QWidget* parent) : QWidget(parent), table_(table) {
  auto* form = new QFormLayout(this);
  form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
  for (const auto& s : table.specs()) {
    QWidget* editor = nullptr;
    if (!s.choices.empty()) {
      auto* box = new QComboBox(this);
      for (const auto& c : s.choices)
        box->addItem(QString::fromStdString(c));
      connect(box, &QComboBox::currentIndexChanged, this, [this, i = editors_.size()] { touch(i); });
      editor = box;
    } else if (s.integer) {
      auto* box = new QSpinBox(this);
      box->setRange(static_cast<int>(std::max(s.min, -2e9)), static_cast<int>(std::min(s.max, 2e9)));
      connect(box, &QSpinBox::valueChanged, this, [this, i = editors_.size()] { touch(i); });
      editor = box;
    } else {
      auto* box = new NumberBox(this); // parameters such as accuracies span many decades
      box->setRange(std::max(s.min, -1e12), std::min(s.max, 1e12));
      box->setSingleStep(
          s.defaultValue != 0 ? std::pow(10.0, std::floor(std::log10(std::abs(s.defaultValue)))) / 10 : 0.1);
      connect(box, &QDoubleSpinBox::valueChanged, this, [this, i = editors_.size()] { touch(i); });
      editor = box;
    }
    editor->setObjectName(QString::fromStdString(s.id));
    const QString tip =
        QString::fromStdString(s.id + ": " + s.description + (s.unit.empty() ? "" : " (" + s.unit + ")"));
    editor->setToolTip(tip);
    auto* label = new QLabel(QString::fromStdString(s.label), this);
    label->setToolTip(tip);
    form->addRow(label, editor);
    editors_.push_back(editor);
  }
  touched_.assign(editors_.size(), false);
  setValues(ParameterValues(table));
}

void ParameterForm::touch(std::size_t i) {
  if (blocked_) return;
  touched_[i] = true;
  emit edited();
}

std::vector<std::string> ParameterForm::touched() const {
  std::vector<std::string> ids;
  for (std::size_t i = 0; i < touched_.size(); ++i)
    if (touched_[i]) ids.push_back(table_.specs()[i].id);
  return ids;
}

void ParameterForm::setValues(const ParameterValues& values) {
  blocked_ = true; // programmatic changes are not the user's edits
  touched_.assign(editors_.size(), false);
  for (std::size_t i = 0; i < editors_.size(); ++i) {
    const double v = values.values()[i];
    if (auto* c = qobject_cast<QComboBox*>(editors_[i]))
      c->setCurrentIndex(static_cast<int>(v));
    else if (auto* n = qobject_cast<QSpinBox*>(editors_[i]))
      n->setValue(static_cast<int>(v));
    else if (auto* d = qobject_cast<QDoubleSpinBox*>(editors_[i]))
      d->setValue(v);
  }
  blocked_ = false;
}

ParameterValues ParameterForm::values() const {
  ParameterValues v(table_);
  const auto& specs = table_.specs();
  for (std::size_t i = 0; i < editors_.size(); ++i) {
    double x = 0;
    if (auto* c = qobject_cast<QComboBox*>(editors_[i]))
      x = c->currentIndex();
    else if (auto* n = qobject_cast<QSpinBox*>(editors_[i]))
      x = n->value();
    else if (auto* d = qobject_cast<QDoubleSpinBox*>(editors_[i]))
      x = d->value();
    v.set(specs[i].id, x);
  }
  return v;
}

QWidget* ParameterForm::editor(const std::string& id) const {
  const int i = table_.find(id);
  return i < 0 ? nullptr : editors_[i];
}

} // namespace rv
