// ParameterForm.h -- a form generated from a parameter table (design.md: parameters declared once generate
// GUI, CLI and scene keys): a spin box per number (its range, a whole-number box for integers), a combo box
// per choice, the manual's label and the description as tooltip.
#pragma once
#include "dynamics/core/ParameterTable.h"

#include <QWidget>

class QLabel;
#include <vector>

namespace rv {

class ParameterForm : public QWidget {
  Q_OBJECT
public:
  ParameterForm(const ParameterTable& table, QWidget* parent = nullptr);
  /// Shows these values (of the same table).
  void setValues(const ParameterValues& values);
  /// The values as edited.
  ParameterValues values() const;
  const ParameterTable& table() const { return table_; }
  /// The ids of the parameters the user changed since setValues (their labels are bold until then: a value
  /// that waits for Apply).
  std::vector<std::string> touched() const;
  /// The editor of parameter `id` (for tests), or nullptr.
  QWidget* editor(const std::string& id) const;
  /// What is wrong with the text typed into parameter `id`'s field (empty: nothing; shown next to the field).
  QString problem(const std::string& id) const;

signals:
  void edited();
  /// A field was left holding what it cannot take (out of range, not a number): Qt put back its last valid
  /// value; `message` says what was typed, why it was refused and what the field keeps.
  void rejected(const QString& message);

private:
  void touch(std::size_t i);
  const ParameterTable& table_;
  bool blocked_ = false;
  std::vector<QWidget*> editors_;
  std::vector<QLabel*> problems_;
  std::vector<QLabel*> labels_;
  std::vector<bool> touched_;
  std::vector<double> set_; ///< the values setValues showed: a field put back to its value is not pending
};

} // namespace rv
