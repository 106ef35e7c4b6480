#include "app/gui/ParameterForm.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QVBoxLayout>
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
  form->setRowWrapPolicy(QFormLayout::WrapLongRows); // a narrow panel puts the field under its label
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
      box->setKeyboardTracking(false); // a value is taken when committed, never half-typed
      box->setRange(static_cast<int>(std::max(s.min, -2e9)), static_cast<int>(std::min(s.max, 2e9)));
      connect(box, &QSpinBox::valueChanged, this, [this, i = editors_.size()] { touch(i); });
      editor = box;
    } else {
      auto* box = new NumberBox(this); // parameters such as accuracies span many decades
      box->setKeyboardTracking(false); // "1e400" typed is not "1e4" taken on the way
      box->setRange(std::max(s.min, -1e12), std::min(s.max, 1e12));
      box->setSingleStep(
          s.defaultValue != 0 ? std::pow(10.0, std::floor(std::log10(std::abs(s.defaultValue)))) / 10 : 0.1);
      connect(box, &QDoubleSpinBox::valueChanged, this, [this, i = editors_.size()] { touch(i); });
      editor = box;
    }
    editor->setObjectName(QString::fromStdString(s.id));
    editor->setMinimumWidth(90); // fields shrink with the panel instead of a horizontal scroll bar
    const QString tip =
        QString::fromStdString(s.id + ": " + s.description + (s.unit.empty() ? "" : " (" + s.unit + ")"));
    editor->setToolTip(tip);
    auto* label = new QLabel(QString::fromStdString(s.label), this);
    label->setToolTip(tip);
    // the field and, under it, what is wrong with what is typed (shown only then)
    auto* field = new QWidget(this);
    auto* column = new QVBoxLayout(field);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(1);
    column->addWidget(editor);
    auto* problem = new QLabel(field);
    problem->setObjectName(QString::fromStdString(s.id) + "_problem");
    problem->setStyleSheet("color: #b00020");
    problem->setWordWrap(true); // the whole range shows in a narrow panel
    problem->hide();
    column->addWidget(problem);
    if (auto* box = qobject_cast<QAbstractSpinBox*>(editor)) {
      const auto bound = [](double v) { // the tables write infinity as 1e300
        return std::abs(v) >= 1e300 ? QString(v < 0 ? "-inf" : "inf") : QString::number(v, 'g', 6);
      };
      const QString range = QString("must lie in [%1, %2]").arg(bound(s.min), bound(s.max));
      connect(box->findChild<QLineEdit*>(), &QLineEdit::textEdited, this,
              [box, problem, range](const QString& t) {
                QString text = t;
                int pos = 0;
                const bool ok = box->validate(text, pos) == QValidator::Acceptable;
                bool number = false;
                t.trimmed().toDouble(&number);
                problem->setText(ok ? QString() : number ? range : "not a number");
                problem->setProperty("typed", t.trimmed());
                problem->setVisible(!ok);
              });
      // leaving the field, Qt puts back the last valid value: say so (where it lasts) rather than silently
      connect(box, &QAbstractSpinBox::editingFinished, this, [this, box, problem, label = s.label] {
        if (problem->isHidden()) return;
        emit rejected(QString("%1: %2 %3; kept %4")
                          .arg(QString::fromStdString(label), problem->property("typed").toString(),
                               problem->text(), QString::number(box->property("value").toDouble(), 'g', 15)));
      });
      connect(box, &QAbstractSpinBox::editingFinished, problem, &QLabel::hide);
    }
    form->addRow(label, field);
    labels_.push_back(label);
    editors_.push_back(editor);
    problems_.push_back(problem);
  }
  touched_.assign(editors_.size(), false);
  setValues(ParameterValues(table));
}

void ParameterForm::touch(std::size_t i) {
  if (blocked_) return;
  // a changed value not yet run: its label says so until Apply (or another scene) sets the values again, or
  // the value is put back to what was set
  const bool changed = i >= set_.size() || values().values()[i] != set_[i];
  touched_[i] = changed;
  QFont font = labels_[i]->font();
  font.setBold(changed);
  labels_[i]->setFont(font);
  labels_[i]->setProperty("pending", changed);
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
  for (QLabel* l : labels_) {
    QFont plain = l->font();
    plain.setBold(false);
    l->setFont(plain);
    l->setProperty("pending", false);
  }
  for (std::size_t i = 0; i < editors_.size(); ++i) {
    const double v = values.values()[i];
    if (auto* c = qobject_cast<QComboBox*>(editors_[i]))
      c->setCurrentIndex(static_cast<int>(v));
    else if (auto* n = qobject_cast<QSpinBox*>(editors_[i]))
      n->setValue(static_cast<int>(v));
    else if (auto* d = qobject_cast<QDoubleSpinBox*>(editors_[i]))
      d->setValue(v);
  }
  set_ = this->values().values(); // as the fields show them (a spin box rounds to its decimals)
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

QString ParameterForm::problem(const std::string& id) const {
  const int i = table_.find(id);
  return i >= 0 && !problems_[i]->isHidden() ? problems_[i]->text() : QString();
}

} // namespace rv
