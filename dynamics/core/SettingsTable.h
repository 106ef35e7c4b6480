// SettingsTable.h -- a settings struct's parameter table, declared once: each parameter's declaration
// (ParameterTable.h: scene key, `--set`, GUI field, `describe-tool` line) beside the member of the struct it
// sets. The table takes its defaults from a default-constructed struct, and read() fills the struct from a
// scene section's values, so no tool writes its defaults twice or a mapper from values to its settings.
#pragma once
#include "dynamics/core/ParameterTable.h"

#include <algorithm>
#include <functional>
#include <initializer_list>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace rv {

template <class S> class SettingsTable {
public:
  /// One parameter: its declaration and how its value sets the struct (none: a parameter the tool reads by
  /// id where it uses it, e.g. fixedpoint.order).
  struct Field {
    ParameterSpec spec;
    std::function<void(const ParameterValues&, S&)> set = {};
  };

  SettingsTable(std::initializer_list<Field> fields) : fields_(fields), table_(specs(fields_)) {}

  /// A number held by `member` (a member pointer, or a function of S& giving a reference to a nested
  /// member): its default is the default struct's; an integral member makes it a whole number.
  template <class Member> static Field number(Member member, ParameterSpec spec) {
    using T = std::remove_cvref_t<std::invoke_result_t<Member, S&>>;
    S defaults;
    spec.defaultValue = static_cast<double>(std::invoke(member, defaults));
    if constexpr (std::is_integral_v<T>) spec.integer = true;
    std::string id = spec.id;
    return {std::move(spec), [member, id = std::move(id)](const ParameterValues& v, S& s) {
              std::invoke(member, s) = static_cast<T>(v[id]);
            }};
  }

  /// The same with a default of the table's own where the struct's cannot be written (an open side of a box:
  /// the struct's infinity, the table's 1e300).
  template <class Member> static Field number(Member member, ParameterSpec spec, double defaultValue) {
    Field f = number(member, std::move(spec));
    f.spec.defaultValue = defaultValue;
    return f;
  }

  /// A choice among spec.choices held by `member` as the value of the same place in `values` (an enum, a
  /// bool): its default is the name of the default struct's value.
  template <class Member, class T>
  static Field choice(Member member, ParameterSpec spec, std::vector<T> values) {
    S defaults;
    const auto at = std::find(values.begin(), values.end(), std::invoke(member, defaults));
    spec.defaultValue = static_cast<double>(at - values.begin());
    spec.min = 0;
    spec.max = static_cast<double>(spec.choices.size()) - 1;
    spec.integer = true;
    std::string id = spec.id;
    return {std::move(spec),
            [member, values = std::move(values), id = std::move(id)](const ParameterValues& v, S& s) {
              std::invoke(member, s) = values.at(static_cast<std::size_t>(v[id]));
            }};
  }

  const ParameterTable& table() const { return table_; }
  /// The settings the values give, on top of `s` (the members no parameter sets keep its values).
  S read(const ParameterValues& v, S s = S{}) const {
    for (const auto& f : fields_)
      if (f.set) f.set(v, s);
    return s;
  }

private:
  static std::vector<ParameterSpec> specs(const std::vector<Field>& fields) {
    std::vector<ParameterSpec> s;
    s.reserve(fields.size());
    for (const auto& f : fields)
      s.push_back(f.spec);
    return s;
  }
  std::vector<Field> fields_;
  ParameterTable table_;
};

} // namespace rv
