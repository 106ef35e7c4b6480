// ParameterTable.h -- every parameter is declared once here; GUI fields, `--set ID=VALUE` and scene keys
// are all generated from these declarations.
#pragma once
#include <string>
#include <vector>

namespace rv {

/// Declaration of one numeric parameter (manual symbol in ASCII as the id).
struct ParameterSpec {
  std::string id;          ///< e.g. "I1", "energy"; the scene key and the --set name
  std::string label;       ///< label as in the manual, e.g. "I1" or "Energy"
  double defaultValue = 0; ///< value when a scene does not give one
  double min = -1e300;     ///< inclusive lower bound
  double max = 1e300;      ///< inclusive upper bound
  std::string unit;        ///< free text, may be empty
  std::string description; ///< one sentence for tooltips and `rollviz describe`
  bool integer = false;    ///< value must be a whole number (orders, counts)
  /// A choice among names (the value is the index; scenes and --set take the name), e.g. {"newton",
  /// "gradient"}. Empty for numbers.
  std::vector<std::string> choices;
};

/// An ordered list of parameter declarations.
class ParameterTable {
public:
  ParameterTable() = default;
  ParameterTable(std::initializer_list<ParameterSpec> specs) : specs_(specs) {}
  explicit ParameterTable(std::vector<ParameterSpec> specs) : specs_(std::move(specs)) {}
  /// Index of the parameter with this id, or -1.
  int find(const std::string& id) const;
  const std::vector<ParameterSpec>& specs() const { return specs_; }
  std::size_t size() const { return specs_.size(); }

private:
  std::vector<ParameterSpec> specs_;
};

/// Values of the parameters of one table, initialised to the defaults; setters validate the range.
class ParameterValues {
public:
  explicit ParameterValues(const ParameterTable& table);
  /// Sets a value; throws InputError naming `context` and the id when unknown or out of range.
  void set(const std::string& id, double value, const std::string& context = "");
  double get(const std::string& id) const;
  double operator[](const std::string& id) const { return get(id); }
  /// Sets a choice parameter by name; InputError listing the names otherwise.
  void setChoice(const std::string& id, const std::string& name, const std::string& context = "");
  /// The name of a choice parameter's value.
  const std::string& choice(const std::string& id) const;
  const ParameterTable& table() const { return *table_; }
  const std::vector<double>& values() const { return values_; }

private:
  const ParameterTable* table_;
  std::vector<double> values_;
};

} // namespace rv
