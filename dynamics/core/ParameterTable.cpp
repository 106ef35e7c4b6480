#include "dynamics/core/ParameterTable.h"

#include "dynamics/core/Errors.h"

#include <cmath>
#include <sstream>

namespace rv {

int ParameterTable::find(const std::string& id) const {
  for (std::size_t i = 0; i < specs_.size(); ++i)
    if (specs_[i].id == id) return static_cast<int>(i);
  return -1;
}

ParameterValues::ParameterValues(const ParameterTable& table) : table_(&table) {
  for (const auto& s : table.specs())
    values_.push_back(s.defaultValue);
}

void ParameterValues::set(const std::string& id, double value, const std::string& context) {
  const std::string where = context.empty() ? id : context;
  const int i = table_->find(id);
  if (i < 0) {
    std::ostringstream known;
    for (const auto& s : table_->specs())
      known << ' ' << s.id;
    throw InputError(where + ": unknown parameter '" + id + "' (known:" + known.str() + ")");
  }
  const ParameterSpec& s = table_->specs()[i];
  if (!std::isfinite(value)) throw InputError(where + ": " + id + " must be a finite number");
  if (value < s.min || value > s.max) {
    std::ostringstream os;
    os << where << ": " << id << " = " << value << " is out of range [" << s.min << ", " << s.max << "]";
    throw InputError(os.str());
  }
  if (s.integer && value != std::floor(value))
    throw InputError(where + ": " + id + " must be a whole number");
  values_[i] = value;
}

void ParameterValues::setChoice(const std::string& id, const std::string& name, const std::string& context) {
  const int i = table_->find(id);
  if (i < 0) return set(id, 0, context); // reports the unknown id
  const auto& c = table_->specs()[i].choices;
  for (std::size_t k = 0; k < c.size(); ++k)
    if (c[k] == name) return set(id, static_cast<double>(k), context);
  std::string known;
  for (const auto& n : c)
    known += " " + n;
  throw InputError((context.empty() ? id : context) + ": " + id + " is one of" + known + ", not '" + name +
                   "'");
}

const std::string& ParameterValues::choice(const std::string& id) const {
  const int i = table_->find(id);
  if (i < 0 || table_->specs()[i].choices.empty()) throw InputError("no choice parameter '" + id + "'");
  return table_->specs()[i].choices[static_cast<std::size_t>(values_[i])];
}

double ParameterValues::get(const std::string& id) const {
  const int i = table_->find(id);
  if (i < 0) throw InputError("no parameter '" + id + "'");
  return values_[i];
}

} // namespace rv
